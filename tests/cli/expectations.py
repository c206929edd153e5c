"""The pass/fail tally of the CLI test scripts: expect() records one check (and prints it when
it fails), finish() prints the counts and exits 0 when nothing failed, 1 otherwise."""
import sys

_counts = {"passed": 0, "failed": 0}


def expect(what, ok, detail=""):
    if ok:
        _counts["passed"] += 1
    else:
        _counts["failed"] += 1
        print(f"FAIL {what}" + (f": {detail}" if detail else ""))


def finish():
    print(f"{_counts['passed']} passed, {_counts['failed']} failed")
    sys.exit(1 if _counts["failed"] else 0)
