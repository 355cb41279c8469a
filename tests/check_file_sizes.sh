#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Files under src/ and apps/ stay under 600 lines, unless src/README.md names
# the file, with its reason, in its section "Files above 600 lines" as a
# line of the form
#     - `src/scene/validate.cpp`: the reason ...
# Fails on a longer file that is not named there and on a name there that
# is stale (no such file, or one no longer above the limit).
#
#   check_file_sizes.sh SOURCE_DIR      checks the tree
#   check_file_sizes.sh --self-test     shows that it can fail
set -euo pipefail
limit=600

check() {  # ROOT: prints what is wrong, returns 1 if anything is
  local root=$1 status=0 file lines
  local named
  named=$(awk '/^## Files above 600 lines/{on=1; next} /^## /{on=0} on' "$root/src/README.md" |
          sed -n -E 's/^- `([^`]+)`: .+/\1/p')
  while IFS= read -r file; do
    lines=$(wc -l < "$root/$file")
    if [ "$lines" -gt "$limit" ] && ! grep -qxF "$file" <<<"$named"; then
      echo "$file: $lines lines (over $limit) and not named, with a reason, in src/README.md"
      status=1
    fi
  done < <(cd "$root" && find src apps -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.inc' -o -name '*.in' \) | sort)
  while IFS= read -r file; do
    [ -n "$file" ] || continue
    if [ ! -f "$root/$file" ]; then
      echo "src/README.md names $file, which does not exist"
      status=1
    elif [ "$(wc -l < "$root/$file")" -le "$limit" ]; then
      echo "src/README.md names $file as over $limit lines; it has $(wc -l < "$root/$file")"
      status=1
    fi
  done <<<"$named"
  return $status
}

if [ "${1:-}" = "--self-test" ]; then
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
  mkdir -p "$scratch/src/a" "$scratch/apps"
  printf '# src\n\n## Files above 600 lines\n\n- `src/a/long.cpp`: a reason.\n\n## Next\n' > "$scratch/src/README.md"
  seq 601 > "$scratch/src/a/long.cpp"
  seq 600 > "$scratch/src/a/short.cpp"
  check "$scratch" > /dev/null || { echo "FAIL: a named long file was refused"; exit 1; }
  seq 601 > "$scratch/apps/other.hpp"
  if check "$scratch" > /dev/null; then echo "FAIL: an unnamed 601-line file passed"; exit 1; fi
  rm "$scratch/apps/other.hpp"
  seq 10 > "$scratch/src/a/long.cpp"
  if check "$scratch" > /dev/null; then echo "FAIL: a stale name passed"; exit 1; fi
  echo "self-test passed"
  exit 0
fi
check "${1:?usage: check_file_sizes.sh SOURCE_DIR | --self-test}"
