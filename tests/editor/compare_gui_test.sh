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
gui_setup
data="$here/../data/compare"
mkdir -p "$art/lib"
cp "$data/surface.vimg" "$art/lib/copy_a.vimg"
cp "$data/surface.vimg" "$art/lib/copy_b.vimg"
for f in dot line surface; do cp "$data/$f.vimg" "$art/lib/$f.vimg"; done

source "$here/library_driver.sh"

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
