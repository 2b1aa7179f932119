#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb with xdotool: the file chooser. Opens a file by clicking
# into folders and double-clicking it (the filter hides a .txt), goes Up, saves under a typed
# name without extension (the filter's extension is added), and finds the folder among the recent
# folders after a restart, kept in the config folder.
# usage: file_chooser_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR   (screenshots and files stay there)
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
check() { python3 "$here/gui_check.py" "$@"; }
source "$here/gui_driver.sh"
gui_setup
mkdir -p "$art/work/lib/sub"

cat >"$art/work/lib/sub/pic.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="100">
  <dot id="picked" x="33" y="44" radius="3" gain="1"/>
</vibroimage>
VIMG
echo "not an image" >"$art/work/lib/sub/notes.txt"
cp "$art/work/lib/sub/pic.vimg" "$art/work/lib/top.vimg"

# item NAME [CLICKS]: clicks the chooser entry NAME (printed by --print-layout) near its left end.
item() { click_layout "chooser_item_$1" "${2:-1}" 20; sleep 0.1; }
wait_prompt() {
  for _ in $(seq 300); do grep -q "^layout file_prompt$1 " "$art/$current.layout" && return 0; sleep 0.1; done
  echo "FAIL: no file chooser"; shot no-chooser; exit 1
}

current=chooser
cd "$art/work"
start chooser --output none --recovery-dir "$art/recovery"
key ctrl+o; wait_prompt 1
item lib; item sub
shot chooser-sub
if grep -q '^layout chooser_item_notes.txt ' "$art/$current.layout"; then
  echo "FAIL: the image filter lists notes.txt"; exit 1
fi
item pic.vimg 2                     # a double-click opens it
sleep 0.5
prompts=1
# Save As starts in the document's folder: go Up, type a bare name, the XML filter adds .vimg.
key ctrl+shift+s; wait_prompt 2
widget chooser_up
sleep 0.3
shot chooser-up
widget chooser_name                 # back to the name field
key ctrl+a
xdotool type --delay 20 "copy"; sleep 0.2
key Return
for _ in $(seq 100); do [ -s "$art/work/lib/copy.vimg" ] && break; sleep 0.1; done
[ -s "$art/work/lib/copy.vimg" ] || { echo "FAIL: copy.vimg not saved in lib/"; ls -R "$art/work"; exit 1; }
python3 - "$art/work/lib/copy.vimg" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
dots = [e for e in root if e.tag == "dot" and e.get("id") == "picked"]
if len(dots) != 1:
    print(f"FAIL: {sys.argv[1]} does not hold the opened image"); sys.exit(1)
print(f"ok: {sys.argv[1]} holds the image opened through the chooser")
PY
quit_editor

grep -qx "$art/work/lib" "$art/home/.config/vimg-editor/recent-folders.txt" ||
  { echo "FAIL: lib/ is not a recent folder"; cat "$art/home/.config/vimg-editor/recent-folders.txt"; exit 1; }
grep -qx "$art/work/lib/sub" "$art/home/.config/vimg-editor/recent-folders.txt" ||
  { echo "FAIL: lib/sub is not a recent folder"; exit 1; }

# After a restart elsewhere, the chooser opens in the most recent folder and lists the others.
current=again
cd "$art"
start again --output none --recovery-dir "$art/recovery"
key ctrl+o; wait_prompt 1
sleep 0.3
shot chooser-recent
grep -q '^layout chooser_recent_1 ' "$art/$current.layout" || { echo "FAIL: recent folders not offered"; exit 1; }
grep -q '^layout chooser_item_top.vimg ' "$art/$current.layout" ||
  { echo "FAIL: the chooser did not open in the most recent folder (lib/)"; exit 1; }
key Escape
quit_editor
echo "PASS: editor file chooser GUI test (artifacts in $art)"
