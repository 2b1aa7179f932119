#include "player/drive_sinks.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
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

namespace {
constexpr std::size_t kFileBufferBytes = 256 * 1024;
}  // namespace

FileSink::FileSink(std::filesystem::path target) : target_(std::move(target)) {}

FileSink::~FileSink() {
  if (file_ && !done_) abort();
}

void FileSink::fail(const std::string& what) {
  if (!error_) error_ = target_.string() + ": " + what;
}

void FileSink::open(double sample_rate_hz) {
  sample_rate_hz_ = sample_rate_hz;
  samples_written_ = 0;
  done_ = false;
  error_.reset();
  file_ = std::make_unique<AtomicFileWriter>(target_, new_file_mode_);
  if (!file_->ok()) {
    error_ = file_->error();
    return;
  }
  buffer_.clear();
  buffer_.reserve(kFileBufferBytes);
  write_header(buffer_, sample_rate_hz);
}

bool FileSink::flush() {
  if (!file_->write(buffer_)) {
    if (!error_) error_ = file_->error();
    return false;
  }
  buffer_.clear();
  return true;
}

void FileSink::write(std::span<const float> drive, double block_start_time_s) {
  if (!file_ || error_ || done_) return;
  // Whole blocks fit the reserved buffer, in pieces if a block is larger than it.
  const std::size_t per_piece = kFileBufferBytes / kMaxBytesPerSample;
  for (std::size_t first = 0; first < drive.size(); first += per_piece) {
    const std::span<const float> piece = drive.subspan(first, std::min(per_piece, drive.size() - first));
    if (buffer_.size() + piece.size() * kMaxBytesPerSample > buffer_.capacity() && !flush()) return;
    write_samples(buffer_, piece, block_start_time_s + static_cast<double>(first) / sample_rate_hz_);
    samples_written_ += piece.size();
  }
}

void FileSink::close() {
  if (done_ || !file_) return;
  done_ = true;
  if (!error_ && flush()) finish(*file_);
  if (!error_ && !file_->ok()) error_ = file_->error();
  if (error_) {
    file_->abort();
    return;
  }
  if (auto e = file_->commit()) error_ = *e;
}

void FileSink::abort() {
  done_ = true;
  if (file_) file_->abort();
}

namespace {

void put_u32(std::string& out, std::uint32_t v) {
  const char b[4] = {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF), static_cast<char>((v >> 16) & 0xFF),
                     static_cast<char>((v >> 24) & 0xFF)};
  out.append(b, 4);
}
void put_u16(std::string& out, std::uint16_t v) {
  const char b[2] = {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF)};
  out.append(b, 2);
}

// RIFF/WAVE with a 'fmt ' chunk of 18 bytes (cbSize = 0), a 'fact' chunk and 'data'.
constexpr long kRiffSizeOffset = 4;
constexpr long kFactValueOffset = 12 + (8 + 18) + 8;
constexpr long kDataSizeOffset = kFactValueOffset + 4 + 4;
constexpr std::uint32_t kHeaderBytes = static_cast<std::uint32_t>(kDataSizeOffset + 4);

}  // namespace

void WavSink::write_header(std::string& out, double sample_rate_hz) {
  const auto rate = static_cast<std::uint32_t>(std::lround(sample_rate_hz));
  out += "RIFF";
  put_u32(out, 0);  // patched in finish()
  out += "WAVE";
  out += "fmt ";
  put_u32(out, 18);
  put_u16(out, 3);  // WAVE_FORMAT_IEEE_FLOAT
  put_u16(out, 1);  // mono
  put_u32(out, rate);
  put_u32(out, rate * 4);  // bytes per second
  put_u16(out, 4);         // block align
  put_u16(out, 32);        // bits per sample
  put_u16(out, 0);         // cbSize
  out += "fact";
  put_u32(out, 4);
  put_u32(out, 0);  // sample frames, patched
  out += "data";
  put_u32(out, 0);  // patched
}

void WavSink::write_samples(std::string& out, std::span<const float> drive, double) {
  for (float v : drive) {
    std::uint32_t bits = 0;
    static_assert(sizeof bits == sizeof v);
    std::memcpy(&bits, &v, sizeof bits);
    put_u32(out, bits);  // little-endian whatever the host order
  }
}

void WavSink::finish(AtomicFileWriter& file) {
  const std::uint64_t data_bytes = samples_written_ * 4;
  if (data_bytes + kHeaderBytes > 0xFFFFFFFFull) {
    fail("too many samples for a WAV file");
    return;
  }
  const auto data = static_cast<std::uint32_t>(data_bytes);
  std::string field;
  put_u32(field, kHeaderBytes - 8 + data);
  file.write_at(kRiffSizeOffset, field);
  field.clear();
  put_u32(field, static_cast<std::uint32_t>(samples_written_));
  file.write_at(kFactValueOffset, field);
  field.clear();
  put_u32(field, data);
  file.write_at(kDataSizeOffset, field);
}

void CsvSink::write_header(std::string& out, double) { out += "time_s," + column_ + "\n"; }

void CsvSink::write_samples(std::string& out, std::span<const float> drive, double block_start_time_s) {
  for (std::size_t i = 0; i < drive.size(); ++i) {
    const double t = block_start_time_s + static_cast<double>(i) / sample_rate_hz_;
    // to_chars: '.' as the separator whatever the locale, shortest round-trip form.
    char line[kMaxBytesPerSample];
    char* p = std::to_chars(line, line + 38, t).ptr;
    *p++ = ',';
    p = std::to_chars(p, line + 78, drive[i]).ptr;
    *p++ = '\n';
    out.append(line, static_cast<std::size_t>(p - line));
  }
}

}  // namespace vimg
