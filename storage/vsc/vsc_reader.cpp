// The .vsc reader (layout in vsc_format.hpp): every read is bounds-checked, every count is checked
// against the bytes left before anything is allocated, and every number against its range. No
// exceptions (the WebAssembly build has none): the first problem is kept, the reader jumps to the end
// of the input, and every later read gives zero, so loops and recursion end at once.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "storage/limits.hpp"
#include "storage/parameter_table.hpp"
#include "storage/vsc/vsc_format.hpp"
#include "storage/vsc/vsc_image.hpp"

namespace vimg {

static_assert(std::endian::native == std::endian::little, "the .vsc reader takes numbers as the host stores them");

namespace {

class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

  std::size_t offset() const { return at_; }
  std::size_t left() const { return bytes_.size() - at_; }
  bool failed() const { return !problem_.empty(); }
  const std::string& problem() const { return problem_; }
  std::size_t problem_offset() const { return problem_offset_; }
  void fail(std::string problem) {
    if (failed()) return;
    problem_ = std::move(problem);
    problem_offset_ = at_;
    at_ = bytes_.size();
  }

  std::uint8_t u8() {
    if (!need(1, "a byte")) return 0;
    return static_cast<std::uint8_t>(bytes_[at_++]);
  }
  std::uint32_t u32() { return raw<std::uint32_t>("a 4-byte count"); }
  std::int32_t i32() { return raw<std::int32_t>("a 4-byte integer"); }
  double f64() {
    const double v = raw<double>("an 8-byte number");
    if (!std::isfinite(v)) {
      fail("a number is not finite");
      return 0.0;
    }
    return v;
  }
  std::string str() {
    const std::uint32_t n = u32();
    if (n > vsc::kMaxStringBytes) fail("a text of " + std::to_string(n) + " bytes (limit " + std::to_string(vsc::kMaxStringBytes) + ")");
    if (!need(n, "a text of " + std::to_string(n) + " bytes")) return {};
    std::string s(bytes_.substr(at_, n));
    at_ += n;
    return s;
  }
  // A count of items of at least `item_bytes` each, no more than `limit`.
  std::uint32_t count(std::size_t item_bytes, std::size_t limit, const char* what) {
    const std::uint32_t n = u32();
    if (n > limit) fail(std::to_string(n) + " " + what + " (limit " + std::to_string(limit) + ")");
    if (static_cast<std::uint64_t>(n) * item_bytes > left())
      fail(std::to_string(n) + " " + what + " do not fit in the " + std::to_string(left()) + " bytes left");
    return failed() ? 0 : n;
  }

 private:
  bool need(std::size_t n, const std::string& what) {
    if (left() >= n && !failed()) return true;
    fail("the file ends inside " + what);
    return false;
  }
  template <class T>
  T raw(const char* what) {
    if (!need(sizeof(T), what)) return T{};
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
  std::string problem_;
  std::size_t problem_offset_ = 0;
};

constexpr std::size_t kMinElementBytes = 5;  // an empty id and a kind

class VscParser {
 public:
  explicit VscParser(std::string_view bytes) : in_(bytes) {}

  const ByteReader& input() const { return in_; }

  VscImage parse() {
    VscImage v;
    if (in_.left() < vsc::kHeaderBytes) in_.fail("too short for a .vsc header");
    for (char c : vsc::kMagic) {
      if (static_cast<char>(in_.u8()) != c) in_.fail("not a .vsc file (the magic is not VIMGVSC)");
    }
    const std::uint32_t version = in_.u32();
    if (version != vsc::kFormatVersion)
      in_.fail("format version " + std::to_string(version) + "; this build reads version " + std::to_string(vsc::kFormatVersion));
    const std::uint32_t rest = in_.u32();
    if (rest != in_.left()) in_.fail("the header says " + std::to_string(rest) + " bytes follow, " + std::to_string(in_.left()) + " do");
    read_actuator(v.actuator);
    read_canvas(v.image);
    v.image.children = read_elements(0);
    if (in_.left() != 0) in_.fail(std::to_string(in_.left()) + " bytes after the last element");
    return v;
  }

 private:
  void read_actuator(ResponseParams& a) {
    const std::uint8_t model = in_.u8();
    if (model > static_cast<std::uint8_t>(ResponseModel::voice_coil)) in_.fail("unknown response model " + std::to_string(model));
    if (!in_.failed()) a.model = static_cast<ResponseModel>(model);
    a.resonance_hz = ranged(kMinCornerHz, kMaxCornerHz, "resonance_hz");
    a.q = ranged(kMinResponseQ, kMaxResponseQ, "q");
    a.low_hz = ranged(kMinCornerHz, kMaxCornerHz, "low_hz");
    a.high_hz = ranged(kMinCornerHz, kMaxCornerHz, "high_hz");
    if (a.low_hz >= a.high_hz) in_.fail("the response's low_hz is not below its high_hz");
    a.spin_up_s = ranged(kMinSpinTimeS, kMaxSpinTimeS, "spin_up_s");
    a.spin_down_s = ranged(kMinSpinTimeS, kMaxSpinTimeS, "spin_down_s");
  }

