#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "storage/read_file.hpp"
#include "storage/volume/nrrd.hpp"

namespace vimg {
namespace {

enum class SampleType { i8, u8, i16, u16, i32, u32, i64, u64, f32, f64 };

std::size_t sample_bytes(SampleType t) {
  switch (t) {
    case SampleType::i8: case SampleType::u8: return 1;
    case SampleType::i16: case SampleType::u16: return 2;
    case SampleType::i32: case SampleType::u32: case SampleType::f32: return 4;
    case SampleType::i64: case SampleType::u64: case SampleType::f64: return 8;
  }
  return 1;
}

std::optional<SampleType> parse_type(const std::string& name) {
  static const std::map<std::string, SampleType> types = {
      {"signed char", SampleType::i8}, {"int8", SampleType::i8}, {"int8_t", SampleType::i8},
      {"uchar", SampleType::u8}, {"unsigned char", SampleType::u8}, {"uint8", SampleType::u8},
      {"uint8_t", SampleType::u8},
      {"short", SampleType::i16}, {"short int", SampleType::i16}, {"signed short", SampleType::i16},
      {"signed short int", SampleType::i16}, {"int16", SampleType::i16}, {"int16_t", SampleType::i16},
      {"ushort", SampleType::u16}, {"unsigned short", SampleType::u16}, {"unsigned short int", SampleType::u16},
      {"uint16", SampleType::u16}, {"uint16_t", SampleType::u16},
      {"int", SampleType::i32}, {"signed int", SampleType::i32}, {"int32", SampleType::i32},
      {"int32_t", SampleType::i32},
      {"uint", SampleType::u32}, {"unsigned int", SampleType::u32}, {"uint32", SampleType::u32},
      {"uint32_t", SampleType::u32},
      {"longlong", SampleType::i64}, {"long long", SampleType::i64}, {"long long int", SampleType::i64},
      {"signed long long", SampleType::i64}, {"signed long long int", SampleType::i64},
      {"int64", SampleType::i64}, {"int64_t", SampleType::i64},
      {"ulonglong", SampleType::u64}, {"unsigned long long", SampleType::u64},
      {"unsigned long long int", SampleType::u64}, {"uint64", SampleType::u64}, {"uint64_t", SampleType::u64},
      {"float", SampleType::f32}, {"double", SampleType::f64}};
  const auto it = types.find(name);
  if (it == types.end()) return std::nullopt;
  return it->second;
}

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return std::string(s);
}

std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> words;
  std::istringstream in(s);
  std::string w;
  while (in >> w) words.push_back(w);
  return words;
}

// A finite decimal number, or nothing (std::from_chars is locale-independent).
std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_integer(std::string_view text) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// "(a,b,c)" -> three numbers.
std::optional<Vec3> parse_vector(const std::string& text) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') return std::nullopt;
  std::array<double, 3> v{};
  std::string_view inner(text.data() + 1, text.size() - 2);
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = inner.find(',');
    if ((i < 2) != (comma != std::string_view::npos)) return std::nullopt;
    const auto number = parse_number(trim(inner.substr(0, comma)));
    if (!number) return std::nullopt;
    v[static_cast<std::size_t>(i)] = *number;
    if (i < 2) inner.remove_prefix(comma + 1);
  }
  return Vec3{v[0], v[1], v[2]};
}

