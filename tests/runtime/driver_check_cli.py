#!/usr/bin/env python3
"""`arbiter check --driver-check`: the note, the exit codes and the flags, on the real binary.

Usage: driver_check_cli.py ARBITER. Writes small shaders to a temporary directory and checks:
a note `driver-check-differs` only where Mesa's verdict differs from arbiter's (both ways, with
Mesa's first error line and its position mapped back to the source), the exit code always
arbiter's verdict, several strings of one shader (--stage), the JSON rendering, identical
output whatever -j, ARB inputs untouched, and the flag errors (unknown driver, --driver without
--driver-check: exit 2). Also that nothing starts Mesa without --driver-check: a
GALLIUM_DRIVER value that would crash OSMesa is harmless then, and overridden with it.
Exit 0 when every check passed, 1 otherwise.
"""

import json
import os
import subprocess
import sys
import tempfile

SHADERS = {
    # Both accept.
    "agree-pass.frag": "void main() { gl_FragColor = vec4(1.0); }\n",
    # Both reject.
    "agree-fail.frag": "void main() { float x = 1; gl_FragColor = vec4(x); }\n",
    # arbiter rejects (1.10 has no float suffix), Mesa only warns.
    "arbiter-rejects.frag": "void main() { gl_FragColor = vec4(1.0f); }\n",
    # arbiter accepts (dmat2 is not reserved in 1.10), Mesa rejects at compile time.
    "mesa-rejects.vert": "#version 110\nvoid main()\n{\n  float dmat2 = 1.0;\n"
                         "  gl_Position = vec4(dmat2);\n}\n",
    # arbiter warns (gl_Position never written), Mesa refuses to link.
    "mesa-rejects-link.vert": "void main() { }\n",
    "program.vp": "!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n",
}

failures = []


def check(condition, what, detail=""):
    if not condition:
        failures.append(f"{what}\n{detail}".rstrip())


