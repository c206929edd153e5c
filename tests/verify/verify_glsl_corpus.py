#!/usr/bin/env python3
"""arbiter verify over the GLSL corpus (issue 23): every shader of corpus/glsl the checker
passes and every GLSL .shader_test of corpus/exec runs on softpipe, llvmpipe and the Vulkan
engine, and must agree, or be listed with its cause in glsl-known-disagreements.txt. No
engine may fail; a listed shader that agrees fails the test too (the list must stay true).

usage: verify_glsl_corpus.py ARBITER SOURCE_DIR
"""
import json
import pathlib
import subprocess
import sys


def main():
    arbiter, source = sys.argv[1], pathlib.Path(sys.argv[2])
    shaders = sorted(str(p) for p in (source / "corpus/glsl").rglob("*.pass.*")
                     if p.suffix in (".vert", ".frag"))
    known = {}
    for line in (source / "tests/verify/glsl-known-disagreements.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            name, _, cause = line.partition(" ")
            known[name] = cause.strip()
    run = subprocess.run([arbiter, "verify", "-j", "2", "--format", "json", *shaders,
                          str(source / "corpus/exec")],
                         capture_output=True, text=True, check=False)
    report = json.loads(run.stdout)
    failures = []
    agree = 0
    for p in report["programs"]:
        name = str(pathlib.Path(p["file"]).resolve().relative_to(source.resolve())) \
            if p["file"].startswith("/") else p["file"]
        if p["verdict"] == "error":
            failures.append(f"{name}: engine error: {p.get('error')}")
        elif p["verdict"] == "disagree" and name not in known:
            first = p["disagreements"][0] if p["disagreements"] else {}
            failures.append(f"{name}: {p['disagreement_count']} disagreement(s), first {first}")
        elif p["verdict"] == "agree" and name in known:
            failures.append(f"{name}: agrees now: take it off glsl-known-disagreements.txt")
        elif p["verdict"] == "agree":
            agree += 1
    print(f"{len(report['programs'])} GLSL subjects verified, {agree} agree, "
          f"{len(known)} known disagreement(s)")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
