#!/usr/bin/env python3
"""Median ratio of two commands' wall times, run in pairs (A then B, N times).

On a shared machine the same command drifts by 10-30 % from one minute to the next; within
a pair the drift mostly cancels, so the median of the per-pair ratios is steadier than a
ratio of means. Usage:
  bench/pair-ratio.py N 'COMMAND A' 'COMMAND B'
A word FILES in a command stands for the paths listed (one per line) in $FILELIST, for lists
longer than an environment variable may hold. Output goes to /dev/null.
"""
import os
import statistics
import subprocess
import sys
import time


def expand(command, files):
    words = []
    for word in command.split():
        words += files if word == "FILES" else [word]
    return words


def timed(argv):
    start = time.perf_counter()
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    return time.perf_counter() - start


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    runs = int(sys.argv[1])
    files = open(os.environ["FILELIST"]).read().split() if "FILELIST" in os.environ else []
    a, b = expand(sys.argv[2], files), expand(sys.argv[3], files)
    times_a, times_b, ratios = [], [], []
    for _ in range(runs):
        ta, tb = timed(a), timed(b)
        times_a.append(ta)
        times_b.append(tb)
        ratios.append(ta / tb)
    ratios.sort()
    print(f"A median {statistics.median(times_a) * 1000:.1f} ms (min {min(times_a) * 1000:.1f}), "
          f"B median {statistics.median(times_b) * 1000:.1f} ms (min {min(times_b) * 1000:.1f}), "
          f"A/B: median {statistics.median(ratios):.2f}, "
          f"quartiles {ratios[len(ratios) // 4]:.2f}-{ratios[3 * len(ratios) // 4]:.2f}")


if __name__ == "__main__":
    main()
