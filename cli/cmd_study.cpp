// `vimg study report TRIALS.csv... [--predicted COMPARE.json]... --out REPORT.html|.json|.md`: the
// report of the matching test (primitives paper, section 3) and of the location study (volume
// paper, section 5) from the trial files the study runners write (docs/studies.md).
// `vimg study fit`: the discrimination model fitted on the trials (cmd_study_fit.cpp).
// `vimg study link DIR --participant ID [--url BASE]`: a participant's link to the matching test
// in the browser (vimg serve --study; docs/studies.md, "In the browser").
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include "cli/command.hpp"
#include "cli/serve_study.hpp"
#include "storage/atomic_file.hpp"
#include "storage/file_extension.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/study/trial_log.hpp"
#include "storage/study/served_url_file.hpp"
#include "study/report_inputs.hpp"
#include "study/report_writers.hpp"
#include "web/study_server/study_keys.hpp"

namespace vimg::cli {

namespace {

constexpr const char* kProgram = "vimg study report";

struct ReportArgs {
  std::vector<std::string> trials;
  std::vector<std::string> predicted;
  std::string out;
};

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec) && !ec;
}

int run_report(const ReportArgs& a) {
  const std::string ext = lower_extension(a.out);
  if (ext != ".html" && ext != ".json" && ext != ".md")
    return usage_error(kProgram, "--out must end in .html, .json or .md: '" + a.out + "'");
  for (const std::vector<std::string>* inputs : {&a.trials, &a.predicted}) {
    for (const std::string& input : *inputs) {
      if (same_file(input, a.out)) return usage_error(kProgram, "--out names an input file: '" + a.out + "'");
    }
  }

  const study::ReportInputs inputs = study::read_report_inputs({a.trials.begin(), a.trials.end()},
                                                               {a.predicted.begin(), a.predicted.end()});
  print_diagnostics(inputs.diagnostics);
  if (!inputs.ok()) {
    std::fprintf(stderr, "%s: %s not written\n", kProgram, a.out.c_str());
    return kExitFailure;
  }
  if (!inputs.has_trials()) {
    std::fprintf(stderr, "%s: error: the trial files hold no trials; %s not written\n", kProgram, a.out.c_str());
    return kExitFailure;
  }
  std::vector<Diagnostic> warnings;
  const study::StudyReport report = study::make_study_report(inputs, warnings);
  print_diagnostics(warnings);
  const std::string text = ext == ".json"   ? study::report_json(report)
                           : ext == ".html" ? study::report_html(report)
                                            : study::report_markdown(report);
  // A new report takes the permission bits all its inputs share: trial files hold participants'
  // data, and a private one keeps the report private.
  std::vector<std::filesystem::path> sources(a.trials.begin(), a.trials.end());
  sources.insert(sources.end(), a.predicted.begin(), a.predicted.end());
  if (const auto error = write_file_atomically(a.out, text, NewFileMode::of_all(sources))) {
    std::fprintf(stderr, "%s: %s\n", kProgram, error->c_str());
    return kExitFailure;
  }
  return kExitOk;
}

struct LinkArgs {
  std::string dir;
  std::string participant;
  std::string url;
};

// BASE: --url, else what `vimg serve --study` recorded in DIR. "http(s)://..." ending in '/'.
int run_link(const LinkArgs& a) {
  const char* program = "vimg study link";
  if (!valid_participant_id(a.participant)) {
    return usage_error(program, "--participant '" + a.participant + "' is not 1 to 64 of A-Z a-z 0-9 _ -");
  }
  std::string base = a.url;
  if (base.empty()) {
    const ServedUrlRead recorded = read_served_url(a.dir);
    if (!recorded.url) {
      std::fprintf(stderr, "%s: error: %s; give the address participants reach the server at with --url "
                           "(vimg serve --study records it here when it starts)\n",
                   recorded.file.c_str(), recorded.error.c_str());
      return kExitFailure;
    }
    base = *recorded.url;
  }
  if (base.rfind("http://", 0) != 0 && base.rfind("https://", 0) != 0) {
    return usage_error(program, "the address must begin with http:// or https://: '" + base + "'");
  }
  if (base.back() != '/') base += '/';
  auto keys = web::StudyKeys::open(a.dir);
  if (const auto* error = std::get_if<std::string>(&keys)) {
    std::fprintf(stderr, "%s\n", error->c_str());
    return kExitFailure;
  }
  const std::string key = std::get<web::StudyKeys>(keys).participant_key(a.participant);
  std::printf("%s\n", participant_link(base, a.participant, key).c_str());
  return kExitOk;
}

}  // namespace

void add_study_command(CLI::App& vimg, int& exit_code) {
  CLI::App* study = vimg.add_subcommand("study", "the matching test and the location study: report their trials, fit the model on them (docs/studies.md)");
  study->set_version_flag("--version", std::string(cmdline::version()), "print the version and exit");
  study->require_subcommand(1);
  CLI::App* report = study->add_subcommand(
      "report", "tables, statistics and figures of the trial files of the matching test and of the location study");
  report->set_version_flag("--version", std::string(cmdline::version()), "print the version and exit");
  auto a = std::make_shared<ReportArgs>();
  report->add_option("TRIALS", a->trials,
                     "trial files (CSV, one per participant, as vimg-player --study and vimg-force --study write them); "
                     "matching and location files may be mixed")
      ->required();
  report->add_option("--predicted", a->predicted,
                     "the JSON report of `vimg compare` on a set's images: predicted confusion beside the measured one "
                     "(images matched by file stem; may be repeated, one per set)");
  report->add_option("--out", a->out, "REPORT.html (self-contained, inline SVG), REPORT.json or REPORT.md, written atomically")
      ->required();
  report->footer(
      "Matching: per set the comparison matrix, TP/FN/FP/TN with hit and false-alarm rates, accuracy with its 95 % Wilson "
      "interval against chance, accuracy per participant, Welch's t-test and Cohen's d between sets. Location: per metaphor "
      "n, mean error, SD, 99 % t interval, chance, Welch's t-test between metaphors, per-participant means. Statistics, "
      "formulas and the JSON keys: see docs/studies.md. Exit 1 on a malformed file (FILE:LINE: error), nothing written.");
  report->callback([a, &exit_code] { exit_code = run_report(*a); });

  add_study_fit(*study, exit_code);

  CLI::App* link = study->add_subcommand("link", "print a participant's link to the matching test in the browser (vimg serve --study)");
  auto l = std::make_shared<LinkArgs>();
  link->add_option("DIR", l->dir, "the results folder of vimg serve --study (it holds the study's secret)")->required()
      ->check(CLI::ExistingDirectory);
  link->add_option("--participant", l->participant, "the participant's ID ([A-Za-z0-9_-]{1,64})")->required();
  link->add_option("--url", l->url,
                   "the address participants reach the server at, e.g. https://study.example.org/ behind a reverse proxy "
                   "(default: the one vimg serve --study recorded in DIR/vimg-serve.url)");
  link->footer("The link carries the participant's key after '#': 128 bits derived from DIR/vimg-study.secret (made, "
               "mode 0600, when there is none), valid across restarts. See docs/studies.md.");
  link->callback([l, &exit_code] { exit_code = run_link(*l); });
}

}  // namespace vimg::cli
