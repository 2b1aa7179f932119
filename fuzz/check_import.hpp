#pragma once
// What the import fuzzers check of a result: an image exactly when there is no error, printable
// and bounded messages, and an image that reads back without errors (what `vimg validate` says).
#include <cstdlib>

#include "fuzz/check_messages.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"

namespace vimg::fuzz {

inline void check_import(const ImportResult& r) {
  if (r.ok() == has_errors(r.diagnostics)) std::abort();
  check_messages(r.diagnostics);
  if (r.image && !parse_image_xml(write_image_xml(*r.image), "fuzz.vimg").ok()) std::abort();
}

}  // namespace vimg::fuzz
