#pragma once
// Drive to a sound card through SDL2 (an LRA or voice coil on an amplifier): a DriveSink.
// Mono float32 at the render rate, small device buffers. The renderer's blocks go through a
// lock-free ring to SDL's audio callback; write() waits (on the device) while the ring is full.
// The device clock paces the stream (paces_stream() is true): the renderer does not keep its own
// deadlines against this sink, so nothing is skipped and every rendered sample plays in order.
// The callback starts taking samples once a device buffer is queued (silence before), so the
// stream plays without gaps; later, an empty ring in the callback plays silence and counts an
// underrun. After close() begins, the rest drains and silence follows without counting.
// Rest: once rest_requested() (a signal), the callback plays silence and write() queues silence
// and returns, still paced by the device; write() never closes the device (SDL_CloseAudioDevice
// blocks and frees), close() does that on the control thread. A device that stops taking
// samples for kStallTimeout_s makes write() drop the rest of its block and return.
// Headless: SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE=FILE writes the raw samples to FILE.
//
// Threads: open(), close() and the accessors on the control thread; write() on the render thread
// (it never allocates or locks; it sleeps only while the device has no room); the callback on
// SDL's audio thread. underruns() from any thread.
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
  // Our queue in front of it (rounded up to a power of two); 0: two device buffers.
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
  bool paces_stream() const override { return true; }
  double output_latency_s() const override { return buffer_latency_s(); }

  static constexpr double kStallTimeout_s = 0.5;

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
  enum class Phase : int { priming, playing, draining };
  std::atomic<Phase> phase_{Phase::priming};
  std::atomic<std::uint64_t> underruns_{0};
};

}  // namespace vimg
