#include "apps/vimg-player/study_stream_sink.hpp"

#include "realtime/clock.hpp"

namespace vimg::player_app {

void StudyStreamSink::open(double sample_rate_hz) {
  if (open_) return;
  output_.open(sample_rate_hz);
  open_ = true;
  sample_rate_hz_ = sample_rate_hz;
  start_ns_ = monotonic_ns();
}

void StudyStreamSink::write(std::span<const float> drive, double) {
  const double stream_time_s = static_cast<double>(samples_) / sample_rate_hz_;
  if (!output_.paces_stream()) sleep_until_ns(start_ns_ + static_cast<std::int64_t>(stream_time_s * 1e9));
  output_.write(drive, stream_time_s);
  samples_ += drive.size();
}

void StudyStreamSink::finish() {
  if (!open_ || finished_) return;
  finished_ = true;
  output_.close();
}

}  // namespace vimg::player_app
