#pragma once
// The matching test's screens (docs/player.md, "Matching test"), drawn from the flow's state:
//   welcome    the participant, the trial it starts at; "Tap to begin"
//   training   the set's selected picture at true size where the trials' images will be, the set's
//              thumbnails with their names below (a tap selects one), the countdown, "S skips"
//   rubbing    no picture at all; "Trial k of N"; the Answer button (dimmed until the first touch)
//   answering  every picture of the set as on printed sheets (study_layout.hpp), names below
//   pause      "Set s of S done"; "Tap to continue"
//   end        "All N trials done"; "Tap or press Esc to close"
// Where things are (for the input handling) comes from the same functions as the drawing.
// Threads: the UI thread only (SDL rendering).
#include <SDL.h>

#include <string>

#include "study/study_flow.hpp"
#include "apps/vimg-player/study_layout.hpp"
#include "apps/vimg-player/study_pictures.hpp"
#include "apps/vimg-player/study_setup.hpp"
#include "apps/vimg-player/study_text.hpp"

namespace vimg::player_app {

struct StudyScreenView {
  const StudyMaterial* material = nullptr;
  const study::StudyFlow* flow = nullptr;
  std::string participant;
  StudyLayout layout;
  double px_per_mm = 4.0;  // true size on this screen
  bool scripted = false;   // the header says so
};

// The canvas of image `image` of the flow's current set at true size in the stage.
PixelRect study_canvas(const StudyScreenView& view, std::size_t image);
// The answer screen's sheets and the training screen's thumbnails of the current set.
PictureGrid study_answer_grid(const StudyScreenView& view);
PictureGrid study_thumbnails(const StudyScreenView& view);

void draw_study_screen(SDL_Renderer* renderer, StudyPictures& pictures, const StudyText& text,
                       const StudyScreenView& view, double now_s);

}  // namespace vimg::player_app
