#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/compare.sh [--quick] [--targets] [--rounds R] [--frames K]
#
# litkit against a plain OpenGL program (bench/gl_peer: litkit_gl_peer, an
# OpenGL 3.3 core program on a headless EGL context, Mesa's llvmpipe where
# there is no GPU, written for each scene as a competent programmer would:
# shaders specialised to the scene's lights and model, indexed meshes, one
# draw per object, glFinish + glReadPixels every frame). Three sides, same
# scenes, same thread count (--threads 2 for litkit's CPU backend,
# LP_NUM_THREADS=2 for llvmpipe), in one run: litkit --backend cpu, litkit
# --backend gl, and the peer. Two tables: the CPU backend against the peer
# (peer time / CPU time: > 1, litkit is faster) and litkit's GL backend
# against the peer (GL time / peer time: 1 is as fast as the plain program).
# Each round runs every scene on the three sides, the first side rotating
# from round to round; the tables show medians over the rounds.
#
#   picture checks  first: the peer's picture against litkit's CPU picture
#                  (litkit_gl_peer --check: >= 99.5% of interior pixels within
#                  2/255, tests/picture_agreement.hpp), and --backend gl's
#                  against --backend cpu's (litkit_png_diff)
#   whole process  default scene to a PNG at 800x600 and 1920x1080: process
#                  start to file written (hyperfine when installed, else a
#                  plain loop of date +%s%N)
#   steady frames  median frame time (one warm-up frame, then K frames, each
#                  read back to memory), 1920x1080
#   set-up         what each side reports before its frames (meshes, normals,
#                  world space; GL and the peer add the EGL context, shader
#                  compilation and upload), 1920x1080
#   memory         peak resident set size of the 1080p runs (GNU time -v)
#
# Default: 5 rounds of 20 frames. --quick: one round of 3 frames, a smoke
# run for CI (no timing is asserted). --targets: only the rows with
# targets (docs/performance.md) (the default scene to PNG at 800x600, and at 1920x1080 the
# cube, the full-screen fill and the 261k sphere), with their picture
# checks; 5 whole-process runs per round. Installs what it needs through
# `scripts/install-deps.sh --bench`. Builds what it runs in build-bench/
# (LITKIT_BENCH_BUILD overrides: an existing tree, such as the tests' Release
# tree `build` that CI uses, gets the benchmarks added and keeps its tests),
# with at most 2 parallel jobs. Raw numbers
# go to build-bench/compare/. LITKIT_BENCH_HYPERFINE=0 uses the plain loop
# even where hyperfine is installed; LITKIT_BENCH_THREADS sets the thread
# count of both sides (default 2).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
build=${LITKIT_BENCH_BUILD:-$root/build-bench}
scenes=$here/scenes

rounds=5
frames=20
whole_runs=10   # hyperfine runs per command per round
whole_warmup=2
targets=no      # --targets: only the rows with targets
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) rounds=1; frames=3; whole_runs=2; whole_warmup=1 ;;
    --targets) targets=yes ;;
    --rounds) rounds=$2; shift ;;
    --frames) frames=$2; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--quick] [--targets] [--rounds R] [--frames K]" >&2; exit 2 ;;
  esac
  shift
done

# ---- build -----------------------------------------------------------------
# One command from a clean checkout: install what the build and the timing
# need (apt; a no-op when everything is there).
"$root/scripts/install-deps.sh" --bench
[ $targets = yes ] && [ "$whole_runs" -gt 5 ] && whole_runs=5
if [ ! -f "$build/CMakeCache.txt" ]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "$root" -B "$build" "${generator[@]}" -DLITKIT_BUILD_BENCH=ON \
        -DCMAKE_BUILD_TYPE=Release -DLITKIT_BUILD_TESTS=OFF >/dev/null
elif ! grep -qs '^LITKIT_BUILD_BENCH:BOOL=ON' "$build/CMakeCache.txt"; then
  # A tree made for something else (LITKIT_BENCH_BUILD=build, as CI does): add the
  # benchmarks and keep everything else it has (its tests, its build type).
  cmake -S "$root" -B "$build" -DLITKIT_BUILD_BENCH=ON >/dev/null
