#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How litkit's frame time, set-up time and peak memory grow with pixels and
# with triangles. Prints a Markdown table (docs/performance.md keeps one).
# Usage: bench/scaling.sh [BUILD_DIR]   (default: build, as the README builds)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
litkit="$build/litkit"
[ -x "$litkit" ] || { echo "scaling: build litkit first ($litkit missing)" >&2; exit 1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# A sphere of about 2·segments·(rings−1) triangles, from the 261k bench scene.
sphere() {  # segments rings file
  sed -e "s/^segments = .*/segments = $1/" -e "s/^rings = .*/rings = $2/" \
      bench/scenes/sphere-261k.toml > "$3"
}

row() {  # label width height frames scene...
  local label=$1 width=$2 height=$3 frames=$4; shift 4
  local out
  out=$(/usr/bin/time -v "$litkit" bench "$@" --width "$width" --height "$height" \
        --frames "$frames" 2> "$scratch/time")
  local triangles setup median rss
  triangles=$(sed -n 's/^image: [0-9x]*, \([0-9]*\) triangles.*/\1/p' <<< "$out")
  setup=$(sed -n 's/^setup: \([0-9.]*\) ms.*/\1/p' <<< "$out")
  median=$(sed -n 's/^median_frame_ms=\([0-9.]*\).*/\1/p' <<< "$out")
  rss=$(awk '/Maximum resident set size/ {printf "%.0f", $6 / 1024}' "$scratch/time")
  printf '| %s | %sx%s | %s | %s | %s | %s |\n' "$label" "$width" "$height" "$triangles" \
         "$setup" "$median" "$rss"
}

echo "| scene | image | triangles | set-up ms | median frame ms | peak MiB |"
echo "| --- | --- | --- | --- | --- | --- |"
for size in "640 480" "1920 1080" "3840 2160"; do
  set -- $size
  row "default cube" "$1" "$2" 20
  row "full-screen fill" "$1" "$2" 10 bench/scenes/fill.toml
done
for rings in 32 128 256 512 1024; do
  segments=$((rings * 2))
  sphere "$segments" "$rings" "$scratch/sphere-$rings.toml"
  row "sphere $segments×$rings" 1920 1080 10 "$scratch/sphere-$rings.toml"
done
