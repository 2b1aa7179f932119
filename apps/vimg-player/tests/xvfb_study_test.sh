#!/usr/bin/env bash
# The live matching test under Xvfb (docs/player.md, "Matching test"): a person's clicks through
# one trial with xdotool. Welcome (tap) -> training (the picture shown; S skips) -> rubbing (no
# picture anywhere: the stage is one colour; a drag over the invisible image) -> Answer -> the
# set's pictures (each the PNG export's picture, pixel for pixel) -> a click on the second picture
# records trial 1 with that choice -> Escape ends the session (exit 0; running again continues).
# Screenshots of every screen are kept in the work folder.
set -euo pipefail
player="$1"
vimg="$2"
examples="$3"
work="$4"
source "$(dirname "$0")/../../../tests/xvfb_display.sh"
rm -rf "$work" && mkdir -p "$work/study" "$work/results"
# Two sets of two example images, once each: 4 trials.
cp "$examples"/{dot,line,surface_top,surface_bottom}.vimg "$work/study/"
cat > "$work/study/study.xml" <<'XML'
<?xml version="1.0" encoding="UTF-8"?>
<matchingStudy version="1" seed="7" repetitions="1" trainingMinutes="3">
  <set name="complexity"><image file="dot.vimg"/><image file="line.vimg"/></set>
  <set name="same-complexity"><image file="surface_top.vimg"/><image file="surface_bottom.vimg"/></set>
</matchingStudy>
XML
start_xvfb 1024x768x24 "$work/xvfb.log"
trap stop_xvfb EXIT
SDL_AUDIODRIVER=dummy "$player" --study "$work/study/study.xml" --participant X1 --results "$work/results" \
  --window 1024x768 --px-per-mm 3 --output "wav:$work/out.wav" >"$work/player.log" 2>&1 &
player_pid=$!
window=$(timeout 30 xdotool search --sync --name '^vimg-player study$' | head -1)
xdotool windowactivate --sync "$window" 2>/dev/null || xdotool windowfocus "$window"
shot() { sleep 0.5; import -window "$window" "$work/$1.png"; }
click() { xdotool mousemove --window "$window" "$1" "$2" click 1; }
# Colours of a region: "N" distinct colours in the crop WxH+X+Y of a screenshot.
colours() { convert "$work/$1.png" -crop "$2" +repage -depth 8 txt:- | tail -n +2 | awk '{print $3}' | sort -u | wc -l; }

shot welcome
click 512 300
shot training
# Layout (study_layout.hpp) for 1024 x 768: header 56 px, footer 150 px, the stage 56..618; the
# 60 x 110 mm canvas at 3 px/mm is 180 x 330 px at (422, 172); the Answer button's centre (512, 693).
[ "$(colours training 170x320+427+177)" -ge 2 ] || { echo "FAIL: no training picture"; cat "$work/player.log"; exit 1; }
xdotool key --window "$window" s
shot rubbing_before
[ "$(colours rubbing_before 1024x562+0+56)" = 1 ] || { echo "FAIL: the rubbing screen shows something"; exit 1; }
xdotool mousemove --window "$window" 430 320 mousedown 1
for x in $(seq 430 10 600); do xdotool mousemove --window "$window" "$x" 330; sleep 0.01; done
xdotool mouseup 1
shot rubbing
[ "$(colours rubbing 1024x562+0+56)" = 1 ] || { echo "FAIL: the rubbing screen shows a picture"; exit 1; }
click 512 693
shot answering
# Both pictures at 3 px/mm (the true scale caps the sheets' scale), 180 x 330 px at (166, 232) and
# (678, 232): inside their borders, the PNG export's pixels.
"$vimg" convert "$work/study/line.vimg" "$work/line.png" --scale 3 >/dev/null
convert "$work/answering.png" -crop 178x328+679+233 +repage "$work/shown_line.png"
convert "$work/line.png" -crop 178x328+1+1 +repage "$work/expected_line.png"
differ=$(compare -metric AE "$work/shown_line.png" "$work/expected_line.png" "$work/diff.png" 2>&1 || true)
echo "answer screen: pixels that differ from the PNG export: $differ"
[ "$differ" = "0" ] || { echo "FAIL: the answer screen does not show the PNG's picture"; exit 1; }
click 768 400
for _ in $(seq 100); do [ "$(wc -l <"$work/results/X1.trials.csv")" -ge 2 ] && break; sleep 0.05; done
shot after_answer
xdotool key --window "$window" Escape
status=0
wait "$player_pid" || status=$?
cat "$work/player.log"
[ "$status" = 0 ] || { echo "FAIL: vimg-player exited with $status"; exit 1; }
grep -q "stopped before trial 2 of 4" "$work/player.log" || { echo "FAIL: no stop message"; exit 1; }
row=$(sed -n 2p "$work/results/X1.trials.csv")
echo "row: $row"
IFS=, read -r participant set trial presented chosen correct rub response path stamp <<<"$row"
[ "$participant,$set,$trial,$chosen" = "X1,complexity,1,line" ] || { echo "FAIL: wrong row"; exit 1; }
case "$presented" in dot|line) ;; *) echo "FAIL: presented '$presented'"; exit 1 ;; esac
[ "$correct" = "$([ "$presented" = line ] && echo 1 || echo 0)" ] || { echo "FAIL: correct"; exit 1; }
awk -v r="$rub" -v s="$response" -v p="$path" 'BEGIN { exit !(r > 0.05 && s > 0.1 && p > 40 && p < 80) }' ||
  { echo "FAIL: rub_s $rub, response_s $response, path_mm $path"; exit 1; }
[ "$(wc -l <"$work/results/X1.trials.csv")" = 2 ] || { echo "FAIL: more than one row"; exit 1; }
echo "PASS"
