#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Interleaved A/B timing of two litkit binaries on the CPU backend:
#   bench/ab.sh OLD_LITKIT NEW_LITKIT [ROUNDS] [FRAMES]
# Each round runs every scene on both binaries, alternating which goes first;
# prints per scene the median over rounds of `litkit bench`'s median frame
# time, and of the process's CPU time per frame (user + system, from GNU
# time), which moves less than wall time when other work shares the machine.
# Last row: the whole process, `litkit render` of the default scene (800x600)
# to a PNG file, wall and CPU time per run (median of FRAMES runs a round).
set -euo pipefail
old=$1 new=$2 rounds=${3:-5} frames=${4:-30}
here=$(cd "$(dirname "$0")" && pwd)
scenes=("" "$here/scenes/fill.toml" "$here/scenes/sphere-261k.toml" "$here/scenes/teapot-64.toml")
names=(default-cube fill sphere-261k teapot-64)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "load: $(uptime)"
run() {  # binary scene-index side round
    local scene=${scenes[$2]}
    /usr/bin/time -f "%U %S" -o "$tmp/t" "$1" bench ${scene:+"$scene"} --frames "$frames" \
        --width 1920 --height 1080 --threads 2 > "$tmp/out"
    local ms; ms=$(sed -n 's/^median_frame_ms=\([0-9.]*\).*/\1/p' "$tmp/out")
    local cpu; cpu=$(awk -v f="$frames" '{printf "%.3f", ($1 + $2) * 1000 / (f + 1)}' "$tmp/t")
    echo "$ms $cpu" >> "$tmp/$3-$2"
}
whole() {  # binary side: one round of FRAMES whole runs, their medians
    : > "$tmp/w"
    for ((k = 0; k < frames; k++)); do
        local t0; t0=$(date +%s%N)
        /usr/bin/time -f "%U %S" -o "$tmp/t" "$1" render -o "$tmp/out.png" > /dev/null 2>&1
        local t1; t1=$(date +%s%N)
        echo "$(( (t1 - t0) / 1000 )) $(awk '{print ($1 + $2) * 1000}' "$tmp/t")" >> "$tmp/w"
    done
    echo "$(cut -d' ' -f1 "$tmp/w" | median | awk '{printf "%.3f", $1 / 1000}') $(cut -d' ' -f2 "$tmp/w" | median)" >> "$tmp/$2-whole"
}
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
for ((r = 0; r < rounds; r++)); do
    for i in "${!scenes[@]}"; do
        if ((r % 2)); then run "$new" "$i" new; run "$old" "$i" old
        else run "$old" "$i" old; run "$new" "$i" new; fi
    done
    if ((r % 2)); then whole "$new" new; whole "$old" old; else whole "$old" old; whole "$new" new; fi
done
printf "%-12s %10s %10s %7s %12s %12s %7s\n" scene old_ms new_ms ratio old_cpu_ms new_cpu_ms ratio
for i in "${!scenes[@]}"; do
    o=$(cut -d' ' -f1 "$tmp/old-$i" | median); n=$(cut -d' ' -f1 "$tmp/new-$i" | median)
    oc=$(cut -d' ' -f2 "$tmp/old-$i" | median); nc=$(cut -d' ' -f2 "$tmp/new-$i" | median)
    printf "%-12s %10.2f %10.2f %7.2f %12.2f %12.2f %7.2f\n" "${names[$i]}" "$o" "$n" \
        "$(echo "$o / $n" | bc -l)" "$oc" "$nc" "$(echo "$oc / $nc" | bc -l)"
done
o=$(cut -d' ' -f1 "$tmp/old-whole" | median); n=$(cut -d' ' -f1 "$tmp/new-whole" | median)
oc=$(cut -d' ' -f2 "$tmp/old-whole" | median); nc=$(cut -d' ' -f2 "$tmp/new-whole" | median)
printf "%-12s %10.2f %10.2f %7.2f %12.2f %12.2f %7.2f\n" "whole-800" "$o" "$n" \
    "$(echo "$o / $n" | bc -l)" "$oc" "$nc" "$(echo "$oc / $nc" | bc -l)"
echo "load: $(uptime)"