// Splits "(a,b,c) (d,e,f) none" into its items.
std::vector<std::string> split_vectors(const std::string& text) {
  std::vector<std::string> items;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t') { ++i; continue; }
    std::size_t end = text[i] == '(' ? text.find(')', i) : text.find_first_of(" \t", i);
    if (end == std::string::npos) end = text.size() - 1;
    else if (text[i] != '(') --end;
    items.push_back(text.substr(i, end - i + 1));
    i = end + 1;
  }
  return items;
}

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file) : bytes_(bytes), list_(file) {}

  NrrdLoadResult run() {
    if (parse_header() && check_header()) decode();
    if (failed()) {
      result_.scalar.reset();
      result_.vector.reset();
    }
    result_.diagnostics = list_.take();
    return std::move(result_);
  }

 private:
  void error(int line, std::string_view message) { list_.error(line, message); }
  bool failed() const { return list_.has_errors(); }
  static std::string q(std::string_view input) { return escape_input(input); }

  // Fields that carry nothing the volume backend uses but are valid NRRD.
  static bool ignorable(const std::string& field) {
    static const std::set<std::string> names = {
        "content", "space", "centers", "centerings", "thicknesses", "labels", "units", "min", "max",
        "old min", "oldmin", "old max", "oldmax", "measurement frame", "axis mins", "axismins",
        "axis maxs", "axismaxs", "sample units", "sampleunits", "number", "block size", "blocksize"};
    return names.count(field) > 0;
  }

  bool parse_header() {
    std::size_t pos = 0;
    int line_number = 0;
    bool saw_blank = false;
    // The header is searched within its limit only, however large the file.
    const std::string_view header = bytes_.substr(0, kMaxNrrdHeaderBytes + 1);
    while (pos < header.size()) {
      const std::size_t eol = header.find('\n', pos);
      if (eol == std::string_view::npos) {
        break;
      }
      const std::string_view raw_line = bytes_.substr(pos, eol - pos);
      ++line_number;
      pos = eol + 1;
      std::string line(raw_line);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line_number == 1) {
        if (line.size() != 8 || line.compare(0, 7, "NRRD000") != 0 || line[7] < '1' || line[7] > '5') {
          error(1, "not a NRRD file: the first line must be NRRD0001 to NRRD0005");
          return false;
        }
        continue;
      }
      if (line.empty()) {
        saw_blank = true;
        data_offset_ = pos;
        data_line_ = line_number + 1;
        break;
      }
      if (line[0] == '#') continue;
      if (line.find(":=") != std::string::npos) continue;  // key/value pair
      const std::size_t colon = line.find(": ");
      if (colon == std::string::npos) {
        error(line_number, "expected 'field: value', got '" + q(line) + "'");
        continue;
      }
      const std::string field = line.substr(0, colon);
      const std::string value = trim(std::string_view(line).substr(colon + 2));
      if (fields_.count(field)) {
        error(line_number, "field '" + q(field) + "' given twice (first on line " + std::to_string(fields_[field].line) + ")");
        continue;
      }
      fields_[field] = {value, line_number};
    }
    if (!saw_blank && header.size() > kMaxNrrdHeaderBytes) {
      error(line_number + 1, "the header is longer than " + std::to_string(kMaxNrrdHeaderBytes) + " bytes (limit " +
                                 std::to_string(kMaxNrrdHeaderBytes) + ")");
      return false;
    }
    if (line_number == 0) {
      error(0, "empty file, expected a NRRD header");
      return false;
    }
    if (!saw_blank) {
      error(line_number, "the header does not end with an empty line before the data");
      return false;
    }
    for (const auto& [field, entry] : fields_) {
      static const std::set<std::string> known = {"type", "dimension", "sizes", "encoding", "endian",
                                                  "spacings", "space directions", "space origin",
                                                  "space dimension", "kinds", "space units",
                                                  "byte skip", "byteskip", "line skip", "lineskip",
                                                  "data file", "datafile"};
      if (!known.count(field) && !ignorable(field)) error(entry.line, "unknown field '" + q(field) + "'");
    }
    return !failed();
  }

  struct Entry {
    std::string value;
    int line = 0;
  };

  const Entry* field(const std::string& name) const {
    const auto it = fields_.find(name);
    return it == fields_.end() ? nullptr : &it->second;
  }
  const Entry* required(const std::string& name) {
    const Entry* e = field(name);
    if (!e) error(0, "missing required field '" + name + "'");
    return e;
  }

  bool check_header() {
    for (const char* detached : {"data file", "datafile"}) {
      if (const Entry* e = field(detached)) {
        error(e->line, "detached data ('data file') is not supported: attach the data to the header");
      }
    }
    for (const char* skip : {"byte skip", "byteskip", "line skip", "lineskip"}) {
      if (const Entry* e = field(skip); e && e->value != "0") error(e->line, std::string("'") + skip + "' must be 0");
    }
    const Entry* type = required("type");
    const Entry* dimension = required("dimension");
    const Entry* sizes = required("sizes");
    const Entry* encoding = required("encoding");
    if (!type || !dimension || !sizes || !encoding) return false;

    if (const auto t = parse_type(type->value)) type_ = *t;
    else error(type->line, "unsupported type '" + q(type->value) + "'");

    const auto dim = parse_integer(dimension->value);
    if (!dim || (*dim != 3 && *dim != 4)) {
      error(dimension->line, "dimension must be 3 (scalar) or 4 (3-vector), got '" + q(dimension->value) + "'");
      return false;
    }
    dimension_ = static_cast<int>(*dim);
    vector_ = dimension_ == 4;
    const auto size_words = split_words(sizes->value);
    if (size_words.size() != static_cast<std::size_t>(dimension_)) {
      error(sizes->line, "sizes has " + std::to_string(size_words.size()) + " values, dimension is " + std::to_string(dimension_));
      return false;
    }
    std::size_t samples = 1;
    for (std::size_t i = 0; i < size_words.size(); ++i) {
      const auto n = parse_integer(size_words[i]);
      if (!n || *n < 1 || *n > static_cast<long long>(kMaxVolumeSamples)) {
        error(sizes->line, "size '" + q(size_words[i]) + "' is not a positive integer within limits");
        return false;
      }
      sizes_[i] = static_cast<int>(*n);
      samples *= static_cast<std::size_t>(*n);
      if (samples > kMaxVolumeSamples) {
        error(sizes->line, "volume has more than " + std::to_string(kMaxVolumeSamples) + " samples (limit " +
                               std::to_string(kMaxVolumeSamples) + ")");
        return false;
      }
    }
    samples_ = samples;
    if (samples * sample_bytes(type_) > kMaxVolumeDataBytes) {
      error(sizes->line, "the header declares " + std::to_string(samples * sample_bytes(type_)) + " bytes of data (limit " +
                             std::to_string(kMaxVolumeDataBytes) + ")");
      return false;
    }
    if (vector_ && sizes_[0] != 3) {
      error(sizes->line, "a 4-dimensional volume must have 3 components on its first axis, got " + std::to_string(sizes_[0]));
      return false;
    }
    if (const Entry* kinds = field("kinds"); kinds && vector_) {
      const auto k = split_words(kinds->value);
      static const std::set<std::string> vector_kinds = {"vector", "3-vector", "covariant-vector", "normal", "3-color", "RGB-color", "list", "point"};
      if (k.empty() || !vector_kinds.count(k[0])) error(kinds->line, "the first axis of a vector volume must have a vector kind, got '" + (k.empty() ? std::string() : q(k[0])) + "'");
    }

    if (encoding->value == "raw") encoding_ = Encoding::raw;
    else if (encoding->value == "gzip" || encoding->value == "gz") encoding_ = Encoding::gzip;
    else if (encoding->value == "ascii" || encoding->value == "text" || encoding->value == "txt") encoding_ = Encoding::ascii;
    else error(encoding->line, "unsupported encoding '" + q(encoding->value) + "' (raw, gzip or ascii)");

    if (encoding_ != Encoding::ascii && sample_bytes(type_) > 1) {
      const Entry* endian = field("endian");
      if (!endian) error(0, "missing field 'endian', required for multi-byte binary samples");
      else if (endian->value == "little") big_endian_ = false;
      else if (endian->value == "big") big_endian_ = true;
      else error(endian->line, "endian must be 'little' or 'big', got '" + q(endian->value) + "'");
    }
    if (const Entry* sd = field("space dimension"); sd && sd->value != "3") {
      error(sd->line, "space dimension must be 3");
    }
    if (const Entry* units = field("space units")) {
      for (const auto& u : split_words(units->value)) {
        if (u != "\"mm\"" && u != "mm") error(units->line, "space units must be millimetres (\"mm\"), got " + q(u));
      }
    }
    geometry_.size = {sizes_[vector_ ? 1 : 0], sizes_[vector_ ? 2 : 1], sizes_[vector_ ? 3 : 2]};
    read_geometry();
    return !failed();
  }

  void read_geometry() {
    const Entry* spacings = field("spacings");
    const Entry* directions = field("space directions");
    if (spacings && directions) {
      error(directions->line, "give either 'spacings' or 'space directions', not both");
      return;
    }
    Vec3 spacing_mm{1.0, 1.0, 1.0};
    if (spacings) {
      const auto words = split_words(spacings->value);
      if (words.size() != static_cast<std::size_t>(dimension_)) {
        error(spacings->line, "spacings needs " + std::to_string(dimension_) + " values");
        return;
      }
      std::array<double, 3> s{};
      for (int i = 0; i < 3; ++i) {
        const auto v = parse_number(words[static_cast<std::size_t>(i + (vector_ ? 1 : 0))]);
        if (!v || !(*v > 0.0)) {
          error(spacings->line, "spacing '" + q(words[static_cast<std::size_t>(i + (vector_ ? 1 : 0))]) + "' is not a positive number");
          return;
        }
        s[static_cast<std::size_t>(i)] = *v;
      }
      spacing_mm = {s[0], s[1], s[2]};
    } else if (directions) {
      const auto items = split_vectors(directions->value);
      if (items.size() != static_cast<std::size_t>(dimension_)) {
        error(directions->line, "space directions needs " + std::to_string(dimension_) + " entries");
        return;
      }
      if (vector_ && items[0] != "none") {
        error(directions->line, "the vector axis must have space direction 'none'");
        return;
      }
      std::array<double, 3> s{};
      for (int i = 0; i < 3; ++i) {
        const auto v = parse_vector(items[static_cast<std::size_t>(i + (vector_ ? 1 : 0))]);
        if (!v) {
          error(directions->line, "space direction '" + q(items[static_cast<std::size_t>(i + (vector_ ? 1 : 0))]) + "' is not (x,y,z)");
          return;
        }
        const std::array<double, 3> c{v->x, v->y, v->z};
        for (int j = 0; j < 3; ++j) {
          if (j != i && c[static_cast<std::size_t>(j)] != 0.0) {
            error(directions->line, "space directions must be axis-aligned (a diagonal matrix)");
            return;
          }
        }
        if (!(c[static_cast<std::size_t>(i)] > 0.0)) {
          error(directions->line, "space directions must be positive along each axis");
          return;
        }
        s[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i)];
      }
      spacing_mm = {s[0], s[1], s[2]};
    }
    Vec3 origin_mm;
    if (const Entry* origin = field("space origin")) {
      const auto v = parse_vector(origin->value);
      if (!v) {
        error(origin->line, "space origin must be (x,y,z), got '" + q(origin->value) + "'");
        return;
      }
      origin_mm = *v;
    }
    geometry_.spacing_m = spacing_mm * 1e-3;
    geometry_.origin_m = origin_mm * 1e-3;
  }

  void decode() {
    const std::string_view payload = bytes_.substr(data_offset_);
    // Reject data too short for the header before allocating for it.
    const std::size_t expected_bytes = samples_ * sample_bytes(type_);
    if (encoding_ == Encoding::raw && payload.size() != expected_bytes) {
      error(data_line_, "data holds " + std::to_string(payload.size()) + " bytes, the header needs " + std::to_string(expected_bytes));
      return;
    }
    if (encoding_ == Encoding::gzip && expected_bytes / 1100 > payload.size() + 64) {  // deflate expands at most ~1032:1
      error(data_line_, "gzip data is truncated (too short for the " + std::to_string(expected_bytes) + " bytes the header needs)");
      return;
    }
    if (encoding_ == Encoding::ascii && samples_ > payload.size() / 2 + 1) {  // a digit and a separator each
      error(data_line_, "data holds fewer than the " + std::to_string(samples_) + " samples the header needs");
      return;
    }
    std::vector<float> samples(samples_);
    if (encoding_ == Encoding::ascii) {
      if (!decode_ascii(payload, samples)) return;
    } else if (encoding_ == Encoding::gzip) {
      if (!inflate_samples(payload, samples)) return;
    } else {
      convert(payload, samples.data(), samples.size());
    }
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!std::isfinite(samples[i])) {
        error(data_line_, "sample " + std::to_string(i) + " is not a finite float");
        return;
      }
    }
    if (vector_) result_.vector.emplace(geometry_, std::move(samples));
    else result_.scalar.emplace(geometry_, std::move(samples));
  }

  // Inflates gzip (or zlib) data piece by piece, converting each piece into samples as it comes:
  // never more than the header's declared bytes are inflated (one byte more is the proof of excess),
  // and the inflated bytes are never held whole.
  bool inflate_samples(std::string_view compressed, std::vector<float>& samples) {
    const std::size_t n = sample_bytes(type_);
    const std::size_t expected = samples.size() * n;
    z_stream z{};
    if (inflateInit2(&z, 15 + 32) != Z_OK) {  // gzip or zlib header
      error(data_line_, "cannot start gzip decoder");
      return false;
    }
    // An odd-sized piece: samples straddle pieces, the partial one is carried to the next.
    constexpr std::size_t kPiece = 65521;
    std::vector<char> buffer(kPiece + 8);
    std::size_t carried = 0, converted = 0, total = 0;
    std::string_view input = compressed;
    int status = Z_OK;
    std::string problem;
    while (status == Z_OK) {
      if (z.avail_in == 0 && !input.empty()) {
        const std::size_t feed = std::min<std::size_t>(input.size(), std::numeric_limits<uInt>::max());
        z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
        z.avail_in = static_cast<uInt>(feed);
        input.remove_prefix(feed);
      }
      const std::size_t room = std::min(kPiece, expected - total + 1);
      z.next_out = reinterpret_cast<Bytef*>(buffer.data() + carried);
      z.avail_out = static_cast<uInt>(room);
      status = ::inflate(&z, Z_NO_FLUSH);
      const std::size_t produced = room - z.avail_out;
      total += produced;
      if (total > expected) {
        problem = "gzip data inflates to more than the " + std::to_string(expected) + " bytes the header declares";
        break;
      }
      const std::size_t bytes = carried + produced;
      const std::size_t whole = bytes / n;
      convert(std::string_view(buffer.data(), whole * n), samples.data() + converted, whole);
      converted += whole;
      carried = bytes - whole * n;
      std::memmove(buffer.data(), buffer.data() + whole * n, carried);
      if (status == Z_BUF_ERROR && z.avail_in == 0 && input.empty()) {
        problem = "gzip data is truncated";
      } else if (status == Z_BUF_ERROR) {
        status = Z_OK;  // no progress possible with this output room; go on
      } else if (status != Z_OK && status != Z_STREAM_END) {
        problem = std::string("gzip data is corrupt (") + (z.msg ? z.msg : "zlib error") + ")";
      }
    }
    inflateEnd(&z);
    if (problem.empty() && total != expected) {
      problem = "data holds " + std::to_string(total) + " bytes, the header needs " + std::to_string(expected);
    }
    if (!problem.empty()) {
      error(data_line_, problem);
      return false;
    }
    return true;
  }

  template <class T>
  static T load(const char* p, bool swap) {
    std::array<unsigned char, sizeof(T)> b;
    std::memcpy(b.data(), p, sizeof(T));
    const bool host_big = std::endian::native == std::endian::big;
    if (swap != host_big) std::reverse(b.begin(), b.end());
    T v;
    std::memcpy(&v, b.data(), sizeof(T));
    return v;
  }

  // Converts `count` samples from the start of `binary` into out[0..count).
  void convert(std::string_view binary, float* out, std::size_t count) const {
    const std::size_t n = sample_bytes(type_);
    const bool big = big_endian_;
    for (std::size_t i = 0; i < count; ++i) {
      const char* p = binary.data() + i * n;
      double v = 0.0;
      switch (type_) {
        case SampleType::i8: v = static_cast<signed char>(*p); break;
        case SampleType::u8: v = static_cast<unsigned char>(*p); break;
        case SampleType::i16: v = load<std::int16_t>(p, big); break;
        case SampleType::u16: v = load<std::uint16_t>(p, big); break;
        case SampleType::i32: v = load<std::int32_t>(p, big); break;
        case SampleType::u32: v = load<std::uint32_t>(p, big); break;
        case SampleType::i64: v = static_cast<double>(load<std::int64_t>(p, big)); break;
        case SampleType::u64: v = static_cast<double>(load<std::uint64_t>(p, big)); break;
        case SampleType::f32: v = load<float>(p, big); break;
        case SampleType::f64: v = load<double>(p, big); break;
      }
      out[i] = static_cast<float>(v);
    }
  }

  bool decode_ascii(std::string_view text, std::vector<float>& samples) {
    std::size_t count = 0;
    int line = data_line_;
    std::size_t i = 0;
    while (i < text.size()) {
      const char c = text[i];
      if (c == '\n') { ++line; ++i; continue; }
      if (c == ' ' || c == '\t' || c == '\r' || c == ',') { ++i; continue; }
      std::size_t end = i;
      while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != '\r' && text[end] != '\n' && text[end] != ',') ++end;
      const std::string_view word = text.substr(i, end - i);
      const auto v = parse_number(word);
      if (!v) {
        error(line, "'" + q(word) + "' is not a number");
        return false;
      }
      if (count == samples.size()) {
        error(line, "more than the " + std::to_string(samples.size()) + " samples the header declares");
        return false;
      }
      samples[count++] = static_cast<float>(*v);
      i = end;
    }
    if (count != samples.size()) {
      error(line, "data holds " + std::to_string(count) + " samples, the header needs " + std::to_string(samples.size()));
      return false;
    }
    return true;
  }

  enum class Encoding { raw, gzip, ascii };

  std::string_view bytes_;
  DiagnosticList list_;
  NrrdLoadResult result_;
  std::map<std::string, Entry> fields_;
  std::size_t data_offset_ = 0;
  int data_line_ = 0;
  SampleType type_ = SampleType::f32;
  Encoding encoding_ = Encoding::raw;
  bool big_endian_ = false;
  int dimension_ = 3;
  bool vector_ = false;
  std::array<int, 4> sizes_{};
  std::size_t samples_ = 0;
  GridGeometry geometry_;
};

}  // namespace

NrrdLoadResult parse_nrrd(std::string_view bytes, const std::string& file_name) {
  return Reader(bytes, file_name).run();
}

NrrdLoadResult load_nrrd_file(const std::filesystem::path& path) {
  const FileReadResult read = read_regular_file(path, kMaxVolumeFileBytes);
  if (!read.bytes) {
    NrrdLoadResult r;
    const std::string problem = read.error.starts_with("cannot open") ? "cannot open file" : read.error;
    r.diagnostics.push_back({Diagnostic::Severity::error, path.string(), 0, printable_message(problem)});
    return r;
  }
  return parse_nrrd(*read.bytes, path.string());
}

}  // namespace vimg
