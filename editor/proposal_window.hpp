#pragma once
// "Propose changes" (docs/editor-actuator-and-confusion.md, docs/separate.md): the images compared in the "Predicted
// confusion" window handed to `vimg separate`'s engine (study/separate.hpp, the same code, with
// the actuator the editor designs for and its felt band), shown in a window of its own: per image
// the share identified before and after and each change ("surface 'texture': period 2.2 -> 3.1
// mm"), the predicted confusion before and after. Each change can be auditioned (played on the
// canvas in playing mode without touching the document), applied alone, or all of an image's
// changes at once; the window only asks, the app does it (take_action): a change applies to the
// open document when it is that image, else the image is opened first.
//
// Threads: start(), draw(), take_action() and the destructor on the GUI thread. The search runs
// on a worker thread (rendering on every core through run_separate), hands its result over under
// a mutex and wakes the GUI's event loop with an SDL user event. A new start() or the destructor
// stops a search under way (at its next render block) and waits for the worker.
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "study/separate.hpp"

namespace vimg::editor {

class LayoutLog;

struct ProposalAction {
  enum class Kind { open, apply, apply_all, audition, stop_audition };
  Kind kind = Kind::open;
  std::filesystem::path image;                 // the image the action is for
  std::vector<study::ParameterChange> changes;  // apply: one; apply_all and audition: those to make
  std::string label;                           // for messages: "texture_2_4mm.vimg: pattern sine -> square"
};

class ProposalWindow {
 public:
  explicit ProposalWindow(LayoutLog& layout) : layout_(layout) {}
  ~ProposalWindow();
  ProposalWindow(const ProposalWindow&) = delete;
  ProposalWindow& operator=(const ProposalWindow&) = delete;

  // Searches a proposal for `images` on `actuator` (its profile file gives the felt band; empty:
  // the ideal actuator, nothing is barely felt); opens the window.
  void start(std::vector<std::filesystem::path> images, study::CompareActuator actuator);
  // `open_document`: the path of the document open in the editor (its changes can be applied).
  void draw(float x, float y, float w, float h, const std::string& open_document);
  bool running() const;
  // What the designer asked for since the last call.
  std::optional<ProposalAction> take_action();
  // While a change is auditioned (its label; empty: none) the window shrinks to one line above the
  // canvas with "Stop audition".
  void set_auditioning(std::string label) { auditioning_ = std::move(label); }

 private:
  void stop();
  void draw_result(const study::SeparateResult& r, const std::string& open_document);
  void draw_image(const study::SeparateImage& image, std::size_t index, bool is_open);
  void draw_matrix(const char* id, const study::SeparateResult& r, const PerceptionMatrix& m);

  LayoutLog& layout_;
  std::thread worker_;
  mutable std::mutex mutex_;
  std::optional<study::SeparateResult> result_;  // written by the worker, under mutex_
  std::string progress_;                         // the search's last progress line, under mutex_
  bool running_ = false;                         // under mutex_
  bool open_ = false;
  bool place_ = false;
  std::size_t image_count_ = 0;
  std::optional<ProposalAction> action_;
  std::string auditioning_;
};

}  // namespace vimg::editor
