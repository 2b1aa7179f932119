#pragma once
// "Predicted confusion": the library's selected images compared as `vimg compare` compares them
// (study/compare.hpp, the same code: the standard exploration of their canvas, the actuator the
// editor designs for, ST-SIM with the sensation level, Shepard-Luce choice), shown in a window of
// its own: the predicted confusion matrix (rows presented, columns chosen, cells shaded by p) and
// one warning per pair likely confused, in the words of `vimg compare`, and "Propose changes",
// which hands the images to `vimg separate`'s engine (proposal_window.hpp). docs/editor-actuator-and-confusion.md.
//
// Threads: start(), draw() and the destructor on the GUI thread. The comparison runs on a worker
// thread (which renders on every core through run_compare); it hands its result over under a mutex
// and wakes the GUI's event loop with an SDL user event. A new start() or the destructor stops a
// comparison under way (at its next render block) and waits for the worker.
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "study/compare.hpp"

namespace vimg::editor {

class LayoutLog;

class CompareWindow {
 public:
  explicit CompareWindow(LayoutLog& layout) : layout_(layout) {}
  ~CompareWindow();
  CompareWindow(const CompareWindow&) = delete;
  CompareWindow& operator=(const CompareWindow&) = delete;

  // Compares `images` (at least two) on `actuator`; opens the window.
  void start(std::vector<std::filesystem::path> images, study::CompareActuator actuator);
  // The window, if open, first placed at (x, y) with size (w, h).
  void draw(float x, float y, float w, float h);
  bool running() const;
  // The images and actuator of the comparison shown, once "Propose changes" was pressed
  // (proposal_window.hpp searches what to change).
  std::optional<std::pair<std::vector<std::filesystem::path>, study::CompareActuator>> take_proposal_request();

 private:
  void stop();
  void draw_result(const study::CompareResult& result);
  void draw_matrix(const study::CompareResult& result);

  LayoutLog& layout_;
  std::thread worker_;
  mutable std::mutex mutex_;
  std::optional<study::CompareResult> result_;  // written by the worker, under mutex_
  bool running_ = false;                        // under mutex_
  bool open_ = false;
  bool place_ = false;  // place the window on the next frame
  std::size_t image_count_ = 0;
  std::string actuator_name_;
  std::vector<std::filesystem::path> images_;  // of the comparison under way or shown
  study::CompareActuator actuator_;
  bool propose_requested_ = false;
};

}  // namespace vimg::editor
