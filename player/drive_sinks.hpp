#pragma once
// DriveSink implementations for files and memory. File sinks write to `PATH.tmp-XXXX` next to the
// target and rename it over the target on close(), so the output is complete or absent.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "player/drive_sink.hpp"

namespace vimg {

// Keeps every sample. reserve() ahead of a real-time run so write() does not allocate.
class MemorySink final : public DriveSink {
 public:
  explicit MemorySink(std::size_t reserve_samples = 0) { samples_.reserve(reserve_samples); }
  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override { closed_ = true; }

  const std::vector<float>& samples() const { return samples_; }
  double sample_rate_hz() const { return sample_rate_hz_; }
  double first_block_time_s() const { return first_block_time_s_; }
  bool closed() const { return closed_; }

 private:
  std::vector<float> samples_;
  double sample_rate_hz_ = 0.0;
  double first_block_time_s_ = 0.0;
  bool closed_ = false;
};

// Common part of the file sinks: temporary file, error state, atomic rename.
class FileSink : public DriveSink {
 public:
  explicit FileSink(std::filesystem::path target);
  ~FileSink() override;
  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  // Completes the file and renames it over the target. After an error, removes the temporary.
  void close() override;
  // Abandons the output: the temporary is removed and the target is left untouched.
  void abort();
  // The first I/O error, if any ("PATH: problem").
  const std::optional<std::string>& error() const { return error_; }

 protected:
  virtual void write_header(std::FILE* f, double sample_rate_hz) = 0;
  virtual void write_samples(std::FILE* f, std::span<const float> drive, double block_start_time_s) = 0;
  virtual void finish(std::FILE* f) = 0;  // e.g. patch sizes in the header
  void fail(const std::string& what);
  std::uint64_t samples_written_ = 0;
  double sample_rate_hz_ = 0.0;

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
  std::optional<std::string> error_;
  bool done_ = false;
};

// Mono 32-bit IEEE float WAV (format tag 3) at the render rate.
class WavSink final : public FileSink {
 public:
  using FileSink::FileSink;

 protected:
  void write_header(std::FILE* f, double sample_rate_hz) override;
  void write_samples(std::FILE* f, std::span<const float> drive, double block_start_time_s) override;
  void finish(std::FILE* f) override;
};

// `time_s,drive` rows, one per sample.
class CsvSink final : public FileSink {
 public:
  using FileSink::FileSink;

 protected:
  void write_header(std::FILE* f, double sample_rate_hz) override;
  void write_samples(std::FILE* f, std::span<const float> drive, double block_start_time_s) override;
  void finish(std::FILE*) override {}
};

}  // namespace vimg
