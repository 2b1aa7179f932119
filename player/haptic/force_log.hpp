#pragma once
// The haptic loop's per-cycle log as CSV, one row per cycle:
//   time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,flags
// the loop's time, the probe position read, the force sent after the safety stack, and the safety
// flags that acted, as names joined with '|' in layer order ("gate|clamp|slew"; empty for none).
// Numbers are locale-independent, in the shortest form that reads back to the same double.
//
// ForceLogWriter drains the loop's ring on a normal (not real-time) thread into an
// AtomicFileWriter, so readers see either no file or the complete log: the file appears only at
// finish(), after the loop has stopped, and its last row is the zero force sent at stop (or at a
// fault). Without finish() (an error, an exception), the temporary file is removed.
//
// Threads: the writer's own thread is the ring's one consumer until finish(), which joins it and
// drains the rest on the calling thread; construct, start and finish on one control thread.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

#include "player/haptic/haptic_loop.hpp"
#include "storage/atomic_file.hpp"

namespace vimg {

inline constexpr const char* kForceLogHeader = "time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,flags\n";

// One CSV line, with its newline.
std::string format_force_log_row(const ForceCycleRecord& record);

class ForceLogWriter {
 public:
  // Creates the temporary file next to `path` and writes the header; ok() says whether it could.
  ForceLogWriter(HapticLoop& loop, std::filesystem::path path);
  ~ForceLogWriter();
  ForceLogWriter(const ForceLogWriter&) = delete;
  ForceLogWriter& operator=(const ForceLogWriter&) = delete;

  bool ok() const { return file_.ok(); }
  const std::string& error() const { return file_.error(); }

  // Starts the thread that drains the loop's ring every few milliseconds.
  void start();
  // Call after the loop has stopped: drains what is left, then commits the file. Returns the
  // error message, or nothing.
  std::optional<std::string> finish();
  std::uint64_t rows_written() const { return rows_.load(std::memory_order_relaxed); }

 private:
  std::size_t drain();  // one batch; returns the rows taken

  HapticLoop& loop_;
  AtomicFileWriter file_;
  std::atomic<bool> finishing_{false};
  std::atomic<std::uint64_t> rows_{0};
  std::string text_;  // the batch being formatted (writer thread)
  std::thread thread_;
};

}  // namespace vimg
