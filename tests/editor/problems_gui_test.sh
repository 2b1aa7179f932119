#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb: a file with gain="3" opens with all its primitives and
# exactly one problem listed; "Clamp all" fixes it, the saved file validates (vimg validate exits 0)
# with every primitive; Ctrl+Z brings the 3 back (the saved copy is invalid again).
# usage: problems_gui_test.sh PATH/TO/vimg-editor PATH/TO/vimg ARTIFACT_DIR   (screenshots stay there)
set -euo pipefail
editor=$(realpath "$1")
vimg=$(realpath "$2")
art=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup

cat >"$art/gain3.vimg" <<'VIMG'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="100">
  <surface id="face" shape="ellipse" cx="50" cy="50" rx="30" ry="40" period="2" relief="0.5" pattern="sine" gain="0.6"/>
  <dot id="eye" x="40" y="40" radius="2" gain="3"/>
  <line id="mouth" x1="35" y1="70" x2="65" y2="70" width="2" frequency="175" damping="0.05" gain="0.8"/>
</vibroimage>
VIMG
if "$vimg" validate "$art/gain3.vimg" >"$art/gain3.validate" 2>&1; then
  echo "FAIL: vimg validate accepts gain=\"3\""; exit 1
fi

current=problems
start problems "$art/gain3.vimg" --output none --recovery-dir "$art/recovery"
for _ in $(seq 100); do grep -q '^layout clamp_all ' "$art/problems.layout" && break; sleep 0.1; done
sleep 0.8  # the live check runs 0.3 s after opening; it must not add a second message
shot opened
grep -q '^layout clamp_all ' "$art/problems.layout" || { echo "FAIL: no Clamp all button"; exit 1; }
listed=$(grep -c '^layout problem[0-9]* ' "$art/problems.layout" | tr -d ' ')
[ "$(grep '^layout problem' "$art/problems.layout" | awk '{print $2}' | sort -u | wc -l)" -eq 1 ] ||
  { echo "FAIL: the problem list has more than one entry:"; grep '^layout problem' "$art/problems.layout"; exit 1; }
echo "problems listed: $listed layout line(s), one entry"

click_mm 40 40  # the dot: the inspector shows its gain out of range
sleep 0.4
shot dot-selected
widget clamp_all
sleep 0.5
shot clamped
save_as "$art/fixed.vimg"
"$vimg" validate "$art/fixed.vimg" >"$art/fixed.validate" 2>&1 ||
  { echo "FAIL: the clamped file does not validate"; cat "$art/fixed.validate"; exit 1; }
python3 - "$art/fixed.vimg" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
ids = {e.get("id"): e for e in root}
assert set(ids) >= {"face", "eye", "mouth"}, f"primitives lost: {sorted(ids)}"
assert float(ids["eye"].get("gain")) == 1.0, ids["eye"].get("gain")
assert float(ids["face"].get("gain")) == 0.6 and float(ids["mouth"].get("gain")) == 0.8, "other values changed"
PY

key ctrl+z
save_as "$art/undone.vimg"
grep -q 'id="eye" x="40" y="40" radius="2" gain="3"' "$art/undone.vimg" ||
  { echo "FAIL: undo did not bring gain 3 back"; cat "$art/undone.vimg"; exit 1; }
quit_editor
echo "PASS"
