#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb with --actuator assets/profiles/lra-175hz-drv2605l.xml on a
# page with a 20 Hz and a 175 Hz surface (fullSpeed 100 mm/s): exactly one, the 20 Hz one, gets the
# weak mark; selecting it shows the vimg validate warning in the inspector; playing shows the drive
# and the predicted acceleration side by side. A bad profile on the command line gives its
# FILE:LINE message and the editor runs on with the ideal actuator (nothing marked); the profile
# chosen first is remembered for a start without --actuator.
# usage: feel_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR   (screenshots stay there)
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup
lra="$here/../../assets/profiles/lra-175hz-drv2605l.xml"

cat >"$art/two.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="60">
  <interaction mass="0.01" fullSpeed="100" maxDeformation="1"/>
  <surface id="sand" shape="rect" x="5" y="10" width="40" height="40" period="5" relief="0.5" pattern="sine" gain="0.8"/>
  <surface id="silk" shape="rect" x="55" y="10" width="40" height="40" period="0.5714286" relief="0.5" pattern="sine" gain="0.8"/>
</vibroimage>
VIMG

current=feel
start feel "$art/two.vimg" --actuator "$lra" --output none --recovery-dir "$art/recovery"
for _ in $(seq 100); do grep -q '^layout weak_mark' "$art/feel.layout" && break; sleep 0.1; done
sleep 0.5
shot marked
marks=$( (grep '^layout weak_mark' "$art/feel.layout" || true) | awk '{print $2}' | sort -u)
[ "$marks" = "weak_mark0_sand" ] || { echo "FAIL: expected exactly the 20 Hz surface marked, got: $marks"; exit 1; }
echo "marked: $marks"

click_mm 25 30  # select the 20 Hz surface: the inspector shows the warning
for _ in $(seq 30); do grep -q '^layout feel_warning' "$art/feel.layout" && break; sleep 0.1; done
shot sand-selected
grep -q '^layout feel_warning' "$art/feel.layout" || { echo "FAIL: no warning in the inspector"; exit 1; }

key F5  # play: the scope shows the drive and the predicted acceleration while the finger rubs
move_mm 8 30; sleep 0.15
xdotool mousedown 1
for x in 10 12 14 16 18 20 22 24 26 28 30; do move_mm "$x" 30; sleep 0.03; done
shot playing
xdotool mouseup 1; sleep 0.2
grep -q '^layout scope_drive' "$art/feel.layout" && grep -q '^layout scope_acceleration' "$art/feel.layout" ||
  { echo "FAIL: the scope does not show drive and acceleration"; exit 1; }
key F5
quit_editor

printf '<actuator name="bad" type="lra">\n  <resonance hz="-5"/>\n</actuator>\n' >"$art/bad.xml"
current=bad
start bad "$art/two.vimg" --actuator "$art/bad.xml" --output none --recovery-dir "$art/recovery2"
sleep 1
shot bad-profile
grep -q "bad.xml:2: error" "$art/bad.log" || { echo "FAIL: no FILE:LINE message for the bad profile"; cat "$art/bad.log"; exit 1; }
if grep -q '^layout weak_mark' "$art/bad.layout"; then echo "FAIL: marks with the ideal actuator"; exit 1; fi
kill -9 "$editor_pid"; wait "$editor_pid" 2>/dev/null || true; editor_pid=""  # the Problem dialog has no scripted button

# The LRA chosen in the first run is remembered: a start without --actuator marks the same surface.
current=again
start again "$art/two.vimg" --output none --recovery-dir "$art/recovery3"
for _ in $(seq 100); do grep -q '^layout weak_mark' "$art/again.layout" && break; sleep 0.1; done
shot remembered
marks=$( (grep '^layout weak_mark' "$art/again.layout" || true) | awk '{print $2}' | sort -u)
[ "$marks" = "weak_mark0_sand" ] || { echo "FAIL: the profile was not remembered, marked: $marks"; exit 1; }
quit_editor
echo "PASS"
