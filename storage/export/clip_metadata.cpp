#include "storage/export/clip_metadata.hpp"

namespace vimg {

ClipMetadata clip_metadata(const Image& image, const std::filesystem::path& image_path,
                           const std::filesystem::path& gesture_path, std::string editor) {
  ClipMetadata metadata;
  metadata.editor = std::move(editor);
  if (image.meta && image.meta->author) metadata.author = *image.meta->author;
  metadata.source = image_path.filename().string();
  metadata.description = "the gesture " + gesture_path.filename().string() + " over " + metadata.source;
  metadata.tags = {"vibroimage"};
  return metadata;
}

}  // namespace vimg
