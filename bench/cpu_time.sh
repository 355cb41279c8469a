#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/cpu_time.sh [--rounds R] [SCENE-ARGUMENTS...]
#
# CPU time per 1920x1080 frame of the three sides of bench/compare.sh
# (litkit --backend cpu --threads 2, litkit --backend gl, litkit_gl_peer;
# LP_NUM_THREADS=2): user + system time of the whole process, all its
# threads (llvmpipe's included), for 85 frames minus that for 5, over 80.
# Set-up cancels out. On a busy machine wall-clock frame times mostly
# measure the scheduler; CPU time is what the work costs, and moves much
# less with the load (it still grows somewhat when other processes share
# the cores' caches). Not a substitute for bench/compare.sh on a quiet
# machine, which measures what a user waits for.
#
#   bench/cpu_time.sh                              # the default scene (cube)
#   bench/cpu_time.sh bench/scenes/fill.toml
#   bench/cpu_time.sh bench/scenes/sphere-65k.toml --reflection phong --shading flat
#
# Prints, per round, each side's ms of CPU per frame, then the medians.
# Uses the binaries of build-bench/ (LITKIT_BENCH_BUILD overrides); run
# bench/compare.sh once first to build them.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${LITKIT_BENCH_BUILD:-$here/../build-bench}
rounds=3
if [ "${1:-}" = --rounds ]; then rounds=$2; shift 2; fi
export LP_NUM_THREADS=2
for binary in litkit litkit_gl_peer; do
  [ -x "$build/$binary" ] || { echo "error: no $build/$binary: run bench/compare.sh first" >&2; exit 1; }
done

cpu_seconds() {  # command... -> user + system seconds
  /usr/bin/time -f '%U %S' "$@" 2>&1 >/dev/null | tail -n1 | awk '{ print $1 + $2 }'
}
side_command() {  # side frames
  case $1 in
    cpu) echo "$build/litkit bench --backend cpu --threads 2" ;;
    gl) echo "$build/litkit bench --backend gl" ;;
    peer) echo "$build/litkit_gl_peer" ;;
  esac
}
declare -A all
for ((r = 1; r <= rounds; r++)); do
  line="round $r:"
  for side in cpu gl peer; do
    read -r -a command <<<"$(side_command "$side")"
    a=$(cpu_seconds "${command[@]}" "$@" --width 1920 --height 1080 --frames 5)
    b=$(cpu_seconds "${command[@]}" "$@" --width 1920 --height 1080 --frames 85)
    ms=$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", (b - a) * 1000 / 80 }')
    all[$side]+="$ms "
    line+=" $side $ms"
  done
  echo "$line ms CPU/frame"
done
median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
c=$(median <<<"${all[cpu]}"); g=$(median <<<"${all[gl]}"); p=$(median <<<"${all[peer]}")
echo "median: cpu $c, gl $g, peer $p ms CPU/frame; peer/cpu $(awk -v a="$c" -v b="$p" 'BEGIN { printf "%.2f", b / a }'), gl/peer $(awk -v a="$p" -v b="$g" 'BEGIN { printf "%.2f", b / a }')"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
