#!/usr/bin/env bash
# Installs what vibroimage needs to build, test and run, from Debian packages. Idempotent:
# it installs only what is missing, so a second run needs no network.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config git
  libsdl2-dev libtinyxml2-dev libpng-dev zlib1g-dev libhidapi-dev libgpiod-dev libimgui-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev
  libteem-dev libcairo2-dev libsdl2-ttf-dev fonts-dejavu-core
  clang libclang-rt-14-dev
  xvfb xdotool imagemagick xauth python3 libxtst-dev strace
  locales
  libboost-math-dev python3-numpy python3-scipy
  help2man desktop-file-utils dpkg-dev file
  emscripten chromium libboost-dev libqrencode-dev libssl-dev openssl
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
  echo "setup: done"
fi

# The browser tests' driver (puppeteer-core, pinned in tests/browser/package-lock.json; it never
# downloads a browser: the tests use Debian's chromium). Node.js and npm come with the machine.
browser_tests="$(dirname "$0")/../tests/browser"
if ! command -v npm >/dev/null; then
  echo "setup: npm is missing: the browser tests need Node.js 18 or later with npm" >&2
  exit 1
fi
if [ ! -f "$browser_tests/node_modules/.package-lock.json" ] ||
   [ "$browser_tests/package-lock.json" -nt "$browser_tests/node_modules/.package-lock.json" ]; then
  echo "setup: npm ci in tests/browser"
  npm ci --prefix "$browser_tests" --no-audit --no-fund --loglevel=error
fi
