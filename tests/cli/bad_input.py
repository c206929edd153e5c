#!/usr/bin/env python3
"""Bad input: every hostile file gets a clear diagnostic (code, line, column) and the documented
exit code, within bounded time and memory. The bounds are guards against hangs and runaway
allocation, not speed measurements (those live in bench/).

Usage: bad_input.py ARBITER [--sanitized]
  --sanitized  the binary runs under ASan/UBSan: generous time bound, no memory bound (the
               sanitizer's shadow memory is not the program's)."""
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

binary = os.path.abspath(sys.argv[1])
sanitized = "--sanitized" in sys.argv[2:]
TIME_BOUND_S = 600 if sanitized else 120
RSS_BOUND_MB = 1024

VP = b"!!ARBvp1.0\nMOV result.position, vertex.position;\nEND\n"
FRAG = b"void main() { gl_FragColor = vec4(1.0); }\n"


def big_comment_vp(size):
    return b"!!ARBvp1.0\n# " + b"x" * size + b"\nMOV result.position, vertex.position;\nEND\n"


def many_instructions_vp(count):
    body = b"".join(b"ADD r0, r0, vertex.position;\n" for _ in range(count))
    return b"!!ARBvp1.0\nTEMP r0;\nMOV r0, vertex.position;\n" + body + \
        b"MOV result.position, r0;\nEND\n"


def long_line_frag(size):
    decls = []
    length = 0
    i = 0
    while length < size:
        decl = f"float a{i} = 1.0; "
        decls.append(decl)
        length += len(decl)
        i += 1
    return ("void main() { " + "".join(decls) + "gl_FragColor = vec4(a0); }\n").encode()


def nested_parens_vert(depth):
    return ("void main() {\n  gl_Position = vec4(" + "(" * depth + "1.0" + ")" * depth +
            ");\n}\n").encode()


rng = random.Random(20261125)
GARBAGE = bytes(rng.randrange(256) for _ in range(4096))

