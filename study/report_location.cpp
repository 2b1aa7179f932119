#include "study/report_location.hpp"

#include <map>
#include <string>

namespace vimg::study {

namespace {

constexpr LocationMetaphor kMetaphorOrder[] = {LocationMetaphor::roughness, LocationMetaphor::transition_cue};

}  // namespace

LocationReport make_location_report(const std::vector<LocationTrial>& trials, const Workspace& workspace) {
  LocationReport report;
  report.workspace = workspace;
  std::map<LocationMetaphor, std::vector<double>> errors;
  std::map<LocationMetaphor, double> chance_sum;
  std::map<std::string, std::map<LocationMetaphor, std::vector<double>>> by_participant;
  double chance_total = 0.0;
  for (const LocationTrial& t : trials) {
    const double chance = expected_uniform_distance_mm(workspace, t.target_x_mm, t.target_z_mm);
    errors[t.metaphor].push_back(t.error_mm);
    chance_sum[t.metaphor] += chance;
    chance_total += chance;
    by_participant[t.participant][t.metaphor].push_back(t.error_mm);
  }
  if (!trials.empty()) report.chance_mm = chance_total / static_cast<double>(trials.size());
  std::vector<LocationMetaphor> present;
  for (const LocationMetaphor m : kMetaphorOrder) {
    const auto found = errors.find(m);
    if (found == errors.end()) continue;
    present.push_back(m);
    const Summary s = summarize(found->second);
    MetaphorReport r;
    r.name = std::string(location_metaphor_name(m));
    r.n = s.n;
    r.mean_mm = s.mean;
    r.sd_mm = s.sd;
    if (s.sd) r.ci99_mm = t_interval_of_mean(s.mean, *s.sd, s.n, 0.99);
    r.chance_mm = chance_sum[m] / static_cast<double>(s.n);
    report.metaphors.push_back(r);
  }
  for (std::size_t i = 0; i < present.size(); ++i) {
    for (std::size_t j = i + 1; j < present.size(); ++j) {
      report.metaphor_comparisons.push_back(compare_groups(report.metaphors[i].name, errors[present[i]],
                                                           report.metaphors[j].name, errors[present[j]]));
    }
  }
  for (const auto& [id, per_metaphor] : by_participant) {
    ParticipantLocation p;
    p.participant = id;
    for (const LocationMetaphor m : present) {
      ParticipantMetaphorMean mean;
      mean.metaphor = std::string(location_metaphor_name(m));
      if (const auto found = per_metaphor.find(m); found != per_metaphor.end()) {
        const Summary s = summarize(found->second);
        mean.n = s.n;
        mean.mean_mm = s.mean;
      }
      p.metaphors.push_back(mean);
    }
    report.participants.push_back(p);
  }
  return report;
}

}  // namespace vimg::study
