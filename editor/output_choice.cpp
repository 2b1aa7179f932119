#include "editor/output_choice.hpp"

#include <exception>

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

OutputChoiceResult parse_output_choice(const std::string& text) {
  OutputChoice c;
  c.text = text;
  if (text == "none") {
    c.kind = OutputChoice::Kind::none;
    return {c, ""};
  }
  if (text.rfind("csv:", 0) == 0 && text.size() > 4) {
    c.kind = OutputChoice::Kind::csv;
    c.csv_path = text.substr(4);
    return {c, ""};
  }
  OutputParseResult parsed = parse_output_spec(text);
  if (!parsed.spec) return {std::nullopt, parsed.error};
  c.kind = OutputChoice::Kind::hal;
  c.hal_spec = *parsed.spec;
  return {c, ""};
}

std::unique_ptr<PlayOutput> make_output(const OutputChoice& choice, std::string& error) {
  switch (choice.kind) {
    case OutputChoice::Kind::none: return play_output(std::make_unique<DiscardSink>());
    case OutputChoice::Kind::csv: return play_output(std::make_unique<CsvSink>(choice.csv_path));
    case OutputChoice::Kind::hal: break;
  }
  try {
    return play_output(open_output(choice.hal_spec, default_lra_profile()));
  } catch (const std::exception& e) {
    error = e.what();
    return nullptr;
  }
}

}  // namespace vimg::editor
