#pragma once
// A file sink that writes the render as a haptic clip for phones (docs/export.md): `.ahap` (Apple
// Core Haptics) or `.haptic` (Meta Haptics Studio v1), chosen by the target's extension. The drive
// goes into a DriveEnvelope; on close() the clip is written through the atomic writer.
//
// Threads: like every FileSink, one thread; it grows with the clip, so it serves offline renders.
#include <filesystem>
#include <string>

#include "player/clip_export/drive_envelope.hpp"
#include "player/drive_sinks.hpp"
#include "storage/export/haptic_clip.hpp"

namespace vimg {

// True for the extensions a ClipSink writes (".ahap", ".haptic", any case).
bool is_clip_extension(const std::filesystem::path& path);

class ClipSink final : public FileSink {
 public:
  ClipSink(std::filesystem::path target, ClipMetadata metadata);

 protected:
  void write_header(std::string& out, double sample_rate_hz) override;
  void write_samples(std::string& out, std::span<const float> drive, double block_start_time_s) override;
  void finish(AtomicFileWriter& file) override;

 private:
  bool ahap_;
  ClipMetadata metadata_;
  DriveEnvelope envelope_{8000.0};
};

}  // namespace vimg
