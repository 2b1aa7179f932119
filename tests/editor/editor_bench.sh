#!/usr/bin/env bash
# The editor's two figures (docs/benchmarks/editor.md, "Editor"), under its own Xvfb display:
#  1. frame time with 10 000 primitives on the canvas (whole page visible);
#  2. in playing mode, the time from a mouse event to the output's write() of the first block that
#     carries the drive it caused (what comes before the audio device's own buffer).
# usage: editor_bench.sh PATH/TO/vimg-editor OUT_DIR     (use a Release build)
set -euo pipefail
editor=$(realpath "$1")
out=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
out=$(realpath "$out")
export HOME="$out/home" XDG_CONFIG_HOME="$out/home/.config" XDG_STATE_HOME="$out/home/.state"
mkdir -p "$HOME"
source "$here/../xvfb_display.sh"
trap stop_xvfb EXIT
start_xvfb 1400x900x24 "$out/xvfb.log"

python3 "$here/make_many_primitives.py" 10000 "$out/many.vimg"
echo "== frame time, 10 000 primitives, 3 runs of 300 frames"
for run in 1 2 3; do
  "$editor" "$out/many.vimg" --zoom 0.9 --output none --recovery-dir "$out/rec" --benchmark-frames 300 | grep benchmark
done
echo "== frame time, the smiley (4 primitives)"
"$editor" "$here/../../assets/examples/smiley.vimg" --output none --recovery-dir "$out/rec" --benchmark-frames 300 | grep benchmark

echo "== idle CPU: the smiley open, no input, 5 s after a 3 s settle (share of one core)"
"$editor" "$here/../../assets/examples/smiley.vimg" --output none --recovery-dir "$out/rec" >/dev/null 2>&1 &
pid=$!
sleep 3
t0=$(awk '{print $14 + $15}' "/proc/$pid/stat"); s0=$(date +%s.%N)
sleep 5
t1=$(awk '{print $14 + $15}' "/proc/$pid/stat"); s1=$(date +%s.%N)
kill "$pid"; wait "$pid" 2>/dev/null || true
awk -v a="$t0" -v b="$t1" -v s0="$s0" -v s1="$s1" -v hz="$(getconf CLK_TCK)" \
  'BEGIN { printf "idle cpu_percent=%.2f\n", 100 * (b - a) / hz / (s1 - s0) }'

echo "== mouse event to first drive sample, 20 strokes across a row of DOTs"
{
  echo '<?xml version="1.0" encoding="UTF-8"?>'
  echo '<vibroimage version="1.0" width="100" height="60">'
  for i in 0 1 2 3 4 5 6 7 8 9; do echo "  <dot id=\"d$i\" x=\"$((10 + 8 * i))\" y=\"30\" radius=\"2\" gain=\"1\"/>"; done
  echo '</vibroimage>'
} >"$out/dots.vimg"
"$editor" "$out/dots.vimg" --zoom 2 --play --output none --recovery-dir "$out/rec" --print-layout \
  >"$out/dots.layout" 2>"$out/dots.log" &
pid=$!
for _ in $(seq 100); do grep -q page_origin "$out/dots.layout" 2>/dev/null && break; sleep 0.1; done
sleep 1
X=$(grep '^layout window' "$out/dots.layout" | tail -1 | awk '{print $3}')
Y=$(grep '^layout window' "$out/dots.layout" | tail -1 | awk '{print $4}')
line=$(grep '^layout page_origin' "$out/dots.layout" | tail -1)
ppm=$(echo "$line" | sed 's/.*ppm\([0-9.]*\) .*/\1/')
ox=$(echo "$line" | awk '{print $3}')
oy=$(echo "$line" | awk '{print $4}')
y=$(awk -v w="$Y" -v o="$oy" -v p="$ppm" 'BEGIN { printf "%d", w + o + 30 * p }')
x0=$(awk -v w="$X" -v o="$ox" -v p="$ppm" 'BEGIN { printf "%d", w + o + 4 * p }')
x1=$(awk -v w="$X" -v o="$ox" -v p="$ppm" 'BEGIN { printf "%d", w + o + 90 * p }')
for stroke in 1 2; do
  xdotool mousemove "$x0" "$y" mousedown 1
  for ((x = x0; x <= x1; x += 4)); do xdotool mousemove "$x" "$y"; sleep 0.004; done
  xdotool mouseup 1
  sleep 0.3
done
xdotool key F5
sleep 0.5
kill "$pid"
wait "$pid" 2>/dev/null || true
grep latency "$out/dots.log"
