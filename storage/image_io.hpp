#pragma once
// Reading and writing vibrotactile images (spec sections 1 and 2): XML `.vimg` and PNG with the
// XML embedded. This header is the contract the editor, the player and `vimg` use.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

struct LoadResult {
  std::optional<Image> image;            // set only when there is no error: never half-loaded
  std::vector<Diagnostic> diagnostics;   // errors and warnings, in file order
  bool ok() const { return image.has_value(); }
};

// Parses XML text; `file_name` is used in messages only.
LoadResult parse_image_xml(std::string_view xml, const std::string& file_name);

// Loads `.vimg` (XML) or `.png` (with the `vibroimage` iTXt chunk), chosen by content.
LoadResult load_image_file(const std::filesystem::path& path);

// The canonical XML text (spec section 1, "Round trip"). Assigns ids to elements that lack one.
std::string write_image_xml(const Image& image);

struct SaveOptions {
  double scale_px_per_mm = 10.0;  // PNG only
};

// Saves as XML or PNG, chosen by the extension (`.png`, anything else is XML). Atomic: the target
// is either the old file or the complete new one. Returns an error message, or nothing on success.
std::optional<std::string> save_image_file(const Image& image, const std::filesystem::path& path,
                                           const SaveOptions& options = {});

}  // namespace vimg
