#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite through ctest. The suite runs on the Release build
# (warnings as errors, benchmarks built too), so a test that depends on the build being slow fails
# here; the Debug build's assertions run under the sanitizers (.ci/run's asan preset keeps them on).
# VIMG_TEST_PRESET=dev runs the same suite on the Debug build.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${VIMG_TEST_PRESET:-release}"
bash scripts/setup.sh
# The web player first (Emscripten): the suite's web tests compare it with the native renderer
# and drive it in Chromium.
cmake --preset web >/dev/null
cmake --build --preset web
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
ctest --preset "$preset" --no-tests=error
