#pragma once
// Names that end up in trial-file cells (storage/study/trial_table.hpp): a set's name, an image's
// stem, a participant ID. Cells are joined by commas without quoting, so a name is checked where it
// is made (the study file, the command line) and again where a trial file is read.
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// Why `name` cannot be a cell of a trial file ("is empty", "holds a comma", ...), or nothing.
// At most kMaxStudyNameBytes; no comma, double quote or control character (ASCII 0-31, 127).
std::optional<std::string> study_name_problem(std::string_view name);

}  // namespace vimg
