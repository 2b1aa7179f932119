#pragma once
// Drive to a sound card through SDL2 (an LRA or voice coil on an amplifier): a DriveSink.
// Mono float32 at the render rate, small device buffers. The renderer's blocks go through a
// lock-free ring to SDL's audio callback; write() waits (on the device) when the ring is full, so
// the device clock paces the renderer. An empty ring in the callback plays silence and counts an
// underrun. Headless: SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE=FILE writes the raw samples to FILE.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "realtime/spsc_ring.hpp"
#include "player/drive_sink.hpp"

namespace vimg {

struct SdlAudioOptions {
  std::string device_name;            // empty: the system default; otherwise the exact SDL name
  // SDL's buffer, the main part of the output latency; 0: the power of two nearest 8 ms.
  int device_buffer_frames = 0;
  // Our queue in front of it; 0: four device buffers.
  int ring_frames = 0;
};

class SdlAudioSink final : public DriveSink {
 public:
  explicit SdlAudioSink(SdlAudioOptions options = {});
  ~SdlAudioSink() override;
  SdlAudioSink(const SdlAudioSink&) = delete;
  SdlAudioSink& operator=(const SdlAudioSink&) = delete;

  void open(double sample_rate_hz) override;  // throws std::runtime_error naming driver and device
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;

  std::uint64_t underruns() const { return underruns_.load(std::memory_order_relaxed); }
  // Device buffer plus ring, in seconds: the worst-case time from write() to the speaker.
  double buffer_latency_s() const;
  int obtained_buffer_frames() const { return obtained_frames_; }
  static std::vector<std::string> output_device_names();  // needs the audio subsystem

 private:
  static void callback(void* self, std::uint8_t* stream, int length);

  SdlAudioOptions options_;
  std::unique_ptr<SpscRing<float>> ring_;
  std::uint32_t device_ = 0;
  bool subsystem_ = false;
  double sample_rate_hz_ = 0.0;
  int obtained_frames_ = 0;
  int ring_frames_ = 0;
  std::atomic<bool> started_{false};
  std::atomic<std::uint64_t> underruns_{0};
};

}  // namespace vimg
