#include <tinyxml2.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <optional>

#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"
#include "storage/load_file.hpp"
#include "storage/named_file.hpp"
#include "storage/number_text.hpp"
#include "storage/xml_attributes.hpp"
#include "storage/xml_limits.hpp"
#include "storage/xml_parse_problem.hpp"
#include "storage/volume/nrrd.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLElement;

class SceneReader {
 public:
  explicit SceneReader(DiagnosticList& list) : list_(list), attributes_(list) {}

  std::optional<VolumeScene> run(std::string_view xml) {
    if (const auto over = check_xml_limits(xml)) {
      error(over->line, over->message);
      return std::nullopt;
    }
    tinyxml2::XMLDocument doc;
    if (doc.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS) {
      error(doc.ErrorLineNum(), xml_parse_problem(doc.ErrorID()));
      return finish();
    }
    const XMLElement* root = doc.RootElement();
    if (!root || std::string_view(root->Name()) != "volumeScene") {
      error(root ? root->GetLineNum() : 1, "the root element must be <volumeScene>");
      return finish();
    }
    check_attributes(root, {"version"});
    if (const char* v = root->Attribute("version"); !v || std::string_view(v).substr(0, 2) != "1.") {
      error(root->GetLineNum(), "<volumeScene> needs version=\"1.x\"");
    }
    bool saw_device = false;
    for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string_view name = e->Name();
      if (name == "scalarData" || name == "vectorData") read_data(e, name == "vectorData");
      else if (name == "device") {
        if (saw_device) error(e->GetLineNum(), "second <device>");
        saw_device = true;
        read_device(e);
      } else if (name == "kinaesthetic") {
        if (scene_.kinaesthetic) error(e->GetLineNum(), "second <kinaesthetic>");
        read_kinaesthetic(e);
      } else if (name == "roughness") read_roughness(e);
      else if (name == "transitionCue") read_cue(e);
      else error(e->GetLineNum(), "unknown element <" + q(name) + ">");
    }
    check_references();
    return finish();
  }

 private:
  void error(int line, std::string_view message) { list_.error(line, message); }
  static std::string q(std::string_view input) { return escape_input(input); }

  std::optional<VolumeScene> finish() {
    if (list_.has_errors()) return std::nullopt;
    return std::move(scene_);
  }

  // The attribute checks every XML reader shares (storage/xml_attributes.hpp).
  void check_attributes(const XMLElement* e, std::initializer_list<std::string_view> allowed) {
    attributes_.check_attributes(*e, allowed);
  }

  std::optional<std::string> text(const XMLElement* e, const char* name, bool required) {
    return attributes_.text(*e, name, required);
  }

  // Reads a number attribute into `out` when present; checks min (inclusive or exclusive).
  void number(const XMLElement* e, const char* name, double& out, double min, bool exclusive_min, bool required = false) {
    if (const auto v = attributes_.number(*e, name, exclusive_min ? NumberRange::above(min) : NumberRange::at_least(min), required)) {
      out = *v;
    }
  }

  void any_number(const XMLElement* e, const char* name, double& out, bool required = false) {
    if (const auto v = attributes_.number(*e, name, NumberRange{}, required)) out = *v;
  }

  void vector3(const XMLElement* e, const char* name, Vec3& out, bool nonzero) {
    const auto t = text(e, name, false);
    if (!t) return;
    std::istringstream in(*t);
    std::string w[4];
    int n = 0;
    while (n < 4 && in >> w[n]) ++n;
    if (n != 3) {
      error(e->GetLineNum(), std::string("attribute '") + name + "' needs three numbers, got '" + q(*t) + "'");
      return;
    }
    double v[3];
    for (int i = 0; i < 3; ++i) {
      const ParsedNumber p = parse_decimal(w[i]);
      if (!std::holds_alternative<double>(p)) {
        error(e->GetLineNum(), std::string("attribute '") + name + "': '" + q(w[i]) + "' is not a number");
        return;
      }
      v[i] = std::get<double>(p);
    }
    const Vec3 result{v[0], v[1], v[2]};
    if (nonzero && norm(result) == 0.0) {
      error(e->GetLineNum(), std::string("attribute '") + name + "' must not be the zero vector");
      return;
    }
    out = result;
  }

  void read_data(const XMLElement* e, bool vector) {
    check_attributes(e, {"id", "file"});
    VolumeDataRef ref;
    ref.kind = vector ? VolumeDataRef::Kind::vector : VolumeDataRef::Kind::scalar;
    ref.source_line = e->GetLineNum();
    ref.id = text(e, "id", true).value_or("");
    ref.file = text(e, "file", true).value_or("");
    for (const auto& other : scene_.data) {
      if (!ref.id.empty() && other.id == ref.id) {
        error(e->GetLineNum(), "duplicate data id '" + q(ref.id) + "' (first on line " + std::to_string(other.source_line) + ")");
      }
    }
    if (e->FirstChildElement()) error(e->GetLineNum(), "<" + q(e->Name()) + "> takes no children");
    scene_.data.push_back(std::move(ref));
  }

  void read_device(const XMLElement* e) {
    check_attributes(e, {"name", "maxForce", "maxStiffness", "workspace", "rate", "gateForce", "rampTime"});
    DeviceProfile& d = scene_.device;
    if (auto n = text(e, "name", false)) d.name = *n;
    number(e, "maxForce", d.max_force_N, 0.0, true);
    number(e, "maxStiffness", d.max_stiffness_N_per_m, 0.0, true);
    vector3(e, "workspace", d.workspace_mm, true);
    number(e, "rate", d.rate_hz, 100.0, false);
    if (d.rate_hz > 4000.0) error(e->GetLineNum(), "attribute 'rate' must be at most 4000 Hz");
    number(e, "gateForce", d.gate_force_N, 0.0, true);
    number(e, "rampTime", d.ramp_time_ms, 0.0, false);
  }

  void read_kinaesthetic(const XMLElement* e) {
    check_attributes(e, {"mode", "data", "scale", "stiffness", "damping", "yieldForce", "friction",
                         "minGradient", "acrossForce", "followForce"});
    KinaestheticSpec k;
    const std::string mode = text(e, "mode", true).value_or("");
    if (mode == "gradientForce") k.mode = KinaestheticMode::gradient_force;
    else if (mode == "yieldingSurface") k.mode = KinaestheticMode::yielding_surface;
    else if (mode == "vectorGuidance") k.mode = KinaestheticMode::vector_guidance;
    else if (!mode.empty()) error(e->GetLineNum(), "mode must be gradientForce, yieldingSurface or vectorGuidance, got '" + q(mode) + "'");
    k.data = text(e, "data", true).value_or("");
    any_number(e, "scale", k.scale_N_mm);
    number(e, "stiffness", k.stiffness_N_per_m, 0.0, true);
    number(e, "damping", k.damping_N_s_per_m, 0.0, false);
    number(e, "yieldForce", k.yield_force_N, 0.0, false);
    number(e, "friction", k.friction, 0.0, false);
    number(e, "minGradient", k.min_gradient_per_mm, 0.0, false);
    number(e, "acrossForce", k.across_force_N, 0.0, false);
    number(e, "followForce", k.follow_force_N, 0.0, false);
    kinaesthetic_line_ = e->GetLineNum();
    scene_.kinaesthetic = k;
  }

  // Children <NAME value=".." OUTPUT=".."/>, sorted by strictly increasing value.
  void read_points(const XMLElement* point, const char* output, std::vector<TransferPoint>& out, double min_output,
                   bool exclusive) {
    check_attributes(point, {"value", output});
    TransferPoint p;
    any_number(point, "value", p.value, true);
    number(point, output, p.output, min_output, exclusive, true);
    if (!out.empty() && !(p.value > out.back().value)) {
      error(point->GetLineNum(), "transfer function values must increase strictly");
    }
    out.push_back(p);
  }

  void read_roughness(const XMLElement* e) {
    check_attributes(e, {"data", "direction", "fullAmplitudeSpeed"});
    RoughnessSpec r;
    r.data = text(e, "data", true).value_or("");
    vector3(e, "direction", r.direction, true);
    number(e, "fullAmplitudeSpeed", r.full_amplitude_speed_mm_per_s, 0.0, true);
    bool saw_period = false, saw_omega = false;
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string_view name = c->Name();
      if (name == "period") {
        saw_period = true;
        read_points(c, "mm", r.omega_points, 0.0, true);
      } else if (name == "omega") {
        saw_omega = true;
        read_points(c, "radPerMm", r.omega_points, 0.0, false);
      } else if (name == "amplitude") {
        read_points(c, "N", r.amplitude_points, 0.0, false);
      } else {
        error(c->GetLineNum(), "unknown element <" + q(name) + "> in <roughness>");
      }
    }
    if (saw_period && saw_omega) error(e->GetLineNum(), "<roughness> takes <period> or <omega> points, not both");
    if (!saw_period && !saw_omega) error(e->GetLineNum(), "<roughness> needs <period> or <omega> points");
    if (r.amplitude_points.empty()) error(e->GetLineNum(), "<roughness> needs <amplitude> points");
    r.omega_given_as_period = !saw_omega;
    roughness_lines_.push_back(e->GetLineNum());
    scene_.roughness.push_back(std::move(r));
  }

  void read_cue(const XMLElement* e) {
    check_attributes(e, {"data", "isoValue", "direction", "frequency", "amplitude", "decayTime"});
    TransitionCueSpec c;
    c.data = text(e, "data", true).value_or("");
    any_number(e, "isoValue", c.iso_value);
    vector3(e, "direction", c.direction, true);
    number(e, "frequency", c.frequency_hz, 0.0, true);
    number(e, "amplitude", c.amplitude_N, 0.0, false);
    number(e, "decayTime", c.decay_time_ms, 0.0, true);
    if (c.decay_time_ms > 0.0 && 1.0 / (c.decay_time_ms * 1e-3) >= 2.0 * 3.141592653589793 * c.frequency_hz) {
      error(e->GetLineNum(), "decayTime is too short for the frequency: the cue would not oscillate");
    }
    if (e->FirstChildElement()) error(e->GetLineNum(), "<transitionCue> takes no children");
    cue_lines_.push_back(e->GetLineNum());
    scene_.transition_cues.push_back(c);
  }

  const VolumeDataRef* find(const std::string& id) const {
    for (const auto& d : scene_.data) {
      if (d.id == id) return &d;
    }
    return nullptr;
  }

  void expect_data(const std::string& id, VolumeDataRef::Kind kind, int line, const char* who) {
    if (id.empty()) return;  // already reported
    const VolumeDataRef* d = find(id);
    if (!d) error(line, std::string(who) + " names data '" + q(id) + "', which the scene does not declare");
    else if (d->kind != kind) {
      error(line, std::string(who) + " needs " + (kind == VolumeDataRef::Kind::scalar ? "scalar" : "vector") + " data, '" + q(id) + "' is not");
    }
  }

  // The vibration must stay below the strength of the kinaesthetic features (volume paper,
  // section 3.3), or it masks them: a warning, since the file is still usable.
  void check_below_kinaesthetic(double amplitude_N, int line, const char* what) {
    if (!scene_.kinaesthetic || scene_.kinaesthetic->mode == KinaestheticMode::gradient_force) return;
    const double strength = scene_.kinaesthetic->mode == KinaestheticMode::yielding_surface
                                ? scene_.kinaesthetic->yield_force_N
                                : scene_.kinaesthetic->across_force_N;
    if (amplitude_N >= strength) {
      list_.warning(line, std::string(what) + " amplitude " + format_decimal(amplitude_N) +
                              " N is not below the kinaesthetic strength " + format_decimal(strength) +
                              " N: the vibration may mask the structure");
    }
  }

  void check_references() {
    if (scene_.kinaesthetic) {
      const auto kind = scene_.kinaesthetic->mode == KinaestheticMode::vector_guidance ? VolumeDataRef::Kind::vector
                                                                                      : VolumeDataRef::Kind::scalar;
      expect_data(scene_.kinaesthetic->data, kind, kinaesthetic_line_, "<kinaesthetic>");
      if (scene_.kinaesthetic->stiffness_N_per_m > scene_.device.max_stiffness_N_per_m) {
        error(kinaesthetic_line_, "stiffness exceeds the device's maxStiffness");
      }
    }
    for (std::size_t i = 0; i < scene_.roughness.size(); ++i) {
      expect_data(scene_.roughness[i].data, VolumeDataRef::Kind::scalar, roughness_lines_[i], "<roughness>");
      double peak = 0.0;
      for (const auto& p : scene_.roughness[i].amplitude_points) peak = std::max(peak, p.output);
      check_below_kinaesthetic(peak, roughness_lines_[i], "roughness");
    }
    for (std::size_t i = 0; i < scene_.transition_cues.size(); ++i) {
      expect_data(scene_.transition_cues[i].data, VolumeDataRef::Kind::scalar, cue_lines_[i], "<transitionCue>");
      check_below_kinaesthetic(scene_.transition_cues[i].amplitude_N, cue_lines_[i], "transition cue");
    }
  }

  DiagnosticList& list_;
  XmlAttributes attributes_;
  VolumeScene scene_;
  int kinaesthetic_line_ = 0;
  std::vector<int> roughness_lines_;
  std::vector<int> cue_lines_;
};

