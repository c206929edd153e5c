#!/usr/bin/env python3
"""How much faster `-j 2` is than `-j 1`, beside what the machine itself gives two processes.

Each round runs, in an order that rotates from round to round:
  j1      COMMAND -j 1 on all the files
  j2      COMMAND -j 2 on all the files
  halves  two `COMMAND -j 1` processes side by side, one on the even-numbered files and one
          on the odd-numbered ones (the same work with nothing shared: what two cores of
          this machine give, the ceiling for -j 2)
and prints the medians of the per-round ratios j1/j2 and j1/halves with their quartiles.
On a shared machine the same command drifts by 10-30 % from one minute to the next; within
a round the drift mostly cancels. Usage:
  bench/scaling.py ROUNDS FILELIST COMMAND...
FILELIST names a file with one input path per line; COMMAND is the arbiter command without
-j and files, e.g. `build/release/cli/arbiter check`. Output goes to /dev/null.
"""
import statistics
import subprocess
import sys
import time


def run_all(argvs):
    start = time.perf_counter()
    procs = [
        subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for argv in argvs
    ]
    for proc in procs:
        proc.wait()
    return time.perf_counter() - start


def describe(name, ratios):
    q = statistics.quantiles(ratios, n=4) if len(ratios) > 1 else ratios * 3
    return f"{name}: median {statistics.median(ratios):.2f}x, quartiles {q[0]:.2f}-{q[2]:.2f}"


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    rounds = int(sys.argv[1])
    files = open(sys.argv[2]).read().split()
    command = sys.argv[3:]
    variants = {
        "j1": [command + ["-j", "1"] + files],
        "j2": [command + ["-j", "2"] + files],
        "halves": [command + ["-j", "1"] + files[0::2], command + ["-j", "1"] + files[1::2]],
    }
    names = list(variants)
    times = {name: [] for name in names}
    run_all(variants["j2"])  # warm the page cache
    for r in range(rounds):
        for name in names[r % 3 :] + names[: r % 3]:
            times[name].append(run_all(variants[name]))
    for name in names:
        print(f"{name}: median {statistics.median(times[name]) * 1e3:.1f} ms")
    j1 = times["j1"]
    print(describe("j1/j2", [a / b for a, b in zip(j1, times["j2"])]))
    print(describe("j1/halves", [a / b for a, b in zip(j1, times["halves"])]))


if __name__ == "__main__":
    main()
