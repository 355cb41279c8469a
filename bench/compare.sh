#!/usr/bin/env bash
# bench/compare.sh [--quick] [--rounds R] [--frames K]
#
# litkit against plain OpenGL (bench/gl_peer: EGL headless, GLSL per-pixel
# Phong, on Mesa's llvmpipe where there is no GPU), same scenes, same thread
# count, in one run. Each round runs every scene on both sides, alternating
# which goes first; the table shows the median over the rounds of each side
# and the ratio OpenGL time / litkit time (> 1: litkit is faster).
#
#   whole process  default scene to a PNG at 800×600 and 1920×1080: process
#                  start to file written (hyperfine when installed, else a
#                  plain loop of date +%s%N)
#   steady frames  median frame time of `litkit bench` and of
#                  `litkit_gl_peer` (one warm-up frame, then K frames, each
#                  read back to memory), 1920×1080
#   memory         peak resident set size of the 1080p runs (GNU time -v)
#
# Default: 5 rounds of 20 frames (about ten minutes on 2 cores). --quick:
# one round of 3 frames, a smoke run for CI. Installs what it needs through
# `scripts/install-deps.sh --bench`. Builds what it runs in build-bench/
# (LITKIT_BENCH_BUILD overrides), with at most 2 parallel jobs. Raw numbers
# go to build-bench/compare/. LITKIT_BENCH_HYPERFINE=0 uses the plain loop
# even where hyperfine is installed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)
build=${LITKIT_BENCH_BUILD:-$root/build-bench}
scenes=$here/scenes

rounds=5
frames=20
whole_runs=10   # hyperfine runs per command per round
whole_warmup=2
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) rounds=1; frames=3; whole_runs=2; whole_warmup=1 ;;
    --rounds) rounds=$2; shift ;;
    --frames) frames=$2; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "usage: $0 [--quick] [--rounds R] [--frames K]" >&2; exit 2 ;;
  esac
  shift
done

# ---- build -----------------------------------------------------------------
# One command from a clean checkout: install what the peer needs (apt; a
# no-op when everything is there).
"$root/scripts/install-deps.sh" --bench
if ! pkg-config --exists epoxy 2>/dev/null; then
  echo "error: the OpenGL peer needs libepoxy, EGL and Mesa: run scripts/install-deps.sh --bench" >&2
  exit 1
