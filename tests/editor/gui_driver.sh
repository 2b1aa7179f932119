# Sourced by the editor's Xvfb tests: drive the real vimg-editor with xdotool.
# The caller sets `art` (artifact folder), `current` (the run's name) before using these, and
# calls `cleanup` from its EXIT trap. The editor prints its layout (--print-layout) and the
# functions turn millimetres on the page into screen pixels from it.
#   gui_setup               check the tools, a fresh $art with its own HOME, Xvfb on a display
#                           of its own (tests/xvfb_display.sh; stopped on exit)
#   start NAME ARGS...      launch the editor (--print-layout --zoom 2 ARGS), wait for the canvas
#   move_mm/click_mm X Y    move to / click at a page point; drag_mm X0 Y0 X1 Y1
#   key KEYS...             xdotool key; widget NAME clicks a printed widget in its middle;
#                           click_layout NAME [CLICKS] [X] clicks it CLICKS times, X px from its left
#   save_as FILE            Ctrl+Shift+S, type FILE, Enter, wait until FILE exists
#   shot NAME               screenshot into $art/NAME.png; quit_editor: Ctrl+Q and wait
editor_pid=""
gui_setup() {
  local tool
  for tool in Xvfb xdotool import python3; do
    command -v "$tool" >/dev/null || { echo "FAIL: $tool is missing (bash scripts/setup.sh installs it)"; exit 1; }
  done
  rm -rf "$art"
  mkdir -p "$art/home"
  art=$(realpath "$art")
  export HOME="$art/home" XDG_CONFIG_HOME="$art/home/.config" XDG_STATE_HOME="$art/home/.state"
  source "$(dirname "${BASH_SOURCE[0]}")/../xvfb_display.sh"
  trap cleanup EXIT
  start_xvfb 1400x900x24 "$art/xvfb.log"
}
cleanup() {
  if [ -n "$editor_pid" ]; then kill -9 "$editor_pid" 2>/dev/null || true; fi
  stop_xvfb
}

WX=0 WY=0 OX=0 OY=0 PPM=1
# start NAME ARGS...: launches the editor, waits for its window and its canvas layout.
start() {
  local name=$1
  shift
  "$editor" --print-layout --zoom 2 "$@" >"$art/$name.layout" 2>"$art/$name.log" &
  editor_pid=$!
  prompts=0
  # Generous: on a loaded CI machine a debug build can take many seconds to show its first frame.
  for _ in $(seq 600); do
    grep -q '^layout window' "$art/$name.layout" && grep -q '^layout page_origin' "$art/$name.layout" && break
    kill -0 "$editor_pid" 2>/dev/null || { echo "FAIL: the editor exited"; cat "$art/$name.log"; exit 1; }
    sleep 0.1
  done
  grep -q '^layout page_origin' "$art/$name.layout" || { echo "FAIL: the editor shows no canvas"; exit 1; }
  WX=$(grep '^layout window' "$art/$name.layout" | tail -1 | awk '{print $3}')
  WY=$(grep '^layout window' "$art/$name.layout" | tail -1 | awk '{print $4}')
  local line
  line=$(grep '^layout page_origin' "$art/$name.layout" | tail -1)
  PPM=$(echo "$line" | sed 's/.*ppm\([0-9.]*\) .*/\1/')
  OX=$(echo "$line" | awk '{print $3}')
  OY=$(echo "$line" | awk '{print $4}')
  sleep 0.5
}
px() { awk -v w="$WX" -v o="$OX" -v p="$PPM" -v m="$1" 'BEGIN { printf "%d", w + o + m * p + 0.5 }'; }
py() { awk -v w="$WY" -v o="$OY" -v p="$PPM" -v m="$1" 'BEGIN { printf "%d", w + o + m * p + 0.5 }'; }
move_mm() { xdotool mousemove "$(px "$1")" "$(py "$2")"; }
click_mm() { move_mm "$1" "$2"; sleep 0.15; xdotool click 1; sleep 0.2; }
drag_mm() {
  move_mm "$1" "$2"; sleep 0.15
  xdotool mousedown 1; sleep 0.15
  move_mm "$(awk -v a="$1" -v b="$3" 'BEGIN{print (a+b)/2}')" "$(awk -v a="$2" -v b="$4" 'BEGIN{print (a+b)/2}')"; sleep 0.1
  move_mm "$3" "$4"; sleep 0.15
  xdotool mouseup 1; sleep 0.2
}
key() { xdotool key "$@"; sleep 0.25; }
# widget NAME: clicks a widget whose layout the editor printed.
click_layout() {
  local line="" clicks=${2:-1} x y w h
  for _ in $(seq 200); do
    line=$(grep "^layout $1 " "$art/$current.layout" | tail -1 || true)
    [ -n "$line" ] && break
    sleep 0.1
  done
  [ -n "$line" ] || { echo "FAIL: widget $1 not shown"; shot "no-$1"; exit 1; }
  read -r _ _ x y w h <<<"$line"
  xdotool mousemove $((WX + x + ${3:-$((w / 2))})) $((WY + y + h / 2)); sleep 0.15
  xdotool click --repeat "$clicks" --delay 60 1; sleep 0.3
}
widget() { click_layout "$1"; }
prompts=0
save_as() {
  prompts=$((prompts + 1))
  key ctrl+shift+s
  for _ in $(seq 300); do grep -q "^layout file_prompt$prompts " "$art/$current.layout" && break; sleep 0.1; done
  grep -q "^layout file_prompt$prompts " "$art/$current.layout" || { echo "FAIL: no file prompt"; shot no-prompt; exit 1; }
  key ctrl+a
  xdotool type --delay 20 "$1"; sleep 0.2
  key Return
  for _ in $(seq 200); do [ -s "$1" ] && return 0; sleep 0.1; done
  echo "FAIL: $1 was not saved"; cat "$art/$current.log"; exit 1
}
shot() { import -window root "$art/$1.png"; }
quit_editor() {
  key ctrl+q
  for _ in $(seq 100); do kill -0 "$editor_pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$editor_pid" 2>/dev/null; then echo "FAIL: the editor did not quit"; shot "$current-not-quitting"; exit 1; fi
  wait "$editor_pid" || { echo "FAIL: the editor exited with $?"; cat "$art/$current.log"; exit 1; }
  editor_pid=""
}
