#!/usr/bin/env bash
# ctest's entry to the browser checks: says what is missing instead of failing obscurely.
# usage: run_browser_tests.sh VIMG SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
vimg=$1; source_dir=$2; art=$3
here=$(cd "$(dirname "$0")" && pwd)
command -v node >/dev/null || { echo "FAIL: node is missing (Node.js 18 or later)"; exit 1; }
[ -x "${VIMG_CHROMIUM:-/usr/bin/chromium}" ] || { echo "FAIL: Debian's chromium is missing (bash scripts/setup.sh)"; exit 1; }
[ -d "$here/node_modules/puppeteer-core" ] || { echo "FAIL: tests/browser/node_modules is missing (bash scripts/setup.sh runs npm ci)"; exit 1; }
exec node "$here/run_browser_tests.mjs" "$vimg" "$source_dir" "$art"