fi
if ! grep -qs '^LITKIT_BUILD_BENCH:BOOL=ON' "$build/CMakeCache.txt"; then
  generator=()
  [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "$root" -B "$build" "${generator[@]}" -DLITKIT_BUILD_BENCH=ON \
        -DCMAKE_BUILD_TYPE=Release -DLITKIT_BUILD_TESTS=OFF >/dev/null
fi
if ! cmake --build "$build" -j2 --target litkit_cli litkit_gl_peer litkit_png_diff >"$build/compare-build.log" 2>&1; then
  tail -n 20 "$build/compare-build.log" >&2
  if [ -x "$build/litkit" ] && [ -x "$build/litkit_gl_peer" ] && [ -x "$build/litkit_png_diff" ] &&
     [ "${LITKIT_BENCH_STALE_OK:-}" = 1 ]; then
    echo "warning: the build failed; LITKIT_BENCH_STALE_OK=1: timing the binaries of the last good build" >&2
  else
    echo "error: the build failed (full log: $build/compare-build.log); LITKIT_BENCH_STALE_OK=1 times the last good build" >&2
    exit 1
  fi
fi
litkit=$build/litkit
peer=$build/litkit_gl_peer
png_diff=$build/litkit_png_diff

# ---- one thread count for both ---------------------------------------------
threads=$(nproc)
export LP_NUM_THREADS=$threads

out=$build/compare
mkdir -p "$out"
rm -f "$out"/*.png "$out"/*.json "$out"/*.toml "$out"/*.time "$out"/*.log
raw=$out/raw.tsv
printf 'round\tscene\tside\tms\trss_kib\n' >"$raw"
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
gl_renderer=$("$peer" --info | sed -n 's/^gl_renderer: //p')
gl_version=$("$peer" --info | sed -n 's/^gl_version: //p')
egl_platform=$("$peer" --info | sed -n 's/^egl_platform: //p')

echo "litkit vs OpenGL: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "cpu:     ${cpu:-unknown}, $(nproc) hardware threads"
echo "litkit:  $("$litkit" --version), --threads $threads"
echo "opengl:  $gl_renderer, $gl_version (EGL $egl_platform), LP_NUM_THREADS=$LP_NUM_THREADS"
echo "rounds:  $rounds; steady frames: $frames per run after 1 warm-up;" \
     "whole process: $([ $have_hyperfine = yes ] && echo "hyperfine, $whole_warmup warm-up + $whole_runs runs" || echo "plain loop, $whole_runs runs") per round"
echo "idle:    $(idle_percent)% of CPU time idle over 1 s before starting (anything else running skews both sides)"
echo

# ---- the two pictures agree? -----------------------------------------------
echo "picture check (fraction of pixels within 2/255 of litkit's):"
for scene in "" "$root/examples/reflection-models.toml"; do
  name=${scene:+$(basename "$scene" .toml)}
  name=${name:-default}
  "$litkit" render ${scene:+"$scene"} --threads "$threads" -o "$out/check-$name-litkit.png" >>"$log" 2>&1
  "$peer" ${scene:+"$scene"} --png "$out/check-$name-opengl.png" >>"$log" 2>&1
  printf '  %-18s %s\n' "$name" \
    "$("$png_diff" "$out/check-$name-litkit.png" "$out/check-$name-opengl.png")"
done
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
record() { printf '%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "${5:-}" >>"$raw"; }

# ---- whole process: default scene to PNG -----------------------------------------
whole_round() {  # round, label, width, height, first side
  local r=$1 label=$2 w=$3 h=$4 first=$5
  local lk=("$litkit" render --width "$w" --height "$h" --threads "$threads" -o "$out/whole-litkit.png")
  local gl=("$peer" --width "$w" --height "$h" --png "$out/whole-opengl.png")
  local lk_cmd gl_cmd
  lk_cmd=$(printf '%q ' "${lk[@]}")
  gl_cmd=$(printf '%q ' "${gl[@]}")
  if [ $have_hyperfine = yes ]; then
    local json=$out/whole-$label-$r.json
    if [ "$first" = litkit ]; then
      hyperfine -N --style none --warmup "$whole_warmup" --runs "$whole_runs" --export-json "$json" \
        -n litkit "$lk_cmd" -n opengl "$gl_cmd" >>"$log" 2>&1
    else
      hyperfine -N --style none --warmup "$whole_warmup" --runs "$whole_runs" --export-json "$json" \
        -n opengl "$gl_cmd" -n litkit "$lk_cmd" >>"$log" 2>&1
    fi
    # results in command order: "command": name ... "median": seconds
    local side
    for side in litkit opengl; do
      local s
      s=$(tr -d '\n ' <"$json" | grep -o "\"command\":\"$side\"[^}]*" | grep -o '"median":[0-9.eE+-]*' | cut -d: -f2)
      record "$r" "$label" "$side" "$(awk -v s="$s" 'BEGIN { printf "%.3f", s * 1000 }')"
    done
  else
    local i t0
    "${lk[@]}" >>"$log" 2>&1; "${gl[@]}" >>"$log" 2>&1   # warm-up
    for ((i = 0; i < whole_runs; i++)); do
      t0=$(now_ns); "${lk[@]}" >>"$log" 2>&1
      record "$r" "$label-run" litkit "$(( ($(now_ns) - t0) / 1000 ))e-3"
      t0=$(now_ns); "${gl[@]}" >>"$log" 2>&1
      record "$r" "$label-run" opengl "$(( ($(now_ns) - t0) / 1000 ))e-3"
    done
    local side
    for side in litkit opengl; do
      record "$r" "$label" "$side" "$(awk -F'\t' -v r="$r" -v l="$label-run" -v s="$side" \
        '$1 == r && $2 == l && $3 == s { print $4 + 0 }' "$raw" | median)"
    done
  fi
  # peak memory of the 1080p whole process, once per round, outside the timing
  if [ "$h" -ge 1080 ] && [ -n "$gnu_time" ]; then
    timed "${lk[@]}" >/dev/null; record "$r" "$label" litkit-rss "" "$(last_rss)"
    timed "${gl[@]}" >/dev/null; record "$r" "$label" opengl-rss "" "$(last_rss)"
  fi
}

# ---- steady frames ---------------------------------------------------------------
# A steady-frame row: label, scene file ("" = the built-in default), and for
# the reflection × shading rows the models.
rows=()
add_row() { rows+=("$1|$2|${3:-}|${4:-}"); }
add_row "cube (default)" ""
add_row "full-screen fill" "$scenes/fill.toml"
add_row "sphere 65k" "$scenes/sphere-65k.toml"
add_row "sphere 261k" "$scenes/sphere-261k.toml"
add_row "teapot 64" "$scenes/teapot-64.toml"
for reflection in lambert half-lambert phong blinn-phong; do
  for shading in flat gouraud phong; do
    add_row "65k $reflection/$shading" "$scenes/sphere-65k.toml" "$reflection" "$shading"
  done
done

# `litkit bench` may not take --reflection/--shading: then it gets a copy of
# the scene with [lighting] rewritten (the peer takes the flags).
litkit_bench_flags=no
"$litkit" bench --help 2>/dev/null | grep -q -- '--reflection' && litkit_bench_flags=yes
litkit_scene_for() {  # scene, reflection, shading -> path
  local scene=$1 reflection=$2 shading=$3
  if [ -z "$reflection" ] || [ $litkit_bench_flags = yes ]; then echo "$scene"; return; fi
  local copy=$out/$(basename "$scene" .toml)-$reflection-$shading.toml
  sed -e "s/^reflection = .*/reflection = \"$reflection\"/" \
      -e "s/^shading = .*/shading = \"$shading\"/" "$scene" >"$copy"
  echo "$copy"
}

