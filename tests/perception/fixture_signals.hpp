#pragma once
// The test signals of tests/data/stsim/signals.csv, built sample for sample as
// tests/data/stsim/make_fixtures.py builds them (README.md there), and the rows of cases.csv.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace vimg::test {

std::vector<double> make_fixture_signal(std::size_t samples, const std::string& recipe);

// name -> samples, from signals.csv; rows of a CSV file with '#' comment lines, by column name.
std::map<std::string, std::vector<double>> load_fixture_signals(const std::string& signals_csv);
std::vector<std::map<std::string, std::string>> read_csv_rows(const std::string& path);

}  // namespace vimg::test
