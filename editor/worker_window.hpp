#pragma once
// What the windows whose work runs on a worker thread (compare_window.hpp, proposal_window.hpp)
// share: waking the GUI when the worker is done, the shade of a confusion cell, and printing the
// last item's place for the GUI tests.
// Threads: wake_gui() from any thread (SDL_PushEvent is thread-safe); the rest on the GUI thread.
#include <imgui.h>

#include <string>

namespace vimg::editor {

class LayoutLog;

// The GUI's event loop sleeps until an event comes: a worker sends one when it is done.
void wake_gui();

// Dark to the blue of the study report's heat maps as p goes from 0 to 1.
ImU32 confusion_shade(double p);

// The last ImGui item's rectangle, as `layout NAME x y w h` (--print-layout).
void print_last_item(LayoutLog& layout, const std::string& name);

}  // namespace vimg::editor
