#pragma once
// What `vimg study report` computes (docs/studies.md "The report"): the matching test per image set
// (primitives paper, section 3) and the location study per metaphor (volume paper, section 5), as
// plain values that the JSON, HTML and Markdown writers (study/report_writers.hpp) lay out.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "study/report_chance.hpp"
#include "study/statistics.hpp"

namespace vimg::study {

// Two groups of values compared with Welch's t-test and Cohen's d (study/statistics.hpp).
struct GroupComparison {
  std::string a, b;  // group names (set names, metaphor names)
  Summary summary_a, summary_b;
  std::optional<WelchTest> welch;   // none when undefined (fewer than two values, no variance)
  std::optional<double> cohens_d;   // pooled SD
};

GroupComparison compare_groups(std::string a, const std::vector<double>& values_a, std::string b,
                               const std::vector<double>& values_b);

// ---- Matching test -------------------------------------------------------------------------

// One image of a set against the rest (the paper's Tables 3-5): TP presented and chosen, FN presented
// and not chosen, FP chosen when another was presented, TN neither.
struct ImageCounts {
  std::string image;
  std::size_t tp = 0, fn = 0, fp = 0, tn = 0;
  std::optional<double> hit_rate;          // TP / (TP + FN); none when never presented
  std::optional<double> false_alarm_rate;  // FP / (FP + TN); none when no other image was presented
};

struct ParticipantAccuracy {
  std::string participant;
  std::size_t correct = 0, trials = 0;
  double accuracy = 0.0;  // correct / trials (trials >= 1)
};

// The predicted confusion of a set from `vimg compare` (study/report_predicted.hpp), in the set's
// image order, rows renormalised over the set's images (attach_predictions), and its agreement
// with the measured confusion (the comparison matrix with each row divided by its total).
struct PredictedComparison {
  std::string source;  // the COMPARE.json as given
  std::optional<DiscriminationConstants> constants;  // the model's constants, when the report names them
  std::string model_file;  // the MODEL.json of `vimg compare --model`; empty: none
  std::vector<std::vector<double>> predicted;  // [presented][chosen], rows sum to 1
  std::vector<std::vector<std::optional<double>>> measured;  // none for an image never presented
  std::size_t off_diagonal_cells = 0;  // cells in the correlation (rows with a measurement)
  std::optional<double> correlation;   // Pearson over those cells; none when either side is constant
};

struct SetReport {
  std::string name;
  std::vector<std::string> images;  // sorted by name; every image presented or chosen in the set
  std::vector<std::vector<std::size_t>> comparison;  // counts, [presented][chosen] (Tables 1-2)
  std::size_t trials = 0, correct = 0;
  double accuracy = 0.0;  // correct / trials
  std::optional<Interval> accuracy_ci95;  // Wilson score interval
  double chance = 0.0;  // 1 / number of images
  std::vector<ImageCounts> per_image;  // in the order of `images`
  std::vector<ParticipantAccuracy> participants;  // sorted by ID
  std::optional<PredictedComparison> predicted;
};

struct MatchingReport {
  std::vector<SetReport> sets;  // in the order the trials first name them (the study file's order)
  // Welch's t-test on per-participant accuracies for every pair of sets (one pair for two sets).
  std::vector<GroupComparison> set_comparisons;
};

// ---- Location study ------------------------------------------------------------------------

struct MetaphorReport {
  std::string name;  // "roughness", "transitionCue"
  std::size_t n = 0;
  double mean_mm = 0.0;
  std::optional<double> sd_mm;            // sample SD; none when n < 2
  std::optional<Interval> ci99_mm;        // two-sided 99 % Student t interval of the mean
  double chance_mm = 0.0;                 // chance for this metaphor's targets (report_chance.hpp)
};

struct ParticipantMetaphorMean {
  std::string metaphor;
  std::size_t n = 0;
  double mean_mm = 0.0;
};

struct ParticipantLocation {
  std::string participant;
  std::vector<ParticipantMetaphorMean> metaphors;  // in the order of LocationReport::metaphors
};

struct LocationReport {
  std::vector<MetaphorReport> metaphors;  // roughness, then transitionCue, those with trials
  Workspace workspace;     // where chance places its marks
  double chance_mm = 0.0;  // over every trial's target
  std::vector<GroupComparison> metaphor_comparisons;  // Welch on the errors, per pair (one for two)
  std::vector<ParticipantLocation> participants;  // sorted by ID
};

// ---- The whole report ----------------------------------------------------------------------

struct StudyReport {
  std::vector<std::string> inputs;  // the trial files as given
  std::optional<MatchingReport> matching;  // when any matching trial file was given
  std::optional<LocationReport> location;  // when any location trial file was given
};

}  // namespace vimg::study
