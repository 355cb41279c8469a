#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/timeline.sh RUNS LITKIT [ARGUMENTS...]
#
# Where the time of a whole `litkit` process goes:
# uprobes at the entry and return of its phases' functions (main, the
# default scene, the renderer's constructor, render_into, encode_png, the
# PNG's halves, write_file_atomically), RUNS runs recorded with
# `perf record`, and per event the median, least and most milliseconds
# since exec. Needs perf and root (uprobes); the probes cost a few
# microseconds each, and more where a thread is created, so they show
# where the time goes, not how long the whole takes (bench/whole_ab.py).
#
#   sudo bench/timeline.sh 30 build/litkit render -o /tmp/x.png --width 800 --height 600
set -euo pipefail
runs=$1
binary=$(realpath "$2")
shift 2
data=$(mktemp)
trap 'rm -f "$data"; perf probe -q -d "probe_litkit:*" 2>/dev/null || true' EXIT
perf probe -q -d 'probe_litkit:*' 2>/dev/null || true
address() { nm -C "$binary" | grep -E " [Tt] $1" | grep -v '\.cold' | head -n 1 | awk '{print "0x" $1}'; }
for pair in "main:main$" "scene:litkit::default_scene\(\)" "renderer:litkit::Renderer::Renderer\(" \
            "draw:litkit::Renderer::render_into\(" "png:litkit::encode_png" \
            "half:litkit::\(anonymous namespace\)::deflate_rows" "file:litkit::write_file_atomically"; do
    name=${pair%%:*}
    at=$(address "${pair#*:}")
    [ -n "$at" ] || continue
    perf probe -q -x "$binary" -a "${name}_in=$at" >/dev/null 2>&1 || true
    perf probe -q -x "$binary" -a "${name}_out=$at%return" >/dev/null 2>&1 || true
done
perf record -q -e 'probe_litkit:*' -e syscalls:sys_enter_execve -e sched:sched_process_exit \
    -o "$data" -- bash -c 'for ((i = 0; i < '"$runs"'; i++)); do "$@" >/dev/null 2>&1; done' _ \
    "$binary" "$@" 2>/dev/null
perf script -i "$data" -F comm,tid,time,event 2>/dev/null | python3 -c '
import statistics, sys
order, times, start, main = [], {}, None, None
for line in sys.stdin:
    words = line.split()
    comm, tid, at = words[0], int(words[1]), float(words[2].rstrip(":")) * 1000
    event = words[3].rstrip(":").split(":")[-1].replace("__return", "")
    if event == "sys_enter_execve":
        start, main = at, None
        continue
    if start is None or not comm.startswith("litkit"):
        continue
    if event == "sched_process_exit":
        if tid != main:
            continue
        event = "exit"
    if event == "main_in":
        main = tid
    if event not in times:
        order.append(event)
        times[event] = []
    times[event].append(at - start)
for event in order:
    t = times[event]
    print("%-14s n=%4d  median %7.2f ms  (least %6.2f, most %6.2f)"
          % (event, len(t), statistics.median(t), min(t), max(t)))
'
