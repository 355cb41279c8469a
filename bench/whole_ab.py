#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Interleaved whole-process timing of a few commands.

    bench/whole_ab.py RUNS 'CMD A' 'CMD B' [...]

Runs each command RUNS times, the commands alternating (their order
reversed every other round, so that neither always follows the other),
each started with posix_spawn (no shell) with its output discarded, and
prints per command the median, first and third quartile of the wall time
from spawn to exit. A command may start with NAME=VALUE words, which go
into its environment. Example, two builds of litkit writing the default
scene's PNG:

    bench/whole_ab.py 300 'OLD/litkit render -o /tmp/a.png --width 800 --height 600' \\
                          'NEW/litkit render -o /tmp/b.png --width 800 --height 600'

Timing, not a test: nothing passes or fails.
"""
import os
import statistics
import sys
import time


def split_environment(words):
    environment = dict(os.environ)
    while words and "=" in words[0] and not words[0].startswith("/"):
        name, value = words[0].split("=", 1)
        environment[name] = value
        words = words[1:]
    return words, environment


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    runs = int(sys.argv[1])
    commands = [split_environment(text.split()) for text in sys.argv[2:]]
    times = [[] for _ in commands]
    null = os.open(os.devnull, os.O_WRONLY)
    quiet = [(os.POSIX_SPAWN_DUP2, null, 1), (os.POSIX_SPAWN_DUP2, null, 2)]
    for run in range(runs):
        order = list(range(len(commands)))
        if run % 2:
            order.reverse()
        for k in order:
            words, environment = commands[k]
            start = time.perf_counter_ns()
            pid = os.posix_spawn(words[0], words, environment, file_actions=quiet)
            _, status = os.waitpid(pid, 0)
            times[k].append((time.perf_counter_ns() - start) / 1e6)
            if status != 0:
                sys.exit(f"whole_ab: '{sys.argv[2 + k]}' failed (status {status})")
    for k, text in enumerate(sys.argv[2:]):
        t = sorted(times[k])
        print(f"{text[:70]:70}  median {statistics.median(t):6.2f} ms  "
              f"p25 {t[len(t) // 4]:6.2f}  p75 {t[3 * len(t) // 4]:6.2f}")


if __name__ == "__main__":
    main()
