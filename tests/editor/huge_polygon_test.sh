#!/usr/bin/env bash
# Regression: a valid image holding one polygon of 250 000 points (about 4 MB) used to overflow the
# stack inside Dear ImGui's stroke code. The editor must open it, draw frames and exit normally.
# usage: huge_polygon_test.sh PATH/TO/vimg-editor OUT_DIR
set -euo pipefail
editor=$1
out=$2
mkdir -p "$out"
export HOME="$out/home" XDG_CONFIG_HOME="$out/home/.config" XDG_STATE_HOME="$out/home/.state"
mkdir -p "$HOME"
python3 - "$out/huge.vimg" <<'PY'
import math, sys
n = 250_000
pts = " ".join(f"{100 + 80 * math.cos(2 * math.pi * i / n):.4f},{100 + 80 * math.sin(2 * math.pi * i / n):.4f}" for i in range(n))
with open(sys.argv[1], "w") as f:
    f.write('<?xml version="1.0" encoding="UTF-8"?>\n<vibroimage version="1.0" width="200" height="200">\n')
    f.write(f'  <surface id="huge" shape="polygon" points="{pts}" period="2" relief="0.5" pattern="sine" gain="0.8"/>\n')
    f.write('</vibroimage>\n')
PY
source "$(dirname "$0")/../xvfb_display.sh"
trap stop_xvfb EXIT
start_xvfb 1400x900x24 "$out/xvfb.log"
status=0
"$editor" "$out/huge.vimg" --output none --recovery-dir "$out/rec" --benchmark-frames 5 >"$out/log.txt" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  echo "huge_polygon_test: the editor exited with $status on a 250 000-point polygon"
  cat "$out/log.txt"
  exit 1
fi
grep -q benchmark "$out/log.txt" || { echo "huge_polygon_test: no frames drawn"; cat "$out/log.txt"; exit 1; }
echo "huge_polygon_test: opened and drew a 250 000-point polygon"
