#!/usr/bin/env bash
# Sets up (Debian packages), builds, and opens the editor on a bundled example:
#   bash scripts/run.sh [EDITOR OPTIONS...]     e.g. --output wav:out.wav, --zoom 2
# Without a display it says so and shows what the headless `vimg` command does instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset dev >/dev/null
cmake --build --preset dev --target vimg-editor vimg

example=assets/examples/smiley.vimg
if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  echo "run: opening the editor on $example (F5 switches to playing mode; see docs/editor.md)"
  exec build/dev/editor/vimg-editor "$example" "$@"
fi

vimg=build/dev/cli/vimg
cat <<MSG

run: there is no display (neither DISPLAY nor WAYLAND_DISPLAY is set), and the editor
     build/dev/editor/vimg-editor needs one (a desktop session, X forwarding, or Xvfb).
     The headless command build/dev/cli/vimg does the rest: info, validate, convert, render.
     Here it is on $example:

MSG
out=$(mktemp -d "${TMPDIR:-/tmp}/vimg-run.XXXXXX")
set -x
"$vimg" info "$example"
"$vimg" validate "$example"
"$vimg" convert "$example" "$out/smiley.png"
"$vimg" validate "$out/smiley.png"
"$vimg" render "$example" --gesture assets/gestures/smiley_eyes.csv --out "$out/smiley_eyes.wav"
set +x
echo
echo "run: wrote $out/smiley.png (the picture, with the image inside) and $out/smiley_eyes.wav"
echo "     (the drive a finger crossing the eyes produces; play it on an LRA or headphones)."
