#include "apps/vimg-player/study_pictures.hpp"

namespace vimg::player_app {

StudyPictures::~StudyPictures() {
  for (auto& e : entries_) {
    if (e.picture.texture != nullptr) SDL_DestroyTexture(e.picture.texture);
  }
}

const StudyPictures::Entry& StudyPictures::entry(const Image& image, double px_per_mm) {
  for (const auto& e : entries_) {
    if (e.image == &image && e.px_per_mm == px_per_mm) return e;
  }
  const Entry e{&image, px_per_mm,
                make_picture_texture(renderer_, image, px_per_mm,
                                     {"a picture is shown without its primitives", "cannot show a picture"})};
  entries_.push_back(e);
  return entries_.back();
}

void StudyPictures::draw(const Image& image, double px_per_mm, double x, double y) {
  const Entry& e = entry(image, px_per_mm);
  const SDL_FRect canvas{static_cast<float>(x), static_cast<float>(y), static_cast<float>(image.width_mm * px_per_mm),
                         static_cast<float>(image.height_mm * px_per_mm)};
  draw_picture_canvas(renderer_, e.picture, canvas);
}

}  // namespace vimg::player_app
