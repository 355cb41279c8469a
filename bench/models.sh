#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every reflection model on the full-screen fill scene (1920x1080, Phong
# shading, one point light), rounds interleaved so that the machine's drift
# hits every model alike; prints each model's median frame time and its ratio
# to phong's from the same run. A measurement, not a test: nothing is asserted.
# Usage: bench/models.sh [ROUNDS] [BUILD_DIR]   (defaults: 5, build)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
build=${2:-build}
litkit="$build/litkit"
[ -x "$litkit" ] || { echo "models: build litkit first ($litkit missing)" >&2; exit 1; }
models=$("$litkit" render --help | sed -n 's/.*--reflection TEXT:{\(.*\)}.*/\1/p' | tr ',' ' ')
[ -n "$models" ] || models="lambert half-lambert phong blinn-phong"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

for round in $(seq "$rounds"); do
  for model in $models; do
    "$litkit" bench bench/scenes/fill.toml --reflection "$model" --width 1920 --height 1080 \
      --frames 20 --threads 2 | sed -n 's/^median_frame_ms=\([0-9.]*\).*/\1/p' >> "$scratch/$model"
  done
done

median() { sort -g "$1" | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
phong=$(median "$scratch/phong")
echo "| model | median frame (ms) | / phong |"
echo "| --- | ---: | ---: |"
for model in $models; do
  m=$(median "$scratch/$model")
  awk -v name="$model" -v m="$m" -v p="$phong" 'BEGIN { printf "| %s | %.2f | %.2f |\n", name, m, m / p }'
done
