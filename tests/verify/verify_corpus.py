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
  verify_corpus.py ARBITER CORPUS agree-engine ENGINE DRIVER [--vectors N]
      the same agreement on one target engine (mesa-glsl330, mesa-es300, mesa-es100: the
      target's translation on an EGL core or ES context; vulkan-spirv: the vk450 translation
      as SPIR-V on lavapipe; each fed through the binding map and glstate) alone with ref:
      no disagreement and no error; programs the target refuses
      are reported by verify as not applicable and counted here, not failed.
  verify_corpus.py ARBITER CORPUS mutations-engine ENGINE [--sanitized]
      every mutation of MUTATIONS (but ENGINE_EXEMPT's) caught on ENGINE's path (--engines
      ref,ENGINE); --sanitized: one per family (TARGET_MUTATIONS, or ENGINE_MUTATIONS where
      an engine has its own) with 16 vectors.
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
# Open disagreements of a target engine, by engine and driver ("file.vp" names per
# (engine, driver); docs/verify.md, "Target engines"): listed so that the test stays red for
# anything else, and fails when one of them starts agreeing. None are open.
KNOWN_DISAGREE = {}
# A representative subset for each target engine under the sanitizers (mutations-engine
# --sanitized): one per family of translator bug: operand order, matrix layout, swizzle and
# negation, write masks and saturation, KIL, fog, projective lookups, the approximated
# functions, a step function and the LIT clamp.
TARGET_MUTATIONS = [
    "rsq-no-abs", "lrp-operand-order", "matrix-rows-columns", "swz-sign-lost",
    "negation-dropped", "write-mask-ignored", "saturate-dropped", "kil-on-nan",
    "fog-exp-as-exp2", "txp-no-divide", "sge-strict", "lit-no-y-clamp",
]

# vulkan-spirv runs on lavapipe, whose values computed from a NaN or an infinity are a known
# deviation (llvmpipe-nonfinite, the same compiler as llvmpipe's): kil-on-nan changes only
# kills computed from a NaN, which that deviation leaves uncompared, so the KIL family is
# represented there by kil-only-x.
ENGINE_MUTATIONS = {
    "vulkan-spirv": ["kil-only-x" if m == "kil-on-nan" else m for m in TARGET_MUTATIONS],
}
# The mutations an engine cannot see, left out of its full run: kil-on-nan on vulkan-spirv
# (above; kil-only-x stands for the KIL family).
ENGINE_EXEMPT = {"vulkan-spirv": ("kil-on-nan",)}


def verify(arbiter, corpus, *args):
    cmd = [arbiter, "verify", corpus, "--format", "json", *args]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode not in (0, 1):
        sys.exit(f"{' '.join(cmd)}: exit {proc.returncode}\n{proc.stderr[-2000:]}")
    return proc.returncode, json.loads(proc.stdout)


def agree(arbiter, corpus, driver, *extra, engine=None):
    rc, report = verify(arbiter, corpus, "--driver", driver, *extra)
    known = KNOWN_DISAGREE.get((engine, driver), set())
    name = lambda p: p["file"].rsplit("/", 1)[-1]
    stale = [p["file"] for p in report["programs"] if name(p) in known and p["verdict"] == "agree"]
    for f in stale:
        print(f"{f}: agrees now: remove it from KNOWN_DISAGREE")
    expected = [p for p in report["programs"] if name(p) in known and p["verdict"] == "disagree"]
    for p in expected:
        print(f"{p['file']}: known disagreement on {engine} ({driver})")
    bad = [p for p in report["programs"] if p["verdict"] != "agree" and p not in expected]
    for p in bad:
        print(f"{p['file']}: {p['verdict']} {p.get('error', '')}")
        for d in p["disagreements"][:5]:
            print("   ", json.dumps(d))
    na = [p for p in report["programs"] if p.get("not_applicable")]
    for p in na:
        for engine, why in p["not_applicable"].items():
            print(f"{p['file']}: not applicable on {engine}: {why}")
    print(f"{len(report['programs'])} programs on {driver}, {len(bad)} not agreeing, "
          f"{len(na)} not applicable")
    return 1 if bad or stale or (rc != 0 and not expected) or not report["programs"] else 0


def mutations(arbiter, corpus, names, extra, engine="mesa-glsl"):
    missed = []
    for m in names:
        driver = DRIVER.get(m, "softpipe")
        _, report = verify(arbiter, corpus, "--engines", f"ref,{engine}", "--mutation", m,
                           "--driver", driver, "--max-reports", "0", *extra)
        known = KNOWN_DISAGREE.get((engine, driver), set())
        caught = [p["file"] for p in report["programs"]
                  if p["verdict"] == "disagree" and p["file"].rsplit("/", 1)[-1] not in known]
        print(f"{m} ({engine}, {driver}): caught by {len(caught)} program(s)"
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
    if mode == "agree-engine":
        engine, driver = sys.argv[4:6]
        return agree(arbiter, corpus, driver, "--engines", f"ref,{engine}", *sys.argv[6:],
                     engine=engine)
    if mode == "mutations-engine":
        # Every mutation on each engine; under the sanitizers (ten times slower) one per
        # family, TARGET_MUTATIONS, with 16 vectors.
        sanitized = "--sanitized" in sys.argv[5:]
        extra = ["--vectors", "16"] if sanitized else []
        engine = sys.argv[4]
        names = ENGINE_MUTATIONS.get(engine, TARGET_MUTATIONS) if sanitized else [
            m for m in MUTATIONS if m not in ENGINE_EXEMPT.get(engine, ())]
        return mutations(arbiter, corpus, names, extra, engine)
    if mode in ("mutations", "mutations-nv"):
        extra = ["--vectors", "64"] if "--sanitized" in sys.argv[4:] else []
        return mutations(arbiter, corpus, MUTATIONS if mode == "mutations" else NV_MUTATIONS,
                         extra)
    sys.exit(f"unknown mode {mode}")


if __name__ == "__main__":
    sys.exit(main())
