// The scripted matching test (--responses, --gesture): the same flow and screens as the live run,
// driven by the files instead of a person. Training is skipped and pauses continue at once. Each
// trial, the gesture's touches go to the flow at the gesture's own times (a virtual clock that starts
// at 0 with each trial: rub_s is exactly the gesture's duration, path_mm its length, response_s 0) and its rubbing is rendered with the
// offline renderer over the presented image's scene into the one output stream (study_stream_sink:
// the same samples on any machine, played at the gesture's pace).
#include <algorithm>
#include <cstdio>

#include "apps/vimg-player/study_session.hpp"
#include "apps/vimg-player/study_stream_sink.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/offline_render.hpp"

namespace vimg::player_app {

namespace {

bool stop_asked() { return rest_requested(); }

// Esc, Q or closing the window end the run as in the live one.
bool quit_asked() {
  SDL_Event event;
  bool quit = false;
  while (SDL_PollEvent(&event)) {
    if (event.type == SDL_QUIT) quit = true;
    if (event.type == SDL_KEYDOWN && (event.key.keysym.sym == SDLK_ESCAPE || event.key.keysym.sym == SDLK_q)) quit = true;
  }
  return quit;
}

// The gesture's rows as the flow's touches, `base_s` being the gesture's start.
void feed_touches(study::StudyFlow& flow, const Gesture& gesture, double base_s) {
  const double start_s = gesture.start_time_s();
  for (const auto& stroke : gesture.strokes) {
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
      TouchEvent event;
      event.time_s = base_s + (stroke.points[i].time_s - start_s);
      event.finger = stroke.finger;
      event.phase = i == 0 ? TouchPhase::down : (i + 1 == stroke.points.size() ? TouchPhase::up : TouchPhase::move);
      event.x_mm = stroke.points[i].x_mm;
      event.y_mm = stroke.points[i].y_mm;
      event.pressure = stroke.points[i].pressure;
      flow.touch(event);
    }
  }
}

}  // namespace

int run_scripted_study(StudySession& session, const std::vector<std::size_t>& chosen, const Gesture& gesture) {
  study::StudyFlowOptions options;
  options.training_s = 0.0;
  options.welcome = false;
  constexpr double clock_s = 0.0;  // each trial's virtual clock starts here
  study::StudyFlow flow(session.material.images_per_set(), session.material.plan, session.log.completed(), options, clock_s);

  StudyStreamSink stream(session.drive);
  const double rate_hz = session.args.rate_hz;
  stream.open(rate_hz);
  OfflineRenderOptions render;
  render.sample_rate_hz = rate_hz;
  render.block_samples = std::max<std::size_t>(64, stream.min_block_samples());
  render.max_tail_s = 0.25;  // a ring-down still sounding after the last row (live: Answer fades it out)
  render.should_stop = &stop_asked;
  const double duration_s = gesture.end_time_s() - gesture.start_time_s();

  bool quit = false;
  while (flow.screen() != study::StudyScreen::end && !rest_requested() && !quit) {
    if (flow.screen() == study::StudyScreen::pause) {
      session.draw(flow, true, clock_s);
      flow.resume(clock_s);
      continue;
    }
    // Rubbing: the screen without a picture, the gesture felt over the presented image.
    session.draw(flow, true, clock_s);
    feed_touches(flow, gesture, clock_s);
    const auto& scene = *session.scenes[flow.set()][flow.presented()];
    if (render_gesture(scene, gesture, stream, render).interrupted) break;
    session.report_messages();
    flow.answer(clock_s + duration_s);
    // Answering: the set's pictures; the scripted tap.
    session.draw(flow, true, clock_s + duration_s);
    const auto result = flow.choose(chosen[flow.trial() - 1], clock_s + duration_s);
    if (!result || !session.record(*result)) return cmdline::kExitFailure;
    quit = quit_asked();
  }
  if (flow.screen() == study::StudyScreen::end) session.draw(flow, true, clock_s);
  stream.finish();  // the output at rest, its file complete
  return session.finish(flow);
}

}  // namespace vimg::player_app
