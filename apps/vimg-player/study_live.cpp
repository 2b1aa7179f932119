// The live matching test: a person at the screen, the real-time renderer under the finger.
// A press (left mouse button, or a finger going down) first asks the screen what it hits: the
// welcome and pause screens and the end screen take any tap, the training thumbnails select a
// picture, the Answer button answers, a picture on the answer screen records the trial. Anything
// else is touch: it reaches the renderer, which plays the training picture or the trial's
// invisible image at the canvas's place (nothing otherwise), and while rubbing the flow measures it.
// Keys: S or Space skip the training (the experimenter); Esc or Q end the session (the trial under
// way is not recorded; running again continues with it).
#include <cstdio>
#include <optional>
#include <utility>

#include "apps/vimg-player/study_session.hpp"
#include "apps/vimg-player/touch_input.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg::player_app {

namespace {

// Where a press happened, in window pixels, or nothing for events that are not presses.
std::optional<std::pair<double, double>> press_at(const SDL_Event& event, const StudySession& session) {
  if (event.type == SDL_MOUSEBUTTONDOWN && event.button.which != SDL_TOUCH_MOUSEID &&
      event.button.button == SDL_BUTTON_LEFT) {
    return std::pair{static_cast<double>(event.button.x), static_cast<double>(event.button.y)};
  }
  if (event.type == SDL_FINGERDOWN) {
    return std::pair{static_cast<double>(event.tfinger.x) * session.width_px,
                     static_cast<double>(event.tfinger.y) * session.height_px};
  }
  return std::nullopt;
}

class LiveStudy {
 public:
  LiveStudy(StudySession& session, RealtimeRenderer& renderer)
      : session_(session),
        renderer_(renderer),
        flow_(session.material.images_per_set(), session.material.plan, session.log.completed(), options(session),
              monotonic_s()),
        // Positions in mm from the window's corner; each event is moved to the canvas shown (playing).
        input_(ViewTransform{session.px_per_mm, 0.0, 0.0}, session.width_px, session.height_px) {}

  int run() {
    while (!quit_ && !rest_requested()) {
      flow_.tick(monotonic_s());
      play_what_is_shown();
      SDL_Event event;
      while (SDL_PollEvent(&event)) {
        if (!handle(event)) return cmdline::kExitFailure;
        play_what_is_shown();  // the next event lands on the canvas of what is shown now
      }
      session_.report_messages();
      session_.draw(flow_, false, monotonic_s());
      SDL_Delay(10);
    }
    return session_.finish(flow_);
  }

 private:
  static study::StudyFlowOptions options(const StudySession& session) {
    study::StudyFlowOptions o;
    o.training_s = session.material.study.training_minutes * 60.0;
    return o;
  }

  // The image under the finger: the training picture, the trial's image, or none.
  std::optional<std::size_t> playing() const {
    if (flow_.screen() == study::StudyScreen::training) return flow_.training_picture();
    if (flow_.screen() == study::StudyScreen::rubbing) return flow_.presented();
    return std::nullopt;
  }

  void play_what_is_shown() {
    const auto image = playing();
    const Scene* wanted = image ? session_.scenes[flow_.set()][*image].get() : nullptr;
    if (wanted == current_) return;
    current_ = wanted;
    renderer_.set_scene(image ? session_.scenes[flow_.set()][*image] : nullptr);
    if (image) canvas_ = study_canvas(session_.view(flow_, false), *image);
  }

  // False when a row could not be written.
  bool handle(const SDL_Event& event) {
    const double now_s = monotonic_s();
    if (event.type == SDL_QUIT) quit_ = true;
    if (event.type == SDL_KEYDOWN) {
      const SDL_Keycode key = event.key.keysym.sym;
      if (key == SDLK_ESCAPE || key == SDLK_q) quit_ = true;
      if (key == SDLK_s || key == SDLK_SPACE) flow_.skip_training(now_s);
    }
    if (const auto at = press_at(event, session_)) {
      const auto [x, y] = *at;
      const StudyScreenView view = session_.view(flow_, false);
      switch (flow_.screen()) {
        case study::StudyScreen::welcome:
          flow_.begin(now_s);
          return true;
        case study::StudyScreen::pause:
          flow_.resume(now_s);
          return true;
        case study::StudyScreen::end:
          quit_ = true;
          return true;
        case study::StudyScreen::answering: {
          const std::size_t picture = picture_at(study_answer_grid(view), x, y);
          if (const auto result = flow_.choose(picture, now_s)) return session_.record(*result);
          return true;
        }
        case study::StudyScreen::training: {
          const std::size_t picture = picture_at(study_thumbnails(view), x, y);
          if (picture < flow_.images_in_set()) {
            flow_.show_training_picture(picture);
            return true;
          }
          break;  // a touch on the picture
        }
        case study::StudyScreen::rubbing:
          if (view.layout.answer_button.contains(x, y)) {
            flow_.answer(now_s);
            return true;
          }
          break;  // a touch on the invisible image
      }
    }
    for (TouchEvent touch : input_.translate(event)) {
      // Millimetres on the canvas of the image playing (the renderer gets every event, so that a
      // finger lifted after the screen changed is lifted there too; it plays nothing then).
      touch.x_mm -= canvas_.x / session_.px_per_mm;
      touch.y_mm -= canvas_.y / session_.px_per_mm;
      renderer_.push_event(touch);
      flow_.touch(touch);
    }
    return true;
  }

  StudySession& session_;
  RealtimeRenderer& renderer_;
  study::StudyFlow flow_;
  TouchInput input_;
  const Scene* current_ = nullptr;
  PixelRect canvas_;
  bool quit_ = false;
};

}  // namespace

int run_live_study(StudySession& session) {
  RealtimeOptions realtime;
  realtime.sample_rate_hz = session.args.rate_hz;
  realtime.realtime_priority = session.args.realtime_priority;
  realtime.touch = session.args.touch;
  RealtimeRenderer renderer(session.drive, realtime);
  if (auto error = renderer.start()) {
    std::fprintf(stderr, "vimg-player: %s\n", error->c_str());
    return cmdline::kExitFailure;
  }
  int status = 0;
  {
    LiveStudy study(session, renderer);
    status = study.run();
  }
  renderer.stop();  // stops the thread and puts the output to rest
  return status;
}

}  // namespace vimg::player_app
