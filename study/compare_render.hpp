#pragma once
// What `vimg compare` feels of an image: its predicted acceleration under the exploration gestures,
// at kCompareRateHz (8 kHz), rendered in memory by the same engine as `vimg render --signal
// acceleration --actuator P --rate 8000` (compile_scene with the actuator's resonance as the DOT
// carrier, render_gesture, ActuatorSink with OutputSignal::acceleration into a MemorySink). With the
// ideal actuator the acceleration is the drive.
//
// Gestures are rendered one after another and concatenated. Each one covers a fixed span whatever
// the image, so that every image's signal lines up sample for sample with every other's: from
// min(0, its first time) (where `vimg render` starts) to its last time plus kCompareTailS (ring-downs
// beyond it are cut, a render that ends sooner is padded with zeros).
//
// Threads: the functions are pure; several images may be rendered at once on different threads.
#include <cstddef>
#include <optional>
#include <vector>

#include "primitives/gesture.hpp"
#include "primitives/actuator/response_params.hpp"
#include "primitives/image.hpp"

namespace vimg::study {

inline constexpr double kCompareTailS = 0.25;  // after each gesture's last event

// Samples of the concatenated render of `gestures` (all of them, at 8 kHz).
std::size_t compare_render_samples(const std::vector<Gesture>& gestures);

// The acceleration of `image` on the actuator `response`, concatenated over `gestures`; nothing
// when should_stop() said so.
std::optional<std::vector<float>> render_for_compare(const Image& image, const std::vector<Gesture>& gestures,
                                                     const ResponseParams& response, bool (*should_stop)() = nullptr);

}  // namespace vimg::study
