#!/usr/bin/env python3
"""Tests of `arbiter run` itself (not of the corpus): a probe that must fail fails with the
expected and observed values, unmet [require] lines skip, malformed files fail alone with a
clear message and exit 1, a hanging shader fails alone at its time limit, --junit and --png
write what they promise, and the output does not depend on -j.

  runner_test.py ARBITER [--sanitized]
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

ARBITER = os.path.abspath(sys.argv[1])
# The binary runs under ASan/UBSan: workers have no memory limit (the sanitizers reserve
# terabytes of address space), so only the time limit guards them.
SANITIZED = "--sanitized" in sys.argv[2:]
FAILURES = []

RED_FP = """[require]
GL >= 1.3
GL_ARB_fragment_program

[fragment program]
!!ARBfp1.0
MOV result.color, {1.0, 0.0, 0.0, 1.0};
END

[test]
clear color 0.0 0.0 1.0 1.0
clear
draw rect -1 -1 1 2
"""

CASES = {
    # The left half is red, the right half keeps the clear colour (blue).
    "pass.shader_test": RED_FP + "probe rgba 10 10 1.0 0.0 0.0 1.0\n"
                                 "relative probe rgb (0.75, 0.5) (0.0, 0.0, 1.0)\n"
                                 "probe rect rgba (0, 0, 125, 250) (1.0, 0.0, 0.0, 1.0)\n",
    "probe-fails.shader_test": RED_FP + "probe rgba 10 10 0.0 1.0 0.0 1.0\n",
    "rect-fails.shader_test": RED_FP + "probe all rgba 1.0 0.0 0.0 1.0\n",
    "skip-extension.shader_test": "[require]\nGL_ARB_no_such_extension\n\n[test]\nclear\n",
    "skip-glsl.shader_test": "[require]\nGLSL >= 9.90\n\n[test]\nclear\n",
    "bad-command.shader_test": RED_FP + "frobnicate 1 2 3\n",
    "bad-number.shader_test": RED_FP + "probe rgba 10 10 one 0.0 0.0 1.0\n",
    "bad-require.shader_test": "[require]\nGL >= one\n\n[test]\nclear\n",
    "bad-section.shader_test": "[require]\nGL >= 1.3\n\n[geometry program]\nfoo\n",
    "bad-arb.shader_test": "[require]\nGL >= 1.3\n\n[fragment program]\n!!ARBfp1.0\n"
                           "MOVE result.color, {1.0};\nEND\n\n[test]\nclear\n",
    "glsl-hang.shader_test": "[require]\nGLSL >= 1.10\n\n[vertex shader passthrough]\n\n"
                             "[fragment shader]\nuniform float u;\nvoid main() {\n"
                             "  float x = 0.0;\n  while (u > 0.0) { x += 1.0; }\n"
                             "  gl_FragColor = vec4(x);\n}\n\n[test]\nuniform float u 1.0\n"
                             "draw rect -1 -1 2 2\n",
    # Mesa's compiler allocates for every element of a huge local array without checking
    # its allocations: past the worker's memory limit it crashes.
    "glsl-big-array.shader_test": "[require]\nGLSL >= 1.10\n\n[vertex shader passthrough]\n\n"
                                  "[fragment shader]\nuniform int n;\nvoid main() {\n"
                                  "  float big[200000000];\n"
                                  "  for (int i = 0; i < n; i++) big[i] = float(i);\n"
                                  "  gl_FragColor = vec4(big[n - 1]);\n}\n\n[test]\n"
                                  "uniform int n 4\ndraw rect -1 -1 2 2\n",
    "link-error.shader_test": "[require]\nGLSL >= 1.10\n\n[vertex shader]\nvoid f();\n"
                              "void main() { f(); gl_Position = gl_Vertex; }\n\n"
                              "[test]\nlink error\n",
}


def check(name, condition, detail=""):
    if not condition:
        FAILURES.append(f"{name}: {detail}")


def run(args, cwd):
    p = subprocess.run([ARBITER, "run", *args], cwd=cwd, capture_output=True, text=True,
                       timeout=300)
    return p.returncode, p.stdout, p.stderr


def block(stdout, test):
    """The lines of one test's report: its status line and the indented lines after it."""
    lines = stdout.splitlines()
    for i, line in enumerate(lines):
        if line.endswith(" " + test):
            out = [line]
            for more in lines[i + 1:]:
                if not more.startswith("  "):
                    break
                out.append(more)
            return "\n".join(out)
    return ""


