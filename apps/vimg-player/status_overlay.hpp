#pragma once
// Draws the status lines (StatusText) in a translucent panel at the top left of the screen.
#include <SDL.h>

#include <string>
#include <vector>

namespace vimg::player_app {

void draw_status_panel(SDL_Renderer* renderer, const std::vector<std::string>& lines);

}  // namespace vimg::player_app