# name, {file: bytes}, arguments, exit code, [(code, line, column)] that must be reported.
# A diagnostic's line/column of None is not compared (a file-level diagnostic).
CASES = [
    ("empty ARB file", {"empty.vp": b""}, ["check", "empty.vp"], 1,
     [("arb-input-empty", 1, 1)]),
    ("empty GLSL file", {"empty.vert": b""}, ["check", "empty.vert"], 1,
     [("glsl-syntax-error", 1, 1)]),
    ("binary garbage, ARB extension", {"garbage.vp": GARBAGE}, ["check", "garbage.vp"], 1,
     [("arb-header-missing", 1, 1)]),
    ("binary garbage, GLSL extension", {"garbage.frag": GARBAGE}, ["check", "garbage.frag"], 1,
     [("glsl-invalid-character", None, None)]),
    ("NUL byte in an ARB program",
     {"nul.vp": b"!!ARBvp1.0\nMOV result.position,\0vertex.position;\nEND\n"},
     ["check", "nul.vp"], 1, [("arb-lex-invalid-char", 2, 21)]),
    ("NUL byte in a GLSL shader", {"nul.frag": b"void main() {\0 gl_FragColor = vec4(1.0); }\n"},
     ["check", "nul.frag"], 1, [("glsl-invalid-character", 1, 14)]),
    ("invalid UTF-8 in ARB code",
     {"utf8.vp": b"!!ARBvp1.0\nMOV result.position, \xff\xfevertex.position;\nEND\n"},
     ["check", "utf8.vp"], 1, [("arb-lex-invalid-char", 2, 22)]),
    ("invalid UTF-8 in GLSL code",
     {"utf8.frag": b"void main() { gl_FragColor = vec4(1.0); \xff }\n"},
     ["check", "utf8.frag"], 1, [("glsl-invalid-character", 1, 41)]),
    ("UTF-8 in a GLSL comment is a warning",
     {"comment.frag": b"// caf\xc3\xa9\n" + FRAG}, ["check", "comment.frag"], 0,
     [("glsl-non-ascii-comment", 1, 7)]),
    ("byte-order mark, ARB", {"bom.vp": b"\xef\xbb\xbf" + VP}, ["check", "bom.vp"], 1,
     [("arb-header-missing", 1, 1)]),
    ("byte-order mark, GLSL", {"bom.frag": b"\xef\xbb\xbf" + FRAG}, ["check", "bom.frag"], 1,
     [("glsl-invalid-character", 1, 1)]),
    ("CR-only line ends, ARB (an error on line 3)",
     {"cr.vp": b"!!ARBvp1.0\rTEMP r0;\rMOV result.position, r1;\rEND\r"},
     ["check", "cr.vp"], 1, [("arb-decl-undeclared", 3, 22)]),
    ("CR-only line ends, GLSL (an error on line 3)",
     {"cr.frag": b"void main()\r{\r  gl_FragColor = vec4(x);\r}\r"},
     ["check", "cr.frag"], 1, [("glsl-undeclared-identifier", 3, 23)]),
    ("a 10 MB ARB program", {"big.vp": big_comment_vp(10 << 20)}, ["check", "big.vp"], 0, []),
    ("a 10 MB GLSL shader", {"big.frag": b"// " + b"x" * (10 << 20) + b"\n" + FRAG},
     ["check", "big.frag"], 0, []),
    ("a 1 MB line, ARB", {"line.vp": big_comment_vp(1 << 20)}, ["check", "line.vp"], 0, []),
    ("a 1 MB line, GLSL", {"line.frag": long_line_frag(1 << 20)}, ["check", "line.frag"], 0, []),
    ("100 000 instructions: past the specification's minimum, within Mesa's limit",
     {"many.vp": many_instructions_vp(100_000)}, ["check", "many.vp"], 0, []),
    ("100 000 instructions: past the specification's minimum, as a limit profile",
     {"many.vp": many_instructions_vp(100_000)},
     ["check", "--limits", "spec-min", "many.vp"], 1, [("arb-limit-instructions", 131, 1)]),
    ("10 000 nested parentheses in GLSL", {"parens.vert": nested_parens_vert(10_000)},
     ["check", "parens.vert"], 1, [("glsl-nesting-too-deep", 2, len("  gl_Position = vec4(") + 10_000)]),
    ("a huge ARB array size",
     {"array.vp": b"!!ARBvp1.0\nPARAM p[4294967296] = { program.local[0..3] };\n"
                  b"MOV result.position, p[0];\nEND\n"},
     ["check", "array.vp"], 1, [("arb-binding-index-range", 2, 9)]),
    ("a huge GLSL array size, active uniform past the limit",
     {"array.vert": b"uniform float a[2147483647];\nvoid main() { gl_Position = vec4(a[7]); }\n",
      "ok.frag": FRAG},
     ["link", "array.vert", "ok.frag"], 1, [("glsl-link-limit-uniforms", 1, 15)]),
    ("an ARB number past float range is a warning",
     {"num.vp": b"!!ARBvp1.0\nMOV result.position, {1e999, 0, 0, 1};\nEND\n"},
     ["check", "num.vp"], 0, [("arb-number-range", 2, 23)]),
    ("a GLSL number past float range is a warning",
     {"num.vert": b"void main() { gl_Position = vec4(1e999); }\n"},
     ["check", "num.vert"], 0, [("glsl-number-range", 1, 34)]),
    ("a directory without programs", {"empty/.keep": b""}, ["check", "empty"], 3,
     [("io-read", None, None)]),
    ("a missing file", {}, ["check", "missing.vp"], 3, [("io-read", None, None)]),
    ("a dangling symbolic link", {}, ["check", "dangling.vp"], 3, [("io-read", None, None)]),
    ("an unknown stage: no ARB header, no GLSL extension", {"shader.txt": FRAG},
     ["check", "shader.txt"], 1, [("arb-header-missing", 1, 1)]),
]

# Cases that need the file system prepared beyond writing files.
SETUP = {
    "a dangling symbolic link": lambda d: os.symlink("nowhere.vp", os.path.join(d, "dangling.vp")),
}


