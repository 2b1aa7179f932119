#include "editor/output_choice.hpp"

#include "player/drive_sinks.hpp"

namespace vimg::editor {
namespace {

// Renders and discards: playing mode still shows the drive on the oscilloscope.
class DiscardSink final : public DriveSink {
 public:
  void open(double) override {}
  void write(std::span<const float>, double) override {}
  void close() override {}
};

}  // namespace

std::optional<OutputChoice> parse_output_choice(const std::string& text) {
  auto with_argument = [&](const std::string& prefix, OutputChoice::Kind kind) -> std::optional<OutputChoice> {
    if (text.rfind(prefix, 0) != 0) return std::nullopt;
    return OutputChoice{kind, text.substr(prefix.size())};
  };
  if (text == "audio") return OutputChoice{OutputChoice::Kind::audio, ""};
  if (text == "none") return OutputChoice{OutputChoice::Kind::none, ""};
  if (auto c = with_argument("audio:", OutputChoice::Kind::audio)) return c;
  if (auto c = with_argument("wav:", OutputChoice::Kind::wav); c && !c->argument.empty()) return c;
  if (auto c = with_argument("csv:", OutputChoice::Kind::csv); c && !c->argument.empty()) return c;
  return std::nullopt;
}

std::unique_ptr<DriveSink> make_output(const OutputChoice& choice, std::string& error) {
  switch (choice.kind) {
    case OutputChoice::Kind::wav: return std::make_unique<WavSink>(choice.argument);
    case OutputChoice::Kind::csv: return std::make_unique<CsvSink>(choice.argument);
    case OutputChoice::Kind::none: return std::make_unique<DiscardSink>();
    case OutputChoice::Kind::audio: break;
  }
  error = "SDL audio output is not available in this build";
  return nullptr;
}

std::string describe(const OutputChoice& choice) {
  switch (choice.kind) {
    case OutputChoice::Kind::audio: return choice.argument.empty() ? "audio (default device)" : "audio: " + choice.argument;
    case OutputChoice::Kind::wav: return "wav: " + choice.argument;
    case OutputChoice::Kind::csv: return "csv: " + choice.argument;
    case OutputChoice::Kind::none: return "none";
  }
  return "none";
}

}  // namespace vimg::editor
