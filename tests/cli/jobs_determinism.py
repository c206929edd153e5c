#!/usr/bin/env python3
"""check -j N gives byte-identical output, in input order, whatever N (corpus of ARB programs)."""
import subprocess
import sys

binary, corpus = sys.argv[1], sys.argv[2]
outputs = {}
for jobs in ("1", "2", "8"):
    for fmt in ("json", "text"):
        p = subprocess.run([binary, "check", "-j", jobs, "--format", fmt, corpus],
                           capture_output=True, env={"NO_COLOR": "1", "LC_ALL": "C"})
        outputs.setdefault(fmt, []).append((jobs, p.returncode, p.stdout + p.stderr))
failed = 0
for fmt, runs in outputs.items():
    first = runs[0]
    for run in runs[1:]:
        if run[1:] != first[1:]:
            print(f"FAIL --format {fmt}: -j {run[0]} differs from -j {first[0]}")
            failed += 1
passed = sum(len(r) - 1 for r in outputs.values()) - failed
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
