// Fuzzes the XML image loader: any bytes give diagnostics or an image, never a crash, leak or
// undefined behaviour; every image that loads survives the canonical round trip; a document readable
// with problems holds its values out of range where the problems say, and keeps them when written;
// and its PNG (a small picture) decodes to exactly the drawn picture and carries exactly its XML.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/picture.hpp"
#include "storage/png_codec.hpp"

using vimg::fuzz::check_messages;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::LoadResult first = vimg::parse_image_xml(text, "fuzz.vimg");
  if (first.ok() == vimg::has_errors(first.diagnostics)) std::abort();  // image iff no error
  check_messages(first.diagnostics);
  if (first.readable) {
    // Readable with problems: each value problem is a value out of range where its path says, and
    // writing the document and reading it again keeps every element and every problem.
    if (first.ok()) std::abort();
    for (const vimg::ValueProblem& p : first.value_problems) {
      const double* value = nullptr;
      if (p.path.empty()) {
        value = vimg::number_in(*first.readable, *p.parameter);
      } else {
        const vimg::Element* e = &first.readable->children.at(p.path[0]);
        for (std::size_t i = 1; i < p.path.size(); ++i) e = &std::get<vimg::Group>(e->body).children.at(p.path[i]);
        value = vimg::number_in(*e, *p.parameter);
      }
      if (value == nullptr || *value != p.value || vimg::in_range(*p.parameter, p.value)) std::abort();
    }
    const vimg::LoadResult again = vimg::parse_image_xml(vimg::write_image_xml(*first.readable), "again.vimg");
    const vimg::Image* image = again.image ? &*again.image : again.readable ? &*again.readable : nullptr;
    if (image == nullptr || image->children.size() != first.readable->children.size()) std::abort();
    if (again.value_problems.size() != first.value_problems.size()) std::abort();
  }
  if (!first.ok()) return 0;
  const std::string canonical = vimg::write_image_xml(*first.image);
  const vimg::LoadResult second = vimg::parse_image_xml(canonical, "canonical.vimg");
  if (!second.ok()) std::abort();                                     // the writer wrote an invalid file
  if (vimg::write_image_xml(*second.image) != canonical) std::abort();  // canonical form is stable

  // The PNG encoder (one thread here), at a scale giving at most 40 pixels a side.
  const double scale = 40.0 / std::max(first.image->width_mm, first.image->height_mm);
  const vimg::PngPieces png = vimg::encode_image_png(*first.image, scale, 1);
  if (!png.error.empty()) std::abort();
  std::string bytes;
  for (const std::string& piece : png.pieces) bytes += piece;
  const vimg::PngText carried = vimg::read_png_text(bytes);
  if (!carried.error.empty() || !carried.xml || *carried.xml != canonical) std::abort();
  vimg::RgbRaster drawn;
  if (vimg::draw_picture(*first.image, scale, drawn)) std::abort();
  const vimg::DecodedPng decoded = vimg::decode_png_rgba(bytes, 1e4);
  if (!decoded.error.empty() || decoded.width != drawn.width || decoded.height != drawn.height) std::abort();
  for (std::size_t p = 0; p < drawn.rgb.size() / 3; ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (decoded.rgba[p * 4 + c] != drawn.rgb[p * 3 + c]) std::abort();
    }
  }
  return 0;
}
