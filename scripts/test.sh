#!/usr/bin/env bash
# Sets up, builds (Debug, warnings as errors) and runs the whole test suite through ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset dev >/dev/null
cmake --build --preset dev
ctest --preset dev --no-tests=error
