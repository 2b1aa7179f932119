#!/usr/bin/env bash
# Builds the Debian package from a release build, installs it with apt, runs every program's
# --version, a render with a shipped profile by name from /usr/bin in an empty folder and the
# example consumer (examples/embed, find_package against /usr), then removes it and checks that
# nothing of it is left. Needs root (CI runs as root).
# usage: scripts/package_check.sh [BUILD_DIR]   (default build/release, already built)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
fail() { echo "package_check: FAIL: $*"; exit 1; }
rm -f "$build"/vibroimage_*.deb
(cd "$build" && cpack -G DEB >cpack.log) || { cat "$build/cpack.log"; fail "cpack"; }
deb=$(ls "$build"/vibroimage_*.deb)
echo "package_check: $(basename "$deb"), $(du -h "$deb" | cut -f1)"
dpkg-deb --field "$deb" Depends | grep -q 'libtinyxml2' || fail "Depends lacks the libraries (shlibdeps): $(dpkg-deb --field "$deb" Depends)"
contents=$(dpkg-deb --contents "$deb")
for path in ./usr/bin/vimg ./usr/bin/vimg-editor ./usr/share/man/man1/vimg.1.gz ./usr/lib/udev/rules.d/60-vibroimage.rules \
            ./usr/share/applications/vimg-editor.desktop ./usr/share/mime/packages/vibroimage.xml \
            ./usr/share/vibroimage/profiles/lra-175hz-drv2605l.xml; do
  grep -q " $path\(\$\| \)" <<<"$contents" || grep -q " $path$" <<<"$contents" || fail "the package lacks $path"
done

export DEBIAN_FRONTEND=noninteractive
apt-get install -y -qq "$(realpath "$deb")" >/dev/null || fail "apt-get install"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
source_dir=$PWD
cd "$work"
for program in vimg vimg-editor vimg-player vimg-force vimg-probe; do
  [ "$(command -v "$program")" = "/usr/bin/$program" ] || fail "$program is not in /usr/bin"
  "/usr/bin/$program" --version | grep -q "^$program " || fail "$program --version"
done
/usr/bin/vimg render /usr/share/vibroimage/examples/smiley.vimg --gesture /usr/share/vibroimage/gestures/smiley_eyes.csv \
  --actuator lra-175hz-drv2605l --out eyes.wav || fail "render from /usr/bin"
[ -s eyes.wav ] || fail "no render"
man -w vimg >/dev/null 2>&1 || [ -s /usr/share/man/man1/vimg.1.gz ] || fail "no man page"
# The example consumer, against the package in /usr (no prefix given).
cmake -S "$source_dir/examples/embed" -B embed -G Ninja -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >embed.log 2>&1 &&
  cmake --build embed >>embed.log 2>&1 || { cat embed.log; fail "examples/embed does not build against the package"; }
grep -q "vibroimage_DIR:PATH=/usr/lib/" embed/CMakeCache.txt || fail "examples/embed did not find the package in /usr"
read -r samples _ <<<"$(./embed/embed /usr/share/vibroimage/examples/smiley.vimg)"
[ "${samples:-0}" -gt 1000 ] || fail "examples/embed rendered $samples samples"
cd /
files=$(dpkg -L vibroimage | grep -v '^/\.$')
apt-get remove -y -qq vibroimage >/dev/null || fail "apt-get remove"
left=""
for f in $files; do
  [ -f "$f" ] && left+=" $f"
done
[ -z "$left" ] || fail "left after removal:$left"
[ ! -e /usr/share/vibroimage ] || fail "/usr/share/vibroimage is left after removal"
dpkg -s vibroimage >/dev/null 2>&1 && [ "$(dpkg-query -W -f='${Status}' vibroimage)" != "deinstall ok config-files" ] && fail "still installed"
echo "package_check: installed, ran from /usr/bin, removed without a trace"
