#pragma once
// The text header of a NRRD file, scanned line by line before teem sees it (storage/volume/teem_nrrd.hpp):
//   - it finds where the header ends (an empty line, or the end of a detached `.nhdr` header) within
//     kMaxNrrdHeaderBytes, and where attached data starts;
//   - it remembers the line of every field, so that messages about a field name its line;
//   - it takes out `data file:`, so that teem never opens a file itself: the data file is read by
//     the caller through read_named_file() (confined to the header's folder) and handed to teem
//     after the header, exactly as attached data would follow it.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct NrrdHeaderField {
  std::string name;   // as written, e.g. "space directions"
  std::string value;  // without surrounding blanks
  int line = 0;
};

struct NrrdHeaderScan {
  std::string teem_header;  // the header without `data file`, ended by an empty line
  std::vector<NrrdHeaderField> fields;
  std::size_t data_offset = 0;  // where attached data starts in the bytes (their size when detached)
  int data_line = 0;            // the line on which attached data starts
  std::optional<NrrdHeaderField> data_file;

  // The line of a field (either spelling, e.g. "byte skip" or "byteskip"), or 0 when absent.
  int line_of(std::string_view name) const;
};

// Scans the header, reporting problems to `list`; nothing when the header is unusable.
std::optional<NrrdHeaderScan> scan_nrrd_header(std::string_view bytes, DiagnosticList& list);

}  // namespace vimg
