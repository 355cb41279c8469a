#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How `litkit check` grows with the number of lights and of objects
# (duplicate light positions by hashing, object overlaps behind a
# sort-and-sweep broad phase). Prints a Markdown table (docs/performance.md
# keeps one). A measurement, not a test: nothing passes or fails on speed.
# Usage: bench/check-scale.sh [BUILD_DIR]   (default: build)
#        CHECK_TIMEOUT=60 bench/check-scale.sh OLD_BUILD   (a row past it fails)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
litkit="$build/litkit"
[ -x "$litkit" ] || { echo "check-scale: build litkit first ($litkit missing)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# N point lights on a grid (all at different places) around one sphere, or
# N small spheres on a grid (none touching) lit by one light.
generate() {  # lights|objects N file
  python3 - "$1" "$2" "$3" <<'PY'
import math, sys
kind, n, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
side = math.ceil(n ** (1 / 3))
room = 2 * side + 10
out = [f"[room]\nwidth = {room}\nheight = {room}\ndepth = {room}\n",
       f"[observer]\nposition = [0, 0, {room / 2 - 1}]\nlook_at = [0, 0, 0]\n",
       "[lighting]\nreflection = \"phong\"\nshading = \"phong\"\n",
       "[output]\nwidth = 64\nheight = 48\n"]
def grid(i):
    x, y, z = i % side, (i // side) % side, i // (side * side)
    return [2 * x - side + 0.5, 2 * y - side + 0.5, 2 * z - side - 3.5]
if kind == "lights":
    for i in range(n):
        out.append(f"[[lights]]\ntype = \"point\"\nposition = {grid(i)}\nintensity = 1\n")
    out.append("[[objects]]\ntype = \"sphere\"\nradius = 0.2\nposition = [0.1, 0.1, -0.1]\n"
               "segments = 8\nrings = 4\n")
else:
    out.append(f"[[lights]]\ntype = \"point\"\nposition = [0, 0, {room / 2 - 2}]\nintensity = 1\n")
    for i in range(n):
        # The default tessellation (64 segments, 32 rings): 1,986 hull points each.
        out.append(f"[[objects]]\ntype = \"sphere\"\nradius = 0.4\nposition = {grid(i)}\n")
open(path, "w").write("\n".join(out))
PY
}

echo "| scene | check (s) | peak memory (MiB) |"
echo "| --- | ---: | ---: |"
for spec in "lights 1000" "lights 10000" "lights 100000" "objects 1000" "objects 10000"; do
  set -- $spec
  file="$scratch/$1-$2.toml"
  generate "$1" "$2" "$file"
  /usr/bin/time -f '%e %M' -o "$scratch/time" timeout "${CHECK_TIMEOUT:-600}" "$litkit" check "$file" > /dev/null 2>&1 ||
    { echo "check-scale: litkit check failed on $1 $2" >&2; "$litkit" check "$file" | head -3 >&2; exit 1; }
  read -r seconds kib < "$scratch/time"
  printf '| %s %s | %s | %s |\n' "$2" "$1" "$seconds" "$((kib / 1024))"
done
