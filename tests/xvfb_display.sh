# Sourced by the GUI tests and benchmarks: a private Xvfb display.
#   start_xvfb FIRST LAST WxHxD LOG   starts Xvfb on the first free display number in FIRST..LAST
#                                     (callers use ranges of their own, so tests can run in
#                                     parallel), exports DISPLAY and XVFB_PID, and waits until it
#                                     answers; returns 1 with a message if it cannot.
#   stop_xvfb                         stops it (call it from the caller's EXIT trap).
start_xvfb() {
  local first=$1 last=$2 screen=$3 log=$4 n display=""
  for n in $(seq "$first" "$last"); do
    if [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "/tmp/.X11-unix/X$n" ]; then display=$n; break; fi
  done
  [ -n "$display" ] || { echo "FAIL: no free X display number in $first..$last"; return 1; }
  Xvfb ":$display" -screen 0 "$screen" -nolisten tcp >"$log" 2>&1 &
  XVFB_PID=$!
  export DISPLAY=":$display" XVFB_PID
  for _ in $(seq 100); do
    xdotool getdisplaygeometry >/dev/null 2>&1 && return 0
    sleep 0.1
  done
  echo "FAIL: Xvfb did not start on :$display"
  cat "$log"
  return 1
}

stop_xvfb() {
  if [ -n "${XVFB_PID:-}" ]; then
    kill "$XVFB_PID" 2>/dev/null || true
    wait "$XVFB_PID" 2>/dev/null || true
  fi
}
