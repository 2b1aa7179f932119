#include "hal/sdl_audio_sink.hpp"

#include <SDL.h>

#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "hal/rest_on_exit.hpp"
#include "realtime/clock.hpp"

namespace vimg {

namespace {
std::string driver_name() {
  const char* name = SDL_GetCurrentAudioDriver();
  return name != nullptr ? name : "none";
}
}  // namespace

SdlAudioSink::SdlAudioSink(SdlAudioOptions options) : options_(std::move(options)) {}

SdlAudioSink::~SdlAudioSink() { close(); }

std::vector<std::string> SdlAudioSink::output_device_names() {
  std::vector<std::string> names;
  const int count = SDL_GetNumAudioDevices(0);
  for (int i = 0; i < count; ++i) {
    if (const char* name = SDL_GetAudioDeviceName(i, 0)) names.emplace_back(name);
  }
  return names;
}

void SdlAudioSink::open(double sample_rate_hz) {
  close();
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
    throw std::runtime_error(std::string("audio: cannot start SDL audio: ") + SDL_GetError());
  }
  subsystem_ = true;
  const char* device_name = nullptr;
  if (!options_.device_name.empty()) {
    const auto names = output_device_names();
    bool found = false;
    std::string list;
    for (const auto& name : names) {
      found = found || name == options_.device_name;
      list += (list.empty() ? "" : ", ") + ("'" + name + "'");
    }
    if (!found) {
      const std::string driver = driver_name();
      close();
      throw std::runtime_error("audio (" + driver + "): no output device named '" + options_.device_name +
                               "'; available: " + (list.empty() ? "none" : list));
    }
    device_name = options_.device_name.c_str();
  }
  int buffer_frames = options_.device_buffer_frames;
  if (buffer_frames <= 0) {
    buffer_frames = 16;
    while (buffer_frames < 4096 && buffer_frames * 1.5 < sample_rate_hz * 0.008) buffer_frames *= 2;
  }
  // The device clock paces the stream, so the renderer keeps this ring full: its length is
  // latency. Two device buffers let the callback always find a whole buffer waiting.
  ring_ = std::make_unique<SpscRing<float>>(static_cast<std::size_t>(options_.ring_frames > 0 ? options_.ring_frames : 2 * buffer_frames));
  ring_frames_ = static_cast<int>(ring_->capacity());
  SDL_AudioSpec wanted{};
  wanted.freq = static_cast<int>(std::lround(sample_rate_hz));
  wanted.format = AUDIO_F32SYS;
  wanted.channels = 1;
  wanted.samples = static_cast<Uint16>(buffer_frames);
  wanted.callback = &SdlAudioSink::callback;
  wanted.userdata = this;
  SDL_AudioSpec obtained{};
  // No changes allowed: SDL converts to what the hardware takes, we always see mono float32.
  device_ = SDL_OpenAudioDevice(device_name, 0, &wanted, &obtained, 0);
  if (device_ == 0) {
    const std::string error = SDL_GetError();
    const std::string driver = driver_name();
    close();
    throw std::runtime_error("audio (" + driver + "): cannot open " +
                             (device_name != nullptr ? "'" + std::string(device_name) + "'" : std::string("the default device")) +
                             " at " + std::to_string(wanted.freq) + " Hz: " + error);
  }
  sample_rate_hz_ = sample_rate_hz;
  obtained_frames_ = obtained.samples;
  phase_.store(Phase::priming);
  SDL_PauseAudioDevice(device_, 0);
}

void SdlAudioSink::callback(void* self_pointer, std::uint8_t* stream, int length) {
  auto& self = *static_cast<SdlAudioSink*>(self_pointer);
  const std::span<float> out(reinterpret_cast<float*>(stream), static_cast<std::size_t>(length) / sizeof(float));
  const Phase phase = self.phase_.load(std::memory_order_acquire);
  const std::size_t got = phase == Phase::priming ? 0 : self.ring_->pop_some(out);
  const bool rest = rest_requested();
  for (std::size_t i = rest ? 0 : got; i < out.size(); ++i) out[i] = 0.0f;
  if (!rest && got < out.size() && phase == Phase::playing) {
    self.underruns_.fetch_add(1, std::memory_order_relaxed);
  }
}

void SdlAudioSink::write(std::span<const float> drive, double) {
  if (device_ == 0) return;
  static constexpr std::array<float, 64> kSilence{};
  const bool rest = rest_requested();
  std::size_t left = drive.size();
  // The device takes a whole buffer per callback: poll about four times per buffer.
  const auto poll_ns = static_cast<std::int64_t>(1e9 * obtained_frames_ / sample_rate_hz_ / 4.0);
  std::int64_t last_progress_ns = monotonic_ns();
  while (left > 0) {
    std::span<const float> chunk = rest ? std::span<const float>(kSilence.data(), std::min(left, kSilence.size()))
                                        : drive.subspan(drive.size() - left);
    const std::size_t pushed = ring_->push_some(chunk);
    left -= pushed;
    if (phase_.load(std::memory_order_relaxed) == Phase::priming &&
        ring_->size() >= std::min(ring_->capacity(), static_cast<std::size_t>(obtained_frames_))) {
      phase_.store(Phase::playing, std::memory_order_release);
    }
    if (pushed > 0) {
      last_progress_ns = monotonic_ns();
      continue;
    }
    const std::int64_t now_ns = monotonic_ns();
    if (static_cast<double>(now_ns - last_progress_ns) * 1e-9 > kStallTimeout_s) return;  // the device stalled
    sleep_until_ns(now_ns + poll_ns);
  }
}

double SdlAudioSink::buffer_latency_s() const {
  if (sample_rate_hz_ <= 0.0) return 0.0;
  return (obtained_frames_ + ring_frames_) / sample_rate_hz_;
}

void SdlAudioSink::close() {
  if (device_ != 0) {
    phase_.store(Phase::draining);  // from here silence is the end of the stream, not an underrun
    if (!rest_requested()) {
      // Let what was written play out (bounded by the ring length), then stop.
      for (int i = 0; i < 100 && ring_->size() > 0; ++i) {
        std::this_thread::sleep_for(std::chrono::duration<double>(obtained_frames_ / sample_rate_hz_ / 2.0));
      }
      std::this_thread::sleep_for(std::chrono::duration<double>(2.0 * obtained_frames_ / sample_rate_hz_));
    }
    SDL_CloseAudioDevice(device_);  // waits for the callback to return
    device_ = 0;
  }
  if (subsystem_) {
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    subsystem_ = false;
  }
}

}  // namespace vimg
