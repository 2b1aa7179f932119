#include "player/haptic/force_log.hpp"

#include <array>

#include "realtime/clock.hpp"
#include "storage/number_text.hpp"

namespace vimg {
namespace {

constexpr std::size_t kBatchRows = 512;
constexpr std::int64_t kDrainPeriod_ns = 5'000'000;

}  // namespace

std::string format_force_log_row(const ForceCycleRecord& r) {
  std::string line = format_decimal(r.time_s);
  for (double v : {r.position_m.x * 1e3, r.position_m.y * 1e3, r.position_m.z * 1e3, r.force_N.x, r.force_N.y, r.force_N.z}) {
    line += ',';
    line += format_decimal(v);
  }
  line += ',';
  line += safety_flag_names(r.flags);
  line += '\n';
  return line;
}

ForceLogWriter::ForceLogWriter(HapticLoop& loop, std::filesystem::path path) : loop_(loop), file_(std::move(path)) {
  file_.write(kForceLogHeader);
}

ForceLogWriter::~ForceLogWriter() {
  finishing_ = true;
  if (thread_.joinable()) thread_.join();
  // Not finished: AtomicFileWriter removes the temporary file.
}

void ForceLogWriter::start() {
  if (thread_.joinable()) return;
  thread_ = std::thread([this] {
    while (!finishing_.load(std::memory_order_acquire)) {
      if (drain() == 0) sleep_until_ns(monotonic_ns() + kDrainPeriod_ns);
    }
  });
}

std::size_t ForceLogWriter::drain() {
  std::array<ForceCycleRecord, kBatchRows> batch;
  const std::size_t n = loop_.take_log_rows(batch);
  if (n == 0) return 0;
  text_.clear();
  for (std::size_t i = 0; i < n; ++i) text_ += format_force_log_row(batch[i]);
  file_.write(text_);  // after an error the writer keeps failing; finish() reports it
  rows_.fetch_add(n, std::memory_order_relaxed);
  return n;
}

std::optional<std::string> ForceLogWriter::finish() {
  finishing_ = true;
  if (thread_.joinable()) thread_.join();
  while (drain() > 0) {
  }
  if (!file_.ok()) {
    std::string error = file_.error();
    file_.abort();
    return error;
  }
  return file_.commit();
}

}  // namespace vimg