def png_pixels(path):
    """Decodes an 8-bit RGBA, non-interlaced PNG (what arbiter writes) into rows of pixels."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour == 6, "not 8-bit RGBA"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * 4, [], bytearray(width * 4)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - 4] if x >= 4 else 0
            b = prev[x]
            c = prev[x - 4] if x >= 4 else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, rows


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in CASES.items():
            with open(os.path.join(tmp, name), "w") as f:
                f.write(text)

        code, out, err = run(["pass.shader_test"], tmp)
        check("pass", code == 0 and out.startswith("PASS pass.shader_test"), out + err)

        code, out, _ = run(["--timeout", "3000", "probe-fails.shader_test"], tmp)
        b = block(out, "probe-fails.shader_test")
        check("probe-fails exit", code == 1, str(code))
        check("probe-fails message",
              "FAIL probe-fails.shader_test" in b and
              "probe-fails.shader_test:14: probe rgba at (10, 10) failed" in b and
              "Expected: 0.000000 1.000000 0.000000 1.000000" in b and
              "Observed: 1.000000 0.000000 0.000000 1.000000" in b, b)
        check("summary", out.rstrip().splitlines()[-1].startswith("0 passed, 1 failed, 0 skipped"),
              out)

        # A whole-window probe reports the first failing pixel: (125, 0), the first blue one.
        code, out, _ = run(["rect-fails.shader_test"], tmp)
        check("rect-fails", "probe rgba at (125, 0) failed" in out and
              "Observed: 0.000000 0.000000 1.000000 1.000000" in out, out)

        code, out, _ = run(["skip-extension.shader_test", "skip-glsl.shader_test"], tmp)
        check("skip exit", code == 0, str(code))
        check("skip extension", "SKIP skip-extension.shader_test" in out and
              "requires GL_ARB_no_such_extension, which the context lacks" in out, out)
        check("skip glsl", "SKIP skip-glsl.shader_test" in out and "requires GLSL >= 9.90" in out,
              out)

        for name, message in [
            ("bad-command", "bad-command.shader_test:14: unknown command 'frobnicate 1 2 3'"),
            ("bad-number", "bad-number.shader_test:14: 'one' is not a number"),
            ("bad-section", "bad-section.shader_test:4: unknown section [geometry program]"),
            ("bad-require", "bad-require.shader_test:2: malformed requirement 'GL >= one'"),
            ("bad-arb", "bad-arb.shader_test:4: Mesa rejects the fragment program"),
            ("missing", "missing.shader_test: cannot read the test: no such file or directory"),
        ]:
            code, out, err = run([name + ".shader_test", "pass.shader_test"], tmp)
            check(name + " exit", code == 1, str(code))
            check(name + " message", f"FAIL {name}.shader_test" in out and message in out, out + err)
            check(name + " others run", "PASS pass.shader_test" in out, out)
        code, out, _ = run(["bad-arb.shader_test"], tmp)
        check("bad-arb diagnostics", "bad-arb.shader_test:6:1: error:" in out, out)

        code, out, _ = run(["link-error.shader_test"], tmp)
        check("link error expected", code == 0 and "PASS" in out, out)

        # A shader that never ends: its worker is stopped at the limit, the rest still runs.
        code, out, _ = run(["-j", "1", "--timeout", "2000", "glsl-hang.shader_test",
                            "pass.shader_test"], tmp)
        check("hang", code == 1 and "FAIL glsl-hang.shader_test" in out and
              "time limit of 2000 ms" in out and "PASS pass.shader_test" in out, out)

        # A shader that makes the driver allocate without bound: the memory limit stops it
        # (under the sanitizers, which need the address space, the time limit does).
        code, out, _ = run(["-j", "1", "--timeout", "20000", "--memory-limit", "1024",
                            "glsl-big-array.shader_test", "pass.shader_test"], tmp)
        stopped = ("time limit of 20000 ms" if SANITIZED else "its memory limit is 1024 MiB")
        check("big array", code == 1 and "FAIL glsl-big-array.shader_test" in out and
              stopped in out and "PASS pass.shader_test" in out, out)

        # --junit: one testcase per test, failures and skips counted.
        junit = os.path.join(tmp, "results.xml")
        code, out, _ = run(["--junit", junit, "pass.shader_test", "probe-fails.shader_test",
                            "skip-glsl.shader_test"], tmp)
        root = ET.parse(junit).getroot()
        suite = root.find("testsuite")
        check("junit counts", suite.get("tests") == "3" and suite.get("failures") == "1" and
              suite.get("skipped") == "1", ET.tostring(root).decode())
        cases = {c.get("name"): c for c in suite.iter("testcase")}
        check("junit failure", cases["probe-fails.shader_test"].find("failure") is not None and
              "Expected: 0.000000 1.000000" in cases["probe-fails.shader_test"].find("failure").text,
              "")
        check("junit skip", cases["skip-glsl.shader_test"].find("skipped") is not None, "")
        code, _, err = run(["--junit", "pass.shader_test", "pass.shader_test"], tmp)
        check("junit over input", code == 2 and "would overwrite an input" in err, err)

        # --png: the picture, red on the left and blue on the right, top row first.
        code, out, _ = run(["--png", "pictures", "pass.shader_test"], tmp)
        width, height, rows = png_pixels(os.path.join(tmp, "pictures", "pass.png"))
        check("png size", (width, height) == (250, 250), f"{width}x{height}")
        check("png pixels", rows[0][0:4] == b"\xff\x00\x00\xff" and
              rows[249][249 * 4:250 * 4] == b"\x00\x00\xff\xff", repr(rows[0][0:8]))

        # --format json: the same results, machine-readable.
        code, out, _ = run(["--format", "json", "pass.shader_test", "probe-fails.shader_test",
                            "skip-glsl.shader_test"], tmp)
        report = json.loads(out)
        check("json counts", (report["passed"], report["failed"], report["skipped"]) == (1, 1, 1),
              out)
        check("json tests", [t["status"] for t in report["tests"]] == ["PASS", "FAIL", "SKIP"] and
              report["tests"][1]["message"][1].strip() ==
              "Expected: 0.000000 1.000000 0.000000 1.000000", out)

        # --translate=T for the targets without built-in state: the GL state the commands set
        # reaches the translation as uniforms (glstate), with GL's own transformations: the
        # light position by the modelview matrix, the fog colour clamped. p = (0.5, 0.5, 0, 1)
        # (0.25 moved by x + 0.25), f = (1, 0.25, 0, 0.5); p * f + env[3] = (0.6, 0.325, 0.3,
        # 0.9) on the right; on the left (local[0].x = 1) the current vertex.color.
        state = os.path.join(tmp, "state-uniforms.shader_test")
        with open(state, "w") as f:
            f.write("[require]\nGL_ARB_vertex_program\n\n[vertex program]\n!!ARBvp1.0\n"
                    "PARAM p = state.light[0].position;\nPARAM f = state.fog.color;\n"
                    "TEMP t, d;\nMOV result.position, vertex.position;\nMUL t, p, f;\n"
                    "ADD t, t, program.env[3];\nSUB d, vertex.color, t;\n"
                    "MAD result.color, program.local[0].x, d, t;\nEND\n\n[test]\n"
                    "matrix GL_MODELVIEW 1 0 0 0  0 1 0 0  0 0 1 0  0.25 0 0 1\n"
                    "light 0 GL_POSITION float 0.25 0.5 0 1\n"
                    "matrix GL_MODELVIEW 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1\n"
                    "fog GL_FOG_COLOR float 1.5 0.25 -1 0.5\n"
                    "parameter env_vp 3 (0.1, 0.2, 0.3, 0.4)\ncolor 0.2 0.4 0.6 0.8\n"
                    "parameter local_vp 0 (1, 0, 0, 0)\ndraw rect -1 -1 1 2\n"
                    "parameter local_vp 0 (0, 0, 0, 0)\ndraw rect 0 -1 1 2\n"
                    "probe rgba 200 100 0.6 0.325 0.3 0.9\n"
                    "probe rgba 50 100 0.2 0.4 0.6 0.8\n")
        for options in ([], ["--translate"], ["--translate=glsl330"], ["--translate=es300"]):
            code, out, _ = run([*options, "state-uniforms.shader_test"], tmp)
            check(f"state uniforms {options}", code == 0 and "PASS" in out, out)
        # A fragment program alone gets a vertex stage standing for GL's fixed-function one:
        # the colour, and texture coordinate 1 by texture matrix 1 (scale 0.5): (0.4, 0.2) ->
        # (0.2, 0.1); t.xy = (0.2, 0.3) + (0.2, 0.1).
        with open(os.path.join(tmp, "fp-alone.shader_test"), "w") as f:
            f.write("[require]\nGL_ARB_fragment_program\n\n[fragment program]\n!!ARBfp1.0\n"
                    "TEMP t;\nMOV t, fragment.color;\nADD t.xy, t, fragment.texcoord[1];\n"
                    "MOV result.color, t;\nEND\n\n[test]\northo 0 1 0 1\n"
                    "matrix GL_TEXTURE1 0.5 0 0 0  0 0.5 0 0  0 0 1 0  0 0 0 1\n"
                    "color 0.2 0.3 0.4 0.5\ntexcoord 1 (0.4, 0.2, 0, 1)\ndraw rect 0 0 1 1\n"
                    "probe all rgba 0.4 0.4 0.4 0.5\n")
        for options in ([], ["--translate=glsl330"], ["--translate=es300"],
                        ["--translate=es100"]):
            code, out, _ = run([*options, "fp-alone.shader_test"], tmp)
            check(f"fragment program alone {options}", code == 0 and "PASS" in out, out)
        # A program the target cannot express is skipped with the refusal, not failed.
        tex1d = os.path.join(tmp, "tex1d.shader_test")
        with open(tex1d, "w") as f:
            f.write("[require]\nGL_ARB_fragment_program\n\n[fragment program]\n!!ARBfp1.0\n"
                    "TEX result.color, fragment.texcoord[0], texture[0], 1D;\nEND\n\n[test]\n"
                    "texture rgbw 1D 0\ndraw rect -1 -1 2 2\n")
        tex3d = os.path.join(tmp, "tex3d.shader_test")
        with open(tex3d, "w") as f:
            f.write("[require]\nGL_ARB_fragment_program\n\n[fragment program]\n!!ARBfp1.0\n"
                    "TEX result.color, fragment.texcoord[0], texture[0], 3D;\nEND\n\n[test]\n"
                    "texture rgbw 3D 0\ndraw rect -1 -1 2 2\n")
        code, out, _ = run(["--translate=es100", "tex3d.shader_test"], tmp)
        check("es100 refusal", code == 0 and "SKIP tex3d.shader_test" in out and
              "the translation to GLSL ES 1.00 refuses the program" in out and
              "3D" in out and "0 passed, 0 failed, 1 skipped" in out, out)
        # ES 3.00 has no 1D samplers either, but the translation emulates them (a 2D texture
        # of height 1, which the runner makes).
        code, out, _ = run(["--translate=es300", "tex1d.shader_test"], tmp)
        check("es300 emulates 1D", code == 0 and "PASS tex1d.shader_test" in out, out)
        code, out, err = run(["--translate=vk450", "tex1d.shader_test"], tmp)
        check("vk450 refused", code == 2 and "--translate=vk450: run translates to" in err, err)

        # The output does not depend on the number of workers.
        names = sorted(n for n in CASES if n != "glsl-hang.shader_test")
        outputs = {run(["-j", str(j), *names], tmp)[1] for j in (1, 3)}
        check("-j determinism", len(outputs) == 1, "\n---\n".join(outputs))

    for f in FAILURES:
        print("FAILED", f)
    print(f"runner_test: {len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
