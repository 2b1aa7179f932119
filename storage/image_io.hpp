#pragma once
// Reading and writing vibrotactile images (spec sections 1 and 2): XML `.vimg` and PNG with the
// XML embedded. This header is the contract the editor, the player and `vimg` use.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/image.hpp"
#include "storage/atomic_file.hpp"
#include "storage/diagnostic.hpp"
#include "storage/parameter_table.hpp"
#include "storage/png_codec.hpp"

namespace vimg {

// A number outside its range (an error, spec section 1), kept as read in LoadResult::readable so
// that an editor can show it and clamp it (storage/parameter_table.hpp has the range).
struct ValueProblem {
  int line = 0;                        // of the attribute
  std::vector<std::size_t> path;       // the element: indices into children, through groups; empty for
                                       // the canvas and <interaction>
  const ParameterSpec* parameter = nullptr;
  double value = 0.0;                  // as read
};

struct LoadResult {
  std::optional<Image> image;            // set only when there is no error: never half-loaded
  std::vector<Diagnostic> diagnostics;   // errors and warnings, in file order
  // Set instead of `image` when there are errors but the document could be read: well-formed XML
  // with a <vibroimage> root of a readable version and size. It holds every element that could be
  // read: numbers out of range as read (each in value_problems), invalid ids left empty, duplicate
  // ids as they are. An element with any other error (a missing or unreadable attribute, an unknown
  // shape, too few points, groups nested too deep) is left out. For editors; tools that need a valid
  // image use `image`.
  std::optional<Image> readable;
  std::vector<ValueProblem> value_problems;  // all of them, in file order (diagnostics are capped)
  bool ok() const { return image.has_value(); }
};

// Parses XML text; `file_name` is used in messages only.
LoadResult parse_image_xml(std::string_view xml, const std::string& file_name);

// Loads `.vimg` (XML) or `.png` (with the `vibroimage` iTXt chunk), chosen by content.
LoadResult load_image_file(const std::filesystem::path& path);

// What a PNG file is before a program opens it: an image saved by vibroimage (it carries the
// `vibroimage` text chunk) or a picture to import, and the width in mm its pHYs chunk gives.
// Nothing when the file does not read (the open or the import then says why) or is not a PNG.
struct PngFileKind {
  bool vibroimage = false;
  std::optional<double> width_mm;
};
std::optional<PngFileKind> png_file_kind(const std::filesystem::path& path);

// The canonical XML text (spec section 1, "Round trip"). Assigns ids to elements that lack one.
std::string write_image_xml(const Image& image);

// An error when an image's XML text is one no reader accepts: longer than kMaxImageFileBytes, or
// refused by check_xml_limits (more elements or attributes than a file may hold, a control
// character a program put in a name). Such a text is never saved, as XML or inside a PNG.
std::optional<std::string> saved_text_error(std::string_view xml);

struct SaveOptions {
  double scale_px_per_mm = 10.0;  // PNG only
  int threads = 0;                // PNG only: threads drawing and compressing; <= 0: one per core
  NewFileMode new_file_mode = {};  // a new file's permission bits (NewFileMode::of the input it is made from)
};

// The PNG of an image (spec section 2) at `scale_px_per_mm`: the picture drawn and compressed band
// by band while the XML is written, on `threads` threads (<= 0: one per core); the pieces are the
// file in order. What save_image_file writes for a `.png`.
PngPieces encode_image_png(const Image& image, double scale_px_per_mm, int threads);

// Saves as XML or PNG, chosen by the extension (`.png`, anything else is XML). Atomic: the target
// is either the old file or the complete new one. Returns an error message, or nothing on success.
std::optional<std::string> save_image_file(const Image& image, const std::filesystem::path& path,
                                           const SaveOptions& options = {});

}  // namespace vimg
