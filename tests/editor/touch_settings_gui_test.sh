#!/usr/bin/env bash
# The Mode menu's touch-latency choice is kept on this device (docs/latency.md, "Settings"): the real
# vimg-editor under Xvfb reads $XDG_CONFIG_HOME/vimg-editor/touch-latency.txt at start and writes
# it when the choice changes in the menu; the command line wins over the file for its run.
#   1. the file says 40 ms, prediction on; Mode -> Touch Prediction turns it off: the file now says
#      40 ms (read at start: a fresh editor would write its default 8 ms) and off;
#   2. started with --touch-latency-ms 12, the same click turns prediction on again (read from the
#      file: off) and the file says 12 ms, on.
# usage: touch_settings_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup
export SDL_AUDIODRIVER=dummy
settings="$XDG_CONFIG_HOME/vimg-editor/touch-latency.txt"
mkdir -p "$(dirname "$settings")"
printf 'touch_latency_ms = 40\ntouch_prediction = on\n' >"$settings"

# wait_for_settings LATENCY ON|OFF: the file says so (the editor writes it atomically).
wait_for_settings() {
  for _ in $(seq 200); do
    grep -qx "touch_latency_ms = $1" "$settings" && grep -qx "touch_prediction = $2" "$settings" && return 0
    sleep 0.1
  done
  echo "FAIL: $settings does not say $1 ms, $2:"; cat "$settings"; shot "settings-$1-$2"; exit 1
}

current=first
start first --output none --recovery-dir "$art/recovery"
widget menu_mode
widget menu_touch_prediction
wait_for_settings 40 off
quit_editor

current=second
start second --output none --recovery-dir "$art/recovery" --touch-latency-ms 12
widget menu_mode
widget menu_touch_prediction
wait_for_settings 12 on
quit_editor

# A value out of range is refused with its line, and the editor still starts with its default.
printf 'touch_latency_ms = 900\n' >"$settings"
current=bad
start bad --output none --recovery-dir "$art/recovery"
quit_editor
grep -q 'touch-latency.txt:1: error: touch_latency_ms must be a number of ms from 0 to 500' "$art/bad.log" ||
  { echo "FAIL: no message for the bad line:"; cat "$art/bad.log"; exit 1; }
echo "PASS"
