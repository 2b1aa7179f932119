// import_file: the format from the extension, the bytes through the one bounded reader; and the last
// check of every importer, that the result reads back as a valid image (what `vimg validate` will
// say of it).
#include "storage/import/import.hpp"

#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/png_codec.hpp"
#include "storage/png_signature.hpp"
#include "storage/read_file.hpp"
#include "storage/file_extension.hpp"

namespace vimg {

void check_imported_image(ImportResult& r, const std::string& file) {
  if (!r.image) return;
  LoadResult back = parse_image_xml(write_image_xml(*r.image), file + " (imported)");
  for (Diagnostic& d : back.diagnostics) {
    d.file = file;
    d.line = 0;
    if (d.severity == Diagnostic::Severity::error && d.not_shown_errors == 0) {
      d.message = printable_message("the imported image could not be opened again: " + d.message);
    }
  }
  r.diagnostics = merge_diagnostics(std::move(r.diagnostics), std::move(back.diagnostics), file);
  if (!back.ok()) r.image.reset();
}

ImportResult import_failure(const std::string& file, std::string message) {
  ImportResult r;
  r.diagnostics.push_back({Diagnostic::Severity::error, file, 0, std::move(message)});
  return r;
}

ImportResult import_file(const std::filesystem::path& path, const ImportOptions& options) {
  const std::string name = path.string();
  const std::string ext = lower_extension(path);
  if (ext != ".svg" && ext != ".png") return import_failure(name, "cannot import '" + ext + "' files (only .svg and .png)");
  FileReadResult read = read_regular_file(path, kMaxImageFileBytes);
  if (!read.bytes) return import_failure(name, read.error);
  ImportResult result;
  if (ext == ".svg") {
    result = import_svg(*read.bytes, name, options);
  } else {
    if (const auto damage = damaged_png_signature(*read.bytes)) return import_failure(name, damaged_png_signature_message(*damage));
    if (!looks_like_png(*read.bytes)) return import_failure(name, "is not a PNG file (no PNG signature)");
    const PngText text = read_png_text(*read.bytes);
    if (!text.error.empty()) return import_failure(name, (text.damaged ? "damaged PNG: " : "") + text.error);
    if (text.xml) {  // already a vibroimage: opened as one
      const LoadResult loaded = parse_image_xml(*text.xml, name);
      result.image = loaded.image;
      result.diagnostics = loaded.diagnostics;
      result.opened_vibroimage = true;
      return result;
    }
    result = import_picture(*read.bytes, name, options);
  }
  return result;
}

}  // namespace vimg
