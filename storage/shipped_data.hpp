#pragma once
// Where the files the project ships (actuator profiles, examples, gestures, the web player) are
// found at run time, from the running program's own location and never from the source tree:
//   1. the folder named by the environment variable VIBROIMAGE_DATA_DIR, when it is set and not empty;
//   2. else the first `share/vibroimage` found next to an ancestor of the executable's folder, at most
//      three levels up: an installed program at PREFIX/bin/vimg finds PREFIX/share/vibroimage (one
//      level, so a moved prefix still works), a program in the build tree at build/dev/cli/vimg
//      finds build/dev/share/vibroimage (two levels; the build links it to the sources' assets).
// A folder counts only if it holds `profiles/`. Nothing found: std::nullopt, and callers say so
// with shipped_data_help().
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vimg {

inline constexpr const char* kShippedDataEnvironmentVariable = "VIBROIMAGE_DATA_DIR";

// The pure rule behind shipped_data_dir(), for tests: `environment_value` is the variable's value
// (nullptr when unset), `executable` the program's absolute path.
std::optional<std::filesystem::path> find_shipped_data_dir(const char* environment_value,
                                                           const std::filesystem::path& executable);

// The rule applied to this process (/proc/self/exe).
std::optional<std::filesystem::path> shipped_data_dir();

// "no shipped data found: set VIBROIMAGE_DATA_DIR to the folder that holds profiles/ ..."
std::string shipped_data_help();

// A shipped actuator profile's name ("lra-175hz-drv2605l") is a bare word: no folder, no
// extension. Such a name that is not a file in the working folder means DATA/profiles/NAME.xml.
// Anything else is a path and is returned as given.
std::filesystem::path resolve_profile_argument(const std::filesystem::path& argument);

// The shipped profiles' names (file stems under DATA/profiles), sorted; empty when none are found.
std::vector<std::string> shipped_profile_names();

}  // namespace vimg