def run(args, cwd, user=None):
    """Runs arbiter; returns (exit code, stdout, stderr, seconds, peak RSS in MB). GNU time
    measures the peak resident set of arbiter alone (scripts/setup-deps installs it)."""
    def demote():
        if user is not None:
            os.setgid(user)
            os.setuid(user)
    rss_file = os.path.join(cwd, ".rss")
    start = time.monotonic()
    proc = subprocess.Popen(["/usr/bin/time", "-f", "%M", "-o", rss_file, binary] + args,
                            cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=dict(os.environ, NO_COLOR="1"), preexec_fn=demote)
    try:
        out, err = proc.communicate(timeout=TIME_BOUND_S)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        return None, b"", b"", TIME_BOUND_S, 0
    seconds = time.monotonic() - start
    try:
        with open(rss_file) as f:
            rss = int(f.read().strip().splitlines()[-1]) / 1024
        os.remove(rss_file)
    except (OSError, ValueError, IndexError):
        rss = 0
    return proc.returncode, out, err, seconds, rss


def diagnostics(stdout):
    try:
        doc = json.loads(stdout)
    except ValueError:
        return None
    found = []
    for f in doc.get("files", []):
        for d in f.get("diagnostics", []):
            found.append((d["code"], d.get("line"), d.get("column")))
    return found


def check_case(name, files, args, want_exit, want_diags, root):
    work = os.path.join(root, f"case{CASES.index(next(c for c in CASES if c[0] == name))}")
    os.makedirs(work)
    for rel, data in files.items():
        path = os.path.join(work, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    if name in SETUP:
        SETUP[name](work)
    code, out, err, seconds, rss = run(args + ["--format", "json"], work)
    problems = []
    if code is None:
        problems.append(f"no answer within {TIME_BOUND_S} s")
    elif code != want_exit:
        problems.append(f"exit {code}, want {want_exit}")
    found = diagnostics(out)
    if found is None:
        # I/O errors before any file is read are reported as text on stderr.
        found = [(c, None, None) for c in ("io-read",) if b"[io-read]" in err]
    for want in want_diags:
        if not any(f[0] == want[0] and (want[1] is None or (f[1], f[2]) == want[1:])
                   for f in found):
            problems.append(f"missing {want}; reported {found[:6]}")
    if code not in (None, 0) and not want_diags and not found:
        problems.append("a failure without a diagnostic")
    if not sanitized and rss > RSS_BOUND_MB:
        problems.append(f"peak memory {rss:.0f} MB > {RSS_BOUND_MB} MB")
    if b"Sanitizer" in err or b"runtime error" in err:
        problems.append("sanitizer report: " + err.decode(errors="replace")[-2000:])
    return problems, seconds, rss


def unreadable_case(root):
    """A file its reader may not open: exit 3 and an io-read naming it. Root reads every
    file, so as root the check runs arbiter as 'nobody'."""
    work = os.path.join(root, "unreadable")
    os.makedirs(work)
    os.chmod(root, 0o755)
    os.chmod(work, 0o777)  # GNU time, as the same user, writes its figure there
    path = os.path.join(work, "secret.vp")
    with open(path, "wb") as f:
        f.write(VP)
    os.chmod(path, 0)
    user = 65534 if os.geteuid() == 0 else None
    code, _, err, _, _ = run(["check", "secret.vp"], work, user)
    problems = []
    if code != 3:
        problems.append(f"exit {code}, want 3")
    if b"secret.vp" not in err or b"[io-read]" not in err:
        problems.append("no io-read diagnostic naming the file: " + err.decode(errors="replace"))
    return problems


def main():
    failed = 0
    root = tempfile.mkdtemp(prefix="arbiter-bad-input-")
    try:
        for name, files, args, want_exit, want_diags in CASES:
            problems, seconds, rss = check_case(name, files, args, want_exit, want_diags, root)
            status = "FAIL" if problems else "ok"
            print(f"{status:4} {name} ({seconds:.2f} s, {rss:.0f} MB)")
            for p in problems:
                print(f"     {p}")
            failed += bool(problems)
        problems = unreadable_case(root)
        print(f"{'FAIL' if problems else 'ok':4} an unreadable file")
        for p in problems:
            print(f"     {p}")
        failed += bool(problems)
    finally:
        for dirpath, dirnames, filenames in os.walk(root):
            for n in dirnames + filenames:
                try:
                    os.chmod(os.path.join(dirpath, n), 0o700, follow_symlinks=False)
                except (OSError, NotImplementedError):
                    pass
        shutil.rmtree(root, ignore_errors=True)
    print(f"{len(CASES) + 1 - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
