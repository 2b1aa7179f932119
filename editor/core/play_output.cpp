#include "editor/core/play_output.hpp"

namespace vimg::editor {
namespace {

class HalPlayOutput final : public PlayOutput {
 public:
  explicit HalPlayOutput(std::unique_ptr<Output> output) : output_(std::move(output)) {}
  void open(double sample_rate_hz) override { output_->sink().open(sample_rate_hz); }
  void write(std::span<const float> drive, double block_start_time_s) override {
    output_->sink().write(drive, block_start_time_s);
  }
  void close() override { output_->sink().close(); }
  bool paces_stream() const override { return output_->sink().paces_stream(); }
  std::size_t min_block_samples() const override { return output_->sink().min_block_samples(); }
  double output_latency_s() const override { return output_->sink().output_latency_s(); }
  std::vector<std::string> take_messages() override { return output_->take_messages(); }

 private:
  std::unique_ptr<Output> output_;
};

class SilentPlayOutput final : public PlayOutput {
 public:
  explicit SilentPlayOutput(std::unique_ptr<DriveSink> sink) : sink_(std::move(sink)) {}
  void open(double sample_rate_hz) override { sink_->open(sample_rate_hz); }
  void write(std::span<const float> drive, double block_start_time_s) override { sink_->write(drive, block_start_time_s); }
  void close() override { sink_->close(); }
  bool paces_stream() const override { return sink_->paces_stream(); }
  std::size_t min_block_samples() const override { return sink_->min_block_samples(); }
  double output_latency_s() const override { return sink_->output_latency_s(); }

 private:
  std::unique_ptr<DriveSink> sink_;
};

}  // namespace

std::unique_ptr<PlayOutput> play_output(std::unique_ptr<Output> output) {
  return std::make_unique<HalPlayOutput>(std::move(output));
}

std::unique_ptr<PlayOutput> play_output(std::unique_ptr<DriveSink> sink) {
  return std::make_unique<SilentPlayOutput>(std::move(sink));
}

}  // namespace vimg::editor
