#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, the prefix moved elsewhere, and from an empty folder:
# every program answers --version; `vimg render` with a shipped profile BY NAME gives the same
# samples as the build tree's program given the profile's path; an unknown name is refused with
# the shipped names listed; every program has its man page, the editor its desktop entry, MIME type
# and icon, and the udev rules are in lib/udev/rules.d. Then the installed editor, under Xvfb, lists
# the shipped examples in its library and the shipped profiles in its actuator list.
# usage: install_relocation_test.sh BUILD_DIR SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
build=$(realpath "$1")
source_dir=$(realpath "$2")
art=$3
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$art"; mkdir -p "$art"; art=$(realpath "$art")
root=$art
cmake --install "$build" --prefix "$art/first" >"$art/install.log" || { cat "$art/install.log"; fail "cmake --install"; }
mv "$art/first" "$art/moved"
prefix="$art/moved"
mkdir -p "$art/empty"; cd "$art/empty"
unset VIBROIMAGE_DATA_DIR

for program in vimg vimg-force vimg-editor vimg-player vimg-probe; do
  [ -x "$prefix/bin/$program" ] || fail "$program is not installed"
  "$prefix/bin/$program" --version | grep -q "^$program " || fail "$program --version"
  [ -s "$prefix/share/man/man1/$program.1.gz" ] || fail "no man page for $program"
  zcat "$prefix/share/man/man1/$program.1.gz" | grep -q "^\.TH ${program^^} " || fail "$program.1.gz is not a man page"
  zcat "$prefix/share/man/man1/$program.1.gz" | grep -q 'print the version and exit' || fail "$program.1.gz lacks the options"
done
[ -s "$prefix/share/applications/vimg-editor.desktop" ] || fail "no desktop entry"
grep -q '^MimeType=application/x-vibroimage;' "$prefix/share/applications/vimg-editor.desktop" || fail "desktop entry without the MIME type"
grep -q 'glob pattern="\*.vimg"' "$prefix/share/mime/packages/vibroimage.xml" || fail "no .vimg MIME type"
[ -s "$prefix/share/icons/hicolor/scalable/apps/vibroimage.svg" ] || fail "no icon"
grep -q 'SUBSYSTEM=="i2c-dev"' "$prefix/lib/udev/rules.d/60-vibroimage.rules" || fail "no udev rules"
[ -s "$prefix/share/doc/vibroimage/hardware.md" ] || fail "no docs"
if command -v desktop-file-validate >/dev/null; then desktop-file-validate "$prefix/share/applications/vimg-editor.desktop"; fi

# A shipped profile by name, from an empty folder, equals the build tree's program given the path.
data="$prefix/share/vibroimage"
"$prefix/bin/vimg" render "$data/examples/smiley.vimg" --gesture "$data/gestures/smiley_eyes.csv" \
  --actuator lra-175hz-drv2605l --out by_name.csv || fail "render with a shipped profile by name"
"$build/cli/vimg" render "$source_dir/assets/examples/smiley.vimg" --gesture "$source_dir/assets/gestures/smiley_eyes.csv" \
  --actuator "$source_dir/assets/profiles/lra-175hz-drv2605l.xml" --out by_path.csv
cmp -s by_name.csv by_path.csv || fail "the profile by name renders differently from the profile by path"
[ "$(wc -l <by_name.csv)" -gt 100 ] || fail "the render is empty"

set +e
"$prefix/bin/vimg" render "$data/examples/smiley.vimg" --gesture "$data/gestures/smiley_eyes.csv" \
  --actuator no-such-profile --out never.csv 2>unknown.err
code=$?
set -e
[ "$code" = 1 ] || fail "an unknown profile name exits $code, not 1"
grep -q "not a shipped profile either (shipped: .*lra-175hz-drv2605l" unknown.err || { cat unknown.err; fail "the shipped names are not listed"; }
[ ! -e never.csv ] || fail "an output was written for an unknown profile"

# The web player, when the web preset was built: installed with the data, and `vimg web` from the
# moved prefix writes a site with it.
if [ -f "$build/share/vibroimage/web/vimg.wasm" ]; then
  [ -f "$data/web/vimg.wasm" ] && [ -f "$data/web/index.html" ] || fail "the web player is not installed"
  "$prefix/bin/vimg" web "$data/examples/smiley.vimg" --out site >web.log 2>&1 || { cat web.log; fail "vimg web from the moved prefix"; }
  cmp -s site/vimg.wasm "$data/web/vimg.wasm" || fail "the site's vimg.wasm is not the installed one"
  [ -s site/images/smiley.vsc ] || fail "the site lacks the compiled smiley"
fi

# The installed editor, from the empty folder, lists the shipped examples and profiles.
editor="$prefix/bin/vimg-editor"
source "$source_dir/tests/editor/gui_driver.sh"
art="$root/gui"  # gui_setup empties its folder
gui_setup
cd "$root/empty"
current=installed
start installed "$data/examples/smiley.vimg" --actuator lra-175hz-drv2605l --output none --recovery-dir "$root/recovery"
for _ in $(seq 100); do grep -q '^layout library_examples/smiley.vimg ' "$art/installed.layout" && break; sleep 0.1; done
grep -q '^layout library_examples/smiley.vimg ' "$art/installed.layout" || { shot no-examples; fail "the library does not list the shipped examples"; }
grep -q ": error" "$art/installed.log" && { cat "$art/installed.log"; fail "the editor reported an error"; }
widget actuator_combo
for _ in $(seq 100); do grep -q '^layout actuator_item_lra-175hz-drv2605l ' "$art/installed.layout" && break; sleep 0.1; done
shot profiles
for profile in "$data"/profiles/*.xml; do
  name=$(basename "$profile" .xml)
  grep -q "^layout actuator_item_$name " "$art/installed.layout" || fail "the actuator list lacks the shipped profile $name"
done
widget actuator_item_lra-175hz-drv2605l  # choosing closes the list
quit_editor
echo "PASS: the moved install runs with its shipped data"
