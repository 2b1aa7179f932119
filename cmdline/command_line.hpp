#pragma once
// How every program of the project reads its command line: CLI11, with one set of conventions.
//   --help / -h      prints the help to stdout, exit 0
//   --version        prints "PROGRAM VERSION" to stdout, exit 0
//   a usage error    prints "PROGRAM: error: PROBLEM" and "Run 'PROGRAM --help' for usage." to
//                    stderr, exit 2 (a missing or unknown option, a bad value, a missing argument)
// Bad input files exit 1 and interrupted runs 130 (SIGINT) or 143 (SIGTERM); those are the
// programs' own business, the codes are named in exit_codes.hpp so that they are the same everywhere.
//
// Number options are checked with finite_in(): CLI11's own ranges let NaN through.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "cmdline/exit_codes.hpp"

namespace vimg::cmdline {

// The project's version, as every program prints it.
const char* version();

// An app named `program` with the standard flags (--help, --version) and error format.
void configure(CLI::App& app, const std::string& program);

// Parses the arguments (without the program name). Returns the exit code when the program must
// stop now (0 after --help or --version, 2 after a usage error, with the text printed), or
// nothing when it should go on.
std::optional<int> parse(CLI::App& app, int argc, const char* const* argv);
std::optional<int> parse(CLI::App& app, std::vector<std::string> args);

// A number that is finite and within [min, max] (NaN and infinities are refused).
CLI::Validator finite_in(double min, double max);

// "X,Y" with two finite numbers.
CLI::Validator point_2d();
// Parses "X,Y" (the validator has already checked it); false if it does not parse.
bool parse_point_2d(const std::string& text, double& x, double& y);

}  // namespace vimg::cmdline
