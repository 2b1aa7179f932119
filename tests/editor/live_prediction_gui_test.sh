#!/usr/bin/env bash
# The editor's default live path, touch prediction on, end to end: under Xvfb a pointer that
# moves at a steady rate (steady_pointer: an XTest motion every 8 ms at absolute deadlines) drags
# across a DOT while the editor plays to a WAV file and records the gesture; the pulse must be felt
# where the recorded finger crosses the dot, ahead of it by the prediction horizon and no more
# (live_prediction_check.py).
# usage: live_prediction_gui_test.sh PATH/TO/vimg-editor PATH/TO/steady_pointer ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
pointer=$(realpath "$2")
art=$3
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)

source "$here/gui_driver.sh"
gui_setup
export SDL_AUDIODRIVER=dummy

# The horizon of the default path: the mouse's default panel latency (a fresh HOME keeps no
# setting) plus the output's latency, 0 for a WAV file (docs/latency.md).
latency_s=$(sed -n 's/.*kDefaultMousePanelLatency_s = \([0-9.]*\);.*/\1/p' \
  "$src/primitives/touch_prediction/touch_latency_defaults.hpp")
[ -n "$latency_s" ] || { echo "FAIL: no default mouse latency in touch_latency_defaults.hpp"; exit 1; }

cat >"$art/play.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="60">
  <dot id="target" x="40" y="30" radius="5" gain="1"/>
</vibroimage>
VIMG
current=play
start play "$art/play.vimg" --play --output "wav:$art/play.wav" --record-gesture "$art/play_gesture.csv" \
  --recovery-dir "$art/recovery-play"
timeout 60 xdotool search --sync --onlyvisible --pid "$editor_pid" >/dev/null ||
  { echo "FAIL: the editor's window is not shown"; exit 1; }
# 10 -> 70 mm in 400 ms (150 mm/s), one motion every 8 ms.
"$pointer" "$(px 10)" "$(py 30)" "$(px 70)" "$(py 30)" 8 400 "$art/pointer.csv"
shot playing
quit_editor
grep -h 'latency' "$art/play.log" || true
[ -s "$art/play.wav" ] || { echo "FAIL: no WAV written"; cat "$art/play.log"; exit 1; }
python3 "$here/live_prediction_check.py" "$art/play.wav" "$art/play_gesture.csv" "$art/pointer.csv" 40 30 5 \
  "$latency_s"
echo "PASS: the default live path (artifacts in $art)"
