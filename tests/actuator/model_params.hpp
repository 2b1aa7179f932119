#pragma once
// The response parameters the actuator tests use: the 175 Hz LRA of a given Q, the 50-500 Hz voice
// coil and an ERM.
#include "primitives/actuator/response_params.hpp"

namespace vimg::test {

inline ResponseParams lra(double q = 10.0) {
  ResponseParams p;
  p.model = ResponseModel::lra;
  p.resonance_hz = 175.0;
  p.q = q;
  return p;
}

inline ResponseParams voice_coil(double low_hz = 50.0, double high_hz = 500.0) {
  ResponseParams p;
  p.model = ResponseModel::voice_coil;
  p.low_hz = low_hz;
  p.high_hz = high_hz;
  return p;
}

inline ResponseParams erm(double spin_up_s, double spin_down_s, double rated_hz = 200.0) {
  ResponseParams p;
  p.model = ResponseModel::erm;
  p.resonance_hz = rated_hz;
  p.spin_up_s = spin_up_s;
  p.spin_down_s = spin_down_s;
  return p;
}

}  // namespace vimg::test
