#!/usr/bin/env python3
"""arbiter verify over the ARB corpus (issue 5's acceptance checks).

  verify_corpus.py ARBITER CORPUS agree DRIVER
      every valid program verifies on DRIVER with zero disagreements and no engine error
      (undefined components, unstable ones and the documented deviations are reported by
      verify and not counted here).
  verify_corpus.py ARBITER CORPUS mutations [--sanitized]
      each test-only translator mutation of the ARB instructions (arbiter/arbvp/
      emit_mutation.h), injected alone into the GLSL translation, makes verify report a
      disagreement on at least one corpus program; the 0^0 rule of LIT is checked on
      llvmpipe, the driver whose pow(0, 0) differs from 1.
  verify_corpus.py ARBITER CORPUS mutations-nv [--sanitized]
      the same for the mutations of the NV options' constructs, over the NV corpus
      (corpus/arb/valid-nv: the interpreter against Mesa running the translation).
      --sanitized (the binary runs under ASan/UBSan, where the reference interpreter is ten
      times slower): 64 random vectors per program instead of verify's default, besides
      the edge vectors; every mutation is still caught (measured on this corpus).
"""
import json
import subprocess
import sys

# The mutations of arbvp::Mutation (emit_mutation.h), in its order: those of the ARB
# instructions, then those of the NV options (an unknown name is a usage error).
MUTATIONS = [
    "rsq-no-abs", "lrp-operand-order", "matrix-rows-columns", "lit-no-zero-pow-zero",
    "lit-exponent-clamp-180", "lit-no-y-clamp", "swz-sign-lost", "swz-zero-one-swapped",
    "arl-truncate", "saturate-dropped", "kil-on-nan", "kil-only-x", "fog-exp-as-exp2",
    "fog-linear-start-end", "cmp-less-equal", "dph-no-w", "dst-components",
    "xpd-operand-order", "log-no-abs", "exp-fraction", "txp-no-divide", "negation-dropped",
    "write-mask-ignored", "scs-sin-cos-swapped", "pow-operands-swapped", "frc-truncate",
    "sge-strict", "fog-color-unclamped",
]
NV_MUTATIONS = [
    "cc-update-ignored", "cc-gt-as-ge", "cc-write-mask-ignored", "fp16-rounding-dropped",
    "fx12-clamp-dropped", "ssat-unit-range", "ssg-zero-positive", "div-by-vector",
    "brk-ignored", "rep-count-plus-one", "rfl-no-double", "seq-sne-swapped",
]
DRIVER = {"lit-no-zero-pow-zero": "llvmpipe"}


def verify(arbiter, corpus, *args):
    cmd = [arbiter, "verify", corpus, "--format", "json", *args]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode not in (0, 1):
        sys.exit(f"{' '.join(cmd)}: exit {proc.returncode}\n{proc.stderr[-2000:]}")
    return proc.returncode, json.loads(proc.stdout)


def agree(arbiter, corpus, driver):
    rc, report = verify(arbiter, corpus, "--driver", driver)
    bad = [p for p in report["programs"] if p["verdict"] != "agree"]
    for p in bad:
        print(f"{p['file']}: {p['verdict']} {p.get('error', '')}")
        for d in p["disagreements"][:5]:
            print("   ", json.dumps(d))
    print(f"{len(report['programs'])} programs on {driver}, {len(bad)} not agreeing")
    return 1 if bad or rc != 0 or not report["programs"] else 0


def mutations(arbiter, corpus, names, extra):
    missed = []
    for m in names:
        driver = DRIVER.get(m, "softpipe")
        _, report = verify(arbiter, corpus, "--engines", "ref,mesa-glsl", "--mutation", m,
                           "--driver", driver, "--max-reports", "0", *extra)
        caught = [p["file"] for p in report["programs"] if p["verdict"] == "disagree"]
        print(f"{m} ({driver}): caught by {len(caught)} program(s)"
              + (f", e.g. {caught[0]}" if caught else ""))
        if not caught:
            missed.append(m)
    if missed:
        print("not caught:", ", ".join(missed))
    return 1 if missed else 0


def main():
    arbiter, corpus, mode = sys.argv[1:4]
    if mode == "agree":
        return agree(arbiter, corpus, sys.argv[4])
    if mode in ("mutations", "mutations-nv"):
        extra = ["--vectors", "64"] if "--sanitized" in sys.argv[4:] else []
        return mutations(arbiter, corpus, MUTATIONS if mode == "mutations" else NV_MUTATIONS,
                         extra)
    sys.exit(f"unknown mode {mode}")


if __name__ == "__main__":
    sys.exit(main())
