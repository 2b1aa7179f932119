#!/usr/bin/env bash
# Drives the real vimg-editor under Xvfb: the four confused textures of assets/examples/separate
# are compared in the library on the LRA, "Propose changes" shows what to change (vimg separate's
# engine), an image with changes is opened from the proposal, one change is applied (one undo
# step: Ctrl+Z gives the file back exactly), then every change of that image at once (again one
# undo step), and a change is auditioned: playing mode plays it (the WAV is driven) while the
# document stays as it was. The screenshots stay in ARTIFACT_DIR.
# usage: proposal_gui_test.sh PATH/TO/vimg-editor PATH/TO/vimg ARTIFACT_DIR
set -euo pipefail
editor=$(realpath "$1")
vimg=$(realpath "$2")
art=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gui_driver.sh"
gui_setup
source "$here/library_driver.sh"
check() { python3 "$here/gui_check.py" "$@"; }
examples="$here/../../assets/examples/separate"
lra="$here/../../assets/profiles/lra-175hz-drv2605l.xml"
mkdir -p "$art/lib" "$art/canonical"
for f in texture_2_0mm texture_2_2mm texture_2_4mm texture_2_6mm; do
  cp "$examples/$f.vimg" "$art/lib/$f.vimg"
  "$vimg" convert "$examples/$f.vimg" "$art/canonical/$f.vimg"  # as the editor saves it
done

# wait_layout NAME SECONDS: until the editor printed the widget NAME.
wait_layout() {
  for _ in $(seq "$(($2 * 10))"); do
    grep -q "^layout $1 " "$art/$current.layout" && return 0
    sleep 0.1
  done
  echo "FAIL: $1 not shown within $2 s"; shot "$current-no-$1"; cat "$art/$current.log"; exit 1
}
# save_and_wait FILE: Ctrl+S, then until FILE is newer than the marker.
save_and_wait() {
  touch -d '1 second ago' "$art/marker"
  key ctrl+s
  for _ in $(seq 100); do [ "$1" -nt "$art/marker" ] && return 0; sleep 0.1; done
  echo "FAIL: $1 was not saved"; cat "$art/$current.log"; exit 1
}

current=proposal
start proposal --library-dir "$art/lib" --actuator "$lra" --output "wav:$art/audition.wav" --recovery-dir "$art/recovery"
pick texture_2_0mm.vimg 1
pick texture_2_2mm.vimg 2 ctrl
pick texture_2_4mm.vimg 3 ctrl
pick texture_2_6mm.vimg 4 ctrl
widget compare_button
wait_result
grep -q '^layout compare_warning0 ' "$art/proposal.layout" || { echo "FAIL: the set should be predicted confused"; exit 1; }
widget propose_button
# The search renders every variant under the standard exploration: seconds in a release build.
for _ in $(seq 3000); do
  grep -q '^layout proposal_ready \|^layout proposal_failed \|^layout proposal_none ' "$art/proposal.layout" && break
  sleep 0.1
done
shot proposed
grep -q '^layout proposal_ready ' "$art/proposal.layout" || { echo "FAIL: no proposal"; cat "$art/proposal.log"; exit 1; }
grep -q '^layout proposal_matrices ' "$art/proposal.layout" || { echo "FAIL: no before/after matrices"; exit 1; }

# The first image with changes: open it from the proposal.
index=$(grep -o '^layout proposal_image[0-9]*_open ' "$art/proposal.layout" | head -1 | sed 's/.*proposal_image\([0-9]*\)_open /\1/')
[ -n "$index" ] || { echo "FAIL: no image has a change"; exit 1; }
widget "proposal_image${index}_open"
wait_layout "proposal_image${index}_apply_all" 30
file=$(grep -o "^layout proposal_image${index}_is_[^ ]*" "$art/proposal.layout" | tail -1 | sed 's/.*_is_//; s/\.vimg$//')
[ -n "$file" ] || { echo "FAIL: the proposal does not name image $index"; exit 1; }
echo "opened $file (image $index of the proposal)"
shot opened

# One change applied: the file differs; one Ctrl+Z gives it back exactly.
widget "proposal_image${index}_change0_apply"
save_and_wait "$art/lib/$file.vimg"
if cmp -s "$art/lib/$file.vimg" "$art/canonical/$file.vimg"; then echo "FAIL: Apply changed nothing"; exit 1; fi
cp "$art/lib/$file.vimg" "$art/one_change.vimg"
shot applied
key ctrl+z
save_and_wait "$art/lib/$file.vimg"
check same "$art/lib/$file.vimg" "$art/canonical/$file.vimg"
echo "one change: one undo step"

# Every change at once: one undo step too.
widget "proposal_image${index}_apply_all"
save_and_wait "$art/lib/$file.vimg"
if cmp -s "$art/lib/$file.vimg" "$art/canonical/$file.vimg"; then echo "FAIL: Apply all changed nothing"; exit 1; fi
key ctrl+z
save_and_wait "$art/lib/$file.vimg"
check same "$art/lib/$file.vimg" "$art/canonical/$file.vimg"
echo "every change: one undo step"

# Audition: playing mode plays the change; the document stays as it was.
widget "proposal_image${index}_change0_audition"
wait_layout audition_on 30
drag_mm 12 30 48 80
drag_mm 48 30 12 80
shot auditioning
widget proposal_stop_audition
save_and_wait "$art/lib/$file.vimg"
check same "$art/lib/$file.vimg" "$art/canonical/$file.vimg"
quit_editor
[ -s "$art/audition.wav" ] || { echo "FAIL: no WAV written"; cat "$art/proposal.log"; exit 1; }
check driven "$art/audition.wav"
echo "PASS"
