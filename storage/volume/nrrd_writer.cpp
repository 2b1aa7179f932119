#include <zlib.h>

#include <bit>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "storage/number_text.hpp"
#include "storage/volume/nrrd.hpp"

namespace vimg {
namespace {

std::string little_endian_floats(const std::vector<float>& values) {
  std::string bytes(values.size() * 4, '\0');
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto u = std::bit_cast<std::uint32_t>(values[i]);
    for (std::size_t b = 0; b < 4; ++b) bytes[4 * i + b] = static_cast<char>((u >> (8 * b)) & 0xFFu);
  }
  return bytes;
}

std::string gzip(const std::string& raw) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error("cannot start gzip encoder");
  }
  std::string out(deflateBound(&z, static_cast<uLong>(raw.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
  z.avail_in = static_cast<uInt>(raw.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  const std::size_t produced = out.size() - z.avail_out;
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw std::runtime_error("gzip encoder failed");
  out.resize(produced);
  return out;
}

std::string mm(double metres) { return format_decimal(metres * 1e3); }

std::string header(const GridGeometry& g, bool vector, NrrdEncoding encoding, const std::string& content) {
  std::ostringstream h;
  h << "NRRD0004\n# written by vibroimage\n";
  if (!content.empty()) h << "content: " << content << "\n";
  h << "type: float\n";
  h << "dimension: " << (vector ? 4 : 3) << "\n";
  h << "space dimension: 3\n";
  h << "sizes: " << (vector ? "3 " : "") << g.size.nx << " " << g.size.ny << " " << g.size.nz << "\n";
  h << "space directions: " << (vector ? "none " : "") << "(" << mm(g.spacing_m.x) << ",0,0) (0,"
    << mm(g.spacing_m.y) << ",0) (0,0," << mm(g.spacing_m.z) << ")\n";
  if (vector) h << "kinds: vector domain domain domain\n";
  h << "space units: \"mm\" \"mm\" \"mm\"\n";
  h << "space origin: (" << mm(g.origin_m.x) << "," << mm(g.origin_m.y) << "," << mm(g.origin_m.z) << ")\n";
  h << "endian: little\n";
  h << "encoding: " << (encoding == NrrdEncoding::gzip ? "gzip" : "raw") << "\n\n";
  return h.str();
}

std::string body(const std::vector<float>& values, NrrdEncoding encoding) {
  const std::string raw = little_endian_floats(values);
  return encoding == NrrdEncoding::gzip ? gzip(raw) : raw;
}

}  // namespace

std::string write_nrrd(const ScalarGrid& grid, NrrdEncoding encoding, const std::string& content) {
  return header(grid.geometry(), false, encoding, content) + body(grid.values(), encoding);
}

std::string write_nrrd(const VectorGrid& grid, NrrdEncoding encoding, const std::string& content) {
  return header(grid.geometry(), true, encoding, content) + body(grid.components(), encoding);
}

}  // namespace vimg
