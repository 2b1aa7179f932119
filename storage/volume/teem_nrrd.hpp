#pragma once
// The one place that calls teem (libteem, the reference NRRD library) to read and write NRRD.
//   - teem keeps its errors on a process-wide stack (biff) and its settings in globals, so every
//     call here holds one mutex; callers may load volumes from several threads.
//   - teem never prints and never touches a file: it reads from memory through a FILE* over the
//     given bytes, and writes into memory; files are read and written by storage/ (read_named_file,
//     write_file_atomically), which enforce the limits and the confinement of data files.
// Not for real-time threads (allocates, locks).
#include <teem/nrrd.h>

#include <memory>
#include <string>
#include <string_view>

namespace vimg {

struct TeemNrrdDeleter {
  void operator()(Nrrd* nrrd) const;  // nrrdNuke: the struct and its data
};
using TeemNrrdPtr = std::unique_ptr<Nrrd, TeemNrrdDeleter>;

struct TeemReadResult {
  TeemNrrdPtr nrrd;   // set on success
  std::string error;  // teem's message (biff), most specific line last, without "[nrrd] function:" prefixes
  // How the data is stored, from the header.
  std::string encoding;  // teem's name: "raw", "ASCII", "hex", "gzip", "bzip2"
  bool compressed = false;
  unsigned line_skip = 0;
  long byte_skip = 0;
};

// Reads a NRRD header (with `data file` already taken out, ended by an empty line) followed by
// `data`. With `header_only`, teem reads the header and allocates nothing for the data.
TeemReadResult teem_read(std::string_view header, std::string_view data, bool header_only);

// Writes `nrrd` as one attached NRRD file into `out` (gzip or raw); returns teem's error, or "".
std::string teem_write(const Nrrd& nrrd, bool gzip, std::string& out);

}  // namespace vimg
