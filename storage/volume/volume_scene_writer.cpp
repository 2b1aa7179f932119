#include <sstream>

#include "storage/number_text.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

std::string num(double v) { return format_decimal(v); }
std::string vec(const Vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }

// XML attribute text: escapes the five special characters.
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* mode_name(KinaestheticMode m) {
  switch (m) {
    case KinaestheticMode::gradient_force: return "gradientForce";
    case KinaestheticMode::yielding_surface: return "yieldingSurface";
    case KinaestheticMode::vector_guidance: return "vectorGuidance";
  }
  return "vectorGuidance";
}

}  // namespace

std::string write_volume_scene_xml(const VolumeScene& scene) {
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<volumeScene version=\"1.0\">\n";
  for (const auto& d : scene.data) {
    x << "  <" << (d.kind == VolumeDataRef::Kind::vector ? "vectorData" : "scalarData") << " id=\"" << escape(d.id)
      << "\" file=\"" << escape(d.file) << "\"/>\n";
  }
  const DeviceProfile& dev = scene.device;
  x << "  <device name=\"" << escape(dev.name) << "\" maxForce=\"" << num(dev.max_force_N) << "\" maxStiffness=\""
    << num(dev.max_stiffness_N_per_m) << "\" workspace=\"" << vec(dev.workspace_mm) << "\" rate=\"" << num(dev.rate_hz)
    << "\" gateForce=\"" << num(dev.gate_force_N) << "\" rampTime=\"" << num(dev.ramp_time_ms) << "\"/>\n";
  if (const auto& k = scene.kinaesthetic) {
    x << "  <kinaesthetic mode=\"" << mode_name(k->mode) << "\" data=\"" << escape(k->data) << "\" scale=\""
      << num(k->scale_N_mm) << "\" stiffness=\"" << num(k->stiffness_N_per_m) << "\" damping=\""
      << num(k->damping_N_s_per_m) << "\" yieldForce=\"" << num(k->yield_force_N) << "\" friction=\""
      << num(k->friction) << "\" minGradient=\"" << num(k->min_gradient_per_mm) << "\" acrossForce=\""
      << num(k->across_force_N) << "\" followForce=\"" << num(k->follow_force_N) << "\"/>\n";
  }
  for (const auto& r : scene.roughness) {
    x << "  <roughness data=\"" << escape(r.data) << "\" direction=\"" << vec(r.direction)
      << "\" fullAmplitudeSpeed=\"" << num(r.full_amplitude_speed_mm_per_s) << "\">\n";
    for (const auto& p : r.omega_points) {
      if (r.omega_given_as_period) x << "    <period value=\"" << num(p.value) << "\" mm=\"" << num(p.output) << "\"/>\n";
      else x << "    <omega value=\"" << num(p.value) << "\" radPerMm=\"" << num(p.output) << "\"/>\n";
    }
    for (const auto& p : r.amplitude_points) {
      x << "    <amplitude value=\"" << num(p.value) << "\" N=\"" << num(p.output) << "\"/>\n";
    }
    x << "  </roughness>\n";
  }
  for (const auto& c : scene.transition_cues) {
    x << "  <transitionCue data=\"" << escape(c.data) << "\" isoValue=\"" << num(c.iso_value) << "\" direction=\""
      << vec(c.direction) << "\" frequency=\"" << num(c.frequency_hz) << "\" amplitude=\"" << num(c.amplitude_N)
      << "\" decayTime=\"" << num(c.decay_time_ms) << "\"/>\n";
  }
  x << "</volumeScene>\n";
  return x.str();
}

}  // namespace vimg
