#pragma once
// What `vimg separate` may change in an image (docs/separate.md, "What it changes"): the tactile
// parameters only, never the geometry. An image moves as a whole: every primitive that has a
// parameter takes the same step of it, so the relations the designer drew inside an image (a crown
// coarser than a trunk, a dot louder than a texture) stay as they were.
//
// A setting is one step index per parameter; 0 everywhere is the designer's original. The steps:
//   period    (SURFACE)       x 2^(k/3), k in [-6, 6]: about one frequency JND (Weber 0.25) a step
//   relief    (SURFACE)       x 2^(k/2), k in [-4, 4]
//   pattern   (SURFACE)       k = 0 keeps each surface's own; k = 1, 2, 3 sets sine, square, triangle
//   gain      (DOT, LINE, SURFACE)  x 10^(2k/20), k in [-8, 3]: one level JND (2 dB) a step
//   frequency (LINE)          x 2^(k/3), k in [-6, 6]
//   damping   (LINE)          x 2^(k/2), k in [-3, 3]
// Each value is rounded for people (3 significant digits, gain to 0.01) and kept inside the
// format's range (storage/parameter_table.hpp): a step that would leave it lands on the bound.
//
// Threads: pure functions over caller-owned data.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/image.hpp"

namespace vimg::study {

enum class TactileParameter : std::uint8_t { period, relief, pattern, gain, frequency, damping };
inline constexpr std::size_t kTactileParameterCount = 6;

// "period", "relief", "pattern", "gain", "frequency", "damping".
std::string_view tactile_parameter_name(TactileParameter p);
std::optional<TactileParameter> parse_tactile_parameter(std::string_view name);
// The unit a change is written in: "mm", "", "", "Hz", "".
std::string_view tactile_parameter_unit(TactileParameter p);

// A set of parameters, one flag each.
using TactileParameterSet = std::array<bool, kTactileParameterCount>;
TactileParameterSet all_tactile_parameters();
// "period,pattern" -> {period, pattern}; an error naming the unknown word and the known ones.
struct TactileParameterList {
  TactileParameterSet set{};  // empty when there is an error
  std::string error;          // empty when every word is known and one is named
};
TactileParameterList parse_tactile_parameter_list(std::string_view comma_separated);

// The steps of one image, per parameter (index: TactileParameter).
using SeparationSetting = std::array<std::int8_t, kTactileParameterCount>;

struct StepRange {
  int lowest = 0;
  int highest = 0;
};
StepRange step_range(TactileParameter p);
// Whether p is a choice (pattern): its steps are not ordered.
bool is_choice_parameter(TactileParameter p);

// The parameters that act on the image (it has a primitive that holds them).
TactileParameterSet parameters_present(const Image& image);

// The image with `setting` applied to every primitive (groups included); setting 0 gives it back.
Image apply_setting(const Image& original, const SeparationSetting& setting);

// The tactile values of every primitive in paint order, as a text key: two settings that give the
// same image give the same key.
std::string tactile_key(const Image& image);

// One change of one primitive between an original and a proposal, as a report lists it.
struct ParameterChange {
  std::string element;        // the primitive: "surface 'crown'"
  std::string element_id;     // its id ("" when it has none)
  std::size_t primitive = 0;  // its index among the image's primitives in paint order
  TactileParameter parameter = TactileParameter::period;
  std::string from, to;       // "2.2", "3.1"; "sine", "square"
  double to_value = 0.0;      // the new number (pattern: the SurfacePattern's value)
  std::string text;           // "surface 'crown': period 2.2 -> 3.1 mm"
};
std::vector<ParameterChange> list_changes(const Image& original, const Image& proposal);

// `image` with one change made (the editor's Apply): the primitive at change.primitive, when it is
// of the change's kind, takes change.to_value; anything else is left as it is. Applying every
// change of list_changes(original, proposal) to the original gives the proposal.
Image apply_change(const Image& image, const ParameterChange& change);

}  // namespace vimg::study
