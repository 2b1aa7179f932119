#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb with xdotool: draws one of each primitive, edits a
# property, undoes and redoes, saves as .vimg and .png and reopens; plays a drag across a DOT to a
# WAV file and checks the pulse timing; kills the editor after an edit and recovers it.
# usage: editor_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR   (screenshots and files stay there)
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
check() { python3 "$here/gui_check.py" "$@"; }

source "$here/gui_driver.sh"
gui_setup
export SDL_AUDIODRIVER=dummy

echo "== draw one of each primitive, edit, undo/redo, save, reopen"
current=draw
start draw --output none --recovery-dir "$art/recovery-draw"
key d; click_mm 20 20
key l; drag_mm 10 40 50 40
key r; drag_mm 10 50 40 70
key e; drag_mm 50 50 80 70
key p; click_mm 10 76; click_mm 30 76; click_mm 20 88; key Return
key v; click_mm 20 20
sleep 0.3
widget radius
key ctrl+a
xdotool type --delay 30 "3.5"; sleep 0.2
key Return
shot draw-edited
key ctrl+z
save_as "$art/undone.vimg"
key ctrl+y
save_as "$art/drawn.vimg"
save_as "$art/drawn.png"
shot draw-saved
quit_editor
check drawn "$art/undone.vimg" 2
check drawn "$art/drawn.vimg" 3.5
[ "$(head -c 8 "$art/drawn.png" | od -An -tx1 | tr -d ' ')" = "89504e470d0a1a0a" ] || { echo "FAIL: drawn.png is not a PNG"; exit 1; }

current=reopen
start reopen "$art/drawn.png" --output none --recovery-dir "$art/recovery-reopen"
shot reopened-png
save_as "$art/reopened.vimg"
quit_editor
check same "$art/drawn.vimg" "$art/reopened.vimg"

echo "== play: drag across a DOT, output to WAV"
cat >"$art/play.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="60">
  <dot id="target" x="40" y="30" radius="3" gain="1"/>
</vibroimage>
VIMG
current=play
# Prediction off: this check is the live path from pointer events to the drive (dead reckoning).
# The touch predictor (on by default; tested on real traces in tests/primitives and tests/player)
# leads the recorded events by its horizon by design, and further on xdotool's pointer, which
# comes in bursts of two or three events at one instant 30-40 ms apart: a stop-and-go history.
start play "$art/play.vimg" --play --output "wav:$art/play.wav" --record-gesture "$art/play_gesture.csv" \
  --recovery-dir "$art/recovery-play" --touch-prediction off
move_mm 10 30; sleep 0.3
xdotool mousedown 1; sleep 0.1
x0=$(px 10); x1=$(px 70); y=$(py 30)
for ((x = x0; x <= x1; x += 3)); do xdotool mousemove "$x" "$y"; sleep 0.004; done
xdotool mouseup 1; sleep 0.3
shot playing
key F5
sleep 0.5
quit_editor
[ -s "$art/play.wav" ] || { echo "FAIL: no WAV written"; cat "$art/play.log"; exit 1; }
check pulse "$art/play.wav" "$art/play_gesture.csv" 40 30 3
grep -h 'latency' "$art/play.log" || true

echo "== SIGKILL after an edit, restart, recover"
cp "$src/assets/examples/smiley.vimg" "$art/recover_me.vimg"
current=crash
start crash "$art/recover_me.vimg" --output none --recovery-dir "$art/recovery" --autosave-interval 1
key d; click_mm 60 20
recovery_file() { compgen -G "$art/recovery/slot-*/document.vimg" | head -n 1; }  # one slot per document
for _ in $(seq 60); do [ -n "$(recovery_file)" ] && [ -s "$(recovery_file)" ] && break; sleep 0.1; done
[ -n "$(recovery_file)" ] || { echo "FAIL: no autosave"; cat "$art/crash.log"; exit 1; }
key ctrl+q  # unsaved changes: the editor asks instead of quitting
sleep 0.3
kill -0 "$editor_pid" || { echo "FAIL: the editor quit without asking about unsaved changes"; exit 1; }
shot unsaved-prompt
key Escape
kill -9 "$editor_pid"
wait "$editor_pid" 2>/dev/null || true
editor_pid=""
current=recover
start recover "$art/recover_me.vimg" --output none --recovery-dir "$art/recovery" --autosave-interval 1
for _ in $(seq 200); do grep -q '^layout recover_dialog' "$art/recover.layout" && break; sleep 0.1; done
grep -q '^layout recover_dialog' "$art/recover.layout" || { echo "FAIL: no recovery offered"; shot recover-missing; exit 1; }
shot recovery-offered
key Return
save_as "$art/recovered.vimg"
shot recovered
quit_editor
check recovered "$art/recovered.vimg" 60 20
[ -z "$(recovery_file)" ] || { echo "FAIL: the recovery file outlived a clean exit: $(recovery_file)"; exit 1; }
echo "PASS: editor GUI test (artifacts in $art)"
