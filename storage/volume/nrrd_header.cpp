#include "storage/volume/nrrd_header.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <sstream>
#include <utility>
#include <vector>

#include "storage/limits.hpp"
#include "storage/text_trim.hpp"

namespace vimg {
namespace {

// NRRD allows some field names without their blank ("byteskip"); compare without blanks.
std::string squeeze(std::string_view name) {
  std::string s;
  for (char c : name) {
    if (c != ' ') s += c;
  }
  return s;
}

// The number of "quoted" strings (with \" escapes) a value lists, or -1 when it is not such a list.
int count_quoted(std::string_view v) {
  int count = 0;
  std::size_t i = 0;
  for (;;) {
    while (i < v.size() && (v[i] == ' ' || v[i] == '\t')) ++i;
    if (i == v.size()) return count;
    if (v[i] != '"') return -1;
    for (++i; i < v.size() && v[i] != '"'; ++i) {
      if (v[i] == '\\') ++i;
    }
    if (i >= v.size()) return -1;
    ++i;
    ++count;
  }
}

// The dimension of a named NRRD space ("right-anterior-superior", "RAST", ...), 0 when unknown.
int space_dimension_of(std::string_view name) {
  static const std::vector<std::pair<std::string_view, int>> spaces = {
      {"right-anterior-superior", 3}, {"RAS", 3}, {"left-anterior-superior", 3}, {"LAS", 3},
      {"left-posterior-superior", 3}, {"LPS", 3}, {"right-anterior-superior-time", 4}, {"RAST", 4},
      {"left-anterior-superior-time", 4}, {"LAST", 4}, {"left-posterior-superior-time", 4}, {"LPST", 4},
      {"scanner-xyz", 3}, {"scanner-xyz-time", 4}, {"3D-right-handed", 3}, {"3D-left-handed", 3},
      {"3D-right-handed-time", 4}, {"3D-left-handed-time", 4}};
  for (const auto& [n, d] : spaces) {
    if (n == name) return d;
  }
  return 0;
}

std::string in_quotes(std::string_view input) { return "'" + escape_input(input) + "'"; }

// teem leaks memory when a list of quoted strings is unterminated or, for `space units`, longer
// than the space; such values are refused here, before teem reads them.
// teem also leaks when a per-axis field comes before `dimension`, or a space field before the
// space is given; the order NRRD asks for is checked here first.
void check_order(const NrrdHeaderScan& scan, DiagnosticList& list, bool& failed) {
  static const std::vector<std::string_view> per_axis = {"sizes", "spacings", "thicknesses", "axis mins", "axismins",
                                                         "axis maxs", "axismaxs", "centers", "centerings", "labels",
                                                         "units", "kinds", "space directions"};
  static const std::vector<std::string_view> per_space = {"space units", "space origin", "space directions",
                                                          "measurement frame"};
  bool dimension = false, space = false;
  for (const auto& f : scan.fields) {
    dimension = dimension || f.name == "dimension";
    space = space || f.name == "space" || f.name == "space dimension";
    const auto is = [&](const std::vector<std::string_view>& names) {
      return std::find(names.begin(), names.end(), f.name) != names.end();
    };
    const char* needed = is(per_axis) && !dimension ? "dimension" : is(per_space) && !space ? "space' or 'space dimension" : nullptr;
    if (needed) {
      list.error(f.line, "field " + in_quotes(f.name) + " must come after '" + needed + "'");
      failed = true;
    }
  }
}

void check_quoted_lists(const NrrdHeaderScan& scan, DiagnosticList& list, bool& failed) {
  int space_dim = 0;
  for (const auto& f : scan.fields) {
    if (f.name == "space dimension") space_dim = std::atoi(f.value.c_str());
    if (f.name == "space") space_dim = space_dimension_of(f.value);
  }
  for (const auto& f : scan.fields) {
    if (f.name != "labels" && f.name != "units" && f.name != "space units") continue;
    const int n = count_quoted(f.value);
    if (n < 0) {
      list.error(f.line, "field " + in_quotes(f.name) + ": expected a list of \"quoted\" strings");
      failed = true;
    } else if (f.name == "space units" && space_dim > 0 && n != space_dim) {
      list.error(f.line, "field 'space units': " + std::to_string(n) + " units for a space of " + std::to_string(space_dim) +
                             " dimensions");
      failed = true;
    }
  }
}

// NRRD allows one negative byte skip, -1: the data are the last bytes of the file. teem reads any
// negative value as -1; pynrrd refuses them. Refused here at its line.
void check_byte_skip(const NrrdHeaderScan& scan, DiagnosticList& list, bool& failed) {
  for (const auto& f : scan.fields) {
    if (squeeze(f.name) != "byteskip") continue;
    long long skip = 0;
    const char* end = f.value.data() + f.value.size();
    const auto [at, problem] = std::from_chars(f.value.data(), end, skip);
    const bool negative = !f.value.empty() && f.value[0] == '-';
    if (negative && (problem != std::errc{} || at != end || skip != -1)) {
      list.error(f.line, "field " + in_quotes(f.name) + ": " + escape_input(f.value) +
                             " is not allowed: -1 (the data are the last bytes of the file) is the only negative byte skip");
      failed = true;
    }
  }
}

}  // namespace

int NrrdHeaderScan::line_of(std::string_view name) const {
  const std::string wanted = squeeze(name);
  for (const auto& f : fields) {
    if (squeeze(f.name) == wanted) return f.line;
  }
  if (data_file && squeeze(data_file->name) == wanted) return data_file->line;
  return 0;
}

std::optional<NrrdHeaderScan> scan_nrrd_header(std::string_view bytes, DiagnosticList& list) {
  NrrdHeaderScan scan;
  const std::string_view header = bytes.substr(0, kMaxNrrdHeaderBytes + 1);
  std::size_t pos = 0;
  int line_number = 0;
  bool ended = false;
  bool failed = false;
  while (pos < header.size()) {
    std::size_t eol = header.find('\n', pos);
    if (eol == std::string_view::npos) {
      if (header.size() > kMaxNrrdHeaderBytes) break;
      eol = header.size();  // a detached header may end without a newline
    }
    const std::string_view raw = bytes.substr(pos, eol - pos);
    ++line_number;
    pos = std::min(eol + 1, bytes.size());
    std::string_view line = raw;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find('\0') != std::string_view::npos) {  // teem reads lines as C strings
      list.error(line_number, "the header holds a NUL byte");
      return std::nullopt;
    }
    if (line.find('\r') != std::string_view::npos) {  // teem ends a line there: it would read other lines than these
      list.error(line_number, "the header holds a carriage return inside a line (header lines end with a newline)");
      return std::nullopt;
    }
    if (line_number == 1) {
      if (line.size() != 8 || line.substr(0, 7) != "NRRD000" || line[7] < '1' || line[7] > '5') {
        list.error(1, "not a NRRD file: the first line must be NRRD0001 to NRRD0005");
        return std::nullopt;
      }
      scan.teem_header += std::string(line) + "\n";
      continue;
    }
    if (line.empty()) {
      ended = true;
      scan.data_offset = pos;
      scan.data_line = line_number + 1;
      break;
    }
    if (line[0] == '#') {
      scan.teem_header += std::string(line) + "\n";
      continue;
    }
    // teem overflows its message buffer on long words. Checked before a key/value line is told
    // apart: teem reads a line that starts with a field's name as that field even when it holds
    // ':=', so every line but a comment is held to the limit.
    if (line.size() > kMaxNrrdFieldLineBytes) {
      list.error(line_number, "the field line is longer than " + std::to_string(kMaxNrrdFieldLineBytes) + " bytes (limit " +
                                  std::to_string(kMaxNrrdFieldLineBytes) + ")");
      failed = true;
      continue;
    }
    if (line.find(":=") != std::string_view::npos) {
      scan.teem_header += std::string(line) + "\n";
      continue;
    }
    const std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos) {
      list.error(line_number, "expected 'field: value', got " + in_quotes(line));
      failed = true;
      continue;
    }
    NrrdHeaderField field{std::string(line.substr(0, colon)), std::string(trim_blanks(line.substr(colon + 2))), line_number};
    if (const int first = scan.line_of(field.name)) {
      list.error(line_number, "field " + in_quotes(field.name) + " given twice (first on line " + std::to_string(first) + ")");
      failed = true;
      continue;
    }
    if (squeeze(field.name) == "datafile") {
      std::istringstream words(field.value);
      std::string first, second;
      words >> first >> second;
      if (first.empty() || first == "LIST" || !second.empty()) {
        list.error(line_number, "field 'data file': only a single data file is supported, got " + in_quotes(field.value));
        failed = true;
      }
      scan.data_file = field;
      continue;  // teem never sees it: the caller reads the file
    }
    scan.teem_header += std::string(line) + "\n";
    scan.fields.push_back(std::move(field));
  }
  if (!ended && header.size() > kMaxNrrdHeaderBytes) {
    list.error(line_number + 1, "the header is longer than " + std::to_string(kMaxNrrdHeaderBytes) + " bytes (limit " +
                                    std::to_string(kMaxNrrdHeaderBytes) + ")");
    return std::nullopt;
  }
  if (line_number == 0) {
    list.error(0, "empty file, expected a NRRD header");
    return std::nullopt;
  }
  if (!ended && !scan.data_file) {
    list.error(line_number, "the header does not end with an empty line before the data");
    return std::nullopt;
  }
  if (!ended) {
    scan.data_offset = bytes.size();
    scan.data_line = line_number + 1;
  } else if (scan.data_file &&
             bytes.substr(scan.data_offset).find_first_not_of(" \t\r\n") != std::string_view::npos) {
    list.error(scan.data_line, "a header with 'data file' may not be followed by data");
    failed = true;
  }
  check_order(scan, list, failed);
  check_quoted_lists(scan, list, failed);
  check_byte_skip(scan, list, failed);
  if (failed) return std::nullopt;
  scan.teem_header += "\n";
  return scan;
}

}  // namespace vimg
