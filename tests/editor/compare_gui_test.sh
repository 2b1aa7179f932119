#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb: in the library (--library-dir), two copies of one texture
# and a DOT are selected (click, Ctrl+click) and "Predict confusion" shows the predicted confusion
# matrix with exactly one warning, the copies' (the same code as `vimg compare`); then a DOT, a LINE
# and a SURFACE give no warning. The screenshots stay in ARTIFACT_DIR.
# usage: compare_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup 441 480
data="$here/../data/compare"
mkdir -p "$art/lib"
cp "$data/surface.vimg" "$art/lib/copy_a.vimg"
cp "$data/surface.vimg" "$art/lib/copy_b.vimg"
for f in dot line surface; do cp "$data/$f.vimg" "$art/lib/$f.vimg"; done

# scroll_to NAME: wheels the library list until the entry's row is inside it (both as printed).
scroll_to() {
  local y h ly lh
  for _ in $(seq 60); do
    read -r _ _ _ ly _ lh <<<"$(grep '^layout library_list ' "$art/$current.layout" | tail -1)"
    read -r _ _ _ y _ h <<<"$(grep "^layout library_lib/$1 " "$art/$current.layout" | tail -1)"
    [ -n "${y:-}" ] && [ "$y" -ge "$ly" ] && [ "$((y + h))" -le "$((ly + lh))" ] && return 0
    xdotool mousemove $((WX + 100)) $((WY + ly + lh / 2)); sleep 0.1
    xdotool click 5; sleep 0.2
  done
  echo "FAIL: library entry $1 not reachable"; shot "no-$1"; exit 1
}
# selection_is N: the editor's last printed selection count is N.
selection_is() {
  [ "$(grep '^layout compare_selection_' "$art/$current.layout" | tail -1 | cut -d' ' -f2)" = "compare_selection_$1" ]
}
# pick NAME COUNT [ctrl]: clicks the library entry (with Ctrl held when asked), then waits until
# the editor says that COUNT images are selected, at most 30 s.
pick() {
  scroll_to "$1"
  local x y w h
  read -r _ _ x y w h <<<"$(grep "^layout library_lib/$1 " "$art/$current.layout" | tail -1)"
  xdotool mousemove --sync $((WX + x + w / 2)) $((WY + y + h / 2))
  if [ "${3:-}" = ctrl ]; then
    # ImGui's SDL backend reads the modifier state once a frame, not in event order: Ctrl is held
    # across the click for a few frames (the selection count below is what the test waits on).
    xdotool keydown ctrl; sleep 0.2; xdotool click 1; sleep 0.2; xdotool keyup ctrl
  else
    xdotool click 1
  fi
  for _ in $(seq 3000); do
    selection_is "$2" && return 0
    sleep 0.01
  done
  echo "FAIL: $1 did not make the selection $2"; shot "no-selection-$1"; exit 1
}
# wait_result: until the window shows the matrix (or failed), at most 60 s.
wait_result() {
  for _ in $(seq 600); do
    grep -q '^layout compare_matrix\|^layout compare_failed' "$art/$current.layout" && return 0
    sleep 0.1
  done
  echo "FAIL: no result"; shot "$current-no-result"; exit 1
}

current=compare
start compare --library-dir "$art/lib" --output none --recovery-dir "$art/recovery"
pick copy_a.vimg 1
pick copy_b.vimg 2 ctrl
pick dot.vimg 3 ctrl
widget compare_button
wait_result
shot confused
grep -q '^layout compare_failed' "$art/compare.layout" && { echo "FAIL: the comparison failed"; cat "$art/compare.log"; exit 1; }
grep -q '^layout compare_warning0 ' "$art/compare.layout" || { echo "FAIL: no warning for the two copies"; exit 1; }
if grep -q '^layout compare_warning1 ' "$art/compare.layout"; then echo "FAIL: more than one warning"; exit 1; fi
echo "copies: one warning"
quit_editor

current=apart
start apart --library-dir "$art/lib" --output none --recovery-dir "$art/recovery2"
pick dot.vimg 1
pick line.vimg 2 ctrl
pick surface.vimg 3 ctrl
widget compare_button
wait_result
shot apart
grep -q '^layout compare_no_warning ' "$art/apart.layout" || { echo "FAIL: a DOT, a LINE and a SURFACE should give no warning"; exit 1; }
if grep -q '^layout compare_warning' "$art/apart.layout"; then echo "FAIL: a warning for a DOT, a LINE and a SURFACE"; exit 1; fi
echo "dot, line, surface: no warning"
quit_editor
echo "PASS"
