// Embedding vibroimage: load an image, feed a finger path, get the drive samples.
//   embed IMAGE.vimg [SAMPLES.txt]   prints "SAMPLES RMS PEAK" of a straight swipe across the
//                                    canvas; with SAMPLES.txt, also every sample, one a line
//                                    (shortest round-trip form, as `vimg render --out X.csv`)
#include <charconv>
#include <cmath>
#include <cstdio>

#include "player/drive_sinks.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "storage/image_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: embed IMAGE.vimg [SAMPLES.txt]\n");
    return 2;
  }
  const vimg::LoadResult loaded = vimg::load_image_file(argv[1]);
  for (const vimg::Diagnostic& d : loaded.diagnostics) std::fprintf(stderr, "%s\n", d.to_string().c_str());
  if (!loaded.ok()) return 1;
  const vimg::Image& image = *loaded.image;

  // One finger swipes left to right through the middle of the canvas in one second.
  vimg::Gesture swipe;
  vimg::GestureStroke& stroke = swipe.strokes.emplace_back();
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    stroke.points.push_back({t, t * image.width_mm, image.height_mm / 2.0, 1.0});
  }

  const auto scene = vimg::compile_scene(image);
  vimg::MemorySink sink;
  vimg::render_gesture(*scene, swipe, sink);

  double sum_squares = 0.0, peak = 0.0;
  for (const float s : sink.samples()) {
    sum_squares += double(s) * s;
    peak = std::fmax(peak, std::fabs(s));
  }
  const double rms = sink.samples().empty() ? 0.0 : std::sqrt(sum_squares / double(sink.samples().size()));
  std::printf("%zu %.6f %.6f\n", sink.samples().size(), rms, peak);
  if (argc == 3) {
    std::FILE* out = std::fopen(argv[2], "w");
    if (!out) return 1;
    for (const float s : sink.samples()) {
      char text[32];
      *std::to_chars(text, text + sizeof text - 1, s).ptr = '\0';
      std::fprintf(out, "%s\n", text);
    }
    if (std::fclose(out) != 0) return 1;
  }
  return 0;
}
