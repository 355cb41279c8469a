#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds litkit and runs every test (the C++ and Python suites through ctest,
# then the web playground's in headless Chromium). With --sanitize, builds a separate tree
# under AddressSanitizer and UBSan, with clang, and runs the suite there.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--sanitize" ]; then
  ./scripts/install-deps.sh --fuzz  # clang and its sanitizers' runtimes
else
  ./scripts/install-deps.sh
fi

jobs=$(nproc)
# LITKIT_WERROR=ON in the environment (.ci/run sets it) makes every compiler
# warning in litkit's own code an error in the Release tree, the README's
# build. Not in the sanitized tree: another compiler (clang) with other
# warnings, a tree that has not been checked free of them.
werror=()
[ -z "${LITKIT_WERROR:-}" ] || werror=("-DLITKIT_WERROR=$LITKIT_WERROR")
if [ "${1:-}" = "--sanitize" ]; then
  build=build-asan
  # -O1 -g1 (line tables only), not RelWithDebInfo's -O2 -g: half the
  # compile time of this tree (measured on tests/test_lighting.cpp and
  # src/scene/validate.cpp), and what ASan's own documentation suggests.
  # ASan and UBSan check the same at -O1 (if anything, -O2 removes more
  # accesses), and line tables are all that their reports' file:line needs.
  # clang, not GCC: the same tree in about 35% less compile time (measured
  # file by file with each tree's own flags: 62 s against 98 s for six of
  # them; docs/design.md, "CI time"), and a second compiler's view of the
  # code beside the Release tree's GCC. A tree an older version configured
  # with GCC is configured afresh (CMake keeps a cache's compiler).
  if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:FILEPATH=.*clang++' "$build/CMakeCache.txt"; then
    rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
  fi
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLITKIT_SANITIZE=ON \
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" > /dev/null
  cmake --build "$build" -j "$jobs"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # The install check links a plain consumer against the library, which an
  # instrumented build cannot serve; it runs in the normal build. So does
  # build.layers (25 s): it compiles probes to check src/'s includes and
  # runs nothing, so that the sanitizers have nothing to check in it.
  ctest --test-dir "$build" --output-on-failure -j "$jobs" -E '^(install\.|build\.layers$)'
else
  build=build
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${werror[@]}" > /dev/null
  cmake --build "$build" -j "$jobs"
  ctest --test-dir "$build" --output-on-failure -j "$jobs"
  # The playground page in headless Chromium against this build's litkit
  # (docs/web.md): builds the WebAssembly site first.
  ./scripts/test-web.sh
fi
