#!/usr/bin/env bash
# Checks docs/architecture.md's rule "every file format is read in storage/": outside storage/, no
# source includes the raw readers (storage/read_file.hpp, load_file.hpp, csv_lines.hpp) or tinyxml2,
# and none reads a file through iostreams (std::ifstream, std::fstream), which would block on a FIFO
# and has no bound. Exempt: the tests, fuzzers, benchmarks and examples, which make their inputs; and the
# static files, read as bytes and never parsed: web/server/web_server.cpp serves them,
# web/site_builder/web_site.cpp copies the page's own files into a site.
# Prints FILE:LINE: error: ... for each breach and exits 1; exits 0 when the rule holds.
set -euo pipefail
cd "$(dirname "$0")/.."
exempt='^(storage|tests|fuzz|bench|examples|build[^/]*)/|^web/server/web_server\.cpp$|^web/site_builder/web_site\.cpp$'
status=0
while IFS= read -r file; do
  [[ "$file" =~ $exempt ]] && continue
  while IFS=: read -r line text; do
    echo "$file:$line: error: reads a file format outside storage/: ${text#"${text%%[![:space:]]*}"}"
    status=1
  done < <(grep -nE '#include [<"](storage/read_file\.hpp|storage/load_file\.hpp|storage/csv_lines\.hpp|tinyxml2\.h)[>"]|std::(i?fstream)\b' "$file" || true)
done < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find . -name '*.[ch]pp' -printf '%P\n')
exit $status