  double ranged(double lo, double hi, const char* name) {
    const double v = in_.f64();
    if (v < lo || v > hi) in_.fail(std::string("the response's ") + name + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }

  void read_canvas(Image& image) {
    image.version_major = in_.i32();
    image.version_minor = in_.i32();
    if (image.version_major != kFormatMajor || image.version_minor < 0) in_.fail("unsupported image format version");
    image.width_mm = in_.f64();
    image.height_mm = in_.f64();
    check_numbers(ParameterOwner::canvas, [&](const ParameterSpec& s) { return number_in(image, s); });
    const std::uint8_t present = in_.u8();
    if (present > 1) in_.fail("the interaction flag is neither 0 nor 1");
    if (present == 1) {
      InteractionParams p;
      p.mass_kg = in_.f64();
      p.full_speed_mm_per_s = in_.f64();
      p.max_deformation_mm = in_.f64();
      image.interaction = p;
      check_numbers(ParameterOwner::interaction, [&](const ParameterSpec& s) { return number_in(image, s); });
    }
  }

  // Every number of `owner` that `find` locates must be in its range.
  template <class Find>
  void check_numbers(ParameterOwner owner, Find&& find) {
    if (in_.failed()) return;
    for (const ParameterSpec& spec : parameter_table()) {
      if (spec.owner != owner || spec.kind != ParameterKind::number) continue;
      const double* v = find(spec);
      if (v != nullptr && !in_range(spec, *v))
        in_.fail(std::string("<") + std::string(owner_tag(owner)) + "> " + std::string(spec.name) + " must be " + range_text(spec));
    }
  }

  // `depth`: the groups around these elements (0 for the image's own).
  std::vector<Element> read_elements(int depth) {
    if (depth > kMaxGroupDepth) {
      in_.fail("groups nest deeper than " + std::to_string(kMaxGroupDepth));
      return {};
    }
    const std::uint32_t n = in_.count(kMinElementBytes, kMaxXmlElements, "elements");
    std::vector<Element> elements;
    elements.reserve(n);
    for (std::uint32_t i = 0; i < n && !in_.failed(); ++i) {
      if (++element_count_ > kMaxXmlElements) in_.fail("more than " + std::to_string(kMaxXmlElements) + " elements");
      elements.push_back(read_element(depth));
    }
    return elements;
  }

  Element read_element(int depth) {
    Element e;
    e.id = in_.str();
    const std::uint8_t kind = in_.u8();
    switch (static_cast<vsc::ElementKind>(kind)) {
      case vsc::ElementKind::dot: {
        Dot d;
        for (double* v : {&d.x_mm, &d.y_mm, &d.radius_mm, &d.gain}) *v = in_.f64();
        e.body = d;
        check_numbers(ParameterOwner::dot, [&](const ParameterSpec& s) { return number_in(e, s); });
        break;
      }
      case vsc::ElementKind::line: {
        Line l;
        for (double* v : {&l.x1_mm, &l.y1_mm, &l.x2_mm, &l.y2_mm, &l.width_mm, &l.frequency_hz, &l.damping, &l.gain}) *v = in_.f64();
        e.body = l;
        check_numbers(ParameterOwner::line, [&](const ParameterSpec& s) { return number_in(e, s); });
        break;
      }
      case vsc::ElementKind::surface:
        e.body = read_surface();
        check_numbers(ParameterOwner::surface, [&](const ParameterSpec& s) {
          return applies_to_shape(s, std::get<Surface>(e.body).shape) ? number_in(e, s) : nullptr;
        });
        break;
      case vsc::ElementKind::group: {
        Group g;
        const std::uint8_t named = in_.u8();
        if (named > 1) in_.fail("the group name flag is neither 0 nor 1");
        if (named == 1) g.name = in_.str();
        g.children = read_elements(depth + 1);
        e.body = std::move(g);
        break;
      }
      default:
        in_.fail("unknown element kind " + std::to_string(kind));
    }
    return e;
  }

  Surface read_surface() {
    Surface s;
    const std::uint8_t shape = in_.u8();
    if (shape > static_cast<std::uint8_t>(SurfaceShape::polygon)) in_.fail("unknown surface shape " + std::to_string(shape));
    if (!in_.failed()) s.shape = static_cast<SurfaceShape>(shape);
    const std::uint8_t pattern = in_.u8();
    if (pattern > static_cast<std::uint8_t>(SurfacePattern::triangle)) in_.fail("unknown surface pattern " + std::to_string(pattern));
    if (!in_.failed()) s.pattern = static_cast<SurfacePattern>(pattern);
    for (double* v : {&s.x_mm, &s.y_mm, &s.width_mm, &s.height_mm, &s.cx_mm, &s.cy_mm, &s.rx_mm, &s.ry_mm, &s.period_mm,
                      &s.relief_mm, &s.gain})
      *v = in_.f64();
    const std::uint32_t n = in_.count(16, kMaxPolygonPoints, "polygon points");
    if (!in_.failed() && (s.shape == SurfaceShape::polygon ? n < 3 : n != 0))
      in_.fail("a " + std::string(shape_name(s.shape)) + " surface with " + std::to_string(n) + " points");
    s.points.reserve(n);
    for (std::uint32_t i = 0; i < n && !in_.failed(); ++i) {
      const double x = in_.f64();
      const double y = in_.f64();
      s.points.push_back({x, y});
    }
    return s;
  }

  ByteReader in_;
  std::size_t element_count_ = 0;
};

}  // namespace

VscReadResult read_vsc(std::string_view bytes, const std::string& name) {
  VscReadResult result;
  if (bytes.size() > vsc::kMaxFileBytes) {
    result.error = name + ": error: " + std::to_string(bytes.size()) + " bytes (a .vsc is at most " +
                   std::to_string(vsc::kMaxFileBytes) + ")";
    return result;
  }
  VscParser parser(bytes);
  VscImage v = parser.parse();
  if (parser.input().failed()) {
    result.error = name + ": error: byte " + std::to_string(parser.input().problem_offset()) + ": " + parser.input().problem();
  } else {
    result.image = std::move(v);
  }
  return result;
}

}  // namespace vimg
