#!/usr/bin/env python3
"""Batch commands give byte-identical output, in input order, whatever -j: check over the ARB
and GLSL corpora (text and JSON), translate into a directory (the files written), and verify
over a sample of the ARB corpus. Usage: jobs_determinism.py ARBITER CORPUS_DIR."""
import filecmp
import os
import subprocess
import sys
import tempfile

binary, corpus = sys.argv[1], sys.argv[2]
env = {"NO_COLOR": "1", "LC_ALL": "C", "PATH": os.environ.get("PATH", "")}
valid = os.path.join(corpus, "arb", "valid")
sample = sorted(os.path.join(valid, f) for f in os.listdir(valid))[::12]
failed = 0
passed = 0


def run(args):
    p = subprocess.run([binary] + args, capture_output=True, env=env)
    return p.returncode, p.stdout, p.stderr


def same_tree(a, b):
    cmp = filecmp.dircmp(a, b)
    if cmp.left_only or cmp.right_only or cmp.diff_files or cmp.funny_files:
        return False
    return all(filecmp.cmp(os.path.join(a, f), os.path.join(b, f), shallow=False)
               for f in cmp.common_files)


def expect_same(name, runs):
    """runs: [(jobs, outcome)]; every outcome must equal the first."""
    global failed, passed
    for jobs, outcome in runs[1:]:
        if outcome != runs[0][1]:
            print(f"FAIL {name}: -j {jobs} differs from -j {runs[0][0]}")
            failed += 1
        else:
            passed += 1


for what in ("arb", "glsl"):
    for fmt in ("json", "text"):
        expect_same(f"check {what} --format {fmt}",
                    [(j, run(["check", "-j", j, "--format", fmt, os.path.join(corpus, what)]))
                     for j in ("1", "2", "8")])

with tempfile.TemporaryDirectory() as tmp:
    trees = []
    for j in ("1", "3"):
        out = os.path.join(tmp, f"j{j}")
        code, stdout, stderr = run(["translate", "-j", j, "-o", out, "--bindings", out, valid])
        trees.append((j, (code, stdout, stderr), out))
    expect_same("translate (exit, output)", [(j, outcome) for j, outcome, _ in trees])
    if same_tree(trees[0][2], trees[1][2]) and os.listdir(trees[0][2]):
        passed += 1
    else:
        print("FAIL translate: the files written with -j 3 differ from those of -j 1")
        failed += 1

expect_same("verify", [(j, run(["verify", "-j", j, "--vectors", "8"] + sample))
                       for j in ("1", "2", "5")])

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