fi
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
[ "$build_type" = Release ] ||
  echo "warning: $build is a ${build_type:-no-type} build, not Release: its times are not litkit's" >&2
if ! cmake --build "$build" -j2 --target litkit_cli litkit_png_diff litkit_gl_peer >"$build/compare-build.log" 2>&1; then
  tail -n 20 "$build/compare-build.log" >&2
  if [ -x "$build/litkit" ] && [ -x "$build/litkit_png_diff" ] && [ -x "$build/litkit_gl_peer" ] &&
     [ "${LITKIT_BENCH_STALE_OK:-}" = 1 ]; then
    echo "warning: the build failed; LITKIT_BENCH_STALE_OK=1: timing the binaries of the last good build" >&2
  else
    echo "error: the build failed (full log: $build/compare-build.log); LITKIT_BENCH_STALE_OK=1 times the last good build" >&2
    exit 1
  fi
fi
litkit=$build/litkit
png_diff=$build/litkit_png_diff

# ---- one thread count for all three ------------------------------------------
threads=${LITKIT_BENCH_THREADS:-2}
export LP_NUM_THREADS=$threads
peer=$build/litkit_gl_peer
sides=(cpu gl peer)

out=$build/compare
mkdir -p "$out"
rm -f "$out"/*.png "$out"/*.json "$out"/*.toml "$out"/*.time "$out"/*.log
raw=$out/raw.tsv
printf 'round\tscene\tside\tms\trss_kib\tsetup_ms\n' >"$raw"
log=$out/runs.log
: >"$log"

have_hyperfine=no
command -v hyperfine >/dev/null && [ "${LITKIT_BENCH_HYPERFINE:-1}" != 0 ] && have_hyperfine=yes
gnu_time=""
[ -x /usr/bin/time ] && /usr/bin/time -v true 2>/dev/null && gnu_time=/usr/bin/time

# Percentage of CPU time the machine spent idle over one second: run before
# each round, so that a busy machine (a build, another benchmark) shows.
idle_percent() {
  local a b
  read -r -a a < <(head -n1 /proc/stat)
  sleep 1
  read -r -a b < <(head -n1 /proc/stat)
  local total=0 i
  for ((i = 1; i < ${#a[@]}; i++)); do total=$((total + b[i] - a[i])); done
  echo $(( total > 0 ? 100 * (b[4] - a[4] + b[5] - a[5]) / total : 100 ))
}
busy_rounds=""

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n1)
# GL_RENDERER and GL_VERSION, from the `renderer:` line of a tiny GL run; it
# also stops the script here, with litkit's message, where OpenGL cannot run.
gl_renderer=$("$litkit" bench --backend gl --width 16 --height 16 --frames 1 2>>"$log" |
              sed -n 's/^renderer: OpenGL backend: //p') || true
peer_renderer=$("$peer" --width 16 --height 16 --frames 1 2>>"$log" |
                sed -n 's/^renderer: plain OpenGL peer: //p') || true
if [ -z "$gl_renderer" ] || [ -z "$peer_renderer" ]; then
  echo "error: OpenGL does not run here (see $log)" >&2
  tail -n 5 "$log" >&2
  exit 1
fi

echo "litkit against a plain OpenGL program: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "cpu:     ${cpu:-unknown}, $(nproc) hardware threads; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "litkit:  $("$litkit" --version | head -n 1) ($litkit)"
echo "CPU:     litkit --backend cpu --threads $threads"
echo "GL:      litkit --backend gl: $gl_renderer; LP_NUM_THREADS=$LP_NUM_THREADS"
echo "peer:    litkit_gl_peer (bench/gl_peer): $peer_renderer; LP_NUM_THREADS=$LP_NUM_THREADS"
echo "rounds:  $rounds; steady frames: $frames per run after 1 warm-up;" \
     "whole process: $([ $have_hyperfine = yes ] && echo "hyperfine, $whole_warmup warm-up + $whole_runs runs" || echo "plain loop, $whole_runs runs") per round"
echo "idle:    $(idle_percent)% of CPU time idle over 1 s before starting (anything else running skews every side)"
echo

# ---- the pictures agree? ------------------------------------------------------
# Every scene and reflection × shading pair timed below, at the size timed.
failed_checks=0
echo "picture checks (peer: litkit_gl_peer --check against litkit's CPU picture, interior pixels;"
echo "                GL: --backend gl against --backend cpu, litkit_png_diff, every pixel):"
check() {  # name, scene arguments (as for litkit render / litkit_gl_peer)
  local name=$1; shift
  local peer_line gl_line
  if peer_line=$("$peer" "$@" --check 2>&1); then :; else failed_checks=$((failed_checks + 1)); fi
  "$litkit" render "$@" --backend cpu --threads "$threads" -o "$out/check-$name-cpu.png" >>"$log" 2>&1
  "$litkit" render "$@" --backend gl -o "$out/check-$name-gl.png" >>"$log" 2>&1
  gl_line=$("$png_diff" "$out/check-$name-cpu.png" "$out/check-$name-gl.png")
  printf '  %-26s peer %s\n  %-26s GL   %s\n' "$name" "$peer_line" "" "$gl_line"
}
check "default 800x600"
check "default 1920x1080" --width 1920 --height 1080
if [ $targets = yes ]; then
  bench_scenes=(fill sphere-261k)
else
  bench_scenes=(fill sphere-65k sphere-261k teapot-64)
fi
for name in "${bench_scenes[@]}"; do check "$name" "$scenes/$name.toml"; done
[ $targets = yes ] ||
for reflection in lambert half-lambert phong blinn-phong; do
  for shading in flat gouraud phong; do
    check "65k-$reflection-$shading" "$scenes/sphere-65k.toml" --reflection "$reflection" --shading "$shading"
  done
done
[ "$failed_checks" = 0 ] || echo "warning: the peer's picture disagrees with litkit's in $failed_checks check(s): its times are not comparable there"
echo

# ---- helpers ------------------------------------------------------------------
median() {  # numbers on stdin, one a line
  sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) { print "nan"; exit }
    if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
now_ns() { date +%s%N; }
# Runs a command under GNU time when there is one; prints its stdout. The
# peak RSS (KiB) lands in $out/last.time.
timed() {
  if [ -n "$gnu_time" ]; then
    "$gnu_time" -v -o "$out/last.time" "$@" 2>>"$log"
  else
    : >"$out/last.time"
    "$@" 2>>"$log"
  fi
}
last_rss() { sed -n 's/.*Maximum resident set size (kbytes): //p' "$out/last.time"; }
record() { printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "${5:-}" "${6:-}" >>"$raw"; }
# The sides in round r's order: the first rotates, cpu gl peer, gl peer cpu, ...
order() { local r=$1 i; for ((i = 0; i < 3; i++)); do echo "${sides[$(( (r - 1 + i) % 3 ))]}"; done; }

# The command of one side: side, extra arguments (scene, size, models).
command_of() {
  local side=$1; shift
  case $side in
    cpu) printf '%s\n' "$litkit" "$@" --backend cpu --threads "$threads" ;;
    gl) printf '%s\n' "$litkit" "$@" --backend gl ;;
    peer) printf '%s\n' "$peer" "$@" ;;
  esac
}

# ---- whole process: default scene to PNG -----------------------------------------
whole_round() {  # round, label, width, height
  local r=$1 label=$2 w=$3 h=$4 side
  declare -A cmd
  for side in "${sides[@]}"; do
    local words=()
    if [ "$side" = peer ]; then
      mapfile -t words < <(command_of peer --width "$w" --height "$h" -o "$out/whole-peer.png")
    else
      mapfile -t words < <(command_of "$side" render --width "$w" --height "$h" -o "$out/whole-$side.png")
    fi
    cmd[$side]=$(printf '%q ' "${words[@]}")
  done
  if [ $have_hyperfine = yes ]; then
    local json=$out/whole-$label-$r.json named=()
    for side in $(order "$r"); do named+=(-n "$side" "${cmd[$side]}"); done
    hyperfine -N --style none --warmup "$whole_warmup" --runs "$whole_runs" --export-json "$json" \
      "${named[@]}" >>"$log" 2>&1
    for side in "${sides[@]}"; do
      local s
      s=$(tr -d '\n ' <"$json" | grep -o "\"command\":\"$side\"[^}]*" | grep -o '"median":[0-9.eE+-]*' | cut -d: -f2)
      record "$r" "$label" "$side" "$(awk -v s="$s" 'BEGIN { printf "%.3f", s * 1000 }')"
    done
  else
    local i t0
    for side in $(order "$r"); do eval "${cmd[$side]}" >>"$log" 2>&1; done   # warm-up
    for ((i = 0; i < whole_runs; i++)); do
      for side in $(order "$r"); do
        t0=$(now_ns); eval "${cmd[$side]}" >>"$log" 2>&1
        record "$r" "$label-run" "$side" "$(( ($(now_ns) - t0) / 1000 ))e-3"
      done
    done
    for side in "${sides[@]}"; do
      record "$r" "$label" "$side" "$(awk -F'\t' -v r="$r" -v l="$label-run" -v s="$side" \
        '$1 == r && $2 == l && $3 == s { print $4 + 0 }' "$raw" | median)"
    done
  fi
  # peak memory of the 1080p whole process, once per round, outside the timing
  if [ "$h" -ge 1080 ] && [ -n "$gnu_time" ]; then
    for side in $(order "$r"); do
      eval "timed ${cmd[$side]}" >/dev/null; record "$r" "$label" "$side-rss" "" "$(last_rss)"
    done
  fi
}

# ---- steady frames ---------------------------------------------------------------
# A steady-frame row: label, scene file ("" = the built-in default), and for
# the reflection × shading rows the models.
rows=()
add_row() { rows+=("$1|$2|${3:-}|${4:-}"); }
add_row "cube (default)" ""
add_row "full-screen fill" "$scenes/fill.toml"
[ $targets = yes ] || add_row "sphere 65k" "$scenes/sphere-65k.toml"
add_row "sphere 261k" "$scenes/sphere-261k.toml"
[ $targets = yes ] || add_row "teapot 64" "$scenes/teapot-64.toml"
[ $targets = yes ] ||
for reflection in lambert half-lambert phong blinn-phong; do
  for shading in flat gouraud phong; do
    add_row "65k $reflection/$shading" "$scenes/sphere-65k.toml" "$reflection" "$shading"
  done
done

frame_ms() { sed -n 's/^median_frame_ms=\([0-9.]*\).*/\1/p' | tail -n1; }
setup_ms() { sed -n 's/^setup: \([0-9.]*\) ms.*/\1/p' | tail -n1; }

