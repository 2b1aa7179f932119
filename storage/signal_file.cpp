#include "storage/signal_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "storage/file_extension.hpp"
#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/load_file.hpp"
#include "storage/text_trim.hpp"

namespace vimg {

namespace {

const std::size_t kMaxSamples = static_cast<std::size_t>(kMaxSignalDurationS * kCompareRateHz);

SignalReadResult failure(const std::string& file, int line, const std::string& message) {
  SignalReadResult r;
  r.diagnostics.push_back({Diagnostic::Severity::error, file, line, message});
  return r;
}

std::uint32_t u32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 8 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 3])) << 24;
}
std::uint16_t u16(std::string_view b, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8);
}

std::string rate_problem(double rate_hz) {
  char text[200];
  std::snprintf(text, sizeof text,
                "the signal is sampled at %.6g Hz; vimg compare compares signals at %g Hz as they are (it does not "
                "resample): render it with --rate %g",
                rate_hz, kCompareRateHz, kCompareRateHz);
  return text;
}

std::string duration_problem() {
  char text[160];
  std::snprintf(text, sizeof text, "the signal is longer than %g s at %g Hz (limit %zu samples)", kMaxSignalDurationS,
                kCompareRateHz, kMaxSamples);
  return text;
}

}  // namespace

SignalReadResult parse_wav_signal(std::string_view b, const std::string& file) {
  if (b.size() < 12 || b.substr(0, 4) != "RIFF" || b.substr(8, 4) != "WAVE") return failure(file, 0, "is not a WAV file (no RIFF/WAVE header)");
  std::optional<std::uint16_t> format, channels, bits;
  std::optional<std::uint32_t> rate;
  std::size_t at = 12;
  while (at + 8 <= b.size()) {
    const std::string_view id = b.substr(at, 4);
    const std::uint64_t size = u32(b, at + 4);
    const std::size_t body = at + 8;
    if (id == "fmt ") {
      if (size < 16 || body + size > b.size()) return failure(file, 0, "the WAV format chunk is cut short");
      format = u16(b, body);
      channels = u16(b, body + 2);
      rate = u32(b, body + 4);
      bits = u16(b, body + 14);
      if (*format == 0xFFFE) {  // WAVE_FORMAT_EXTENSIBLE: the subformat GUID starts with the tag
        if (size < 40) return failure(file, 0, "the WAV format chunk is cut short");
        format = u16(b, body + 24);
      }
    } else if (id == "data") {
      if (!format) return failure(file, 0, "the WAV data comes before its format chunk");
      if (*channels != 1) return failure(file, 0, "the WAV has " + std::to_string(*channels) + " channels; vimg compare takes a mono signal");
      const bool is_float = *format == 3 && *bits == 32;
      const bool is_pcm16 = *format == 1 && *bits == 16;
      if (!is_float && !is_pcm16)
        return failure(file, 0, "WAV format " + std::to_string(*format) + " with " + std::to_string(*bits) +
                                    " bits per sample; vimg compare reads 32-bit float (as vimg render writes) or 16-bit PCM");
      if (static_cast<double>(*rate) != kCompareRateHz) return failure(file, 0, rate_problem(*rate));
      if (body + size > b.size()) return failure(file, 0, "the WAV data is cut short (" + std::to_string(size) + " bytes declared, " + std::to_string(b.size() - body) + " present)");
      const std::size_t width = is_float ? 4 : 2;
      const std::size_t n = static_cast<std::size_t>(size) / width;
      if (n > kMaxSamples) return failure(file, 0, duration_problem());
      if (n == 0) return failure(file, 0, "the WAV holds no samples");
      std::vector<float> samples(n);
      for (std::size_t i = 0; i < n; ++i) {
        if (is_float) {
          const std::uint32_t bits32 = u32(b, body + 4 * i);
          float v = 0.0f;
          std::memcpy(&v, &bits32, sizeof v);
          if (!std::isfinite(v)) return failure(file, 0, "sample " + std::to_string(i) + " is not a finite number");
          samples[i] = v;
        } else {
          samples[i] = static_cast<float>(static_cast<std::int16_t>(u16(b, body + 2 * i))) / 32768.0f;
        }
      }
      SignalReadResult r;
      r.samples = std::move(samples);
      return r;
    }
    at = body + static_cast<std::size_t>(size) + (size & 1);  // chunks are padded to even sizes
  }
  return failure(file, 0, "the WAV has no data chunk");
}

SignalReadResult parse_csv_signal(std::string_view text, const std::string& file) {
  std::vector<float> samples;
  double first_time = 0.0;
  int line = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = trim_blanks(text.substr(start, end - start));
    start = end + 1;
    ++line;
    if (line == 1) {
      if (row != "time_s,drive" && row != "time_s,acceleration")
        return failure(file, 1, "the header is '" + escape_input(row) + "'; a rendered signal has 'time_s,drive' or 'time_s,acceleration' (vimg render --out X.csv)");
      continue;
    }
    if (row.empty()) continue;
    const std::size_t comma = row.find(',');
    if (comma == std::string_view::npos || row.find(',', comma + 1) != std::string_view::npos)
      return failure(file, line, "a row has two fields, time_s and the value: '" + escape_input(row) + "'");
    const ParsedNumber t = parse_decimal(trim_blanks(row.substr(0, comma)));
    const ParsedNumber v = parse_decimal(trim_blanks(row.substr(comma + 1)));
    if (const auto* why = std::get_if<std::string>(&t)) return failure(file, line, "time_s " + *why);
    if (const auto* why = std::get_if<std::string>(&v)) return failure(file, line, "the value " + *why);
    const double time = std::get<double>(t);
    const double value = std::get<double>(v);
    if (!std::isfinite(time) || !std::isfinite(value) || std::fabs(value) > 1e30)
      return failure(file, line, "a value is not a finite number");
    if (samples.empty()) {
      first_time = time;
    } else if (samples.size() == 1) {
      const double step = time - first_time;
      if (!(step > 0.0)) return failure(file, line, "the times do not increase");
      if (std::fabs(step * kCompareRateHz - 1.0) > 0.25) return failure(file, line, rate_problem(1.0 / step));
    }
    const double expected = first_time + static_cast<double>(samples.size()) / kCompareRateHz;
    if (std::fabs(time - expected) > 0.25 / kCompareRateHz) {
      char message[160];
      std::snprintf(message, sizeof message, "time_s %.9g is not the next sample at %g Hz (expected %.9g)", time,
                    kCompareRateHz, expected);
      return failure(file, line, message);
    }
    if (samples.size() >= kMaxSamples) return failure(file, line, duration_problem());
    samples.push_back(static_cast<float>(value));
  }
  if (line == 0) return failure(file, 0, "is empty; a rendered signal has the header 'time_s,drive' or 'time_s,acceleration'");
  if (samples.empty()) return failure(file, line, "the signal holds no samples");
  SignalReadResult r;
  r.samples = std::move(samples);
  return r;
}

SignalReadResult read_signal_file(const std::filesystem::path& path) {
  const bool wav = lower_extension(path) == ".wav";
  return load_file<SignalReadResult>(path, kMaxSignalFileBytes, [wav](std::string_view bytes, const std::string& name) {
    return wav ? parse_wav_signal(bytes, name) : parse_csv_signal(bytes, name);
  });
}

}  // namespace vimg
