#!/usr/bin/env bash
# The library others embed, as they would use it: `cmake --install` of the development component
# (what a -dev package ships: the libraries, the headers, the CMake package) into a temporary
# prefix, then examples/embed (a program of a few dozen lines) configured with
# find_package(vibroimage CONFIG) against that prefix only, built, and run on the smiley example.
# Its swipe must give, sample for sample, the samples `vimg render` gives for the same swipe. The
# installed headers must be exactly the documented entry headers and the project headers they
# include (docs/embedding.md), each compiling on its own against the prefix. The version file must
# be SameMinorVersion's (docs/embedding.md): 0.1 and 0.1.0 accepted, 0.0 refused (AnyNewerVersion and
# SameMajorVersion would accept it), 0.2 and 1.0 refused.
# usage: embed_test.sh BUILD_DIR SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
build=$(realpath "$1")
source_dir=$(realpath "$2")
art=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$art"; mkdir -p "$art"; art=$(realpath "$art")
cmake --install "$build" --component development --prefix "$art/prefix" >"$art/install.log" || { cat "$art/install.log"; fail "cmake --install"; }
[ -f "$art/prefix/include/vibroimage/player/offline_render.hpp" ] || fail "the renderer's header is not installed"
[ ! -e "$art/prefix/include/vibroimage/editor" ] || fail "the editor's private headers are installed"
if grep -rq "$source_dir\|$build" "$art/prefix/lib/cmake/vibroimage"; then fail "the package files name the build machine's folders"; fi

# The installed headers: the entry headers docs/embedding.md lists and, transitively, every project
# header ("dir/file.hpp") they include; nothing else, and each compiles alone against the prefix.
inc="$art/prefix/include/vibroimage"
entries="primitives/image.hpp primitives/shader.hpp primitives/shader_state.hpp primitives/touch/dot_shader.hpp
  primitives/touch/line_shader.hpp primitives/touch/surface_shader.hpp primitives/actuator/actuator_model.hpp
  primitives/gesture.hpp storage/gesture_csv.hpp
  storage/image_io.hpp storage/diagnostic.hpp player/scene.hpp player/offline_render.hpp
  player/drive_sink.hpp player/drive_sinks.hpp"
declare -A closure=()
todo=($entries)
while [ ${#todo[@]} -gt 0 ]; do
  h=${todo[0]}; todo=("${todo[@]:1}")
  [ -n "${closure[$h]:-}" ] && continue
  closure[$h]=1
  [ -f "$source_dir/$h" ] || fail "$h is documented but not in the sources"
  while read -r included; do todo+=("$included"); done < <(sed -n 's|^#include "\([a-z_]*/[^"]*\)".*|\1|p' "$source_dir/$h")
done
installed=$(cd "$inc" && find . -type f | sed 's|^\./||' | sort)
expected=$(printf '%s\n' "${!closure[@]}" | sort)
[ "$installed" = "$expected" ] || { diff <(echo "$expected") <(echo "$installed") || true; fail "the installed headers are not the documented closure"; }
for h in $installed; do
  cmp -s "$inc/$h" "$source_dir/$h" || fail "$h is installed changed"
  echo "#include \"$h\"" | c++ -std=c++20 -fsyntax-only -Wall -Werror -I "$inc" -x c++ - 2>"$art/header.log" ||
    { cat "$art/header.log"; fail "$h does not compile on its own against the prefix"; }
done
echo "headers: $(echo "$installed" | wc -l) installed, the documented closure, each compiling alone"

# Built against the installed prefix only: the package registry is off, the build tree unknown.
cmake -S "$source_dir/examples/embed" -B "$art/embed" -G Ninja -DCMAKE_PREFIX_PATH="$art/prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$art/configure.log" 2>&1 || { cat "$art/configure.log"; fail "configure"; }
grep -q "vibroimage_DIR:PATH=$art/prefix/" "$art/embed/CMakeCache.txt" || fail "find_package did not use the installed prefix"
cmake --build "$art/embed" >"$art/build.log" 2>&1 || { cat "$art/build.log"; fail "build"; }
read -r count rms peak <<<"$("$art/embed/embed" "$source_dir/assets/examples/smiley.vimg" "$art/embed_samples.txt")"

# The same swipe through vimg render: 101 points across the middle of the 70 x 140 mm canvas in 1 s.
awk 'BEGIN { print "time_s,finger,x_mm,y_mm,pressure,phase";
  for (i = 0; i <= 100; i++) { t = i / 100; printf "%.17g,0,%.17g,70,1,%s\n", t, t * 70, i == 0 ? "down" : (i == 100 ? "up" : "move") } }' >"$art/swipe.csv"
"$build/cli/vimg" render "$source_dir/assets/examples/smiley.vimg" --gesture "$art/swipe.csv" --out "$art/swipe_out.csv"
# Both print each float sample in its shortest round-trip form: the same samples are the same text.
tail -n +2 "$art/swipe_out.csv" | cut -d, -f2 >"$art/render_samples.txt"
ref_count=$(wc -l <"$art/render_samples.txt")
echo "embed: $count samples, RMS $rms, peak $peak; vimg render: $ref_count samples"
[ "$count" = "$ref_count" ] || fail "sample count $count, vimg render gives $ref_count"
[ "$(wc -l <"$art/embed_samples.txt")" = "$count" ] || fail "embed wrote a sample count other than it printed"
cmp "$art/embed_samples.txt" "$art/render_samples.txt" || fail "the embedded render differs from vimg render"
awk '{ if ($1 > 0.01 || $1 < -0.01) loud++ } END { exit !(loud > 100) }' "$art/render_samples.txt" || fail "the swipe is silent"

# The version file: 0.1.0 is installed, SameMinorVersion.
version_request() {  # version_request VERSION: 0 when find_package accepts it
  local dir="$art/version_$1"
  mkdir -p "$dir"
  printf 'cmake_minimum_required(VERSION 3.25)\nproject(t LANGUAGES CXX)\nfind_package(vibroimage %s CONFIG REQUIRED)\n' "$1" >"$dir/CMakeLists.txt"
  cmake -S "$dir" -B "$dir/build" -DCMAKE_PREFIX_PATH="$art/prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$dir.log" 2>&1
}
for v in 0.1 0.1.0; do version_request "$v" || { cat "$art/version_$v.log"; fail "find_package(vibroimage $v) was refused"; }; done
for v in 0.0 0.2 1.0 9.0; do
  if version_request "$v"; then fail "find_package(vibroimage $v) was accepted"; fi
  grep -q "not compatible\|version" "$art/version_$v.log" || { cat "$art/version_$v.log"; fail "no version message for $v"; }
done
echo "version: 0.1 and 0.1.0 accepted; 0.0, 0.2, 1.0 and 9.0 refused"
echo "PASS: the example consumer builds and renders against the installed package"