def run(arbiter, args, cwd, env_extra=None):
    env = dict(os.environ, NO_COLOR="1", TERM="dumb", LC_ALL="C")
    env.update(env_extra or {})
    p = subprocess.run([arbiter] + args, cwd=cwd, capture_output=True, env=env, timeout=120)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def notes_of(stderr, name):
    return [l for l in stderr.splitlines() if l.startswith(name) and "[driver-check-differs]" in l]


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    arbiter = os.path.abspath(sys.argv[1])
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in SHADERS.items():
            with open(os.path.join(tmp, name), "w") as f:
                f.write(text)

        # Agreement: no note, arbiter's exit code.
        for name, code in (("agree-pass.frag", 0), ("agree-fail.frag", 1)):
            rc, _, err = run(arbiter, ["check", "--driver-check", name], tmp)
            check(rc == code, f"{name}: exit {rc}, expected {code}", err)
            check(not notes_of(err, name), f"{name}: a note although both tools agree", err)

        rc, _, err = run(arbiter, ["check", "--driver-check", "arbiter-rejects.frag"], tmp)
        check(rc == 1, f"arbiter-rejects.frag: exit {rc}, expected 1 (arbiter's verdict)", err)
        check(notes_of(err, "arbiter-rejects.frag: note: Mesa (softpipe) accepts this shader, "
                       "arbiter rejects it"), "arbiter-rejects.frag: no 'Mesa accepts' note", err)

        rc, _, err = run(arbiter, ["check", "--driver-check", "mesa-rejects.vert"], tmp)
        check(rc == 0, f"mesa-rejects.vert: exit {rc}, expected 0 (arbiter's verdict)", err)
        notes = notes_of(err, "mesa-rejects.vert:4:3: note: Mesa (softpipe) rejects this shader, "
                         "arbiter accepts it; Mesa says: 0:4(")
        check(notes and "dmat2" in notes[0],
              "mesa-rejects.vert: no note at 4:3 quoting Mesa's error", err)

        rc, _, err = run(arbiter, ["check", "--driver-check", "mesa-rejects-link.vert"], tmp)
        check(rc == 0, f"mesa-rejects-link.vert: exit {rc}, expected 0", err)
        check(notes_of(err, "mesa-rejects-link.vert: note: Mesa (softpipe) rejects this shader "
                       "when linking it, arbiter accepts it; Mesa says: error:"),
              "mesa-rejects-link.vert: no link-time note", err)

        # Without --driver-check nothing differs and no note appears.
        rc, _, err = run(arbiter, ["check", "mesa-rejects.vert"], tmp)
        check(rc == 0 and "driver-check" not in err, "mesa-rejects.vert without the flag", err)

        # Several strings of one shader: Mesa's line maps back into the second file.
        with open(os.path.join(tmp, "head.glsl"), "w") as f:
            f.write("#version 110\nuniform vec4 c;\n")
        with open(os.path.join(tmp, "body.glsl"), "w") as f:
            f.write("void main()\n{\n  float dmat2 = 1.0;\n  gl_FragColor = c * dmat2;\n}\n")
        rc, _, err = run(arbiter, ["check", "--driver-check", "--stage", "frag", "head.glsl",
                                   "body.glsl"], tmp)
        check(rc == 0, f"two strings: exit {rc}, expected 0", err)
        check(notes_of(err, "body.glsl:3:3: note: Mesa (softpipe) rejects"),
              "two strings: the note is not at body.glsl:3:3", err)

        # JSON: a note with a position; ARB inputs get no Mesa verdict.
        rc, out, err = run(arbiter, ["check", "--driver-check", "--format", "json",
                                     "mesa-rejects.vert", "program.vp"], tmp)
        check(rc == 0, f"json: exit {rc}, expected 0", err)
        try:
            files = {f["path"]: f for f in json.loads(out)["files"]}
            diags = files["mesa-rejects.vert"]["diagnostics"]
            check(len(diags) == 1 and diags[0]["code"] == "driver-check-differs" and
                  diags[0]["severity"] == "note" and diags[0]["line"] == 4,
                  "json: expected one note on line 4", out)
            check(files["mesa-rejects.vert"]["errors"] == 0, "json: the note counts as an error",
                  out)
            check(files["program.vp"]["diagnostics"] == [], "json: a note on an ARB program", out)
        except (ValueError, KeyError) as e:
            check(False, f"json: unexpected document ({e})", out)

        # -j N: the same output as one thread.
        names = sorted(n for n in SHADERS)
        one = run(arbiter, ["check", "--driver-check", "-j", "1"] + names, tmp)
        many = run(arbiter, ["check", "--driver-check", "-j", "4"] + names, tmp)
        check(one == many, "-j 4 output differs from -j 1", f"{one}\n---\n{many}")
        check(one[0] == 1, f"all files: exit {one[0]}, expected 1", one[2])

        # llvmpipe works too.
        rc, _, err = run(arbiter, ["check", "--driver-check", "--driver", "llvmpipe",
                                   "mesa-rejects.vert"], tmp)
        check(rc == 0 and notes_of(err, "mesa-rejects.vert:4:3: note: Mesa (llvmpipe) rejects"),
              "--driver llvmpipe: no llvmpipe note", err)

        # Flag errors are usage errors.
        rc, _, err = run(arbiter, ["check", "--driver-check", "--driver", "zink",
                                   "agree-pass.frag"], tmp)
        check(rc == 2, f"--driver zink: exit {rc}, expected 2", err)
        rc, _, err = run(arbiter, ["check", "--driver", "llvmpipe", "agree-pass.frag"], tmp)
        check(rc == 2, f"--driver without --driver-check: exit {rc}, expected 2", err)

        # Lazy: without --driver-check OSMesa is never started (GALLIUM_DRIVER=zink would
        # crash it); with it, --driver wins over the environment.
        zink = {"GALLIUM_DRIVER": "zink"}
        rc, _, err = run(arbiter, ["check", "agree-pass.frag"], tmp, zink)
        check(rc == 0, f"GALLIUM_DRIVER=zink without --driver-check: exit {rc}", err)
        rc, _, err = run(arbiter, ["check", "--driver-check", "mesa-rejects.vert"], tmp, zink)
        check(rc == 0 and notes_of(err, "mesa-rejects.vert:4:3: note: Mesa (softpipe)"),
              f"GALLIUM_DRIVER=zink with --driver-check: exit {rc}", err)

    for f in failures:
        print(f"FAIL {f}\n")
    print(f"driver_check_cli: {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
