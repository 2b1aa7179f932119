#pragma once
// The output of playing mode, chosen on the command line: `audio` (SDL audio, the default),
// `wav:FILE`, `csv:FILE` or `none` (render and show, drive nothing).
#include <memory>
#include <optional>
#include <string>

#include "player/drive_sink.hpp"

namespace vimg::editor {

struct OutputChoice {
  enum class Kind { audio, wav, csv, none };
  Kind kind = Kind::audio;
  std::string argument;  // the file, or the audio device name (empty: the default device)
};

// Parses a choice; nothing when the text names no known output.
std::optional<OutputChoice> parse_output_choice(const std::string& text);

// Makes the sink; null with `error` set when it cannot.
std::unique_ptr<DriveSink> make_output(const OutputChoice& choice, std::string& error);

std::string describe(const OutputChoice& choice);

}  // namespace vimg::editor
