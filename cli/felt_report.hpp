#pragma once
// The predicted feel of an image on an actuator, as `vimg validate --actuator` and `vimg info
// --actuator` report it (docs/actuators.md, "Felt band"). The analysis and the warning's words
// are hal/felt_analysis.hpp's, shared with the editor.
#include <memory>
#include <string>

#include "hal/felt_analysis.hpp"
#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"

namespace vimg::cli {

// Loads the profile; prints its errors to stderr and returns null when it has any.
std::unique_ptr<FeltAnalysis> load_felt_analysis(const std::string& profile_path);

// One warning per SURFACE and LINE whose frequency at fullSpeed is weak on the actuator, at the
// element's line.
void add_felt_warnings(const Image& image, const FeltAnalysis& analysis, DiagnosticList& out);

// `vimg info --actuator`: one row per primitive with its frequency at fullSpeed and its response.
void print_felt_table(const Image& image, const FeltAnalysis& analysis);

}  // namespace vimg::cli
