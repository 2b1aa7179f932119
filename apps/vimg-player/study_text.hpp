#pragma once
// Text on the matching test's screens: DejaVu Sans (the status overlay's font, kOverlayFontPath) in
// two sizes through SDL_ttf. Without the font the screens are drawn without their text and one
// line on stderr names the file and the package (the study still runs: the tests and the trial
// file do not depend on it).
// Threads: the UI thread only (SDL rendering).
#include <SDL.h>
#include <SDL_ttf.h>

#include <string>

namespace vimg::player_app {

enum class TextSize { body, title };
enum class TextAlign { left, centre, right };

class StudyText {
 public:
  StudyText();
  ~StudyText();
  StudyText(const StudyText&) = delete;
  StudyText& operator=(const StudyText&) = delete;

  // Draws `text` with its top at y; x is its left edge, centre or right edge.
  void draw(SDL_Renderer* renderer, const std::string& text, double x, double y, TextSize size, TextAlign align,
            SDL_Color colour) const;
  // Text vertically centred on `centre_y`.
  void draw_centred(SDL_Renderer* renderer, const std::string& text, double x, double centre_y, TextSize size,
                    TextAlign align, SDL_Color colour) const;
  int line_height(TextSize size) const;

 private:
  TTF_Font* font(TextSize size) const { return size == TextSize::title ? title_ : body_; }
  bool started_ = false;
  TTF_Font* body_ = nullptr;
  TTF_Font* title_ = nullptr;
};

}  // namespace vimg::player_app
