#!/usr/bin/env python3
"""Input expansion: which files a directory gives, in which order, and that a long argument
list (which arbiter classifies on several threads once it has taken 20 ms, stat-ing the names
instead of reading them) gives the same inputs in the same order as a short one, whatever -j.
Usage: expansion.py ARBITER CORPUS_DIR."""
import json
import os
import shutil
import subprocess
import sys
import tempfile

from expectations import expect, finish

binary, corpus = os.path.abspath(sys.argv[1]), sys.argv[2]
program = open(os.path.join(corpus, "arb", "valid", "opcode-abs.fp"), "rb").read()


def checked(args, cwd):
    p = subprocess.run([binary, "check", "--format", "json"] + args, capture_output=True,
                       cwd=cwd, text=True)
    return p.returncode, [f["path"] for f in json.loads(p.stdout)["files"]]


with tempfile.TemporaryDirectory() as tmp:
    def put(rel, data=program):
        path = os.path.join(tmp, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)

    # Written in reverse of the expected order, so that a walk in creation order fails.
    for rel in ["top/z.vp", "top/sub/z/deep.vp", "top/sub/c.fp", "top/b.vp", "top/a.fp",
                "top/a-dir/x.vp", "top/a-dir/sub/y.fp"]:
        put(rel)
    put("top/prog.txt", b"!!ARBfp1.0\nEND\n")  # an ARB header: a program
    put("top/notes.txt", b"not a program\n")
    put("top/readme.md", b"# not a program\n")
    os.symlink("sub", os.path.join(tmp, "top", "link-to-sub"))  # not followed
    os.symlink("b.vp", os.path.join(tmp, "top", "link-to-b.vp"))  # a file: listed
    os.symlink("nowhere.vp", os.path.join(tmp, "top", "dangling.vp"))  # skipped
    want = ["top/a-dir/sub/y.fp", "top/a-dir/x.vp", "top/a.fp", "top/b.vp", "top/link-to-b.vp",
            "top/prog.txt", "top/sub/c.fp", "top/sub/z/deep.vp", "top/z.vp"]
    for jobs in ("1", "2"):
        code, got = checked(["-j", jobs, "top"], tmp)
        expect(f"check -j {jobs} top: the files, sorted", got == want, f"{got}")
        expect(f"check -j {jobs} top: exit 0", code == 0, f"exit {code}")
    # GLSL: names that give the stage are shaders; a bare .glsl (an include file, a library) in
    # a directory is not picked up, but named, it is checked (and told to give its stage).
    shader = b"void main() { gl_Position = ftransform(); }\n"
    for rel in ["glsl/common.glsl", "glsl/water.vert.glsl", "glsl/sky.vsh", "glsl/sky.fsh"]:
        put(rel, shader if "common" not in rel else b"float helper() { return 1.0; }\n")
    with open(os.path.join(tmp, "glsl/sky.fsh"), "wb") as f:
        f.write(b"void main() { gl_FragColor = vec4(1.0); }\n")
    code, got = checked(["glsl"], tmp)
    expect("check glsl: staged GLSL names only, sorted",
           got == ["glsl/sky.fsh", "glsl/sky.vsh", "glsl/water.vert.glsl"], f"{got}")
    expect("check glsl: exit 0", code == 0, f"exit {code}")
    code, got = checked(["glsl/common.glsl"], tmp)
    expect("a named .glsl is checked and needs --stage", got == ["glsl/common.glsl"] and code == 1,
           f"{got}, exit {code}")
    code, got = checked(["top/sub", "top/a.fp", "top/sub/"], tmp)
    expect("directories expand where they are named", got == [
        "top/sub/c.fp", "top/sub/z/deep.vp", "top/a.fp", "top/sub/c.fp", "top/sub/z/deep.vp"],
        f"{got}")

    # A long list: enough names that classifying them outlasts 20 ms on any machine this
    # runs on, so both ways (read while classifying, stat then read later) are taken.
    os.makedirs(os.path.join(tmp, "many"))
    names = []
    for i in range(6000):
        name = f"many/p{i:05d}.fp"
        os.link(os.path.join(tmp, "top", "a.fp"), os.path.join(tmp, name))
        names.append(name)
    args = names[:3000] + ["top/sub", "missing.vp"] + names[3000:] + ["top/a-dir"]
    want = (names[:3000] + ["top/sub/c.fp", "top/sub/z/deep.vp", "missing.vp"] + names[3000:]
            + ["top/a-dir/sub/y.fp", "top/a-dir/x.vp"])
    for jobs in ("1", "2"):
        code, got = checked(["-j", jobs] + args, tmp)
        expect(f"check -j {jobs} of {len(args)} arguments: the inputs in order", got == want,
               f"{len(got)} inputs, first difference at "
               f"{next((i for i, (a, b) in enumerate(zip(got, want)) if a != b), len(got))}")
        expect(f"check -j {jobs} of {len(args)} arguments: exit 3 (a missing file)", code == 3,
               f"exit {code}")
    shutil.rmtree(os.path.join(tmp, "many"))

finish()
