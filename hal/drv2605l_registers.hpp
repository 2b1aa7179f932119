#pragma once
// TI DRV2605L register map (datasheet SLOS854), the parts this project uses.
#include <cstdint>

namespace vimg::drv2605l {

inline constexpr std::uint8_t kDefaultAddress = 0x5A;

inline constexpr std::uint8_t kStatus = 0x00;        // DEVICE_ID[7:5] DIAG_RESULT[3] OVER_TEMP[1] OC_DETECT[0]
inline constexpr std::uint8_t kMode = 0x01;          // DEV_RESET[7] STANDBY[6] MODE[2:0]
inline constexpr std::uint8_t kRtpInput = 0x02;
inline constexpr std::uint8_t kLibrarySel = 0x03;
inline constexpr std::uint8_t kGo = 0x0C;
inline constexpr std::uint8_t kRatedVoltage = 0x16;
inline constexpr std::uint8_t kOdClamp = 0x17;
inline constexpr std::uint8_t kACalComp = 0x18;
inline constexpr std::uint8_t kACalBemf = 0x19;
inline constexpr std::uint8_t kFeedback = 0x1A;      // N_ERM_LRA[7] FB_BRAKE_FACTOR[6:4] LOOP_GAIN[3:2] BEMF_GAIN[1:0]
inline constexpr std::uint8_t kControl1 = 0x1B;      // STARTUP_BOOST[7] DRIVE_TIME[4:0]
inline constexpr std::uint8_t kControl2 = 0x1C;
inline constexpr std::uint8_t kControl3 = 0x1D;      // DATA_FORMAT_RTP[3] LRA_OPEN_LOOP[0]
inline constexpr std::uint8_t kControl4 = 0x1E;      // AUTO_CAL_TIME[5:4]
inline constexpr std::uint8_t kOlLraPeriod = 0x20;   // [6:0], 98.46 us units
inline constexpr std::uint8_t kLraResonancePeriod = 0x22;

inline constexpr std::uint8_t kDeviceIdDrv2605l = 7;  // STATUS[7:5]
inline constexpr std::uint8_t kStatusDiagResult = 1u << 3;
inline constexpr std::uint8_t kStatusOverTemp = 1u << 1;
inline constexpr std::uint8_t kStatusOverCurrent = 1u << 0;

inline constexpr std::uint8_t kModeDevReset = 1u << 7;
inline constexpr std::uint8_t kModeStandby = 1u << 6;
inline constexpr std::uint8_t kModeInternalTrigger = 0;
inline constexpr std::uint8_t kModeRtp = 5;
inline constexpr std::uint8_t kModeDiagnostics = 6;
inline constexpr std::uint8_t kModeAutoCalibration = 7;

inline constexpr std::uint8_t kFeedbackLra = 1u << 7;
inline constexpr std::uint8_t kControl3UnsignedRtp = 1u << 3;
inline constexpr std::uint8_t kControl3LraOpenLoop = 1u << 0;
inline constexpr std::uint8_t kLibraryLra = 6;

inline constexpr double kOlLraPeriodUnit_s = 98.46e-6;
inline constexpr std::int64_t kEnableWait_us = 250;

// RATED_VOLTAGE for an LRA in closed loop (datasheet eq. 5, SAMPLE_TIME 300 us):
// V_rms = 20.58 mV * code * sqrt(1 - (4 * 300 us + 300 us) * f).
std::uint8_t rated_voltage_code(double rated_voltage_V, double resonance_hz);
// OD_CLAMP (datasheet eq. 9, closed loop peak): V_peak = 21.96 mV * code.
std::uint8_t overdrive_clamp_code(double overdrive_clamp_V);
// OL_LRA_PERIOD: period / 98.46 us, limited to the 7-bit range 1..127 (about 80 Hz .. 10 kHz).
std::uint8_t open_loop_period_code(double frequency_hz);
double open_loop_period_frequency_hz(std::uint8_t code);
// CONTROL1 DRIVE_TIME for an LRA: half the resonance period, DRIVE_TIME = (t_ms - 0.5) / 0.1.
std::uint8_t drive_time_code(double resonance_hz);

}  // namespace vimg::drv2605l
