#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the litkit playground (docs/web.md) into build-web/site: the page,
# its scripts, the examples and litkit's library compiled to WebAssembly
# with Debian's emscripten. Serve that folder with any static file server:
#
#   scripts/build-web.sh && (cd build-web/site && python3 -m http.server 8000)
#
# It installs what it needs first (scripts/install-deps.sh --web).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --web
# Debian's emscripten runs its JavaScript tools (acorn) with node; a node
# that is not Debian's own does not look in Debian's module folder.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
if command -v ccache >/dev/null; then export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}; fi
if [ ! -f build-web/build.ninja ]; then
  emcmake cmake -S web -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build build-web -j"${JOBS:-2}"
echo "build-web: the site is in build-web/site (serve it: cd build-web/site && python3 -m http.server)"
