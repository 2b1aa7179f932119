#pragma once
// What `vimg study fit` reads before it fits (docs/studies.md, "Fitting the model"): the matching
// study, its participants' trial files, and the cue distances of every set's images rendered
// exactly as `vimg compare` renders them (the standard exploration of the set's canvas, through the
// actuator given; study/compare.hpp). Every trial must belong to the study: its set one of the
// study's, its presented and chosen images images of that set (a trial file of another study is an
// error at its first foreign row), and each participant's trial appears once across the files.
// Everything is read and checked before anything is rendered; every problem is `FILE:LINE: error`.
//
// Threads: blocks the caller; the renders run on every core (run_compare).
#include <filesystem>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "storage/diagnostic.hpp"
#include "storage/study/perception_model_file.hpp"
#include "study/compare.hpp"
#include "study/fit_likelihood.hpp"
#include "study/fit_model.hpp"

namespace vimg::study {

struct StudyFitRequest {
  std::filesystem::path study;
  std::vector<std::filesystem::path> trial_files;
  CompareActuator actuator;
  DiscriminationConstants defaults;
  void (*progress)(const std::string& line) = nullptr;  // stages and renders; null: silent
  bool (*should_stop)() = nullptr;                      // asked while rendering; null: never
};

struct StudyFitInputs {
  FitData data;
  std::size_t sets_with_trials = 0;
  std::vector<Diagnostic> diagnostics;  // errors: nothing else is set
  bool interrupted = false;
  bool ok() const { return !interrupted && !has_errors(diagnostics); }
};

StudyFitInputs read_study_fit_inputs(const StudyFitRequest& request);

// The MODEL.json of a fit (storage/study/perception_model_file.hpp).
PerceptionModel perception_model_of(const ModelFit& fit, const StudyFitRequest& request, const FitData& data);

}  // namespace vimg::study
