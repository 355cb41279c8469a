#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Set-up time of the 261k-triangle sphere (meshes, normals, world space: the
# `setup:` line of `litkit bench`), fresh processes, for each normals option,
# interleaved between two litkit binaries:
#   bench/setup.sh OLD_LITKIT NEW_LITKIT [ROUNDS] [THREADS]
# Prints per option the median over rounds for each binary, and what each
# option adds to `mean` (the default). THREADS threads (1 unless given; the
# renderer lends them to mesh building); one frame after set-up.
# Timing only: nothing here passes or fails.
set -euo pipefail
old=$1 new=$2 rounds=${3:-7} threads=${4:-1}
scene="$(cd "$(dirname "$0")" && pwd)/scenes/sphere-261k.toml"
options=("" "--normals area" "--normals angle" "--normals max" "--crease-angle 60"
         "--normals angle --crease-angle 60")
names=(mean area angle max "mean + crease 60" "angle + crease 60")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "load: $(uptime)"
setup_ms() {  # binary option-index
    # shellcheck disable=SC2086
    "$1" bench "$scene" --frames 1 --threads "$threads" ${options[$2]} |
        sed -n 's/^setup: \([0-9.]*\) ms.*/\1/p'
}
for ((r = 0; r < rounds; r++)); do
    for i in "${!options[@]}"; do
        if ((r % 2)); then setup_ms "$new" "$i" >> "$tmp/new-$i"; setup_ms "$old" "$i" >> "$tmp/old-$i"
        else setup_ms "$old" "$i" >> "$tmp/old-$i"; setup_ms "$new" "$i" >> "$tmp/new-$i"; fi
    done
done
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
printf '| normals | old ms | new ms | old: added to mean | new: added to mean |\n| --- | ---: | ---: | ---: | ---: |\n'
old_mean=$(median < "$tmp/old-0"); new_mean=$(median < "$tmp/new-0")
for i in "${!options[@]}"; do
    o=$(median < "$tmp/old-$i"); n=$(median < "$tmp/new-$i")
    awk -v name="${names[$i]}" -v o="$o" -v n="$n" -v om="$old_mean" -v nm="$new_mean" \
        'BEGIN {printf "| %s | %.1f | %.1f | %+.1f | %+.1f |\n", name, o, n, o - om, n - nm}'
done
echo "load: $(uptime)"
