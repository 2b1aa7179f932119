// `vimg-player --study`: everything a matching test needs is opened in this order, and the first
// problem stops it before anything is shown (docs/player.md, "Matching test"):
//   1. the study file and every image (exit 1 on a bad file), the participant's plan;
//   2. scripted runs: the responses and the gesture (exit 1);
//   3. the trial log: a finished participant is refused unless --restart (exit 1);
//   4. the actuator profile and the output (exit 2 for a bad --output, 1 when it cannot open);
//   5. the masking noise, when the study asks for it (exit 1 naming the audio outputs there are);
//   6. the window.
#include <cstdio>
#include <string>
#include <vector>

#include "apps/vimg-player/player_setup.hpp"
#include "apps/vimg-player/study_masking.hpp"
#include "storage/gesture_csv.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/study/scripted_responses.hpp"
#include "apps/vimg-player/study_session.hpp"
#include "cmdline/exit_codes.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/actuator_sink.hpp"

namespace vimg::player_app {

StudyScreenView StudySession::view(const study::StudyFlow& flow, bool scripted) const {
  StudyScreenView v;
  v.material = &material;
  v.flow = &flow;
  v.participant = args.participant;
  v.layout = study_layout(width_px, height_px);
  v.px_per_mm = px_per_mm;
  v.scripted = scripted;
  return v;
}

void StudySession::draw(const study::StudyFlow& flow, bool scripted, double now_s) const {
  draw_study_screen(renderer, pictures, text, view(flow, scripted), now_s);
  SDL_RenderPresent(renderer);
}

bool StudySession::record(const study::StudyTrialResult& result) const {
  const MatchingTrial row = trial_row(material, args.participant, result, utc_timestamp_now());
  if (auto error = log.append(to_cells(row))) {
    std::fprintf(stderr, "vimg-player: %s: the study stops at trial %zu: %s\n", log.path().string().c_str(), result.trial,
                 error->c_str());
    return false;
  }
  std::printf("%s\n", trial_status_line(material, result).c_str());
  std::fflush(stdout);
  return true;
}

void StudySession::report_messages() const {
  for (const auto& message : output.take_messages()) std::fprintf(stderr, "vimg-player: %s\n", message.c_str());
}

int StudySession::finish(const study::StudyFlow& flow) const {
  if (rest_requested()) return 128 + rest_signal();  // 130 for SIGINT, 143 for SIGTERM
  if (flow.screen() != study::StudyScreen::end) {
    std::printf("vimg-player: stopped before trial %zu of %zu; running again continues there\n", flow.trial(),
                flow.total_trials());
  } else {
    std::printf("vimg-player: all %zu trials done; trial file %s\n", flow.total_trials(), log.path().string().c_str());
  }
  return cmdline::kExitOk;
}

int run_study(const PlayerArgs& args) {
  // 1. The study.
  StudyMaterialResult loaded = load_study_material(*args.study_path, args.participant);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.material) return 1;
  const StudyMaterial& material = *loaded.material;

  // 2. A scripted run's answers and rubbing.
  const bool scripted = args.responses_path.has_value();
  std::vector<std::size_t> chosen;
  Gesture gesture;
  if (scripted) {
    const ResponsesResult responses = load_responses(*args.responses_path, material.stems, study::trial_sets(material.plan));
    print_diagnostics(responses.diagnostics);
    const GestureParseResult rubbing = load_gesture_file(*args.gesture_path);
    for (const auto& error : rubbing.errors) std::fprintf(stderr, "%s\n", error.c_str());
    if (rubbing.ok() && rubbing.gesture->strokes.empty()) {
      std::fprintf(stderr, "%s: error: the gesture has no stroke; a trial needs rubbing\n", args.gesture_path->c_str());
      return 1;
    }
    if (!responses.ok() || !rubbing.ok()) return 1;
    chosen = *responses.chosen;
    gesture = *rubbing.gesture;
  }

  // 3. The trial log.
  TrialLogOptions log_options;
  log_options.total_trials = material.plan.size();
  log_options.restart = args.restart;
  auto opened = TrialLog::open(args.results_dir, args.participant, "trials", kMatchingTrialHeader, log_options);
  if (auto* problems = std::get_if<std::vector<Diagnostic>>(&opened)) {
    print_diagnostics(*problems);
    return 1;
  }
  TrialLog& log = std::get<TrialLog>(opened);
  print_diagnostics(log.warnings());

  // 4. The actuator.
  PlayerActuator actuator;  // whatever happens below, the actuator ends at rest
  if (const int status = actuator.open(args)) return status;
  const ActuatorProfile& profile = actuator.profile();
  Output& output = actuator.output();

  // 5. The masking noise.
  MaskingNoisePlayer noise;
  if (material.study.masking_noise) {
    if (auto error = noise.start(*material.study.masking_noise, actuator.spec())) {
      std::fprintf(stderr, "%s: error: %s\n", args.study_path->c_str(), error->c_str());
      return 1;
    }
  }

  // 6. The window.
  PlayerWindow window;
  if (auto error = open_player_window(args, "vimg-player study", window)) {
    std::fprintf(stderr, "vimg-player: %s\n", error->c_str());
    return 1;
  }
  StudyText text;
  StudyPictures pictures(window.renderer);
  ActuatorSink equalizing(output.sink(), profile.response, OutputSignal::drive, true);
  StudySession session{args, material, log, output,
                       args.equalize ? static_cast<DriveSink&>(equalizing) : output.sink(),
                       {}, window.renderer, window.width_px, window.height_px, window.px_per_mm, text, pictures};
  SceneOptions scene_options;
  scene_options.carrier_frequency_hz = profile.resonance_hz;
  for (const auto& set : material.images) {
    auto& scenes = session.scenes.emplace_back();
    for (const Image& image : set) scenes.push_back(compile_scene(image, scene_options));
  }
  std::printf("vimg-player: study %s, participant %s: %zu trials, %zu done; trial file %s; output %s%s%s\n",
              args.study_path->c_str(), args.participant.c_str(), material.plan.size(), log.completed(),
              log.path().string().c_str(), output.description().c_str(),
              material.study.masking_noise ? "; masking noise " : "", noise.description().c_str());
  std::fflush(stdout);
  const int status = scripted ? run_scripted_study(session, chosen, gesture) : run_live_study(session);
  session.report_messages();
  return status;
}

}  // namespace vimg::player_app
