#pragma once
// What the live and the scripted matching test share once everything is open: the study, the trial
// log, the output (the actuator) and its drive path, the scenes, the window and what draws on it.
// study_run.cpp opens all of it in order (docs/player.md, "Matching test") and hands it over.
// Threads: the UI thread.
#include <SDL.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "apps/vimg-player/player_args.hpp"
#include "study/study_flow.hpp"
#include "apps/vimg-player/study_pictures.hpp"
#include "apps/vimg-player/study_screens.hpp"
#include "apps/vimg-player/study_setup.hpp"
#include "apps/vimg-player/study_text.hpp"
#include "hal/output_spec.hpp"
#include "primitives/gesture.hpp"
#include "player/scene.hpp"
#include "storage/study/trial_log.hpp"

namespace vimg::player_app {

struct StudySession {
  const PlayerArgs& args;
  const StudyMaterial& material;
  TrialLog& log;
  Output& output;
  DriveSink& drive;  // the output's sink, or the equalizer in front of it (--equalize)
  std::vector<std::vector<std::shared_ptr<const Scene>>> scenes;  // [set][image]
  SDL_Renderer* renderer = nullptr;
  int width_px = 0, height_px = 0;
  double px_per_mm = 4.0;
  StudyText& text;
  StudyPictures& pictures;

  StudyScreenView view(const study::StudyFlow& flow, bool scripted) const;
  void draw(const study::StudyFlow& flow, bool scripted, double now_s) const;
  // Appends the result's row (one synced line) and prints the status line. False, with the error
  // on stderr, when it could not be written: the study stops.
  bool record(const study::StudyTrialResult& result) const;
  // Output faults and warnings since the last call, to stderr.
  void report_messages() const;
  // How a run that has left its loop ends: 130/143 after SIGINT/SIGTERM; else 0, with the line that
  // says where the study stopped (running again continues there) or that every trial is done.
  int finish(const study::StudyFlow& flow) const;
};

// The live run (a person at the screen) and the scripted one (--responses, --gesture). Both return
// the exit status: 0 at the end or after Esc, 130/143 after SIGINT/SIGTERM, 1 when a row could not be
// written.
int run_live_study(StudySession& session);
int run_scripted_study(StudySession& session, const std::vector<std::size_t>& chosen, const Gesture& gesture);

// `vimg-player --study ...`: opens everything and runs one of the above.
int run_study(const PlayerArgs& args);

}  // namespace vimg::player_app