steady_round() {  # round, row
  local r=$1 label scene reflection shading
  IFS='|' read -r label scene reflection shading <<<"$2"
  local common=()
  [ -n "$scene" ] && common+=("$scene")
  common+=(--width 1920 --height 1080 --frames "$frames")
  [ -n "$reflection" ] && common+=(--reflection "$reflection" --shading "$shading")
  local side
  for side in $(order "$r"); do
    local words=() output ms
    if [ "$side" = peer ]; then
      mapfile -t words < <(command_of peer "${common[@]}")
    else
      mapfile -t words < <(command_of "$side" bench "${common[@]}")
    fi
    output=$(timed "${words[@]}")
    printf '%s\n' "$output" >>"$log"
    ms=$(frame_ms <<<"$output")
    [ -n "$ms" ] || { echo "error: $side gave no median_frame_ms for '$label' (see $log)" >&2; exit 1; }
    record "$r" "$label" "$side" "$ms" "$(last_rss)" "$(setup_ms <<<"$output")"
  done
}

# ---- the rounds --------------------------------------------------------------------
for ((r = 1; r <= rounds; r++)); do
  idle=$(idle_percent)
  echo "round $r/$rounds (machine ${idle}% idle before it) ..." >&2
  [ "$idle" -ge 90 ] || busy_rounds+=" $r (${idle}% idle)"
  whole_round "$r" "default 800x600 to PNG" 800 600
  [ $targets = yes ] || whole_round "$r" "default 1920x1080 to PNG" 1920 1080
  for row in "${rows[@]}"; do steady_round "$r" "$row"; done