frame_ms() { sed -n 's/^median_frame_ms=\([0-9.]*\).*/\1/p' | tail -n1; }

steady_round() {  # round, row, first side
  local r=$1 first=$3 label scene reflection shading
  IFS='|' read -r label scene reflection shading <<<"$2"
  local lk=("$litkit" bench) gl=("$peer")
  if [ -n "$scene" ]; then
    lk+=("$(litkit_scene_for "$scene" "$reflection" "$shading")")
    gl+=("$scene")
  fi
  lk+=(--width 1920 --height 1080 --frames "$frames" --threads "$threads")
  gl+=(--width 1920 --height 1080 --frames "$frames")
  if [ -n "$reflection" ]; then
    gl+=(--reflection "$reflection" --shading "$shading")
    [ $litkit_bench_flags = yes ] && lk+=(--reflection "$reflection" --shading "$shading")
  fi
  local side
  for side in $first $([ "$first" = litkit ] && echo opengl || echo litkit); do
    local ms
    if [ "$side" = litkit ]; then
      ms=$(timed "${lk[@]}" | tee -a "$log" | frame_ms)
    else
      ms=$(timed "${gl[@]}" | tee -a "$log" | frame_ms)
    fi
    [ -n "$ms" ] || { echo "error: $side gave no median_frame_ms for '$label' (see $log)" >&2; exit 1; }
    record "$r" "$label" "$side" "$ms" "$(last_rss)"
  done
}

# ---- the rounds --------------------------------------------------------------------
for ((r = 1; r <= rounds; r++)); do
  first=$([ $((r % 2)) = 1 ] && echo litkit || echo opengl)
  idle=$(idle_percent)
  echo "round $r/$rounds (machine ${idle}% idle before it) ..." >&2
  [ "$idle" -ge 90 ] || busy_rounds+=" $r (${idle}% idle)"
  whole_round "$r" "default 800x600 to PNG" 800 600 "$first"
  whole_round "$r" "default 1920x1080 to PNG" 1920 1080 "$first"
  for row in "${rows[@]}"; do steady_round "$r" "$row" "$first"; done
done

# ---- the table ---------------------------------------------------------------------
med_of() {  # label, side, column (4 ms, 5 rss) -> median over rounds
  awk -F'\t' -v l="$1" -v s="$2" -v c="$3" '$2 == l && $3 == s && $c != "" { print $c }' "$raw" | median
}
mib() { [ "$1" = nan ] && echo "-" || awk -v k="$1" 'BEGIN { printf "%.0f", k / 1024 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "nan" || b == "nan" || a <= 0) print "-"; else printf "%.2f", b / a }'; }

# The lowest and highest of the per-round ratios: how much the rounds agree.
spread() {
  awk -F'\t' -v l="$1" '$2 == l && $3 == "litkit" { a[$1] = $4 } $2 == l && $3 == "opengl" { b[$1] = $4 }
    END { n = 0; for (r in a) if ((r in b) && a[r] > 0) { q = b[r] / a[r]; if (!n || q < lo) lo = q; if (!n || q > hi) hi = q; n++ }
          if (n) printf "%.2f-%.2f", lo, hi; else print "-" }' "$raw"
}
line() { printf '%-28s %10s %10s %7s %11s %11s %11s\n' "$@"; }
line "scene (1920x1080 unless said)" "litkit ms" "OpenGL ms" "ratio" "per round" "litkit MiB" "OpenGL MiB"
line "----------------------------" "---------" "---------" "-----" "---------" "----------" "----------"
for label in "default 800x600 to PNG" "default 1920x1080 to PNG"; do
  a=$(med_of "$label" litkit 4); b=$(med_of "$label" opengl 4)
  line "$label" "$(printf %.1f "$a")" "$(printf %.1f "$b")" "$(ratio "$a" "$b")" "$(spread "$label")" \
       "$(mib "$(med_of "$label" litkit-rss 5)")" "$(mib "$(med_of "$label" opengl-rss 5)")"
done
for row in "${rows[@]}"; do
  label=${row%%|*}
  a=$(med_of "$label" litkit 4); b=$(med_of "$label" opengl 4)
  line "$label" "$(printf %.2f "$a")" "$(printf %.2f "$b")" "$(ratio "$a" "$b")" "$(spread "$label")" \
       "$(mib "$(med_of "$label" litkit 5)")" "$(mib "$(med_of "$label" opengl 5)")"
done
echo
echo "ratio = OpenGL time / litkit time (> 1: litkit faster), of the medians over $rounds round(s);"
echo "per round: the lowest and highest ratio of a single round (both sides run back to back)."
echo "to PNG rows: whole process, start to file written; the others: median frame time."
idle=$(idle_percent)
[ "$idle" -ge 90 ] || busy_rounds+=" end (${idle}% idle)"
[ -z "$busy_rounds" ] || echo "warning: the machine was busy before or after round(s)$busy_rounds: rerun on a quiet machine"
echo "raw numbers: $raw"
