#pragma once
// DriveSink implementations for files and memory. File sinks write through storage's atomic
// writer (a temporary next to the target, created O_EXCL|O_NOFOLLOW, fsync'ed and renamed over the
// target on close()), so the output is complete or absent, and abort() leaves nothing behind.
// Samples are gathered in a buffer reserved at open() and written in large chunks; write() does
// not allocate.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "player/drive_sink.hpp"
#include "storage/atomic_file.hpp"

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

// Common part of the file sinks: the atomic writer, the sample buffer, the error state.
class FileSink : public DriveSink {
 public:
  explicit FileSink(std::filesystem::path target);
  ~FileSink() override;
  // The permission bits the file gets if it is new (before open(); NewFileMode::of the input it is
  // rendered from, so a private image gives a private render).
  void set_new_file_mode(NewFileMode mode) { new_file_mode_ = mode; }
  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  // Completes the file and renames it over the target. After an error, removes the temporary.
  void close() override;
  // Abandons the output: the temporary is removed and the target is left untouched.
  void abort();
  // The first I/O error, if any ("PATH: problem").
  const std::optional<std::string>& error() const { return error_; }

 protected:
  virtual void write_header(std::string& out, double sample_rate_hz) = 0;
  // Appends the text or bytes of the samples; at most kMaxBytesPerSample each.
  virtual void write_samples(std::string& out, std::span<const float> drive, double block_start_time_s) = 0;
  // After the last sample has been written: patch what needs the total (e.g. sizes in a header).
  virtual void finish(AtomicFileWriter& file) = 0;
  void fail(const std::string& what);
  static constexpr std::size_t kMaxBytesPerSample = 80;
  std::uint64_t samples_written_ = 0;
  double sample_rate_hz_ = 0.0;

 private:
  bool flush();

  std::filesystem::path target_;
  NewFileMode new_file_mode_;
  std::unique_ptr<AtomicFileWriter> file_;
  std::string buffer_;
  std::optional<std::string> error_;
  bool done_ = false;
};

// Mono 32-bit IEEE float WAV (format tag 3) at the render rate.
class WavSink final : public FileSink {
 public:
  using FileSink::FileSink;

 protected:
  void write_header(std::string& out, double sample_rate_hz) override;
  void write_samples(std::string& out, std::span<const float> drive, double block_start_time_s) override;
  void finish(AtomicFileWriter& file) override;
};

// `time_s,drive` rows, one per sample; the second column is named `column` (e.g. "acceleration"
// for `vimg render --signal acceleration`).
class CsvSink final : public FileSink {
 public:
  explicit CsvSink(std::filesystem::path target, std::string column = "drive")
      : FileSink(std::move(target)), column_(std::move(column)) {}

 protected:
  void write_header(std::string& out, double sample_rate_hz) override;
  void write_samples(std::string& out, std::span<const float> drive, double block_start_time_s) override;
  void finish(AtomicFileWriter&) override {}

 private:
  std::string column_;
};

}  // namespace vimg
