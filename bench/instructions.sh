#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per steady frame of the CPU backend, counted by callgrind
# (repeatable where wall time is not): bench/instructions.sh LITKIT [FRAMES]
# Counts only inside Renderer::render_into, at 1920x1080, on 1 thread (so
# that all the work runs under render_into, on the calling thread). Valgrind
# reports no AVX-512 to the program, so this measures the AVX2 kernel set.
set -euo pipefail
litkit=$1 frames=${2:-3}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for scene in default "$here/scenes/fill.toml" "$here/scenes/sphere-261k.toml" "$here/scenes/teapot-64.toml"; do
    args=(); [[ $scene == default ]] || args=("$scene")
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg" \
        --toggle-collect='litkit::Renderer::render_into*' \
        "$litkit" bench "${args[@]}" --frames "$frames" --width 1920 --height 1080 --threads 1 \
        > /dev/null 2> "$tmp/log"
    total=$(sed -n 's/^==[0-9]*== Collected : \([0-9]*\).*/\1/p' "$tmp/log")
    # litkit bench draws one warm-up frame before the timed ones.
    printf "%-16s %8.1f M instructions per frame\n" "$(basename "$scene")" \
        "$(echo "$total / ($frames + 1) / 1000000" | bc -l)"
done
