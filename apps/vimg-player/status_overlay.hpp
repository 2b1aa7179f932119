#pragma once
// Draws the status lines (StatusText) in a translucent panel at the top left of the screen, in
// DejaVu Sans (SDL_ttf; Debian package fonts-dejavu-core). When the font cannot be opened the
// panel is not drawn and one message on stderr says why and what to install; the lines still
// reach stdout/stderr through the player's own messages.
// Threads: the UI thread only (SDL rendering).
#include <SDL.h>

#include <string>
#include <vector>

namespace vimg::player_app {

inline constexpr const char* kOverlayFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr int kOverlayFontPoints = 16;

void draw_status_panel(SDL_Renderer* renderer, const std::vector<std::string>& lines);

}  // namespace vimg::player_app
