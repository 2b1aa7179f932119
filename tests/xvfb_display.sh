# Sourced by the GUI tests and benchmarks: a private Xvfb display.
#   start_xvfb WxHxD LOG   starts Xvfb on a display number it chooses itself (-displayfd: the server
#                          takes the first number whose lock it can create and whose sockets it can
#                          open, atomically, so tests running in parallel never share one, nor meet
#                          another server), exports DISPLAY and XVFB_PID once it accepts
#                          connections; returns 1 with a message and its log if it cannot.
#   stop_xvfb              stops it (call it from the caller's EXIT trap).
# Once started, a command that fails in the caller (set -e) first prints its line, whether this
# Xvfb still runs, and its log: what a failed GUI test needs to be understood.
start_xvfb() {
  local screen=$1 log=$2 number_file number="" _
  number_file=$(mktemp)
  Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp 3>"$number_file" >"$log" 2>&1 &
  XVFB_PID=$!
  # Xvfb writes the number when it is ready to accept connections: wait for that (a loaded machine
  # may take seconds; 60 s is the bound of a server that never comes up).
  for _ in $(seq 600); do
    number=$(head -n 1 "$number_file")
    [[ "$number" =~ ^[0-9]+$ ]] && break
    number=""
    kill -0 "$XVFB_PID" 2>/dev/null || break
    sleep 0.1
  done
  rm -f "$number_file"
  if [ -z "$number" ]; then
    echo "FAIL: Xvfb did not start"
    cat "$log"
    return 1
  fi
  export DISPLAY=":$number" XVFB_PID
  XVFB_LOG=$log
  trap '_xvfb_on_error $LINENO' ERR
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
