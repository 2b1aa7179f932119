# Sourced by the GUI tests and benchmarks: a private Xvfb display.
#   start_xvfb FIRST LAST WxHxD LOG   starts Xvfb on the first free display number in FIRST..LAST
#                                     (callers use ranges of their own, so tests can run in
#                                     parallel), exports DISPLAY and XVFB_PID, and waits until it
#                                     answers; returns 1 with a message if it cannot.
#   stop_xvfb                         stops it (call it from the caller's EXIT trap).
# A number is free when it has no lock file, no socket file and no server answering on it (a
# server may listen on the abstract socket alone). The display counts as started only while the
# Xvfb started here is alive: one that exits at once (the number was taken after all) moves the
# search to the next number, so that the caller never talks to another server, or to none.
# Once started, a command that fails in the caller (set -e) first prints its line, whether this
# Xvfb still runs, and its log: what a failed GUI test needs to be understood.
start_xvfb() {
  local first=$1 last=$2 screen=$3 log=$4 n
  for n in $(seq "$first" "$last"); do
    [ ! -e "/tmp/.X$n-lock" ] && [ ! -e "/tmp/.X11-unix/X$n" ] || continue
    DISPLAY=":$n" xdotool getdisplaygeometry >/dev/null 2>&1 && continue
    Xvfb ":$n" -screen 0 "$screen" -nolisten tcp >"$log" 2>&1 &
    XVFB_PID=$!
    export DISPLAY=":$n" XVFB_PID
    local _
    for _ in $(seq 100); do
      kill -0 "$XVFB_PID" 2>/dev/null || break
      if xdotool getdisplaygeometry >/dev/null 2>&1; then
        if kill -0 "$XVFB_PID" 2>/dev/null; then
          XVFB_LOG=$log
          trap '_xvfb_on_error $LINENO' ERR
          return 0
        fi
        break
      fi
      sleep 0.1
    done
    if kill -0 "$XVFB_PID" 2>/dev/null; then
      echo "FAIL: Xvfb did not answer on :$n"
      cat "$log"
      return 1
    fi
    echo "start_xvfb: Xvfb exited on :$n, trying the next number: $(tr '\n' ' ' <"$log")"
    XVFB_PID=""
  done
  echo "FAIL: no free X display number in $first..$last"
  return 1
}

_xvfb_on_error() {
  local state=gone
  kill -0 "${XVFB_PID:-0}" 2>/dev/null && state=running
  echo "FAIL: a command failed at line $1 of $0 (Xvfb on $DISPLAY: $state); its log:"
  cat "$XVFB_LOG" 2>/dev/null || true
}

stop_xvfb() {
  if [ -n "${XVFB_PID:-}" ]; then
    kill "$XVFB_PID" 2>/dev/null || true
    wait "$XVFB_PID" 2>/dev/null || true
  fi
}
