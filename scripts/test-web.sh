#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Tests the playground (docs/web.md) in a real browser: builds the site
# (scripts/build-web.sh) and the native litkit, installs the test's one npm
# package (puppeteer-core, pinned in tests/web/package-lock.json; it drives
# Debian's /usr/bin/chromium and downloads no browser), then runs
# tests/web/sliders.test.mjs (the sliders' text editing, in node) and
# tests/web/playground.test.mjs, which compares every picture of the page
# with `litkit render` of the same text. Ends with "web: N passed, M failed".
set -euo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
npm_log=$(mktemp)
npm_pid=""
# A failed build stops the script: the download must not outlive it.
trap '[ -z "$npm_pid" ] || kill "$npm_pid" 2>/dev/null || true; rm -f "$log" "$npm_log"' EXIT
# npm (it may come with them) first; then the npm package downloads while
# the site compiles: npm waits on the network, the compilers on the CPU.
./scripts/install-deps.sh --web
(cd tests/web && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error) \
  >"$npm_log" 2>&1 &
npm_pid=$!
./scripts/build-web.sh
if command -v ccache >/dev/null; then export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}; fi
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build -j"${JOBS:-2}" --target litkit_cli
npm_status=0
wait "$npm_pid" || npm_status=$?
npm_pid=""
cat "$npm_log"
if [ "$npm_status" -ne 0 ]; then
  echo "web: npm ci failed (exit $npm_status)" >&2
  exit "$npm_status"
fi
# Both tests run; the last line adds them up.
status=0
node tests/web/sliders.test.mjs build-web/site | tee -a "$log" || status=1
node tests/web/playground.test.mjs build-web/site build/litkit . "${SCREENSHOT:-build-web/playground.png}" \
  | tee -a "$log" || status=1
awk '/^[0-9]+ passed, [0-9]+ failed$/ { p += $1; f += $3; n += 1 }
     END { if (n < 2) f += 1; print "web: " p " passed, " f " failed" }' "$log"
exit $status
