#!/usr/bin/env python3
"""`arbiter run` over a shader-test corpus (issue 6's acceptance checks).

  run_corpus.py ARBITER DIR pass [RUN-OPTIONS...]
      every test under DIR passes (none fails or skips) with the given options
      (--translate, --driver, --backend).
  run_corpus.py ARBITER DIR translated [RUN-OPTIONS...]
      the same, except that a test may be skipped because the --translate=T target refuses
      its programs (a construct the dialect cannot express, named in the SKIP message), and
      the tests translate-known-gaps.txt lists for T must fail (and no other).
  run_corpus.py ARBITER DIR deviation [RUN-OPTIONS...]
      every test under DIR fails: each states what the specification requires where Mesa
      deviates (corpus/exec-deviations/README.md); a pass means Mesa changed and the
      deviation table must be revisited.
"""
import os
import subprocess
import sys


def known_gaps(options):
    """The tests translate-known-gaps.txt lists for the --translate=T among `options`."""
    target = next((o.split("=", 1)[1] for o in options if o.startswith("--translate=")), None)
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "translate-known-gaps.txt")
    gaps = set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            fields = line.split(None, 2)
            if len(fields) >= 2 and not line.startswith("#") and fields[0] == target:
                gaps.add(fields[1])
    return gaps


def main():
    arbiter, corpus, mode, options = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    p = subprocess.run([arbiter, "run", "-j", "2", *options, corpus], capture_output=True,
                       text=True, timeout=1800)
    print(p.stdout[-20000:])
    print(p.stderr, file=sys.stderr)
    lines = p.stdout.splitlines()
    statuses = [l.split(" ", 1)[0] for l in lines if l[:5] in ("PASS ", "FAIL ", "SKIP ")]
    if not statuses:
        print("run_corpus: no test ran")
        return 1
    if mode in ("pass", "translated"):
        bad = [l for l in lines if l.startswith(("FAIL ", "SKIP "))]
        if mode == "translated":
            gaps = known_gaps(options)
            is_gap = lambda l: any(l.endswith("/" + g) for g in gaps)
            # A SKIP's first message line says why: only a target's refusal is expected.
            bad = [l for i, l in enumerate(lines) if (l.startswith("FAIL ") and not is_gap(l)) or (
                l.startswith("SKIP ") and "refuses the program" not in
                (lines[i + 1] if i + 1 < len(lines) else ""))]
            fixed = [l for l in lines if l.startswith("PASS ") and is_gap(l)]
            for l in fixed:
                print(f"run_corpus: a known gap passes now, remove it from "
                      f"translate-known-gaps.txt: {l}")
            bad += fixed
            print(f"run_corpus: {sum(1 for l in lines if l.startswith('FAIL ') and is_gap(l))} "
                  f"known gap(s) failed as listed")
            refused = sum(1 for l in lines if l.startswith("SKIP ")) - sum(
                1 for l in bad if l.startswith("SKIP "))
            print(f"run_corpus: {refused} test(s) refused by the target")
        expected_exit = 1 if mode == "translated" and any(
            l.startswith("FAIL ") for l in lines) else 0
        if p.returncode != expected_exit or bad:
            print(f"run_corpus: {len(bad)} test(s) did not pass (exit {p.returncode})")
            return 1
    else:
        passed = [l for l in lines if l.startswith(("PASS ", "SKIP "))]
        if p.returncode != 1 or passed:
            print(f"run_corpus: {len(passed)} deviation test(s) no longer fail: update the table")
            return 1
    print(f"run_corpus: {len(statuses)} test(s) as expected")
    return 0


if __name__ == "__main__":
    sys.exit(main())
