#include "web/study_server/device_record.hpp"

#include <system_error>

#include "storage/atomic_file.hpp"
#include "storage/export/json_writer.hpp"
#include "storage/study/trial_log.hpp"

namespace vimg::web {

std::string device_record_json(const std::string& participant, const DeviceRecord& device, const std::string& time_utc) {
  JsonWriter w;
  w.begin_object();
  w.key("participant");
  w.string(participant);
  w.key("user_agent");
  w.string(device.user_agent);
  w.key("screen_width_mm");
  w.number(device.screen_width_mm);
  w.key("screen_height_mm");
  w.number(device.screen_height_mm);
  w.key("audio_rate_hz");
  w.number(device.audio_rate_hz);
  w.key("output_latency_s");
  w.number(device.output_latency_s);
  w.key("time_utc");
  w.string(time_utc);
  w.end_object();
  return w.take() + "\n";
}

std::optional<std::string> write_device_record_once(const std::filesystem::path& dir, const std::string& participant,
                                                    const DeviceRecord& device) {
  const std::filesystem::path file = dir / (participant + ".device.json");
  std::error_code ec;
  if (std::filesystem::symlink_status(file, ec).type() != std::filesystem::file_type::not_found) return std::nullopt;
  // The participant's answers are written one at a time (ParticipantLogs), so nothing else makes
  // this file between the look and the write.
  return write_file_atomically(file, device_record_json(participant, device, utc_timestamp_now()));
}

}  // namespace vimg::web
