#pragma once
// A NRRD file as teem reads it (any dimension, type, encoding, attached or detached data), with
// vibroimage's checks on top. This is the general layer; storage/volume/nrrd.hpp turns a volume
// into the scalar or 3-vector grid a scene needs.
//
// Before teem allocates anything:
//   - the header is scanned within kMaxNrrdHeaderBytes (nrrd_header.hpp) and read by teem alone;
//   - the declared samples and bytes are checked against kMaxVolumeSamples and kMaxVolumeDataBytes;
//   - a detached header's `data file` is read with read_named_file(): inside the header's folder
//     (unless the caller allows otherwise), a regular file, no symlink, FIFO or device, within
//     kMaxVolumeFileBytes;
//   - raw data must hold exactly the declared bytes; gzip and bzip2 data are inflated into a
//     small buffer and counted first, so that data inflating past the declared size is refused
//     (at most the declared size plus one byte is ever inflated).
// Every problem is `FILE:LINE: error: …` with the line of the field concerned.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/named_file.hpp"
#include "storage/volume/nrrd_header.hpp"

namespace vimg {

struct NrrdReadOptions {
  // The folder of the header file; without it (bytes from memory), `data file` is refused.
  std::optional<std::filesystem::path> folder;
  NamedFileOptions named;  // whether a data file may lie outside `folder`
  std::string what_folder = "the header's folder";
};

struct NrrdAxis {
  std::size_t size = 0;
  double spacing = 0.0;                // NaN when the header gives none
  std::vector<double> space_direction;  // space-dimension values, empty when "none" or not given
  std::string kind;                     // teem's name ("domain", "vector", …), "" when unknown
  std::string units;                    // "" when not given
};

struct NrrdVolume {
  std::string type;      // teem's name of the sample type, e.g. "unsigned char", "float"
  std::string encoding;  // "raw", "ASCII", "hex", "gzip", "bzip2"
  std::vector<NrrdAxis> axes;  // the fastest axis first
  unsigned space_dimension = 0;
  std::vector<double> space_origin;     // space-dimension values (NaN where not given)
  std::vector<std::string> space_units;  // space-dimension values ("" where not given)
  std::vector<float> values;            // every sample as float, the fastest axis first
  NrrdHeaderScan header;                // the lines of the fields, for messages

  std::size_t sample_count() const { return values.size(); }
};

struct NrrdVolumeResult {
  std::optional<NrrdVolume> volume;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
};

// Reads a NRRD file held in memory; `file_name` names it in messages.
NrrdVolumeResult read_nrrd_volume(std::string_view bytes, const std::string& file_name, const NrrdReadOptions& options = {});
// The same, reporting to `list` (for callers that add their own checks).
std::optional<NrrdVolume> read_nrrd_volume(std::string_view bytes, const NrrdReadOptions& options, DiagnosticList& list);
// The bytes of a .nrrd or .nhdr file (read_regular_file, kMaxVolumeFileBytes) and the options
// that keep its data file in its folder; on failure, the diagnostic that says why, as
// storage/load_file.hpp words it ("FILE: error: cannot open: REASON"). Not load_file itself: the
// caller keeps the bytes (a detached header's data is read after), and load_file's parse step
// would copy a volume of up to kMaxVolumeFileBytes a second time.
struct NrrdFile {
  std::optional<std::string> bytes;
  NrrdReadOptions options;
  std::vector<Diagnostic> diagnostics;
};
NrrdFile read_nrrd_file(const std::filesystem::path& path, const NamedFileOptions& named);

// Reads a .nrrd or .nhdr file (read_regular_file, kMaxVolumeFileBytes); a detached data file must
// be in the header's folder unless `named.allow_outside_folder`.
NrrdVolumeResult load_nrrd_volume(const std::filesystem::path& path, const NamedFileOptions& named = {});

}  // namespace vimg
