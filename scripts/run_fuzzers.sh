#!/usr/bin/env bash
# Runs every fuzzer of the fuzz build for a fixed total time, N at a time (CI: .ci/run).
#   scripts/run_fuzzers.sh [TOTAL_SECONDS] [PARALLEL]      defaults: 480 s, 2 (one per core)
# Each fuzzer gets TOTAL_SECONDS * PARALLEL / COUNT seconds (at least 10), so adding a fuzzer never
# lengthens the stage. Exits 1 when any fuzzer finds a crash, leak, timeout or out-of-memory
# (its artifact is in build/fuzz/artifacts/ and its log in build/fuzz/logs/). Leaks inside Debian's
# libraries that the project cannot fix are suppressed by fuzz/lsan_suppressions.txt, each explained.
set -euo pipefail
cd "$(dirname "$0")/.."
total_s=${1:-${VIMG_FUZZ_TOTAL_SECONDS:-480}}
parallel=${2:-2}
fuzzers=()
for src in fuzz/*_fuzz.cpp; do fuzzers+=("$(basename "$src" .cpp)"); done
count=${#fuzzers[@]}
each_s=$(( total_s * parallel / count ))
(( each_s < 10 )) && each_s=10
echo "fuzz: $count fuzzers, $parallel at a time, $each_s s each (total budget $total_s s)"

# -max_len per fuzzer: above the largest limit its parser enforces, as the fuzz build scales them
# (storage/limits.hpp divides size and count limits by 64 under VIMG_FUZZING; docs/limits.md), so
# that inputs reach every limit and the code refusing it. -timeout: a hang or quadratic case fails.
max_len_of() {
  case "$1" in
    xml_loader_fuzz|png_loader_fuzz) echo 1200000 ;;  # 64 MiB / 64 = 1 MiB of XML; 15 625 elements
    nrrd_loader_fuzz) echo 300000 ;;                  # 16 KiB header, 8 MiB / 64 declared data
    volume_scene_fuzz) echo 100000 ;;                 # 4 MiB / 64 = 64 KiB of scene
    probe_path_fuzz|gesture_parser_fuzz) echo 400000 ;;  # 15 625 rows
    actuator_profile_fuzz|recent_files_fuzz) echo 270000 ;;  # 256 KiB files
    calibration_fuzz) echo 70000 ;;                   # 64 KiB files
    svg_import_fuzz) echo 1200000 ;;                  # 64 MiB / 64 = 1 MiB of SVG; 15 625 elements
    svg_path_fuzz) echo 65536 ;;                      # path data; 2 000 segments in the fuzzer
    picture_import_fuzz) echo 16384 ;;                # small PNGs: at most 65 536 pixels in the fuzzer
    touch_trace_fuzz) echo 1100000 ;;                 # 64 MiB / 64 = 1 MiB recordings; 15 625 samples
    touch_settings_fuzz) echo 8192 ;;                 # 4 KiB settings files
    study_answer_fuzz) echo 4096 ;;                   # answers: bodies above 2 KiB get 413
    *) echo 65536 ;;
  esac
}

mkdir -p build/fuzz/artifacts build/fuzz/logs
run_one() {
  local fuzzer=$1
  # New inputs go to a scratch corpus; the seeds in fuzz/corpus/ stay as committed.
  local work="build/fuzz/work/$fuzzer" log="build/fuzz/logs/$fuzzer.log"
  rm -rf "$work" && mkdir -p "$work" "fuzz/corpus/$fuzzer"
  local status=0
  # teem has no frame pointers: the NRRD fuzzer unwinds each allocation fully (slower), so that its
  # one suppression (fuzz/lsan_suppressions.txt) names the teem function and nothing wider.
  local unwind=""
  [ "$fuzzer" = nrrd_loader_fuzz ] && unwind=":fast_unwind_on_malloc=0"
  ASAN_OPTIONS="detect_leaks=1$unwind" UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan_suppressions.txt:print_suppressions=0" \
    "build/fuzz/fuzz/$fuzzer" "$work" "fuzz/corpus/$fuzzer" -max_total_time="$each_s" \
      -max_len="$(max_len_of "$fuzzer")" -timeout=10 \
      -detect_leaks=1 -rss_limit_mb=2048 -artifact_prefix=build/fuzz/artifacts/ -print_final_stats=1 \
      >"$log" 2>&1 || status=$?
  if (( status == 0 )); then
    echo "--- $fuzzer: ok ($(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?') runs)"
  else
    echo "--- $fuzzer: FAILED (exit $status)"; tail -n 60 "$log"
  fi
  return "$status"
}

failed=0
running=0
for fuzzer in "${fuzzers[@]}"; do
  run_one "$fuzzer" &
  running=$((running + 1))
  if (( running >= parallel )); then
    wait -n || failed=1
    running=$((running - 1))
  fi
done
while (( running > 0 )); do
  wait -n || failed=1
  running=$((running - 1))
done
if (( failed )); then echo "fuzz: a fuzzer failed (artifacts in build/fuzz/artifacts/)"; exit 1; fi
echo "fuzz: every fuzzer ran clean"
