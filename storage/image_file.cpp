// load_image_file and save_image_file: XML or PNG on disk (spec sections 1, 2 and 4).
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "storage/atomic_file.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/picture.hpp"
#include "storage/read_file.hpp"
#include "storage/png_codec.hpp"
#include "storage/file_extension.hpp"
#include "storage/foreign_file.hpp"

namespace vimg {

namespace {

LoadResult failure(const std::string& file, std::string message) {
  LoadResult result;
  result.diagnostics.push_back({Diagnostic::Severity::error, file, 0, std::move(message)});
  return result;
}

bool has_png_extension(const std::filesystem::path& path) { return lower_extension(path) == ".png"; }

}  // namespace

LoadResult load_image_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  FileReadResult read = read_regular_file(path, kMaxImageFileBytes);
  if (!read.bytes) return failure(name, read.error);
  const std::string& bytes = *read.bytes;
  if (const std::optional<ForeignKind> foreign = foreign_file_kind(bytes)) {
    if (foreign->damaged_png) return failure(name, foreign->what);
    LoadResult result;
    result.diagnostics.push_back({Diagnostic::Severity::error, name, foreign->line,
                                  "not an image: this is " + foreign->what +
                                      "; an image is .vimg XML or a PNG that carries a 'vibroimage' chunk"});
    return result;
  }
  if (!looks_like_png(bytes)) return parse_image_xml(bytes, name);

  const PngText text = read_png_text(bytes);
  if (!text.error.empty()) return failure(name, (text.damaged ? "damaged PNG: " : "") + text.error);
  if (!text.xml) {
    return failure(name, "this PNG has no 'vibroimage' text chunk, so it is not a vibroimage (a plain picture "
                         "cannot be opened as an image)");
  }
  return parse_image_xml(*text.xml, name);
}

std::optional<PngFileKind> png_file_kind(const std::filesystem::path& path) {
  const FileReadResult read = read_regular_file(path, kMaxImageFileBytes);
  if (!read.bytes || !looks_like_png(*read.bytes)) return std::nullopt;
  return PngFileKind{read_png_text(*read.bytes).xml.has_value(), png_physical_width_mm(*read.bytes)};
}

PngPieces encode_image_png(const Image& image, double scale_px_per_mm, int threads) {
  const PictureBands bands(image, scale_px_per_mm);
  if (bands.error()) {
    PngPieces failed;
    failed.error = *bands.error();
    return failed;
  }
  PngSource source;
  source.width_px = bands.size().width_px;
  source.height_px = bands.size().height_px;
  source.pixels_per_metre = static_cast<std::uint32_t>(std::lround(scale_px_per_mm * 1000.0));
  source.band_rows = PictureBands::kRows;
  source.draw_band = [&bands](int band, std::uint8_t* first_row, std::size_t stride) {
    PictureWork work;
    bands.draw_band(band, first_row, stride, work);
  };
  source.xml = [&image] { return write_image_xml(image); };
  return encode_png_pieces(source, threads);
}

std::optional<std::string> save_image_file(const Image& image, const std::filesystem::path& path,
                                           const SaveOptions& options) {
  if (!has_png_extension(path)) {
    const std::string xml = write_image_xml(image);
    if (auto error = saved_text_error(xml)) return path.string() + ": " + *error;
    return write_file_atomically(path, xml, options.new_file_mode);
  }
  const PngPieces png = encode_image_png(image, options.scale_px_per_mm, options.threads);
  if (!png.error.empty()) return path.string() + ": " + png.error;
  AtomicFileWriter writer(path, options.new_file_mode);
  for (const std::string& piece : png.pieces) writer.write(piece);
  return writer.commit();
}

}  // namespace vimg
