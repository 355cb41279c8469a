#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The playground's render time in headless Chromium (docs/performance.md):
#   bench/web.sh [RUNS]
# Builds the site and the test's npm package first, as scripts/test-web.sh does.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build-web.sh >/dev/null
(cd tests/web && npm ci --no-audit --no-fund --loglevel=error)
uptime
node bench/web.mjs build-web/site "${1:-40}"
