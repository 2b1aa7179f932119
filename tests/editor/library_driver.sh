# Sourced by the editor's Xvfb tests that choose images in the library panel (after gui_driver.sh;
# the caller sets `art` and `current`):
#   scroll_to NAME          wheels the library list until the entry is inside it
#   selection_is N          the editor's last printed selection count is N
#   pick NAME COUNT [ctrl]  clicks the entry (Ctrl held: adds to the selection), waits for COUNT
#   wait_result             waits for the Predicted confusion window's matrix (or its failure)
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

