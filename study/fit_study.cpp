#include "study/fit_study.hpp"

#include <map>
#include <set>
#include <utility>

#include "storage/diagnostic.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"

namespace vimg::study {

namespace {

// The study's sets by name, each with its images' stems.
struct StudyIndex {
  std::vector<std::string> set_names;
  std::vector<std::vector<std::string>> stems;

  std::optional<std::size_t> set(const std::string& name) const {
    for (std::size_t s = 0; s < set_names.size(); ++s) {
      if (set_names[s] == name) return s;
    }
    return std::nullopt;
  }
  std::optional<std::size_t> image(std::size_t s, const std::string& stem) const {
    for (std::size_t i = 0; i < stems[s].size(); ++i) {
      if (stems[s][i] == stem) return i;
    }
    return std::nullopt;
  }
};

// Why trial `t` is not of the study, or nothing.
std::optional<std::string> foreign(const MatchingTrial& t, const StudyIndex& index, const std::string& study) {
  const auto s = index.set(t.set);
  if (!s) {
    return "set '" + t.set + "' is not a set of " + study + " (its sets: " + listed_names(index.set_names) +
           "): a trial file of another study?";
  }
  for (const std::string* image : {&t.presented, &t.chosen}) {
    if (!index.image(*s, *image)) {
      return "image '" + *image + "' is not in set '" + t.set + "' of " + study + " (its images: " + listed_names(index.stems[*s]) +
             "): a trial file of another study?";
    }
  }
  return std::nullopt;
}

void say(const StudyFitRequest& r, const std::string& line) {
  if (r.progress) r.progress(line);
}

}  // namespace

StudyFitInputs read_study_fit_inputs(const StudyFitRequest& request) {
  StudyFitInputs in;
  const std::string study_name = request.study.string();
  StudyFileResult<MatchingStudy> loaded = load_matching_study(request.study);
  append_diagnostics(in.diagnostics, std::move(loaded.diagnostics));
  if (!loaded.study) return in;
  const MatchingStudy& study = *loaded.study;
  StudyIndex index;
  for (const StudyImageSet& set : study.sets) {
    index.set_names.push_back(set.name);
    index.stems.emplace_back();
    for (const auto& image : set.images) index.stems.back().push_back(study_image_name(image));
  }

  // [participant][set][presented][chosen]
  std::map<std::string, std::vector<ChoiceCounts>> counts;
  std::map<std::pair<std::string, int>, std::pair<std::string, int>> seen;
  for (const auto& path : request.trial_files) {
    const std::string file = path.string();
    const TrialFileKind kind = trial_file_kind(path);
    if (kind == TrialFileKind::location) {
      in.diagnostics.push_back({Diagnostic::Severity::error, file, 1,
                                "a trial file of the location study; the model is fitted on the matching test's trials"});
      continue;
    }
    TrialTableResult<MatchingTrial> table = read_matching_trials(path);
    const bool ok = table.ok();
    append_diagnostics(in.diagnostics, std::move(table.diagnostics));
    if (!ok) continue;
    for (std::size_t k = 0; k < table.rows.size(); ++k) {
      const MatchingTrial& t = table.rows[k];
      const int line = static_cast<int>(k) + 2;
      if (const auto why = foreign(t, index, study_name)) {
        in.diagnostics.push_back({Diagnostic::Severity::error, file, line, *why});
        break;
      }
      const auto [at, inserted] = seen.try_emplace({t.participant, t.trial}, file, line);
      if (!inserted) {
        in.diagnostics.push_back({Diagnostic::Severity::error, file, line,
                                  "participant '" + t.participant + "' trial " + std::to_string(t.trial) + " is also at " +
                                      at->second.first + ":" + std::to_string(at->second.second) +
                                      " (a file given twice, or two logs that overlap)"});
        break;
      }
      std::vector<ChoiceCounts>& mine = counts[t.participant];
      if (mine.empty()) {
        for (const auto& stems : index.stems) mine.emplace_back(stems.size(), std::vector<double>(stems.size(), 0.0));
      }
      const std::size_t s = *index.set(t.set);
      mine[s][*index.image(s, t.presented)][*index.image(s, t.chosen)] += 1.0;
    }
  }
  if (has_errors(in.diagnostics)) return in;

  FitData& data = in.data;
  data.set_names = index.set_names;
  for (auto& [participant, sets] : counts) {
    data.participants.push_back(participant);
    data.counts.push_back(std::move(sets));
  }
  // Sets without trials are not rendered: they add nothing to the likelihood.
  for (std::size_t s = 0; s < study.sets.size(); ++s) {
    double trials = 0.0;
    for (const auto& sets : data.counts) trials += set_trials(sets[s]);
    if (trials == 0.0) {
      data.set_cues.emplace_back(CueMatrix(index.stems[s].size(), std::vector<CueDistances>(index.stems[s].size(), CueDistances{})));
      continue;
    }
    ++in.sets_with_trials;
    say(request, "rendering set '" + study.sets[s].name + "' (" + std::to_string(study.sets[s].images.size()) +
                     " images) as vimg compare does, through the actuator " + request.actuator.name);
    CompareRequest compare;
    compare.inputs = study.sets[s].images;
    compare.actuator = request.actuator;
    compare.discrimination = request.defaults;
    compare.stsim = false;  // the fit reads the cues only
    compare.should_stop = request.should_stop;
    CompareResult r = run_compare(compare);
    if (r.interrupted) {
      in.interrupted = true;
      return in;
    }
    append_diagnostics(in.diagnostics, std::move(r.diagnostics));
    if (!r.ok()) return in;
    data.set_cues.push_back(std::move(r.cues));
  }
  return in;
}

PerceptionModel perception_model_of(const ModelFit& fit, const StudyFitRequest& request, const FitData& data) {
  PerceptionModel m;
  m.constants = fit.constants;
  m.bootstrap_replicates = fit.bootstrap_replicates;
  for (const ConstantFit& c : fit.report) {
    if (!c.fitted) continue;
    m.fitted.push_back(c.name);
    m.intervals.push_back({c.name, c.lower, c.upper, c.profile_lower, c.profile_upper});
  }
  m.study = request.study.string();
  m.actuator.given = request.actuator.file.empty() ? request.actuator.name : request.actuator.file;
  m.actuator.name = request.actuator.name;
  m.actuator.response = request.actuator.response;
  for (const auto& f : request.trial_files) m.trial_files.push_back(f.string());
  m.participants = data.participants.size();
  m.in_sample = {"", fit.trials, fit.ll_fitted, fit.ll_baseline, fit.ll_default, fit.ll_chance};
  for (const HeldOutParticipant& h : fit.held_out)
    m.held_out.push_back({h.participant, h.trials, h.ll_fitted, h.ll_baseline, h.ll_default, h.ll_chance});
  m.held_out_total = {"", fit.trials, fit.held_out_ll_fitted, fit.held_out_ll_baseline, fit.held_out_ll_default,
                      fit.held_out_ll_chance};
  m.warnings = fit.warnings;
  return m;
}

}  // namespace vimg::study
