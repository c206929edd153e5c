#!/usr/bin/env python3
"""What a new user found (issue 22): each case ran wrong before its fix.

Covers: translate writes all of an input's outputs or none and prints nothing first (2),
writes every accepted program of a directory and reports the rejected ones (3), refuses
several shaders on stdout (9); JSON documents carry the diagnostics (4); a GLSL file given to
an ARB command is told so (5); verify counts a rejected file (8); usage, help, version and
unknown commands (11); info lists an inline binding once (13); diagnostics come in line order
(14); run fails what is no shader test or a test with nothing to do (1); exec warns about
inputs that do nothing and takes the ARB texture target spelling (12).
Usage: new_user.py ARBITER. Exit 0 when every case holds, 1 otherwise."""
import json
import os
import subprocess
import sys
import tempfile

from expectations import expect, finish

binary = os.path.abspath(sys.argv[1])

VP = "!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n"
VP_INLINE = ("!!ARBvp1.0\nTEMP t;\nMOV t, vertex.position;\nADD t, t, vertex.position;\n"
             "MOV result.position, t;\nEND\n")
FP = "!!ARBfp1.0\nMOV result.color, fragment.color;\nEND\n"
BAD_FP = "!!ARBfp1.0\nMOV result.color, fragment.colour;\nEND\n"
FRAG = "#version 110\nvoid main() { gl_FragColor = vec4(1.0); }\n"


def run(args, cwd):
    return subprocess.run([binary] + args, capture_output=True, text=True, cwd=cwd, timeout=300)


