// Fuzzes `vimg separate --vary LIST` (study/separate_space.hpp): any text gives a set of known
// parameters or an error naming the unknown word, never both, never a crash; a set it accepts is
// not empty, and its names written back with commas read back to the same set.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "study/separate_space.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const vimg::study::TactileParameterList r = vimg::study::parse_tactile_parameter_list(text);
  bool any = false;
  std::string names;
  for (std::size_t p = 0; p < vimg::study::kTactileParameterCount; ++p) {
    if (!r.set[p]) continue;
    any = true;
    names += (names.empty() ? "" : ",") +
             std::string(vimg::study::tactile_parameter_name(static_cast<vimg::study::TactileParameter>(p)));
  }
  if (r.error.empty() != any) std::abort();
  if (any && vimg::study::parse_tactile_parameter_list(names).set != r.set) std::abort();
  return 0;
}
