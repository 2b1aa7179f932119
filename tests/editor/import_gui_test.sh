#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb with xdotool: File -> Import. Imports the example drawing
# (examples/import/drawing.svg) through the menu and the chooser's typed path, accepts the import
# options, saves the new untitled document through the chooser as .vimg and checks the file with
# `vimg validate` and against what `vimg import` makes of the same drawing (same size, same
# primitives). Then imports the example picture (PNG, no pHYs: 100 mm and 4 levels offered) the
# same way, and a broken SVG, which is reported in the Problem dialog while the document stays.
# usage: import_gui_test.sh PATH/TO/vimg-editor PATH/TO/vimg ARTIFACT_DIR   (screenshots and files stay there)
set -euo pipefail
editor=$(realpath "$1")
vimg=$(realpath "$2")
art=$3
here=$(cd "$(dirname "$0")" && pwd)
examples=$(realpath "$here/../../examples/import")
source "$here/gui_driver.sh"
gui_setup
mkdir -p "$art/work"
printf '<svg xmlns="http://www.w3.org/2000/svg" width="10mm" height="10mm"><rect width="3"' >"$art/work/broken.svg"

wait_layout() {
  for _ in $(seq 300); do grep -q "^layout $1 " "$art/$current.layout" && return 0; sleep 0.1; done
  echo "FAIL: $1 not shown"; shot "no-$1"; exit 1
}
# import_via_menu FILE: File -> Import..., the path typed into the chooser, Enter.
import_via_menu() {
  prompts=$((prompts + 1))
  widget menu_file
  widget menu_import
  wait_layout "file_prompt$prompts"
  key ctrl+a
  xdotool type --delay 10 "$1"; sleep 0.2
  key Return
}
title() { xdotool getwindowname "$(xdotool search --name 'vimg-editor' | head -1)"; }
# primitives FILE: how many DOT, LINE and SURFACE elements the file holds, at any depth.
primitives() {
  python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
print(sum(1 for e in root.iter() if e.tag.split('}')[-1] in ("dot", "line", "surface")))
PY
}
# same_as_cli SAVED REFERENCE: valid, same canvas size, same number of primitives.
same_as_cli() {
  "$vimg" validate "$1" || { echo "FAIL: vimg validate rejects $1"; exit 1; }
  local got want
  got=$(primitives "$1"); want=$(primitives "$2")
  [ "$got" -gt 0 ] && [ "$got" = "$want" ] ||
    { echo "FAIL: $1 holds $got primitives, vimg import makes $want"; exit 1; }
  python3 - "$1" "$2" <<'PY'
import sys, xml.etree.ElementTree as ET
a, b = (ET.parse(p).getroot() for p in sys.argv[1:3])
for k in ("width", "height"):
    if abs(float(a.get(k)) - float(b.get(k))) > 1e-6:
        print(f"FAIL: {sys.argv[1]} {k}={a.get(k)}, vimg import gives {b.get(k)}"); sys.exit(1)
PY
  echo "ok: $1 is valid and holds the $got primitives vimg import makes"
}

current=import
cd "$art/work"
start import --output none --recovery-dir "$art/recovery"

# The drawing: the SVG options popup (mm per unit from the file), Enter imports.
import_via_menu "$examples/drawing.svg"
wait_layout import_dialog
sleep 0.3
shot import-svg-options
# The options are asked first: the document is still the blank, unchanged page.
[ "$(title)" = "untitled - vimg-editor" ] || { echo "FAIL: imported before the options were given ($(title))"; exit 1; }
key Return
sleep 0.5
[ "$(title)" = "*untitled - vimg-editor" ] || { echo "FAIL: no new unsaved document after the import ($(title))"; exit 1; }
shot import-svg
save_as "$art/work/drawing.vimg"
"$vimg" import "$examples/drawing.svg" --out "$art/work/drawing-cli.vimg" 2>/dev/null
same_as_cli "$art/work/drawing.vimg" "$art/work/drawing-cli.vimg"

# The picture: width 100 mm (no pHYs) and 4 levels offered; accepted as they are.
import_via_menu "$examples/picture.png"
sleep 0.8
shot import-png-options
key Return
sleep 0.5
shot import-png
save_as "$art/work/picture.vimg"
"$vimg" import "$examples/picture.png" --width-mm 100 --levels 4 --out "$art/work/picture-cli.vimg" 2>/dev/null
same_as_cli "$art/work/picture.vimg" "$art/work/picture-cli.vimg"

# A broken drawing: the Problem dialog names it; the document stays.
import_via_menu "$art/work/broken.svg"
sleep 0.5
key Return          # the options popup
sleep 0.8
shot import-broken
[ "$(title)" = "picture.vimg - vimg-editor" ] || { echo "FAIL: the document changed on a failed import ($(title))"; exit 1; }
grep -q "broken.svg.*error" "$art/$current.log" || { echo "FAIL: the broken SVG was not reported"; exit 1; }
kill -0 "$editor_pid" || { echo "FAIL: the editor died on a broken SVG"; exit 1; }
key Return          # closes the Problem dialog
sleep 0.3
quit_editor         # the picture was saved: no unsaved-changes question
echo "PASS: editor import GUI test (artifacts in $art)"
