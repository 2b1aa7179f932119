#include "study/report_matching.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace vimg::study {

namespace {

std::size_t index_of(const std::vector<std::string>& sorted, const std::string& name) {
  return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), name) - sorted.begin());
}

std::optional<double> ratio(std::size_t numerator, std::size_t denominator) {
  if (denominator == 0) return std::nullopt;
  return static_cast<double>(numerator) / static_cast<double>(denominator);
}

SetReport make_set_report(const std::string& name, const std::vector<const MatchingTrial*>& trials) {
  SetReport s;
  s.name = name;
  for (const MatchingTrial* t : trials) {
    s.images.push_back(t->presented);
    s.images.push_back(t->chosen);
  }
  std::sort(s.images.begin(), s.images.end());
  s.images.erase(std::unique(s.images.begin(), s.images.end()), s.images.end());
  const std::size_t n = s.images.size();
  s.comparison.assign(n, std::vector<std::size_t>(n, 0));
  std::map<std::string, ParticipantAccuracy> participants;
  for (const MatchingTrial* t : trials) {
    const bool correct = t->presented == t->chosen;
    ++s.comparison[index_of(s.images, t->presented)][index_of(s.images, t->chosen)];
    ParticipantAccuracy& p = participants[t->participant];
    p.participant = t->participant;
    ++p.trials;
    if (correct) ++p.correct;
  }
  s.trials = trials.size();
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t presented = 0, chosen = 0;
    for (std::size_t j = 0; j < n; ++j) {
      presented += s.comparison[i][j];
      chosen += s.comparison[j][i];
    }
    ImageCounts c;
    c.image = s.images[i];
    c.tp = s.comparison[i][i];
    c.fn = presented - c.tp;
    c.fp = chosen - c.tp;
    c.tn = s.trials - c.tp - c.fn - c.fp;
    c.hit_rate = ratio(c.tp, c.tp + c.fn);
    c.false_alarm_rate = ratio(c.fp, c.fp + c.tn);
    s.correct += c.tp;
    s.per_image.push_back(c);
  }
  s.accuracy = s.trials > 0 ? static_cast<double>(s.correct) / static_cast<double>(s.trials) : 0.0;
  s.accuracy_ci95 = wilson_interval(s.correct, s.trials, 0.95);
  s.chance = n > 0 ? 1.0 / static_cast<double>(n) : 0.0;
  for (auto& [id, p] : participants) {
    p.accuracy = static_cast<double>(p.correct) / static_cast<double>(p.trials);
    s.participants.push_back(p);
  }
  return s;
}

std::vector<double> participant_accuracies(const SetReport& s) {
  std::vector<double> values;
  for (const ParticipantAccuracy& p : s.participants) values.push_back(p.accuracy);
  return values;
}

}  // namespace

MatchingReport make_matching_report(const std::vector<MatchingTrial>& trials) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const MatchingTrial*>> by_set;
  for (const MatchingTrial& t : trials) {
    auto& rows = by_set[t.set];
    if (rows.empty()) order.push_back(t.set);
    rows.push_back(&t);
  }
  MatchingReport report;
  for (const std::string& name : order) report.sets.push_back(make_set_report(name, by_set[name]));
  for (std::size_t i = 0; i < report.sets.size(); ++i) {
    for (std::size_t j = i + 1; j < report.sets.size(); ++j) {
      report.set_comparisons.push_back(compare_groups(report.sets[i].name, participant_accuracies(report.sets[i]),
                                                      report.sets[j].name, participant_accuracies(report.sets[j])));
    }
  }
  return report;
}

}  // namespace vimg::study