with tempfile.TemporaryDirectory() as tmp:
    def put(rel, text):
        path = os.path.join(tmp, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)

    put("x.vp", VP)
    put("inline.vp", VP_INLINE)
    put("bad.fp", BAD_FP)
    put("shader.frag", FRAG)
    put("dir/a.vp", VP)
    put("dir/b.fp", FP)
    put("dir/c.fp", BAD_FP)

    # 2: a binding map that cannot be written: no shader file, nothing on stdout.
    p = run(["translate", "x.vp", "-o", "t.vert", "--bindings", "/proc/x.json"], tmp)
    expect("translate, unwritable --bindings: exit 3", p.returncode == 3, p.stderr)
    expect("translate, unwritable --bindings: no t.vert", not os.path.exists(f"{tmp}/t.vert"))
    p = run(["translate", "x.vp", "--bindings", "/proc/x.json"], tmp)
    expect("translate to stdout, unwritable --bindings: nothing on stdout", p.stdout == "",
           p.stdout[:200])
    expect("translate, unwritable --bindings: says which file", "/proc/x.json" in p.stderr,
           p.stderr)

    # 3: one rejected program among several: the others are written, it is reported, exit 1.
    p = run(["translate", "dir", "-o", "out"], tmp)
    expect("translate DIR with a rejected program: exit 1", p.returncode == 1, p.stderr)
    written = sorted(os.listdir(f"{tmp}/out")) if os.path.isdir(f"{tmp}/out") else []
    expect("translate DIR: the accepted programs are written", written == ["a.vert", "b.frag"],
           str(written))
    expect("translate DIR: the rejected one is reported",
           "c.fp:2:28: error" in p.stderr and "1 of 3 programs rejected" in p.stderr, p.stderr)

    # 3, with -Werror: a program with a warning is rejected, and not translated.
    put("warn/a.vp", VP)
    put("warn/w.fp", "!!ARBfp1.0\nOPTION ARB_fog_linear;\nOPTION ARB_fog_linear;\n"
        "MOV result.color, fragment.color;\nEND\n")
    p = run(["translate", "-W", "warn", "-o", "warn-out"], tmp)
    written = sorted(os.listdir(f"{tmp}/warn-out")) if os.path.isdir(f"{tmp}/warn-out") else []
    expect("translate -W: a warned program is rejected and not written",
           p.returncode == 1 and written == ["a.vert"] and "1 of 2 programs rejected" in p.stderr,
           f"{written} {p.stderr}")

    # 9: several programs without -o.
    p = run(["translate", "dir/a.vp", "dir/b.fp"], tmp)
    expect("translate a.vp b.fp without -o: usage error", p.returncode == 2 and p.stdout == "",
           p.stderr)

    # 4: JSON carries the diagnostics (stderr stays empty).
    for args in (["info", "--format", "json", "bad.fp"], ["exec", "--format", "json", "bad.fp"],
                 ["verify", "--format", "json", "bad.fp"]):
        p = run(args, tmp)
        what = " ".join(args[:1]) + " --format json of a rejected program"
        try:
            doc = json.loads(p.stdout)
        except json.JSONDecodeError:
            doc = {}
        codes = [(d["code"], d["line"], d["column"]) for f in doc.get("diagnostics", [])
                 for d in f["diagnostics"]]
        expect(what + ": the diagnostic", ("arb-binding-unknown", 2, 28) in codes, p.stdout[:300])
        expect(what + ": nothing on stderr", p.stderr == "", p.stderr)
        expect(what + ": exit 1", p.returncode == 1, str(p.returncode))

    # 5: a GLSL shader given to an ARB command (exec runs GLSL shaders too, on Mesa).
    p = run(["translate", "shader.frag"], tmp)
    expect("translate of a GLSL file says it takes ARB programs",
           "'arbiter translate' takes ARB programs" in p.stderr, p.stderr)
    p = run(["verify", "--vectors", "4", "shader.frag"], tmp)
    expect("verify of a GLSL file verifies it on the GLSL engines",
           p.returncode == 0 and "shader.frag: agree" in p.stdout, p.stdout + p.stderr)
    p = run(["exec", "shader.frag"], tmp)
    expect("exec of a GLSL file runs it", p.returncode == 0 and "gl_FragColor" in p.stdout,
           p.stdout + p.stderr)

    # 8: verify of a rejected file.
    p = run(["verify", "bad.fp"], tmp)
    expect("verify of a rejected file counts it",
           "1 program(s): 0 agree, 0 disagree, 0 error(s), 1 rejected" in p.stdout, p.stdout)
    expect("verify of a rejected file: exit 1", p.returncode == 1, str(p.returncode))

    # 11: usage and help.
    p = run(["--help"], tmp)
    expect("usage names the program", "Usage: arbiter " in p.stdout, p.stdout[:200])
    p = run(["check", "--help"], tmp)
    expect("check --help shows the defaults", "=20" in p.stdout and "=text" in p.stdout,
           p.stdout)
    p = run(["chek", "x.vp"], tmp)
    expect("a misspelt command: did you mean",
           p.returncode == 2 and "unknown command 'chek'" in p.stderr and
           "did you mean 'check'" in p.stderr, p.stderr)
    p = run(["help"], tmp)
    expect("arbiter help prints the help", p.returncode == 0 and "Usage: arbiter" in p.stdout,
           p.stdout[:200])
    p = run(["help", "translate"], tmp)
    expect("arbiter help COMMAND", p.returncode == 0 and "Usage: arbiter translate" in p.stdout,
           p.stdout[:200])
    p = run(["help", "trnslate"], tmp)
    expect("arbiter help of an unknown command",
           p.returncode == 2 and "did you mean 'translate'" in p.stderr, p.stderr)
    p = run(["-V"], tmp)
    expect("arbiter -V prints the version", p.returncode == 0 and p.stdout.strip()[0].isdigit(),
           p.stdout + p.stderr)
    p = run(["check", "--error-limit", "-1", "x.vp"], tmp)
    expect("--error-limit -1: a short range", p.returncode == 2 and len(p.stderr) < 200 and
           "1000000" in p.stderr, p.stderr)
    p = run(["exec", "x.vp", "--set", "vertex.attrib[1]=1,2,3,4", "vertex.attrib[2]=1"], tmp)
    expect("--set a=1 b=2: a usage error naming the value", p.returncode == 2 and
           "'vertex.attrib[2]=1' is not a file" in p.stderr, p.stderr)
    p = run(["exec", "--help"], tmp)
    expect("repeated options show one value", "--set NAME=V1" in p.stdout and
           "--set TEXT ..." not in p.stdout, p.stdout)

    # 12: exec warns about inputs that do nothing, and takes the ARB target spelling.
    put("tex.fp", "!!ARBfp1.0\nTEX result.color, fragment.texcoord[0], texture[0], 2D;\nEND\n")
    p = run(["exec", "tex.fp", "--set", "fragment.texcoord[1]=1", "--set", "program.local[0]=1",
             "--texture", "1=2D:checker"], tmp)
    for want in ("no program of this run reads fragment.texcoord[1]",
                 "no program of this run reads program.local[0]",
                 "texture unit 1: no instruction samples it",
                 "texture unit 0 is sampled (2D) but given no texture"):
        expect(f"exec warns: {want}", want in p.stderr, p.stderr)
    p = run(["exec", "tex.fp", "--texture", "0=CUBE:checker"], tmp)
    expect("exec warns about a texture of another target",
           "a CUBE texture, but the program samples it as 2D" in p.stderr, p.stderr)
    p = run(["exec", "tex.fp", "--set", "fragment.texcoord=.5,.5", "--texture",
             "0=2D:checker:4x4"], tmp)
    expect("exec --texture 0=2D:... (the ARB spelling), used inputs: no warning",
           p.returncode == 0 and p.stderr == "", p.stderr)

    # 13: an inline binding used twice is listed once.
    p = run(["info", "inline.vp"], tmp)
    expect("info lists an inline binding once",
           p.stdout.count("(inline) = vertex.position") == 1, p.stdout)

    # 1: run fails what is not a shader test, and a test with nothing to draw or probe.
    put("empty.shader_test", "")
    put("require-only.shader_test", "[require]\nGL >= 2.0\n")
    put("README.txt", "hello\n")
    for name in ("empty.shader_test", "require-only.shader_test", "README.txt", "x.vp"):
        p = run(["run", name], tmp)
        expect(f"run {name}: fails", p.returncode == 1 and "FAIL" in p.stdout,
               p.stdout + p.stderr)

finish()
