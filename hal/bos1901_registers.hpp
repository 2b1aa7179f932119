#pragma once
// Boreas BOS1901 piezo driver, SPI register protocol (public register map and application notes).
// Every SPI word is 16 bits, MSB first: [15:12] register address, [11:0] value. Reading: CONFIG.BC
// selects the register that the chip shifts out on SDO during each following word.
#include <cstdint>

namespace vimg::bos1901 {

inline constexpr std::uint8_t kReference = 0x0;  // FIFO input: 12-bit two's complement sample
inline constexpr std::uint8_t kConfig = 0x5;     // PLAY[2:0] DS[3] OE[4] RST[5] LOCK[6] BC[11:7]
inline constexpr std::uint8_t kIcStatus = 0xC;   // FIFO_SPACE[5:0] EMPTY[6] FULL[7] OVT[8] OVV[9] STATE[11:10]

inline constexpr std::uint16_t kConfigDeepSleep = 1u << 3;
inline constexpr std::uint16_t kConfigOutputEnable = 1u << 4;
inline constexpr std::uint16_t kConfigReset = 1u << 5;
inline constexpr unsigned kConfigBroadcastShift = 7;

inline constexpr std::uint16_t kStatusFifoSpaceMask = 0x3F;
inline constexpr std::uint16_t kStatusEmpty = 1u << 6;
inline constexpr std::uint16_t kStatusFull = 1u << 7;
inline constexpr std::uint16_t kStatusOverTemp = 1u << 8;
inline constexpr std::uint16_t kStatusOverVoltage = 1u << 9;

inline constexpr int kFifoDepth = 64;
inline constexpr int kSampleMax = 2047;  // 12-bit two's complement

// PLAY codes: 0 = 1024 ksps, halving each step, 7 = 8 ksps. Returns -1 for other rates.
int play_code_for_rate(double sample_rate_hz);
double rate_for_play_code(int code);

inline std::uint16_t word(std::uint8_t reg, std::uint16_t value) {
  return static_cast<std::uint16_t>(((reg & 0xFu) << 12) | (value & 0xFFFu));
}
// Normalized [-1, 1] to a 12-bit two's complement sample, saturating.
std::uint16_t sample_code(double normalized);
// The signed value of a 12-bit two's complement field.
int sample_value(std::uint16_t code);

}  // namespace vimg::bos1901
