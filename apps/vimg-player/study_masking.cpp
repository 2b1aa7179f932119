#include "apps/vimg-player/study_masking.hpp"

#include <span>

#include "storage/diagnostic.hpp"
#include "storage/number_text.hpp"

namespace vimg::player_app {

namespace {

std::vector<std::string> output_devices() {
  std::vector<std::string> names;
  const int count = SDL_GetNumAudioDevices(0);
  for (int i = 0; i < count; ++i) {
    if (const char* name = SDL_GetAudioDeviceName(i, 0)) names.emplace_back(name);
  }
  return names;
}

std::string quoted_list(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "'" : ", '") + escape_input(name) + "'";
  return text;
}

}  // namespace

MaskingNoisePlayer::~MaskingNoisePlayer() {
  if (device_ != 0) SDL_CloseAudioDevice(device_);
  if (subsystem_) SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void MaskingNoisePlayer::callback(void* self, Uint8* stream, int length) {
  auto* player = static_cast<MaskingNoisePlayer*>(self);
  player->noise_->fill(std::span<float>(reinterpret_cast<float*>(stream), static_cast<std::size_t>(length) / sizeof(float)));
}

std::optional<std::string> MaskingNoisePlayer::start(const MaskingNoise& noise, const OutputSpec& actuator) {
  const std::string name = noise.audio_device;
  const std::string named = "masking noise device '" + escape_input(name) + "'";
  if (const auto* audio = std::get_if<AudioOutput>(&actuator)) {
    if (audio->device_name == name) return named + " is the actuator's output (--output); the noise needs another device";
  }
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) return "cannot start audio for the " + named + ": " + SDL_GetError();
  subsystem_ = true;
  const std::string driver = SDL_GetCurrentAudioDriver() != nullptr ? SDL_GetCurrentAudioDriver() : "none";
  const auto devices = output_devices();
  bool exists = false;
  for (const auto& device : devices) exists = exists || device == name;
  if (!exists) {
    return named + " does not exist; the audio outputs are (SDL driver " + driver + "): " + quoted_list(devices);
  }
  if (const auto* audio = std::get_if<AudioOutput>(&actuator); audio != nullptr && audio->device_name.empty()) {
    char* default_name = nullptr;
    SDL_AudioSpec default_spec;
    if (SDL_GetDefaultAudioInfo(&default_name, &default_spec, 0) == 0 && default_name != nullptr) {
      const bool same = name == default_name;
      SDL_free(default_name);
      if (same) return named + " is the default output, which drives the actuator (--output audio); name another";
    }
  }
  noise_ = std::make_unique<WhiteNoise>(noise.level);
  SDL_AudioSpec want{};
  want.freq = 48000;
  want.format = AUDIO_F32SYS;
  want.channels = 1;
  want.samples = 1024;
  want.callback = &MaskingNoisePlayer::callback;
  want.userdata = this;
  SDL_AudioSpec got{};
  device_ = SDL_OpenAudioDevice(name.c_str(), 0, &want, &got, 0);
  if (device_ == 0) return "cannot open the " + named + ": " + SDL_GetError();
  SDL_PauseAudioDevice(device_, 0);
  description_ = "white noise, RMS " + format_decimal(noise.level) + ", on '" + escape_input(name) + "'";
  return std::nullopt;
}

}  // namespace vimg::player_app
