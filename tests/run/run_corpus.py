#!/usr/bin/env python3
"""`arbiter run` over a shader-test corpus (issue 6's acceptance checks).

  run_corpus.py ARBITER DIR pass [RUN-OPTIONS...]
      every test under DIR passes (none fails or skips) with the given options
      (--translate, --driver, --backend).
  run_corpus.py ARBITER DIR translated [RUN-OPTIONS...]
      the same, except that a test may be skipped because the --translate=T target refuses
      its programs (a construct the dialect cannot express, named in the SKIP message).
  run_corpus.py ARBITER DIR deviation [RUN-OPTIONS...]
      every test under DIR fails: each states what the specification requires where Mesa
      deviates (corpus/exec-deviations/README.md); a pass means Mesa changed and the
      deviation table must be revisited.
"""
import subprocess
import sys


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
            # A SKIP's first message line says why: only a target's refusal is expected.
            bad = [l for i, l in enumerate(lines) if l.startswith("FAIL ") or (
                l.startswith("SKIP ") and "refuses the program" not in
                (lines[i + 1] if i + 1 < len(lines) else ""))]
            refused = sum(1 for l in lines if l.startswith("SKIP ")) - sum(
                1 for l in bad if l.startswith("SKIP "))
            print(f"run_corpus: {refused} test(s) refused by the target")
        if p.returncode != 0 or bad:
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
