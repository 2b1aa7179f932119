#!/usr/bin/env bash
# The library others embed, as they would use it: `cmake --install` into a temporary prefix, then
# examples/embed (a program of a few dozen lines) configured with find_package(vibroimage CONFIG)
# against that prefix only, built, and run on the smiley example. Its swipe must give the samples
# `vimg render` gives for the same swipe (count, RMS and peak within 1e-5 of full scale). A request
# for a version the package is not compatible with must fail at find_package.
# usage: embed_test.sh BUILD_DIR SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
build=$(realpath "$1")
source_dir=$(realpath "$2")
art=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$art"; mkdir -p "$art"; art=$(realpath "$art")
cmake --install "$build" --prefix "$art/prefix" >"$art/install.log" || { cat "$art/install.log"; fail "cmake --install"; }
[ -f "$art/prefix/include/vibroimage/player/offline_render.hpp" ] || fail "the renderer's header is not installed"
[ ! -e "$art/prefix/include/vibroimage/editor" ] || fail "the editor's private headers are installed"
if grep -rq "$source_dir\|$build" "$art/prefix/lib/cmake/vibroimage"; then fail "the package files name the build machine's folders"; fi

# Built against the installed prefix only: the package registry is off, the build tree unknown.
cmake -S "$source_dir/examples/embed" -B "$art/embed" -G Ninja -DCMAKE_PREFIX_PATH="$art/prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$art/configure.log" 2>&1 || { cat "$art/configure.log"; fail "configure"; }
grep -q "vibroimage_DIR:PATH=$art/prefix/" "$art/embed/CMakeCache.txt" || fail "find_package did not use the installed prefix"
cmake --build "$art/embed" >"$art/build.log" 2>&1 || { cat "$art/build.log"; fail "build"; }
read -r count rms peak <<<"$("$art/embed/embed" "$source_dir/assets/examples/smiley.vimg")"

# The same swipe through vimg render: 101 points across the middle of the 70 x 140 mm canvas in 1 s.
awk 'BEGIN { print "time_s,finger,x_mm,y_mm,pressure,phase";
  for (i = 0; i <= 100; i++) { t = i / 100; printf "%.17g,0,%.17g,70,1,%s\n", t, t * 70, i == 0 ? "down" : (i == 100 ? "up" : "move") } }' >"$art/swipe.csv"
"$build/cli/vimg" render "$source_dir/assets/examples/smiley.vimg" --gesture "$art/swipe.csv" --out "$art/swipe_out.csv"
read -r ref_count ref_rms ref_peak <<<"$(awk -F, 'NR > 1 { n++; s += $2 * $2; a = $2 < 0 ? -$2 : $2; if (a > p) p = a }
  END { printf "%d %.9f %.9f\n", n, sqrt(s / n), p }' "$art/swipe_out.csv")"
echo "embed: $count $rms $peak; vimg render: $ref_count $ref_rms $ref_peak"
[ "$count" = "$ref_count" ] || fail "sample count $count, vimg render gives $ref_count"
awk -v a="$rms" -v b="$ref_rms" -v c="$peak" -v d="$ref_peak" 'BEGIN { exit !((a - b) ^ 2 < 1e-10 && (c - d) ^ 2 < 1e-10 && b > 0.01) }' ||
  fail "the embedded render differs from vimg render"

# The version file: 0.1 is what is installed; asking for 9.0 must fail.
mkdir -p "$art/too_new"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(t LANGUAGES CXX)\nfind_package(vibroimage 9.0 CONFIG REQUIRED)\n' >"$art/too_new/CMakeLists.txt"
if cmake -S "$art/too_new" -B "$art/too_new/build" -DCMAKE_PREFIX_PATH="$art/prefix" >"$art/too_new.log" 2>&1; then
  fail "find_package(vibroimage 9.0) was accepted"
fi
grep -q "not compatible\|version" "$art/too_new.log" || { cat "$art/too_new.log"; fail "no version message"; }
echo "PASS: the example consumer builds and renders against the installed package"
