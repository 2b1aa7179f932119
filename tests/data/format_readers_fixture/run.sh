#!/usr/bin/env bash
# ctest format_readers_fixture: scripts/check_format_readers.sh on this tree must exit 1 and report
# exactly the breaches of expected.txt (FILE:LINE KIND), no fewer and no more.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
output=$(bash "$here/../../../scripts/check_format_readers.sh" "$here")
status=$?
if (( status != 1 )); then
  echo "check_format_readers.sh exited $status on the fixture, not 1"
  exit 1
fi
got=$(sed -nE 's/^([^:]+:[0-9]+): error: reads a file outside storage\/ \(([a-z]+)\): .*/\1 \2/p' <<<"$output" | sort)
if [[ $(wc -l <<<"$output") -ne $(wc -l <<<"$got") ]]; then
  echo "lines not in the FILE:LINE: error: form:"; echo "$output"
  exit 1
fi
if ! diff <(sort "$here/expected.txt") <(echo "$got"); then
  echo "(< a breach the script missed, > a report of no breach)"
  exit 1
fi
echo "all $(wc -l <"$here/expected.txt") breaches reported, nothing else"
