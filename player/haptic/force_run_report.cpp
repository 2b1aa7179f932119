#include "player/haptic/force_run_report.hpp"

#include <cstdio>

#include "storage/number_text.hpp"

namespace vimg {
namespace {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

ForceRunReport make_force_run_report(const HapticLoop& loop, std::string exit_reason, std::string device) {
  ForceRunReport r;
  r.target_rate_hz = loop.rate_hz();
  r.timing = loop.timing();
  r.max_force_N = loop.max_sent_N();
  r.clamp_N = loop.safety().clamp_N();
  r.max_slew_N_per_ms = loop.safety().max_slew_N_per_ms();
  r.clamp_hits = loop.clamp_hits();
  r.log_rows_dropped = loop.log_rows_dropped();
  r.exit_reason = std::move(exit_reason);
  r.device = std::move(device);
  r.device_state = describe(loop.state());
  if (loop.failed()) r.device_state += ": " + loop.fault_text();
  r.scheduling = describe(loop.realtime_priority());
  return r;
}

std::string force_run_report_json(const ForceRunReport& r) {
  std::string json = "{";
  auto number = [&](const char* key, double value) {
    if (json.size() > 1) json += ',';
    json += '"';
    json += key;
    json += "\":";
    json += format_decimal(value);
  };
  auto count = [&](const char* key, std::uint64_t value) {
    if (json.size() > 1) json += ',';
    json += '"';
    json += key;
    json += "\":";
    json += std::to_string(value);
  };
  auto text = [&](const char* key, const std::string& value) {
    if (json.size() > 1) json += ',';
    json += '"';
    json += key;
    json += "\":";
    json += json_string(value);
  };
  number("rate_hz", r.timing.rate_hz);
  number("target_rate_hz", r.target_rate_hz);
  number("jitter_p50_us", r.timing.jitter_p50_us);
  number("jitter_p99_us", r.timing.jitter_p99_us);
  number("jitter_max_us", r.timing.jitter_max_us);
  count("overruns", r.timing.overruns);
  count("skips", r.timing.skips);
  count("cycles", r.timing.cycles);
  number("elapsed_s", r.timing.elapsed_s);
  number("max_force_N", r.max_force_N);
  number("clamp_N", r.clamp_N);
  number("max_slew_N_per_ms", r.max_slew_N_per_ms);
  count("clamp_hits", r.clamp_hits);
  count("log_rows_dropped", r.log_rows_dropped);
  text("exit_reason", r.exit_reason);
  text("device", r.device);
  text("device_state", r.device_state);
  text("scheduling", r.scheduling);
  return json + "}\n";
}

}  // namespace vimg
