#include "player/clip_export/clip_sink.hpp"
#include "storage/file_extension.hpp"

namespace vimg {

bool is_clip_extension(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".ahap" || ext == ".haptic";
}

ClipSink::ClipSink(std::filesystem::path target, ClipMetadata metadata)
    : FileSink(target), ahap_(lower_extension(target) == ".ahap"), metadata_(std::move(metadata)) {}

void ClipSink::write_header(std::string&, double sample_rate_hz) { envelope_ = DriveEnvelope(sample_rate_hz); }

void ClipSink::write_samples(std::string&, std::span<const float> drive, double) { envelope_.add(drive); }

void ClipSink::finish(AtomicFileWriter& file) {
  HapticClip clip = envelope_.clip();
  clip.metadata = metadata_;
  if (!file.write(ahap_ ? write_ahap(clip) : write_meta_haptic(clip))) fail(file.error());
}

}  // namespace vimg
