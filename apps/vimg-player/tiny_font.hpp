#pragma once
// A 5x7 bitmap font for the status overlay (SDL2 has no text of its own). Upper-case letters,
// digits and a little punctuation; lower case is drawn as upper case, unknown characters as '?'.
#include <SDL.h>

#include <string_view>

namespace vimg::player_app {

// Draws `text` with its top-left corner at (x, y), each font pixel `scale` screen pixels.
// Returns the width drawn, in screen pixels.
int draw_text(SDL_Renderer* renderer, int x, int y, std::string_view text, int scale);
int text_width(std::string_view text, int scale);
inline constexpr int kGlyphHeight = 7;

}  // namespace vimg::player_app