done

# ---- the tables --------------------------------------------------------------------
med_of() {  # label, side, column (4 ms, 5 rss, 6 setup) -> median over rounds
  awk -F'\t' -v l="$1" -v s="$2" -v c="$3" '$2 == l && $3 == s && $c != "" { print $c }' "$raw" | median
}
mib() { [ "$1" = nan ] && echo "-" || awk -v k="$1" 'BEGIN { printf "%.0f", k / 1024 }'; }
ms2() { [ "$1" = nan ] && echo "-" || printf %.2f "$1"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "nan" || b == "nan" || a <= 0) print "-"; else printf "%.2f", b / a }'; }

# The lowest and highest of the per-round ratios b/a: how much the rounds agree.
spread() {  # label, side a, side b
  awk -F'\t' -v l="$1" -v sa="$2" -v sb="$3" '$2 == l && $3 == sa { a[$1] = $4 } $2 == l && $3 == sb { b[$1] = $4 }
    END { n = 0; for (r in a) if ((r in b) && a[r] > 0) { q = b[r] / a[r]; if (!n || q < lo) lo = q; if (!n || q > hi) hi = q; n++ }
          if (n) printf "%.2f-%.2f", lo, hi; else print "-" }' "$raw"
}
line() { printf '%-28s %9s %9s %6s %11s %8s %8s %9s %9s\n' "$@"; }
# One table: the two sides, their names, the ratio's reading.
table() {  # side a (the denominator), side b, name a, name b
  local a_side=$1 b_side=$2
  line "scene (1920x1080 unless said)" "$3 ms" "$4 ms" "ratio" "per round" "$3 MiB" "$4 MiB" "$3 setup" "$4 setup"
  line "----------------------------" "------" "------" "-----" "---------" "-------" "-------" "--------" "--------"
  local label a b
  local whole_labels=("default 800x600 to PNG")
  [ $targets = yes ] || whole_labels+=("default 1920x1080 to PNG")
  for label in "${whole_labels[@]}"; do
    a=$(med_of "$label" "$a_side" 4); b=$(med_of "$label" "$b_side" 4)
    line "$label" "$(printf %.1f "$a")" "$(printf %.1f "$b")" "$(ratio "$a" "$b")" "$(spread "$label" "$a_side" "$b_side")" \
         "$(mib "$(med_of "$label" "$a_side-rss" 5)")" "$(mib "$(med_of "$label" "$b_side-rss" 5)")" "-" "-"
  done
  for row in "${rows[@]}"; do
    label=${row%%|*}
    a=$(med_of "$label" "$a_side" 4); b=$(med_of "$label" "$b_side" 4)
    line "$label" "$(printf %.2f "$a")" "$(printf %.2f "$b")" "$(ratio "$a" "$b")" "$(spread "$label" "$a_side" "$b_side")" \
         "$(mib "$(med_of "$label" "$a_side" 5)")" "$(mib "$(med_of "$label" "$b_side" 5)")" \
         "$(ms2 "$(med_of "$label" "$a_side" 6)")" "$(ms2 "$(med_of "$label" "$b_side" 6)")"
  done
}

echo "== litkit's CPU backend against the plain OpenGL program"
echo "   ratio = peer time / CPU time (> 1: litkit's CPU backend is faster)"
table cpu peer CPU peer
echo
echo "== litkit's GL backend (--backend gl) against the plain OpenGL program"
echo "   ratio = GL time / peer time (1: as fast as the plain program; > 1: slower)"
table peer gl peer GL
echo
echo "ratios are of the medians over $rounds round(s); per round: the lowest and highest"
echo "ratio of a single round (the sides run back to back, the first rotating)."
echo "to PNG rows: whole process, start to file written; the others: median frame time;"
echo "setup: once per run, before the frames (GL, peer: EGL context, shader compilation, upload)."
idle=$(idle_percent)
[ "$idle" -ge 90 ] || busy_rounds+=" end (${idle}% idle)"
[ -z "$busy_rounds" ] || echo "warning: the machine was busy before or after round(s)$busy_rounds: rerun on a quiet machine"
echo "raw numbers: $raw"
