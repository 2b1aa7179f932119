#pragma once
// Importing drawings and pictures made with other tools as vibroimages (docs/import.md). One entry
// point for `vimg import` and the editor's File -> Import: the format comes from the extension
// (.svg; .png). The result is an Image that `vimg validate` accepts, with warnings for everything
// of the source that could not be carried over; nothing is dropped without a message.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"
#include "storage/limits.hpp"

namespace vimg {

struct ImportOptions {
  // SVG: mm per user unit; when absent, the units come from width, height and viewBox.
  std::optional<double> mm_per_unit;
  double tolerance_mm = 0.05;       // SVG: curves flattened to within this
  double dot_max_radius_mm = 2.0;   // SVG: circles up to this radius become DOTs
  // Picture: the width of the canvas in mm (required); the height follows the aspect ratio.
  std::optional<double> width_mm;
  int levels = 4;                   // Picture: grey levels, 1 .. kMaxPictureLevels (storage/limits.hpp)
  double simplify_mm = 0.1;         // Picture: outlines simplified to within this
  double max_pixels = kMaxPngPixels;  // Picture: pixels decoded at most (docs/limits.md)
};

struct ImportResult {
  std::optional<Image> image;           // set only without errors
  std::vector<Diagnostic> diagnostics;  // errors and warnings, FILE:LINE
  // The PNG already carries a vibroimage: it was opened as such, not imported as a picture.
  bool opened_vibroimage = false;
  bool ok() const { return image.has_value(); }
};

// A result holding one error not tied to a line ("FILE: error: message").
ImportResult import_failure(const std::string& file, std::string message);

// Reads the file (bounded by kMaxImageFileBytes) and imports it by its extension.
ImportResult import_file(const std::filesystem::path& path, const ImportOptions& options);

// The importers on text and bytes already read; `file_name` is for messages. Each ends with
// check_imported_image.
ImportResult import_svg(std::string_view svg_text, const std::string& file_name, const ImportOptions& options);
ImportResult import_picture(std::string_view png_bytes, const std::string& file_name, const ImportOptions& options);

// The image as it will be written, read back: its warnings (a primitive wholly outside the canvas)
// join the import's, and an error (say, more primitives or attributes than a reader accepts) drops
// the image, so that an import never gives an image that cannot be saved and opened again.
void check_imported_image(ImportResult& r, const std::string& file);

}  // namespace vimg
