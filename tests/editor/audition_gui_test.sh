#!/usr/bin/env bash
# "Audition on a device" (Mode menu) in the real vimg-editor under Xvfb: it starts vimg serve's
# server for the open document and says where (stderr and the status bar); the page, the wasm and the
# compiled image are served there; a save from the editor (Ctrl+S) reaches an open /events stream;
# quitting the editor stops the server.
# usage: audition_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup
cp "$here/../../assets/examples/smiley.vimg" "$art/smiley.vimg"

current=audition
start audition "$art/smiley.vimg" --output none --recovery-dir "$art/recovery"
widget menu_mode
widget menu_audition
url=""
for _ in $(seq 300); do
  url=$(sed -n 's/^vimg-editor: audition: serving smiley.vimg at \(http:[^ ]*\)$/\1/p' "$art/audition.log" | tail -1)
  [ -n "$url" ] && break
  kill -0 "$editor_pid" 2>/dev/null || { cat "$art/audition.log"; echo "FAIL: the editor exited"; exit 1; }
  sleep 0.1
done
[ -n "$url" ] || { shot no-audition; cat "$art/audition.log"; echo "FAIL: the editor did not say where it serves"; exit 1; }
shot audition
echo "serving at $url"
port=${url##*:}; port=${port%/}
local_url="http://127.0.0.1:$port/"

# The site: the page, the wasm and the compiled image.
python3 - "$local_url" <<'PY'
import sys, urllib.request
base = sys.argv[1]
for path, kind in (("", "text/html"), ("vimg.wasm", "application/wasm"), ("images/smiley.vsc", "application/octet-stream")):
    with urllib.request.urlopen(base + path, timeout=60) as r:
        body = r.read()
        assert r.status == 200 and r.headers["Content-Type"].startswith(kind) and body, (path, r.status, r.headers["Content-Type"])
print("site served")
PY

# A save from the editor reaches an open event stream: the reader prints the event, then exits.
python3 - "$local_url" >"$art/events.txt" 2>&1 <<'PY' &
import sys, urllib.request
with urllib.request.urlopen(sys.argv[1] + "events", timeout=120) as r:
    print("open", flush=True)
    for raw in r:
        line = raw.decode().strip()
        if line == "data: smiley":
            print("event smiley", flush=True)
            break
PY
reader=$!
for _ in $(seq 300); do grep -q '^open' "$art/events.txt" && break; sleep 0.1; done
grep -q '^open' "$art/events.txt" || { cat "$art/events.txt"; echo "FAIL: /events did not open"; exit 1; }
click_mm 35 70   # select the face
key Delete       # a change, so that Ctrl+S writes the file
key ctrl+s
wait "$reader" || { cat "$art/events.txt"; echo "FAIL: the event reader failed"; exit 1; }
grep -q '^event smiley' "$art/events.txt" || { cat "$art/events.txt"; echo "FAIL: the save did not reach /events"; exit 1; }
grep -q 'id="face"' "$art/smiley.vimg" && { echo "FAIL: the editor did not save the change"; exit 1; }

quit_editor
if python3 -c "import sys, urllib.request; urllib.request.urlopen(sys.argv[1], timeout=10)" "$local_url" 2>/dev/null; then
  echo "FAIL: the server still answers after the editor quit"; exit 1
fi
echo "PASS: the audition served the document, pushed its save and stopped with the editor"
