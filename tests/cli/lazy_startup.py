#!/usr/bin/env python3
"""Lazy start-up: `arbiter check` of ARB programs or GLSL shaders loads no part of Mesa (nor
LLVM); only --driver-check does. The dynamic loader says what it initialises (LD_DEBUG=libs),
dlopen'ed libraries included. Usage: lazy_startup.py ARBITER CORPUS_DIR."""
import os
import subprocess
import sys

binary, corpus = sys.argv[1], sys.argv[2]
arb = os.path.join(corpus, "arb", "valid", "skinning-four-bones.vp")
glsl = os.path.join(corpus, "glsl", "basics", "case-sensitive-identifiers.pass.vert")
DRIVER = ("libOSMesa", "libEGL", "libGL.", "libLLVM", "libglapi")


def loaded(args):
    env = dict(os.environ, LD_DEBUG="libs", NO_COLOR="1")
    p = subprocess.run([binary] + args, capture_output=True, env=env, text=True)
    inits = [line.split("calling init:")[1].strip()
             for line in p.stderr.splitlines() if "calling init:" in line]
    return p.returncode, [lib for lib in inits if any(d in lib for d in DRIVER)]


failed = 0
for args, want_driver in ((["check", arb], False), (["check", glsl], False),
                          (["check", "-j", "2", arb, glsl], False),
                          (["check", "--driver-check", glsl], True)):
    code, driver_libs = loaded(args)
    if code != 0:
        print(f"FAIL {' '.join(args)}: exit {code}")
        failed += 1
    elif bool(driver_libs) != want_driver:
        what = ", ".join(driver_libs) if driver_libs else "nothing of Mesa"
        print(f"FAIL {' '.join(args)}: loaded {what}")
        failed += 1
print(f"{4 - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
