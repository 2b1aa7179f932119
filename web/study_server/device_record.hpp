#pragma once
// The device a participant's page runs on, beside the trial file: DIR/ID.device.json, written once
// (after the first recorded row of an answer that carries it, never before the row; later ones
// leave it as it is), atomically:
//   {"participant": ID, "user_agent": ..., "screen_width_mm": ..., "screen_height_mm": ...,
//    "audio_rate_hz": ..., "output_latency_s": ..., "time_utc": "2026-11-25T16:38:51Z"}
#include <filesystem>
#include <optional>
#include <string>

#include "web/study_server/answer_form.hpp"

namespace vimg::web {

std::string device_record_json(const std::string& participant, const DeviceRecord& device, const std::string& time_utc);

// Writes the record unless the file exists. The error, naming the file, or nothing.
std::optional<std::string> write_device_record_once(const std::filesystem::path& dir, const std::string& participant,
                                                    const DeviceRecord& device);

}  // namespace vimg::web
