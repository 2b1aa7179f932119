#!/usr/bin/env bash
# Sets up, builds, and runs the main job. Until the editor lands it shows what the headless
# `vimg` command can do.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset dev >/dev/null
cmake --build --preset dev
echo
echo "run: built build/dev/cli/vimg; its commands:"
build/dev/cli/vimg --help
