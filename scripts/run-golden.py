#!/usr/bin/env python3
"""Golden CLI tests: runs the real arbiter binary on tests/golden/<verb>/* and compares exit
code, stdout and stderr with the sibling <name>.expected file.

Each input may hold an `ARGS:` comment (in ARB files on a line after the header, e.g.
`# ARGS: --format json`); the command is `arbiter <verb> ARGS... <name>` run from the
directory of the input, so paths in outputs are relative. Files named *.args hold a whole
argument list instead of an input (for --help and flag tests). `--update` rewrites the
expectations; review the diff.
"""
import argparse
import difflib
import os
import re
import shlex
import subprocess
import sys

EXTS = (".vp", ".fp", ".arbvp", ".arbfp", ".vert", ".frag", ".args")


def expected_text(code, out, err):
    return f";;; exit: {code}\n;;; stdout:\n{out};;; stderr:\n{err}"


def run_case(binary, verb_dir, name):
    verb = os.path.basename(verb_dir)
    path = os.path.join(verb_dir, name)
    with open(path, "rb") as f:
        text = f.read().decode("utf-8", "replace")
    if name.endswith(".args"):
        argv = shlex.split(text.strip())
    else:
        m = re.search(r"ARGS:(.*)", text)
        extra = shlex.split(m.group(1)) if m else []
        argv = [verb] + extra + [name]
    env = dict(os.environ, NO_COLOR="1", TERM="dumb", LC_ALL="C")
    p = subprocess.run([binary] + argv, cwd=verb_dir, capture_output=True, env=env, timeout=60)
    return expected_text(p.returncode, p.stdout.decode("utf-8", "replace"),
                         p.stderr.decode("utf-8", "replace"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("verb_dir")
    ap.add_argument("--update", action="store_true")
    ap.add_argument("--only", action="append", default=[],
                    help="run (or update) only this input; repeatable")
    args = ap.parse_args()
    binary = os.path.abspath(args.binary)
    names = sorted(n for n in os.listdir(args.verb_dir)
                   if n.endswith(EXTS) and (not args.only or n in args.only))
    passed = failed = 0
    for name in names:
        got = run_case(binary, args.verb_dir, name)
        exp_path = os.path.join(args.verb_dir, name + ".expected")
        if args.update:
            with open(exp_path, "w") as f:
                f.write(got)
            passed += 1
            continue
        try:
            with open(exp_path) as f:
                want = f.read()
        except FileNotFoundError:
            print(f"FAIL {name}: no {name}.expected (run with --update)")
            failed += 1
            continue
        if got == want:
            passed += 1
        else:
            failed += 1
            print(f"FAIL {name}")
            sys.stdout.writelines(difflib.unified_diff(
                want.splitlines(True), got.splitlines(True), "expected", "actual"))
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not names else 0


if __name__ == "__main__":
    sys.exit(main())
