#pragma once
// What an actuator profile says about how drive becomes acceleration (docs/actuators.md): the
// model and its parameters, with the ranges a profile may give them. Plain data, SI units.
namespace vimg {

enum class ResponseModel { ideal, lra, erm, voice_coil };

struct ResponseParams {
  ResponseModel model = ResponseModel::ideal;
  // lra: the resonance; erm: the vibration frequency at full drive; the DOT carrier for all.
  double resonance_hz = 175.0;
  double q = 10.0;            // lra: quality factor, resonance / (-3 dB bandwidth)
  double low_hz = 50.0;       // voice_coil: lower corner (-3 dB)
  double high_hz = 500.0;     // voice_coil: upper corner (-3 dB)
  double spin_up_s = 0.030;   // erm: time constant of the speed while it rises
  double spin_down_s = 0.045; // erm: time constant of the speed while it falls
};

// Ranges a profile may give (checked by the profile reader, storage/actuator_profile.cpp).
inline constexpr double kMinResponseQ = 0.5;
inline constexpr double kMaxResponseQ = 200.0;
inline constexpr double kMinCornerHz = 1.0;
inline constexpr double kMaxCornerHz = 20000.0;
inline constexpr double kMinSpinTimeS = 0.001;
inline constexpr double kMaxSpinTimeS = 2.0;

}  // namespace vimg
