// Rendered signals as inputs of vimg compare (storage/signal_file.hpp): what `vimg render` writes
// is read back exactly; another rate, more channels, a broken header or a gap in time is refused.
#include "storage/signal_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace vimg::study {
namespace {

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void put_u16(std::string& out, std::uint16_t v) {
  out += static_cast<char>(v & 0xFF);
  out += static_cast<char>(v >> 8);
}

std::string wav(std::uint16_t format, std::uint16_t channels, std::uint32_t rate, std::uint16_t bits, const std::string& data) {
  std::string s = "RIFF";
  put_u32(s, static_cast<std::uint32_t>(36 + data.size()));
  s += "WAVEfmt ";
  put_u32(s, 16);
  put_u16(s, format);
  put_u16(s, channels);
  put_u32(s, rate);
  put_u32(s, rate * channels * bits / 8);
  put_u16(s, static_cast<std::uint16_t>(channels * bits / 8));
  put_u16(s, bits);
  s += "LIST";  // a chunk to skip, of odd size (padded)
  put_u32(s, 3);
  s += "abc";
  s += '\0';
  s += "data";
  put_u32(s, static_cast<std::uint32_t>(data.size()));
  return s + data;
}

std::string floats(std::initializer_list<float> values) {
  std::string s;
  for (float v : values) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    put_u32(s, bits);
  }
  return s;
}

std::string error_of(const SignalReadResult& r) { return r.diagnostics.empty() ? "" : r.diagnostics[0].to_string(); }

TEST(CompareSignal, AFloatWavAt8kHzIsReadExactly) {
  const SignalReadResult r = parse_wav_signal(wav(3, 1, 8000, 32, floats({0.5f, -0.25f, 1e-7f})), "s.wav");
  ASSERT_TRUE(r.ok()) << error_of(r);
  EXPECT_EQ(*r.samples, (std::vector<float>{0.5f, -0.25f, 1e-7f}));
}

TEST(CompareSignal, A16BitPcmWavIsScaledToPlusMinusOne) {
  std::string data;
  put_u16(data, 0x4000);
  put_u16(data, 0x8000);
  const SignalReadResult r = parse_wav_signal(wav(1, 1, 8000, 16, data), "s.wav");
  ASSERT_TRUE(r.ok()) << error_of(r);
  EXPECT_EQ(*r.samples, (std::vector<float>{0.5f, -1.0f}));
}

TEST(CompareSignal, AWavAtAnotherRateIsRefusedWithTheWayToRenderIt) {
  const SignalReadResult r = parse_wav_signal(wav(3, 1, 48000, 32, floats({0.5f})), "s.wav");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(error_of(r),
            "s.wav: error: the signal is sampled at 48000 Hz; vimg compare compares signals at 8000 Hz as they are (it does "
            "not resample): render it with --rate 8000");
}

TEST(CompareSignal, StereoOtherFormatsAndBrokenFilesAreRefused) {
  EXPECT_NE(error_of(parse_wav_signal(wav(3, 2, 8000, 32, floats({0.5f, 0.5f})), "s.wav")).find("2 channels"), std::string::npos);
  EXPECT_NE(error_of(parse_wav_signal(wav(1, 1, 8000, 24, "abc"), "s.wav")).find("WAV format 1 with 24 bits"), std::string::npos);
  EXPECT_NE(error_of(parse_wav_signal("RIFF....WAVE", "s.wav")).find("no data chunk"), std::string::npos);
  EXPECT_NE(error_of(parse_wav_signal("time_s,drive\n", "s.wav")).find("is not a WAV file"), std::string::npos);
  std::string cut = wav(3, 1, 8000, 32, floats({0.5f, 0.5f}));
  cut.resize(cut.size() - 3);
  EXPECT_NE(error_of(parse_wav_signal(cut, "s.wav")).find("cut short"), std::string::npos);
  EXPECT_NE(error_of(parse_wav_signal(wav(3, 1, 8000, 32, floats({std::numeric_limits<float>::infinity()})), "s.wav"))
                .find("not a finite number"),
            std::string::npos);
}

TEST(CompareSignal, ARenderCsvIsReadWithEitherColumn) {
  for (const char* column : {"drive", "acceleration"}) {
    const SignalReadResult r =
        parse_csv_signal(std::string("time_s,") + column + "\n0,0.5\n0.000125,-0.25\r\n0.00025,0\n", "s.csv");
    ASSERT_TRUE(r.ok()) << error_of(r);
    EXPECT_EQ(*r.samples, (std::vector<float>{0.5f, -0.25f, 0.0f}));
  }
}

TEST(CompareSignal, CsvProblemsAreReportedAtTheirLine) {
  EXPECT_EQ(error_of(parse_csv_signal("time,value\n0,1\n", "s.csv")),
            "s.csv:1: error: the header is 'time,value'; a rendered signal has 'time_s,drive' or 'time_s,acceleration' "
            "(vimg render --out X.csv)");
  EXPECT_NE(error_of(parse_csv_signal("time_s,drive\n0,0\n0.0000208333,0\n", "s.csv")).find("s.csv:3: error: the signal is sampled at 48000"),
            std::string::npos);
  EXPECT_NE(error_of(parse_csv_signal("time_s,drive\n0,0\n0.000125,0\n0.0005,0\n", "s.csv"))
                .find("s.csv:4: error: time_s 0.0005 is not the next sample at 8000 Hz"),
            std::string::npos);
  EXPECT_NE(error_of(parse_csv_signal("time_s,drive\n0,abc\n", "s.csv")).find("s.csv:2: error: the value"), std::string::npos);
  EXPECT_NE(error_of(parse_csv_signal("time_s,drive\n0,1,2\n", "s.csv")).find("s.csv:2: error: a row has two fields"),
            std::string::npos);
  EXPECT_NE(error_of(parse_csv_signal("time_s,drive\n", "s.csv")).find("holds no samples"), std::string::npos);
  EXPECT_NE(error_of(parse_csv_signal("", "s.csv")).find("s.csv: error: is empty"), std::string::npos);
}

TEST(CompareSignal, ADeviceIsRefusedWithoutReadingIt) {
  const SignalReadResult r = read_signal_file("/dev/zero");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(error_of(r).find("/dev/zero: error: is not a regular file"), std::string::npos) << error_of(r);
}

}  // namespace
}  // namespace vimg::study
