#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/samples.sh [--rounds R] [--frames K] [--width W] [--height H] [--backend cpu|gl]
#
# The cost of anti-aliasing (docs/spec.md §11) on the CPU renderer (or,
# with --backend gl, the OpenGL backend; LP_NUM_THREADS as the caller sets
# it for Mesa's llvmpipe): the
# default scene (one cube) and scenes/fill.toml (every pixel covered) at
# 1920×1080, each drawn by `litkit bench` with 1, 4 and 16 samples per pixel
# in one run, the counts taking turns within each round. Prints, per scene,
# the medians over the rounds of the frame times and each count's ratio to
# one sample (the target: at most 1.1 × the count, i.e. 4.4 and 17.6), and
# the peak resident memory of a 16-sample render (the target: under 64 MiB).
# Builds what it runs in LITKIT_BENCH_BUILD (default build-bench, Release).
# LITKIT_BENCH_THREADS: threads (default 2). Default: 5 rounds of 10 frames.
# LITKIT_BENCH_NO_BUILD=1 runs the litkit already in LITKIT_BENCH_BUILD.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
build=${LITKIT_BENCH_BUILD:-$root/build-bench}
threads=${LITKIT_BENCH_THREADS:-2}
rounds=5
frames=10
width=1920
height=1080
backend=cpu
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift ;;
    --frames) frames=$2; shift ;;
    --width) width=$2; shift ;;
    --height) height=$2; shift ;;
    --backend) backend=$2; shift ;;
    *) echo "usage: $0 [--rounds R] [--frames K] [--width W] [--height H] [--backend cpu|gl]" >&2; exit 2 ;;
  esac
  shift
done

if [ -z "${LITKIT_BENCH_NO_BUILD:-}" ]; then
  "$root/scripts/install-deps.sh" --bench  # GNU time
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$build" -j 2 --target litkit_cli
fi
litkit=$build/litkit

# The median frame time, in ms, of `litkit bench` with these arguments.
frame_ms() {
  "$litkit" bench "$@" --width "$width" --height "$height" --backend "$backend" \
    $([ "$backend" = cpu ] && echo --threads "$threads") --frames "$frames" | sed -n -E 's/^frames: .*median ([0-9.]+) ms.*/\1/p'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "bench/samples.sh: ${width}x${height}, backend $backend, $threads threads, $rounds rounds of $frames frames"
for scene in default "$here/scenes/fill.toml"; do
  args=()
  [ "$scene" = default ] || args=("$scene")
  declare -A times=()
  for ((round = 0; round < rounds; ++round)); do
    for samples in 1 4 16; do
      times[$samples]+="$(frame_ms "${args[@]}" --samples "$samples") "
    done
  done
  one=$(tr ' ' '\n' <<<"${times[1]}" | grep . | median)
  line="$(basename "$scene" .toml): 1 sample ${one} ms"
  for samples in 4 16; do
    ms=$(tr ' ' '\n' <<<"${times[$samples]}" | grep . | median)
    line+="; $samples samples $ms ms ($(awk -v a="$ms" -v b="$one" 'BEGIN { printf "%.2f", a / b }')x)"
  done
  echo "$line"
  unset times
done
peak=$(/usr/bin/time -f '%M' "$litkit" render --width "$width" --height "$height" --samples 16 \
         --backend "$backend" $([ "$backend" = cpu ] && echo --threads "$threads") \
         -o "$build/samples-16.png" 2>&1 >/dev/null | tail -1)
echo "peak memory, default scene, ${width}x${height}, 16 samples: $((peak / 1024)) MiB ($peak KiB)"
