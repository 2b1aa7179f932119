#!/usr/bin/env bash
# Runs vimg-player under Xvfb with --output wav:FILE, drags the mouse across a textured surface
# with xdotool, quits with Escape, and checks the WAV: it exists, is mono float32 at 8 kHz, and
# holds drive (the texture) while the mouse moved, and silence before the first touch.
set -euo pipefail
player="$1"
work="$2"
rm -rf "$work" && mkdir -p "$work"
cat > "$work/plate.vimg" <<'XML'
<?xml version="1.0" encoding="UTF-8"?>
<vibroimage version="1.0" width="100" height="60">
  <surface id="plate" shape="rect" x="0" y="0" width="100" height="60" period="2.0" relief="0.5" pattern="sine" gain="1.0"/>
</vibroimage>
XML

source "$(dirname "$0")/../../../tests/xvfb_display.sh"
start_xvfb 1024x768x24 "$work/xvfb.log"
trap stop_xvfb EXIT

# Canvas 100 x 60 mm at 5 px/mm = 500 x 300 px, centred in the 800 x 600 window.
# drag_run NAME [player options...]: drags across the plate and quits; the WAV is $work/NAME.wav.
drag_run() {
  local name=$1; shift
  SDL_AUDIODRIVER=dummy "$player" "$work/plate.vimg" --window 800x600 --px-per-mm 5 \
    --output "wav:$work/$name.wav" "$@" >"$work/$name.log" 2>&1 &
  player_pid=$!
  window=$(xdotool search --sync --name '^vimg-player$' | head -1)
  xdotool windowactivate --sync "$window" 2>/dev/null || xdotool windowfocus "$window"
  sleep 0.5
  xdotool mousemove --window "$window" 200 300
  xdotool mousedown 1
  for x in $(seq 200 10 600); do
    xdotool mousemove --window "$window" "$x" 300
    sleep 0.01
  done
  xdotool mouseup 1
  sleep 0.3
  xdotool key --window "$window" Escape
  for _ in $(seq 100); do kill -0 "$player_pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$player_pid" 2>/dev/null; then
    echo "vimg-player did not quit on Escape"; kill "$player_pid"; cat "$work/$name.log"; exit 1
  fi
  wait "$player_pid" || { echo "vimg-player failed"; cat "$work/$name.log"; exit 1; }
  cat "$work/$name.log"
}

# check_wav NAME MIN_LOUD: mono float32 at 8 kHz, |drive| <= 1, at least MIN_LOUD samples above 0.05
# while the mouse moved, silence before the first touch.
check_wav() {
  local wav="$work/$1.wav"
  [ -s "$wav" ] || { echo "no WAV written"; exit 1; }
  [ "$(head -c 4 "$wav")" = "RIFF" ] || { echo "not a RIFF file"; exit 1; }
  format=$(od -A n -t u2 -j 20 -N 4 "$wav" | tr -s ' ')
  [ "$format" = " 3 1" ] || { echo "expected float32 mono, got format/channels:$format"; exit 1; }
  rate=$(od -A n -t u4 -j 24 -N 4 "$wav" | tr -d ' ')
  [ "$rate" = "8000" ] || { echo "expected 8000 Hz, got $rate"; exit 1; }
  data_at=$(LC_ALL=C grep -obUa 'data' "$wav" | head -1 | cut -d: -f1)
  od -A n -t f4 -v -j $((data_at + 8)) "$wav" | tr -s ' ' '\n' | sed '/^$/d' > "$work/$1.samples.txt"
  awk -v min_loud="$2" -v name="$1" '
    { v = $1 + 0; a = v < 0 ? -v : v; n++;
      if (a > 1.0001) bad++;
      if (a > 0.05) { loud++; if (!first) first = n } ;
      if (a > peak) peak = a }
    END {
      printf "%s: samples %d, above 0.05: %d, peak %.3f, first drive at sample %d\n", name, n, loud, peak, first;
      if (n < 4000) { print "too few samples for the run"; exit 1 }
      if (bad) { print "drive outside [-1, 1]"; exit 1 }
      if (loud < min_loud) { print "no texture drive while the mouse moved"; exit 1 }
      if (first < 100) { print "drive before the first touch"; exit 1 }
    }' "$work/$1.samples.txt"
}

drag_run out
check_wav out 400
# The same drag with the LRA profile and --equalize: the equalized drive reaches the WAV, bounded
# (the equalizer never boosts; its exact output is tested in tests/player/actuator_sink_test.cpp).
drag_run equalized --actuator "$(dirname "$0")/../../../assets/profiles/lra-175hz-drv2605l.xml" --equalize
check_wav equalized 100
# SIGTERM: the player leaves its loop, puts the output to rest, completes the file and exits 143.
SDL_AUDIODRIVER=dummy "$player" "$work/plate.vimg" --window 800x600 --px-per-mm 5 \
  --output "wav:$work/term.wav" >"$work/term.log" 2>&1 &
player_pid=$!
xdotool search --sync --name '^vimg-player$' >/dev/null
sleep 0.5
kill -TERM "$player_pid"
status=0
wait "$player_pid" || status=$?
cat "$work/term.log"
[ "$status" = 143 ] || { echo "vimg-player exited with $status on SIGTERM, not 143"; exit 1; }
grep -q "stopped by a signal" "$work/term.log" || { echo "no rest message on SIGTERM"; exit 1; }
size=$(stat -c %s "$work/term.wav")
riff=$(od -A n -t u4 -j 4 -N 4 "$work/term.wav" | tr -d ' ')
[ "$riff" = $((size - 8)) ] || { echo "WAV not completed after SIGTERM (RIFF size $riff, file $size)"; exit 1; }
echo "vimg-player under Xvfb: OK"
