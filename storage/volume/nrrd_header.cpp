#include "storage/volume/nrrd_header.hpp"

#include <algorithm>
#include <sstream>

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

std::string in_quotes(std::string_view input) { return "'" + escape_input(input) + "'"; }

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
    if (line[0] == '#' || line.find(":=") != std::string_view::npos) {
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
  if (failed) return std::nullopt;
  scan.teem_header += "\n";
  return scan;
}

}  // namespace vimg
