#!/usr/bin/env bash
# ctest's entry to the study checks in the browser: says what is missing instead of failing obscurely.
# usage: run_study_tests.sh VIMG VIMG_PLAYER|none SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
command -v node >/dev/null || { echo "FAIL: node is missing (Node.js 18 or later)"; exit 1; }
[ -x "${VIMG_CHROMIUM:-/usr/bin/chromium}" ] || { echo "FAIL: Debian's chromium is missing (bash scripts/setup.sh)"; exit 1; }
[ -d "$here/node_modules/puppeteer-core" ] || { echo "FAIL: tests/browser/node_modules is missing (bash scripts/setup.sh runs npm ci)"; exit 1; }
exec node "$here/run_study_tests.mjs" "$@"
