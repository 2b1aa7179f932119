// Fuzzes the XML image loader: any bytes give diagnostics or an image, never a crash, leak or
// undefined behaviour; every image that loads survives the canonical round trip; a document readable
// with problems holds its values out of range where the problems say, and keeps them when written.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"

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
  return 0;
}
