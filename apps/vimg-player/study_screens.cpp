#include "apps/vimg-player/study_screens.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace vimg::player_app {

namespace {

constexpr SDL_Color kText{235, 235, 225, 255};
constexpr SDL_Color kDim{150, 150, 150, 255};
constexpr SDL_Color kAccent{255, 200, 0, 255};

std::vector<std::pair<double, double>> set_sizes(const StudyScreenView& view) {
  std::vector<std::pair<double, double>> sizes;
  for (const Image& image : view.material->images[view.flow->set()]) sizes.emplace_back(image.width_mm, image.height_mm);
  return sizes;
}

void fill(SDL_Renderer* renderer, const PixelRect& r, SDL_Color c) {
  SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, c.a);
  const SDL_FRect f{static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.w), static_cast<float>(r.h)};
  SDL_RenderFillRectF(renderer, &f);
}

void frame(SDL_Renderer* renderer, const PixelRect& r, SDL_Color c, int thickness) {
  SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, c.a);
  for (int i = 0; i < thickness; ++i) {
    const SDL_FRect f{static_cast<float>(r.x - i), static_cast<float>(r.y - i), static_cast<float>(r.w + 2 * i),
                      static_cast<float>(r.h + 2 * i)};
    SDL_RenderDrawRectF(renderer, &f);
  }
}

std::string set_words(const StudyScreenView& view) {
  return "set " + view.material->set_name(view.flow->set()) + " (" + std::to_string(view.flow->set() + 1) + " of " +
         std::to_string(view.flow->set_count()) + ")";
}

std::string minutes_seconds(double seconds) {
  const long whole = static_cast<long>(std::ceil(seconds));
  const long s = whole % 60;
  return std::to_string(whole / 60) + (s < 10 ? ":0" : ":") + std::to_string(s);
}

void draw_pictures(SDL_Renderer* renderer, StudyPictures& pictures, const StudyText& text, const StudyScreenView& view,
                   const PictureGrid& grid, std::size_t highlighted) {
  const auto& images = view.material->images[view.flow->set()];
  const auto& stems = view.material->stems[view.flow->set()];
  for (std::size_t i = 0; i < grid.pictures.size(); ++i) {
    const PicturePlacement& p = grid.pictures[i];
    pictures.draw(images[i], grid.px_per_mm, p.picture.x, p.picture.y);
    if (i == highlighted) frame(renderer, {p.picture.x - 2, p.picture.y - 2, p.picture.w + 4, p.picture.h + 4}, kAccent, 3);
    text.draw_centred(renderer, stems[i], p.label.x + p.label.w / 2.0, p.label.y + p.label.h / 2.0, TextSize::body,
                      TextAlign::centre, i == highlighted ? kAccent : kText);
  }
}

void header(SDL_Renderer* renderer, const StudyText& text, const StudyScreenView& view, const std::string& left,
            const std::string& right) {
  const PixelRect& h = view.layout.header;
  fill(renderer, h, SDL_Color{20, 20, 24, 255});
  text.draw_centred(renderer, left, h.x + 16, h.y + h.h / 2.0, TextSize::body, TextAlign::left, kText);
  text.draw_centred(renderer, right, h.x + h.w - 16, h.y + h.h / 2.0, TextSize::body, TextAlign::right, kDim);
}

// Lines centred on the stage, the first one large.
void message(SDL_Renderer* renderer, const StudyText& text, const StudyScreenView& view,
             const std::vector<std::string>& lines) {
  const PixelRect& s = view.layout.stage;
  double y = s.y + s.h / 2.0 - static_cast<double>(lines.size()) * text.line_height(TextSize::body);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const TextSize size = i == 0 ? TextSize::title : TextSize::body;
    text.draw(renderer, lines[i], s.x + s.w / 2.0, y, size, TextAlign::centre, i == 0 ? kText : kDim);
    y += text.line_height(size) * 1.4;
  }
}

}  // namespace

PixelRect study_canvas(const StudyScreenView& view, std::size_t image) {
  const Image& i = view.material->images[view.flow->set()][image];
  return canvas_in_stage(view.layout.stage, i.width_mm, i.height_mm, view.px_per_mm);
}

PictureGrid study_answer_grid(const StudyScreenView& view) {
  const PixelRect& stage = view.layout.stage;
  const PixelRect area{stage.x, stage.y, stage.w, view.layout.footer.y + view.layout.footer.h - stage.y};
  return picture_grid(area, set_sizes(view), view.px_per_mm);
}

PictureGrid study_thumbnails(const StudyScreenView& view) { return thumbnail_row(view.layout.footer, set_sizes(view)); }

void draw_study_screen(SDL_Renderer* renderer, StudyPictures& pictures, const StudyText& text,
                       const StudyScreenView& view, double now_s) {
  SDL_SetRenderDrawColor(renderer, 30, 30, 34, 255);
  SDL_RenderClear(renderer);
  const study::StudyFlow& flow = *view.flow;
  const std::string trial_words = "Trial " + std::to_string(flow.trial()) + " of " + std::to_string(flow.total_trials());
  const std::string who = (view.scripted ? "scripted, participant " : "participant ") + view.participant;
  switch (flow.screen()) {
    case study::StudyScreen::welcome:
      header(renderer, text, view, "Matching test", who);
      message(renderer, text, view,
              {"Participant " + view.participant, "Next: trial " + std::to_string(flow.trial()) + " of " +
                                                      std::to_string(flow.total_trials()) + ", " + set_words(view),
               "Tap to begin", "Esc quits at any time; running again continues at the next trial"});
      break;
    case study::StudyScreen::training: {
      header(renderer, text, view, "Training, " + set_words(view) + ": rub the picture; tap a name below for another",
             minutes_seconds(flow.training_left_s(now_s)) + " left  -  S skips");
      const std::size_t shown = flow.training_picture();
      const PixelRect canvas = study_canvas(view, shown);
      pictures.draw(view.material->images[flow.set()][shown], view.px_per_mm, canvas.x, canvas.y);
      draw_pictures(renderer, pictures, text, view, study_thumbnails(view), shown);
      break;
    }
    case study::StudyScreen::rubbing: {
      header(renderer, text, view, trial_words + ": rub the screen to feel the image, then press Answer", who);
      const PixelRect& b = view.layout.answer_button;
      const bool ready = flow.can_answer();
      fill(renderer, b, ready ? SDL_Color{20, 120, 150, 255} : SDL_Color{60, 60, 66, 255});
      frame(renderer, b, ready ? kText : kDim, 2);
      text.draw_centred(renderer, "Answer", b.x + b.w / 2.0, b.y + b.h / 2.0, TextSize::title, TextAlign::centre,
                        ready ? kText : kDim);
      break;
    }
    case study::StudyScreen::answering:
      header(renderer, text, view, trial_words + ": which image did you feel? Tap it.", who);
      draw_pictures(renderer, pictures, text, view, study_answer_grid(view), flow.images_in_set());
      break;
    case study::StudyScreen::pause:
      header(renderer, text, view, "Pause", who);
      message(renderer, text, view,
              {"Set " + std::to_string(flow.set()) + " of " + std::to_string(flow.set_count()) + " done",
               "Take a break. Next: " + set_words(view), "Tap to continue"});
      break;
    case study::StudyScreen::end:
      header(renderer, text, view, "Matching test", who);
      message(renderer, text, view,
              {"All " + std::to_string(flow.total_trials()) + " trials done. Thank you!", "Tap or press Esc to close"});
      break;
  }
}

}  // namespace vimg::player_app
