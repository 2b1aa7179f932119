#!/usr/bin/env bash
# One look (docs/player.md, "The vimg-player window"): vimg-player shows an image exactly as
# `vimg convert` draws it as PNG at the same scale (same colours, stripes running vertically).
# Runs the player under Xvfb, takes a screenshot of its window and compares the canvas, below
# the status overlay and inside the border, with the PNG pixel by pixel.
set -euo pipefail
player="$1"
vimg="$2"
work="$3"
source "$(dirname "$0")/../../../tests/xvfb_display.sh"
rm -rf "$work" && mkdir -p "$work"
cat > "$work/look.vimg" <<'XML'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="120" height="80">
  <surface id="r" shape="rect" x="5" y="25" width="50" height="30" period="4.0" pattern="sine" gain="1.0"/>
  <surface id="e" shape="ellipse" cx="90" cy="40" rx="22" ry="15" period="3.0" pattern="square" gain="0.6"/>
  <surface id="p" shape="polygon" points="10,58 50,58 30,78" period="5.0" pattern="triangle" gain="0.8"/>
  <line id="l" x1="60" y1="60" x2="115" y2="75" width="3" frequency="175" gain="0.8"/>
  <dot id="d" x="70" y="70" radius="3" gain="1"/>
</vibroimage>
XML
"$vimg" convert "$work/look.vimg" "$work/look.png" --scale 5
start_xvfb 1024x768x24 "$work/xvfb.log"
trap stop_xvfb EXIT
# Canvas 120 x 80 mm at 5 px/mm = 600 x 400 px, centred in the 800 x 600 window at (100, 100).
SDL_AUDIODRIVER=dummy "$player" "$work/look.vimg" --window 800x600 --px-per-mm 5 --output "wav:$work/out.wav" >"$work/player.log" 2>&1 &
player_pid=$!
window=$(timeout 30 xdotool search --sync --name '^vimg-player$' | head -1)
sleep 1.5
import -window "$window" "$work/window.png"
xdotool key --window "$window" Escape
wait "$player_pid" || { echo "FAIL: vimg-player failed"; cat "$work/player.log"; exit 1; }
# Rows 20..398 of the canvas (the overlay covers the window's top ~110 rows), columns 1..598.
convert "$work/window.png" -crop 598x379+101+120 +repage "$work/shown.png"
convert "$work/look.png" -crop 598x379+1+20 +repage "$work/expected.png"
differ=$(compare -metric AE "$work/shown.png" "$work/expected.png" "$work/diff.png" 2>&1 || true)
echo "pixels that differ from the PNG export: $differ"
[ "$differ" = "0" ] || { echo "FAIL: the player does not show the PNG's picture"; exit 1; }
# And the stripes run vertically: inside the rectangle every column is one colour.
columns=$(convert "$work/window.png" -crop 240x140+135+230 +repage -scale 240x1! -depth 8 txt:- | tail -n +2 | awk '{print $3}' | sort -u | wc -l)
rows=$(convert "$work/window.png" -crop 240x140+135+230 +repage -scale 1x140! -depth 8 txt:- | tail -n +2 | awk '{print $3}' | sort -u | wc -l)
echo "distinct colours across x: $columns, down y: $rows"
[ "$rows" -le 2 ] && [ "$columns" -ge 5 ] || { echo "FAIL: the stripes do not run vertically"; exit 1; }
echo "PASS"
