#pragma once
// The metadata of a clip rendered from an image along a gesture (docs/export.md). A clip is made to
// be shared: it names the image and the gesture by their file names only, never by the folders
// they are in (a path would tell where the user keeps them), and carries the image's author.
#include <filesystem>
#include <string>

#include "primitives/image.hpp"
#include "storage/export/haptic_clip.hpp"

namespace vimg {

// editor: `editor`; author: the image's <meta><author>, "" without one; source: the image's file
// name; description: "the gesture G.csv over IMAGE.vimg" (file names); project: ""; tags:
// "vibroimage".
ClipMetadata clip_metadata(const Image& image, const std::filesystem::path& image_path,
                           const std::filesystem::path& gesture_path, std::string editor);

}  // namespace vimg
