#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/glass.sh [--rounds R] [--frames K]
#
# litkit's glass (docs/spec.md §10) against Intel Embree: scenes/glass-sphere.toml
# (800×600, a 64×32 glass sphere before a wall of 63 cubes, max_depth 8)
# drawn by `litkit bench --backend cpu --threads T` and by
# litkit_glass_peer (glass_peer/: every ray through Embree's rtcIntersect1,
# the same tree in float, T threads), in one run, the side going first
# alternating from round to round. Prints the medians over the rounds of
# both frame times, the frame-time ratio (peer / litkit: above 1, litkit is
# faster), the rays each side casts per frame and their throughputs (rays
# per second of the whole frame), and the two pictures' agreement.
# Builds what it runs in LITKIT_BENCH_BUILD (default build-bench,
# -DLITKIT_BUILD_BENCH=ON, Release); installs the peer's Embree through
# scripts/install-deps.sh --bench. LITKIT_BENCH_THREADS: threads of both
# sides (default 2). Default: 5 rounds of 10 frames.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
build=${LITKIT_BENCH_BUILD:-$root/build-bench}
scene=$here/scenes/glass-sphere.toml
threads=${LITKIT_BENCH_THREADS:-2}
rounds=5
frames=10
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds=$2; shift ;;
    --frames) frames=$2; shift ;;
    *) echo "usage: $0 [--rounds R] [--frames K]" >&2; exit 2 ;;
  esac
  shift
done

"$root/scripts/install-deps.sh" --bench
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLITKIT_BUILD_BENCH=ON > /dev/null
cmake --build "$build" -j 2 --target litkit_cli litkit_glass_peer litkit_png_diff

out=$build/glass
mkdir -p "$out"
"$build/litkit" render "$scene" --backend cpu --threads "$threads" -o "$out/litkit.png" > /dev/null
"$build/litkit_glass_peer" "$scene" --threads "$threads" --frames 1 -o "$out/peer.png" > /dev/null
echo "pictures: litkit_png_diff $out/litkit.png $out/peer.png"
"$build/litkit_png_diff" "$out/litkit.png" "$out/peer.png" || true

: > "$out/litkit.txt"
: > "$out/peer.txt"
for round in $(seq 1 "$rounds"); do
  run_litkit() {
    "$build/litkit" bench "$scene" --backend cpu --threads "$threads" --frames "$frames" >> "$out/litkit.txt"
  }
  run_peer() {
    "$build/litkit_glass_peer" "$scene" --threads "$threads" --frames "$frames" >> "$out/peer.txt"
  }
  if [ $((round % 2)) -eq 1 ]; then run_litkit; run_peer; else run_peer; run_litkit; fi
done

python3 - "$out/litkit.txt" "$out/peer.txt" <<'PY'
import re, statistics, sys
litkit = open(sys.argv[1]).read()
peer = open(sys.argv[2]).read()
lk_ms = [float(v) for v in re.findall(r"median_frame_ms=([0-9.]+)", litkit)]
lk_rays = [int(v) for v in re.findall(r"rays traced: ([0-9]+)", litkit)]
pe_ms = [float(v) for v in re.findall(r"median_frame_ms ([0-9.]+)", peer)]
pe_rays = [int(v) for v in re.findall(r"^rays ([0-9]+)", peer, re.M)]
pe_setup = [float(v) for v in re.findall(r"setup_ms ([0-9.]+)", peer)]
lk_setup = [float(v) for v in re.findall(r"setup: ([0-9.]+) ms", litkit)]
m = statistics.median
print(f"| side | frame ms | set-up ms | rays per frame | million rays/s |")
print(f"| --- | --- | --- | --- | --- |")
print(f"| litkit (CPU, rasterized first hits + ray tree) | {m(lk_ms):.1f} | {m(lk_setup):.1f} | {lk_rays[0]} | {lk_rays[0] / m(lk_ms) / 1e3:.2f} |")
print(f"| Embree peer (every ray) | {m(pe_ms):.1f} | {m(pe_setup):.1f} | {pe_rays[0]} | {pe_rays[0] / m(pe_ms) / 1e3:.2f} |")
print(f"frame-time ratio peer / litkit: {m(pe_ms) / m(lk_ms):.2f} (above 1: litkit is faster)")
PY
