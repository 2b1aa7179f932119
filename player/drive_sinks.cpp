#include "player/drive_sinks.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <system_error>

namespace vimg {

void MemorySink::open(double sample_rate_hz) {
  sample_rate_hz_ = sample_rate_hz;
  samples_.clear();
  closed_ = false;
  first_block_time_s_ = 0.0;
}

void MemorySink::write(std::span<const float> drive, double block_start_time_s) {
  if (samples_.empty()) first_block_time_s_ = block_start_time_s;
  samples_.insert(samples_.end(), drive.begin(), drive.end());
}

FileSink::FileSink(std::filesystem::path target) : target_(std::move(target)) {}

FileSink::~FileSink() {
  if (file_ != nullptr) abort();
}

void FileSink::fail(const std::string& what) {
  if (!error_) error_ = target_.string() + ": " + what;
}

void FileSink::open(double sample_rate_hz) {
  sample_rate_hz_ = sample_rate_hz;
  samples_written_ = 0;
  done_ = false;
  std::random_device rd;
  temp_ = target_;
  temp_ += ".tmp-" + std::to_string(rd() % 1000000u);
  file_ = std::fopen(temp_.c_str(), "wb");
  if (file_ == nullptr) {
    fail(std::string("cannot create the output file: ") + std::strerror(errno));
    return;
  }
  write_header(file_, sample_rate_hz);
}

void FileSink::write(std::span<const float> drive, double block_start_time_s) {
  if (file_ == nullptr || error_) return;
  write_samples(file_, drive, block_start_time_s);
  samples_written_ += drive.size();
  if (std::ferror(file_)) fail("write failed");
}

void FileSink::close() {
  if (done_) return;
  done_ = true;
  if (file_ == nullptr) return;
  if (!error_) finish(file_);
  if (std::fflush(file_) != 0 || std::ferror(file_)) fail("write failed");
  if (std::fclose(file_) != 0) fail("write failed");
  file_ = nullptr;
  if (error_) {
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
    return;
  }
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) {
    fail("cannot rename the output into place: " + ec.message());
    std::filesystem::remove(temp_, ec);
  }
}

void FileSink::abort() {
  done_ = true;
  if (file_ != nullptr) {
    std::fclose(file_);
    file_ = nullptr;
  }
  std::error_code ec;
  if (!temp_.empty()) std::filesystem::remove(temp_, ec);
}

namespace {

void put_u32(std::FILE* f, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16), static_cast<unsigned char>(v >> 24)};
  std::fwrite(b, 1, 4, f);
}
void put_u16(std::FILE* f, std::uint16_t v) {
  const unsigned char b[2] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8)};
  std::fwrite(b, 1, 2, f);
}

// RIFF/WAVE with a 'fmt ' chunk of 18 bytes (cbSize = 0), a 'fact' chunk and 'data'.
constexpr long kRiffSizeOffset = 4;
constexpr long kFactValueOffset = 12 + (8 + 18) + 8;
constexpr long kDataSizeOffset = kFactValueOffset + 4 + 4;
constexpr std::uint32_t kHeaderBytes = static_cast<std::uint32_t>(kDataSizeOffset + 4);

}  // namespace

void WavSink::write_header(std::FILE* f, double sample_rate_hz) {
  const auto rate = static_cast<std::uint32_t>(std::lround(sample_rate_hz));
  std::fwrite("RIFF", 1, 4, f);
  put_u32(f, 0);  // patched in finish()
  std::fwrite("WAVE", 1, 4, f);
  std::fwrite("fmt ", 1, 4, f);
  put_u32(f, 18);
  put_u16(f, 3);  // WAVE_FORMAT_IEEE_FLOAT
  put_u16(f, 1);  // mono
  put_u32(f, rate);
  put_u32(f, rate * 4);  // bytes per second
  put_u16(f, 4);         // block align
  put_u16(f, 32);        // bits per sample
  put_u16(f, 0);         // cbSize
  std::fwrite("fact", 1, 4, f);
  put_u32(f, 4);
  put_u32(f, 0);  // sample frames, patched
  std::fwrite("data", 1, 4, f);
  put_u32(f, 0);  // patched
}

void WavSink::write_samples(std::FILE* f, std::span<const float> drive, double) {
  for (float v : drive) {
    std::uint32_t bits = 0;
    static_assert(sizeof bits == sizeof v);
    std::memcpy(&bits, &v, sizeof bits);
    put_u32(f, bits);  // little-endian whatever the host order
  }
}

void WavSink::finish(std::FILE* f) {
  const std::uint64_t data_bytes = samples_written_ * 4;
  if (data_bytes + kHeaderBytes > 0xFFFFFFFFull) {
    fail("too many samples for a WAV file");
    return;
  }
  const auto data = static_cast<std::uint32_t>(data_bytes);
  std::fseek(f, kRiffSizeOffset, SEEK_SET);
  put_u32(f, kHeaderBytes - 8 + data);
  std::fseek(f, kFactValueOffset, SEEK_SET);
  put_u32(f, static_cast<std::uint32_t>(samples_written_));
  std::fseek(f, kDataSizeOffset, SEEK_SET);
  put_u32(f, data);
  std::fseek(f, 0, SEEK_END);
}

void CsvSink::write_header(std::FILE* f, double) { std::fputs("time_s,drive\n", f); }

void CsvSink::write_samples(std::FILE* f, std::span<const float> drive, double block_start_time_s) {
  for (std::size_t i = 0; i < drive.size(); ++i) {
    const double t = block_start_time_s + static_cast<double>(i) / sample_rate_hz_;
    // to_chars: '.' as the separator whatever the locale, shortest round-trip form.
    char line[80];
    char* p = std::to_chars(line, line + 38, t).ptr;
    *p++ = ',';
    p = std::to_chars(p, line + 78, drive[i]).ptr;
    *p++ = '\n';
    std::fwrite(line, 1, static_cast<std::size_t>(p - line), f);
  }
}

}  // namespace vimg
