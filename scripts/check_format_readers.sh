#!/usr/bin/env bash
# Checks docs/architecture.md's rule "every file format is read in storage/": outside storage/, no
# C or C++ source (.cpp .hpp .cc .h .c .cxx) reads a file by any of these means (one kind a line):
#   include  includes the raw readers storage/read_file.hpp, load_file.hpp, csv_lines.hpp or
#            tinyxml2.h (also written #include<...> or # include)
#   iostream std::ifstream, std::fstream, std::filebuf (a read that blocks on a FIFO and has no bound)
#   getline  getline( on any stream, std:: or POSIX
#   stdio    fopen, freopen, fdopen, fread, fgets, fscanf, fgetc, getc
#   posix    ::open, ::openat, ::read, ::pread, ::readv; open(... O_RDONLY/O_RDWR ...); read(fd, ...)
#   mmap     mmap(
#   sdl      SDL_RWFromFile, SDL_LoadFile, SDL_LoadBMP
# Text after // and in string literals is not searched. Exempt: storage/, and the tests, fuzzers, benchmarks and examples,
# which make their inputs. A read that is not a format reader (a device node, a lock file, the
# terminal, a static file served as bytes) is named with its reason in scripts/format_readers_allowed.txt
# ("PATH KIND # why"; KIND * for every kind).
# Usage: check_format_readers.sh [ROOT]   ROOT defaults to the repository (its git files; every file
# under ROOT when it is not a git checkout, as for tests/data/format_readers_fixture).
# Prints FILE:LINE: error: ... for each breach and exits 1; exits 0 when the rule holds.
set -euo pipefail
root=${1:-"$(dirname "$0")/.."}
cd "$root"
exempt='^(storage|tests|fuzz|bench|examples|build[^/]*)/'
kinds=(include iostream getline stdio posix mmap sdl)
declare -A pattern=(
  [include]='#[[:space:]]*include[[:space:]]*[<"](storage/(read_file|load_file|csv_lines)\.hpp|tinyxml2\.h)[>"]'
  [iostream]='(^|[^[:alnum:]_<])(std::)?(basic_)?(i?fstream|filebuf)([^[:alnum:]_]|$)'
  [getline]='getline[[:space:]]*\('
  [stdio]='(^|[^[:alnum:]_.>:]|std::|[^[:alnum:]_]::)(fopen|freopen|fdopen|fread|fgets|fscanf|fgetc|getc)[[:space:]]*\('
  [posix]='(^|[^[:alnum:]_])::(open|openat|read|pread|readv)[[:space:]]*\(|(^|[^[:alnum:]_.>:])(open|openat)[[:space:]]*\(.*O_(RDONLY|RDWR)|(^|[^[:alnum:]_.>:])(read|pread)[[:space:]]*\([[:space:]]*[[:alnum:]_]*fd[[:alnum:]_]*[[:space:]]*,'
  [mmap]='(^|[^[:alnum:]_.>:]|::)mmap[[:space:]]*\('
  [sdl]='SDL_(RWFromFile|LoadFile|LoadBMP)([^[:alnum:]_]|$)'
)
declare -A allowed=()
if [[ -f scripts/format_readers_allowed.txt ]]; then
  while read -r path kind _; do
    [[ -z "$path" || "$path" == \#* ]] && continue
    allowed["$path $kind"]=1
  done < scripts/format_readers_allowed.txt
fi
if git rev-parse --show-prefix >/dev/null 2>&1 && [[ -z "$(git rev-parse --show-prefix)" ]]; then
  files=$(git ls-files '*.cpp' '*.hpp' '*.cc' '*.h' '*.c' '*.cxx')
else
  files=$(find . -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cc' -o -name '*.h' -o -name '*.c' -o -name '*.cxx' \) -printf '%P\n' | sort)
fi
mapfile -t checked < <(grep -vE "$exempt" <<<"$files" | grep -v '^$' || true)
status=0
for kind in "${kinds[@]}"; do
  (( ${#checked[@]} )) || break
  while IFS= read -r hit; do
    file=${hit%%:*}
    rest=${hit#*:}
    line=${rest%%:*}
    text=${rest#*:}
    [[ -n "${allowed["$file $kind"]:-}" || -n "${allowed["$file *"]:-}" ]] && continue
    code=${text%%//*}
    [[ $kind == include ]] || code=$(sed -E 's/"([^"\\]|\\.)*"/""/g' <<<"$code")
    grep -qE "${pattern[$kind]}" <<<"$code" || continue  # only in a comment or a string
    echo "$file:$line: error: reads a file outside storage/ ($kind): ${text#"${text%%[![:space:]]*}"}"
    status=1
  done < <(grep -nHE "${pattern[$kind]}" -- "${checked[@]}" || true)
done
exit $status
