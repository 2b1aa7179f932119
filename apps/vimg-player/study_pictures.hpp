#pragma once
// The pictures of the study's images as textures: each image at each scale drawn once with the PNG
// export's painter (storage/picture.hpp, the same pixels as `vimg convert --scale S`) and kept for
// the session: the true-size training picture, the thumbnails and the answer sheets.
// Threads: the UI thread only (SDL rendering).
#include <SDL.h>

#include <vector>

#include "apps/vimg-player/image_view.hpp"
#include "primitives/image.hpp"

namespace vimg::player_app {

class StudyPictures {
 public:
  explicit StudyPictures(SDL_Renderer* renderer) : renderer_(renderer) {}
  ~StudyPictures();
  StudyPictures(const StudyPictures&) = delete;
  StudyPictures& operator=(const StudyPictures&) = delete;

  // Draws `image` at `px_per_mm` with its top-left corner at (x, y), and its canvas border. A
  // picture that cannot be drawn (over the PNG pixel limit) is shown as the bare canvas, with one
  // message on stderr.
  void draw(const Image& image, double px_per_mm, double x, double y);

 private:
  struct Entry {
    const Image* image = nullptr;
    double px_per_mm = 0.0;
    PictureTexture picture;
  };
  const Entry& entry(const Image& image, double px_per_mm);

  SDL_Renderer* renderer_;
  std::vector<Entry> entries_;
};

}  // namespace vimg::player_app
