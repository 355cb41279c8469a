#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints one SHA-256 line per output of a fixed set of litkit runs over every
# example and bench scene: renders on the CPU (1 and 2 threads) and through
# OpenGL, the compare sheet (every reflection x shading pair), every normals
# weighting, a turntable (GIF, PNG frames, animated PNG), explain --json of
# a pixel, and the GLSL and C++ exports. Used to show that a change which
# should leave every picture alone did: run it before and after and diff the
# two lists.
#
#   scripts/picture-hashes.sh [LITKIT] > hashes.txt
set -uo pipefail
cd "$(dirname "$0")/.."
litkit=$(realpath "${1:-build/litkit}")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
run() {  # NAME ARGS...: runs litkit ARGS, hashes what it wrote under $out/NAME
  local name=$1; shift
  mkdir -p "$out/$name"
  if "$litkit" "$@" >"$out/$name/stdout" 2>"$out/$name/stderr"; then :; else echo "exit $? " >>"$out/$name/stdout"; fi
  # Times vary from run to run: out of what is compared.
  sed -i -E -e 's/[0-9.]+ ms\b/T ms/g' -e "s|$out|OUT|g" "$out/$name/stdout" "$out/$name/stderr"
  (cd "$out/$name" && find . -type f -print0 | sort -z | xargs -0 sha256sum) | sed "s|  \./|  $name/|"
}
for scene in examples/*.toml examples/multi-file/*.toml bench/scenes/*.toml; do
  n=$(basename "${scene%.toml}")
  for t in 1 2; do
    run "$n-cpu$t" render "$scene" -y --threads $t -o "$out/$n-cpu$t/p.png"
  done
  case $n in sphere-261k|teapot-64) continue ;; esac
  run "$n-gl" render "$scene" -y --backend gl -o "$out/$n-gl/p.png"
  for w in mean area angle max; do
    run "$n-$w" render "$scene" -y --normals $w --crease-angle 40 --width 200 --height 150 -o "$out/$n-$w/p.png"
  done
  run "$n-compare" compare "$scene" -y --width 120 --height 90 -o "$out/$n-compare/p.png"
  run "$n-explain" explain "$scene" -y --pixel 400,300 --json
  run "$n-explain-text" explain "$scene" -y --pixel 380,280
  run "$n-glsl" export "$scene" -y --format glsl -o "$out/$n-glsl/x"
  run "$n-cpp" export "$scene" -y --format cpp -o "$out/$n-cpp/x" --name prog
done
run default-turntable turntable --frames 8 --width 160 --height 120 -o "$out/default-turntable/t.gif"
run default-turntable-png turntable --frames 4 --width 160 --height 120 -o "$out/default-turntable-png/d/"
run default-turntable-apng turntable --frames 4 --width 160 --height 120 -o "$out/default-turntable-apng/t.png"
