#pragma once
// The output of playing mode, chosen on the command line: any hal output (`audio` (default),
// `audio:DEVICE`, `wav:FILE`, `drv2605l:...`, `spi:...`, `hid:VID:PID`, see hal/output_spec.hpp),
// or, for the editor, `csv:FILE` (time_s,drive rows) and `none` (render and show, drive nothing).
#include <memory>
#include <optional>
#include <string>

#include "editor/core/play_output.hpp"
#include "hal/output_spec.hpp"

namespace vimg::editor {

struct OutputChoice {
  enum class Kind { hal, csv, none };
  Kind kind = Kind::hal;
  OutputSpec hal_spec = AudioOutput{};
  std::string text = "audio";  // as the user wrote it
  std::string csv_path;
};

struct OutputChoiceResult {
  std::optional<OutputChoice> choice;
  std::string error;
};
OutputChoiceResult parse_output_choice(const std::string& text);

// Opens the output; null with `error` set (naming the device) when it cannot.
std::unique_ptr<PlayOutput> make_output(const OutputChoice& choice, std::string& error);

}  // namespace vimg::editor
