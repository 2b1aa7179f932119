#!/usr/bin/env bash
# The device's messages reach the real editor: it plays to a WAV file whose folder is removed while
# it plays, so the stop (F5) cannot write the file; the WAV output says so (hal
# Output::take_messages, as a DRV2605L or HID output says its faults) and the editor prints it on
# stderr as "vimg-editor: MESSAGE" and shows it in the status bar (screenshot stopped.png).
# usage: device_messages_gui_test.sh PATH/TO/vimg-editor ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
art=$2
here=$(cd "$(dirname "$0")" && pwd)

source "$here/gui_driver.sh"
gui_setup
export SDL_AUDIODRIVER=dummy

mkdir -p "$art/gone"
current=play
start play --play --output "wav:$art/gone/out.wav" --recovery-dir "$art/recovery"
rm -rf "$art/gone"
key F5
for _ in $(seq 100); do grep -q '^vimg-editor: .*out\.wav' "$art/play.log" && break; sleep 0.1; done
shot stopped
quit_editor
grep '^vimg-editor: .*out\.wav' "$art/play.log" || { echo "FAIL: the WAV output's message did not reach the editor"; cat "$art/play.log"; exit 1; }
echo "PASS"
