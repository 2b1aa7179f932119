// Fuzzes the two files that stand in for a participant (storage/study/): the matching test's
// scripted responses (`trial,chosen`) and the location study's mark times (`trial,time_s`). The
// first byte picks the reader and the study's size; any bytes give either a complete answer (one
// choice of the trial's own set per trial, one finite time in range per trial) or messages that name
// a line of the input, never a crash.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/study/location_marks_file.hpp"
#include "storage/study/scripted_responses.hpp"

namespace {

void check_lines(const std::vector<vimg::Diagnostic>& diagnostics, std::string_view text) {
  std::size_t lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  for (const vimg::Diagnostic& d : diagnostics) {
    if (d.line < 0 || static_cast<std::size_t>(d.line) > lines) std::abort();
  }
  vimg::fuzz::check_messages(diagnostics);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t trials = 1 + data[0] % 16;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  if (data[0] & 0x80) {
    const vimg::MarkTimesResult marks = vimg::parse_mark_times(text, "fuzz.csv", trials);
    check_lines(marks.diagnostics, text);
    if (marks.ok()) {
      if (marks.times_s->size() != trials) std::abort();
      for (const double t : *marks.times_s) {
        if (!(t > 0.0 && t <= vimg::kMaxProbePathDurationS)) std::abort();
      }
    }
    return 0;
  }
  const std::vector<std::vector<std::string>> stems{{"dot", "line"}, {"a", "b", "c"}};
  std::vector<std::size_t> trial_sets;
  for (std::size_t k = 0; k < trials; ++k) trial_sets.push_back(k % 2);
  const vimg::ResponsesResult responses = vimg::parse_responses(text, "fuzz.csv", stems, trial_sets);
  check_lines(responses.diagnostics, text);
  if (responses.ok()) {
    if (responses.chosen->size() != trials) std::abort();
    for (std::size_t k = 0; k < trials; ++k) {
      if ((*responses.chosen)[k] >= stems[trial_sets[k]].size()) std::abort();
    }
  }
  return 0;
}