// Parses into `list`, which the loader goes on using for the scene's own messages.
std::optional<VolumeScene> parse_scene(std::string_view xml, DiagnosticList& list) {
  if (xml.size() > kMaxSceneFileBytes) {
    list.error(0, "scene file is larger than " + std::to_string(kMaxSceneFileBytes / kMiB) + " MiB (limit " +
                      std::to_string(kMaxSceneFileBytes) + ")");
    return std::nullopt;
  }
  return SceneReader(list).run(xml);
}

const char* element_of(VolumeDataRef::Kind kind) {
  return kind == VolumeDataRef::Kind::scalar ? "<scalarData>" : "<vectorData>";
}

}  // namespace

VolumeSceneParseResult parse_volume_scene_xml(std::string_view xml, const std::string& file_name) {
  VolumeSceneParseResult result;
  DiagnosticList list(file_name);
  result.scene = parse_scene(xml, list);
  result.diagnostics = list.take();
  return result;
}

namespace {

// The scene file's bytes (`text`) parsed, its data files read from its folder.
VolumeSceneLoadResult load_volume_scene_text(std::string_view text, const std::filesystem::path& path,
                                             const VolumeSceneLoadOptions& options) {
  VolumeSceneLoadResult result;
  DiagnosticList list(path.string());
  std::optional<VolumeScene> scene = parse_scene(text, list);
  if (!scene) {
    result.diagnostics = list.take();
    return result;
  }
  LoadedVolumeScene loaded;
  loaded.scene = std::move(*scene);
  std::vector<Diagnostic> data_diagnostics;  // the data files' own messages, each file capped on its own
  NamedFileOptions named;
  named.allow_outside_folder = options.allow_files_outside_scene_folder;
  for (const auto& ref : loaded.scene.data) {
    const NamedFileReadResult data = read_named_file(path.parent_path(), ref.file, kMaxVolumeFileBytes, named,
                                                     "the scene's folder");
    if (!data.read.bytes) {
      list.error(ref.source_line, std::string(element_of(ref.kind)) + " attribute 'file' = \"" + escape_input(ref.file) +
                                      "\": " + data.read.error);
      list.error(ref.source_line, "cannot load data '" + escape_input(ref.id) + "' from " + data.path.string());
      continue;
    }
    NrrdReadOptions nrrd_options;  // a detached header's data file: inside the header's folder too
    nrrd_options.folder = data.path.parent_path();
    nrrd_options.named = named;
    nrrd_options.what_folder = "the folder of " + data.path.filename().string();
    NrrdLoadResult nrrd = parse_nrrd(*data.read.bytes, data.path.string(), nrrd_options);
    append_diagnostics(data_diagnostics, std::move(nrrd.diagnostics));
    if (!nrrd.ok()) {
      list.error(ref.source_line, "cannot load data '" + escape_input(ref.id) + "' from " + data.path.string());
      continue;
    }
    if (ref.kind == VolumeDataRef::Kind::scalar) {
      if (!nrrd.scalar) {
        list.error(ref.source_line, "data '" + escape_input(ref.id) + "' is declared scalar but " + escape_input(ref.file) +
                                        " holds vectors");
        continue;
      }
      loaded.scalars[ref.id] = std::make_shared<const ScalarGrid>(std::move(*nrrd.scalar));
    } else {
      if (!nrrd.vector) {
        list.error(ref.source_line, "data '" + escape_input(ref.id) + "' is declared vector but " + escape_input(ref.file) +
                                        " holds scalars");
        continue;
      }
      loaded.vectors[ref.id] = std::make_shared<const VectorGrid>(std::move(*nrrd.vector));
    }
  }
  const bool failed = list.has_errors() || has_errors(data_diagnostics);
  result.diagnostics = list.take();
  append_diagnostics(result.diagnostics, std::move(data_diagnostics));
  if (!failed) result.loaded = std::move(loaded);
  return result;
}

}  // namespace

VolumeSceneLoadResult load_volume_scene_file(const std::filesystem::path& path, const VolumeSceneLoadOptions& options) {
  return load_file<VolumeSceneLoadResult>(path, kMaxSceneFileBytes, [&](std::string_view text, const std::string&) {
    return load_volume_scene_text(text, path, options);
  });
}

}  // namespace vimg
