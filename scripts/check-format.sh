#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The C++ sources follow .clang-format: fails (listing the files) where
# clang-format would change anything. With --fix, formats them in place.
# Templates and embedded text (*.in, *.inc) are left alone: they are written
# out as they are (the exported programs).
#
#   scripts/check-format.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run -Werror "${files[@]}"
fi
