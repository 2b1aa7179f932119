#include "storage/volume/teem_nrrd.hpp"

#include <stdio.h>  // fopencookie, open_memstream (POSIX / GNU)

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <sstream>

namespace vimg {
namespace {

std::mutex& teem_mutex() {
  static std::mutex m;
  return m;
}

// teem's settings for every call: quiet, and no key/value pointers into freed memory.
void quiet_teem() {
  nrrdStateVerboseIO = 0;
  nrrdStateKeyValueReturnInternalPointers = 0;
}

// biff's text without the "[nrrd] function: " prefixes and the "trouble" lines that say nothing.
std::string take_biff_error() {
  char* text = biffGetDone(NRRD);
  std::string raw = text ? text : "";
  std::free(text);
  std::istringstream lines(raw);
  std::string line, kept;
  while (std::getline(lines, line)) {
    if (line.rfind("[", 0) == 0) {
      const std::size_t close = line.find("] ");
      if (close != std::string::npos) line = line.substr(close + 2);
      const std::size_t colon = line.find(": ");
      if (colon != std::string::npos && line.find(' ') > colon) line = line.substr(colon + 2);
      else if (!line.empty() && line.back() == ':') line.clear();
    }
    if (line.empty() || line == "trouble" || line == "trouble reading NRRD file") continue;
    if (!kept.empty()) kept += "\n";
    kept += line;
  }
  return kept.empty() ? "teem could not read the file" : kept;
}

// A read-only FILE over two pieces of memory, one after the other (header, then data), so that
// the data is never copied to follow the header.
struct TwoPieces {
  std::string_view first, second;
  std::size_t pos = 0;
  std::size_t size() const { return first.size() + second.size(); }
};

ssize_t pieces_read(void* cookie, char* buf, size_t size) {
  auto* p = static_cast<TwoPieces*>(cookie);
  std::size_t done = 0;
  while (done < size && p->pos < p->size()) {
    const bool in_first = p->pos < p->first.size();
    const std::string_view piece = in_first ? p->first : p->second;
    const std::size_t offset = in_first ? p->pos : p->pos - p->first.size();
    const std::size_t n = std::min(size - done, piece.size() - offset);
    std::memcpy(buf + done, piece.data() + offset, n);
    done += n;
    p->pos += n;
  }
  return static_cast<ssize_t>(done);
}

int pieces_seek(void* cookie, off64_t* offset, int whence) {
  auto* p = static_cast<TwoPieces*>(cookie);
  const auto base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? static_cast<off64_t>(p->pos) : static_cast<off64_t>(p->size());
  const auto size = static_cast<off64_t>(p->size());
  // Checked before adding: a header's "byte skip" reaches here as any 64-bit offset.
  if (*offset < -base || *offset > size - base) return -1;
  const off64_t target = base + *offset;
  p->pos = static_cast<std::size_t>(target);
  *offset = target;
  return 0;
}

int pieces_close(void*) { return 0; }

}  // namespace

void TeemNrrdDeleter::operator()(Nrrd* nrrd) const {
  if (nrrd) nrrdNuke(nrrd);
}

TeemReadResult teem_read(std::string_view header, std::string_view data, bool header_only) {
  TeemReadResult result;
  TwoPieces pieces{header, data};
  cookie_io_functions_t io{};
  io.read = pieces_read;
  io.seek = pieces_seek;
  io.close = pieces_close;
  const std::lock_guard lock(teem_mutex());
  quiet_teem();
  FILE* file = fopencookie(&pieces, "r", io);
  if (!file) {
    result.error = "cannot open the bytes for reading";
    return result;
  }
  TeemNrrdPtr nrrd(nrrdNew());
  NrrdIoState* nio = nrrdIoStateNew();
  nio->skipData = header_only ? 1 : 0;
  const int status = nrrdRead(nrrd.get(), file, nio);
  std::fclose(file);
  if (nio->encoding) {
    result.encoding = nio->encoding->name;
    result.compressed = nio->encoding->isCompression != 0;
  }
  result.line_skip = nio->lineSkip;
  result.byte_skip = nio->byteSkip;
  nrrdIoStateNix(nio);
  if (status != 0) {
    result.error = take_biff_error();
    return result;
  }
  result.nrrd = std::move(nrrd);
  return result;
}

std::string teem_write(const Nrrd& nrrd, bool gzip, std::string& out) {
  const std::lock_guard lock(teem_mutex());
  quiet_teem();
  char* buffer = nullptr;
  std::size_t length = 0;
  FILE* file = open_memstream(&buffer, &length);
  if (!file) return "cannot open a memory stream";
  NrrdIoState* nio = nrrdIoStateNew();
  nio->encoding = gzip ? nrrdEncodingGzip : nrrdEncodingRaw;
  nio->skipFormatURL = 1;
  const int status = nrrdWrite(file, &nrrd, nio);
  nrrdIoStateNix(nio);
  std::fclose(file);
  std::string error;
  if (status != 0) error = take_biff_error();
  else out.assign(buffer, length);
  std::free(buffer);
  return error;
}

}  // namespace vimg
