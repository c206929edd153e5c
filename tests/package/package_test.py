#!/usr/bin/env python3
"""The installed package: `cmake --install` of the build tree into a temporary prefix (its path
has a space), then the man page, the bash completion, examples/cmake-pipeline built against
it with Ninja and with Make (one arbiter step per shader: a second build runs nothing, touching
one shader re-runs its step alone, a rejected shader fails the build with its diagnostic and
leaves no output), examples/api-check, a C++ program linked with the installed libraries, and
examples/glstate-check, a host program linked with the header-only arbiter::glstate alone, and
examples/port-to-core, an ARB program pair drawn through its glsl330 translation (Mesa's EGL).

Usage: package_test.py BUILD_DIR SOURCE_DIR CMAKE CXX_COMPILER
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

build_dir, source_dir, cmake, cxx = sys.argv[1:5]
failures = []
# One arbiter step in `ninja -v` output: ... && "<prefix>/bin/arbiter" check ... (quoted: the
# prefix has a space).
STEP = re.compile(r'bin/arbiter"? (check --link|check|translate) ')
# The step Make announces: "[ 50%] arbiter translate shaders/water.vp".
MAKE_STEP = re.compile(r"^\[ *\d+%\] arbiter (check --link|check|translate) ", re.M)


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)
    return condition


def run(args, cwd=None):
    """Runs a command; returns (exit code, stdout and stderr together)."""
    p = subprocess.run(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def must(args, what, cwd=None):
    code, out = run(args, cwd)
    if not check(code == 0, f"{what} (exit {code})"):
        print(out)
        sys.exit(1)
    return out


def touch(path):
    # A clearly newer modification time than the outputs just written, but not in the future
    # (an input newer than every output it ever gets would re-run its step forever).
    time.sleep(1.0)
    os.utime(path)


# The builds below choose their generators; diagnostics without colour.
os.environ["NO_COLOR"] = "1"
for name in ("CMAKE_GENERATOR", "MAKEFLAGS"):
    os.environ.pop(name, None)
tmp = tempfile.mkdtemp(prefix="arbiter package ")
try:

    # --- install -----------------------------------------------------------------------
    prefix = os.path.join(tmp, "prefix")
    must([cmake, "--install", build_dir, "--prefix", prefix], "cmake --install")
    # CMAKE_INSTALL_LIBDIR: "lib", or "lib/<multiarch>" for the prefix /usr on Debian.
    configs = glob.glob(os.path.join(glob.escape(prefix), "lib*", "**", "arbiterConfig.cmake"),
                        recursive=True)
    lib = os.path.relpath(os.path.dirname(configs[0]), prefix)[:-len("/cmake/arbiter")] \
        if configs else "lib"
    for rel in ("bin/arbiter", "share/man/man1/arbiter.1",
                "share/bash-completion/completions/arbiter",
                f"{lib}/cmake/arbiter/arbiterConfig.cmake",
                f"{lib}/cmake/arbiter/arbiterConfigVersion.cmake",
                f"{lib}/cmake/arbiter/arbiterShaders.cmake",
                f"{lib}/cmake/arbiter/arbiterToolTargets.cmake",
                f"{lib}/cmake/arbiter/arbiterLibraryTargets.cmake",
                f"{lib}/libarbiter_runtime.a", "include/arbiter/arbvp/check.h",
                "include/arbiter/runtime/translate.h"):
        check(os.path.isfile(os.path.join(prefix, rel)), f"installed {rel}")
    arbiter = os.path.join(prefix, "bin", "arbiter")
    code, out = run([arbiter, "--version"])
    check(code == 0 and re.match(r"\d+\.\d+\.\d+", out) is not None, "installed arbiter runs")

    # --- man page and completion -------------------------------------------------------
    man = os.path.join(prefix, "share/man/man1/arbiter.1")
    if shutil.which("groff"):
        code, out = run(["groff", "-man", "-ww", "-z", man])
        check(code == 0 and out == "",
              "man page renders without warnings" + (f": {out}" if out else ""))
    else:
        print("skip  man page rendering: no groff (Debian package groff-base)")
    completion = os.path.join(prefix, "share/bash-completion/completions/arbiter")
    code, out = run(["bash", "-c", 'source "$1"; complete -p arbiter', "-", completion])
    check(code == 0 and "-F _arbiter arbiter" in out, "completion registers for arbiter")
    script = ('source "$1"; COMP_WORDS=(arbiter "${@:2}"); COMP_CWORD=$(($# - 1)); _arbiter; '
              'echo "${COMPREPLY[*]}"')
    for words, want in ((["tr"], "translate"), (["check", "--format", ""], "text json sarif"),
                        (["translate", "--stage", ""], "arbvp arbfp"),
                        (["exec", "--driver", ""], "softpipe llvmpipe"),
                        (["check", "--Wer"], "--Werror")):
        code, out = run(["bash", "-c", script, "-", completion] + words)
        check(out.strip() == want, f"completion of 'arbiter {' '.join(words)}' is '{want}' "
              f"(got '{out.strip()}')")

    # Every option of every command's --help is in the man page's section of the command and
    # in the command's completions, and the completions offer nothing else.
    with open(man) as f:
        roff = f.read().replace("\\-", "-")
    for command in ("check", "info", "link", "translate", "exec", "verify", "run"):
        code, out = run([arbiter, command, "--help"])
        options = out.split("Options:", 1)[-1].split("\n\n", 1)[0]
        flags = set(re.findall(r"^  (-[^ ]+)", options, re.M))
        flags = {f for group in flags for f in group.split(",")}
        # CLI11 shows a flag whose value is optional with its default: "--translate{glsl110}".
        # The man page names it bare; completion offers it bare and with "=".
        optional = {f.split("{", 1)[0] for f in flags if "{" in f}
        flags = {f.split("{", 1)[0] for f in flags}
        section = roff.split(f'.SS "arbiter {command} ', 1)[-1].split("\n.S", 1)[0]
        missing = sorted(f for f in flags - {"-h", "--help"}
                         if not re.search(rf"(?<![\w-]){re.escape(f)}(?![\w-])", section))
        check(code == 0 and flags and not missing,
              f"man page documents every option of {command}" + (f": {missing}" if missing else ""))
        code, out = run(["bash", "-c", script, "-", completion, command, "-"])
        offered = set(out.split())
        flags |= {f + "=" for f in optional}
        check(offered == flags, f"completion offers the options of {command} "
              f"(missing {sorted(flags - offered)}, extra {sorted(offered - flags)})")

    # --- examples/cmake-pipeline with Ninja ----------------------------------------------
    project = os.path.join(tmp, "pipeline src")
    shutil.copytree(os.path.join(source_dir, "examples", "cmake-pipeline"), project)
    ninja_build = os.path.join(tmp, "pipeline ninja")
    must([cmake, "-S", project, "-B", ninja_build, "-G", "Ninja", f"-DCMAKE_PREFIX_PATH={prefix}"],
         "configure examples/cmake-pipeline (Ninja)")
    out = must([cmake, "--build", ninja_build, "--", "-v"], "build examples/cmake-pipeline (Ninja)")
    ran = len(STEP.findall(out))
    check(ran == 5, f"first build runs 5 arbiter steps (ran {ran})")
    outputs = ["glsl/water.vert", "glsl/water.vert.bindings.json", "glsl/water.frag",
               "glsl/water.frag.bindings.json", "arbiter/shaders/sky.vert.stamp",
               "arbiter/shaders/sky.frag.stamp", "arbiter/sky.program.stamp"]
    for rel in outputs:
        check(os.path.isfile(os.path.join(ninja_build, rel)), f"build wrote {rel}")
    with open(os.path.join(ninja_build, "glsl/water.vert")) as f:
        check(f.read().startswith("#version 110"), "water.vert is a GLSL 1.10 shader")
    out = must([cmake, "--build", ninja_build], "second build")
    check("no work to do" in out, "second build: ninja has no work to do")

    # sky.frag: its own check and the program's; water.vp: its translation alone.
    for shader, verbs in (("sky.frag", ["check", "check --link"]), ("water.vp", ["translate"])):
        touch(os.path.join(project, "shaders", shader))
        out = must([cmake, "--build", ninja_build, "--", "-v"], f"build after touching {shader}")
        steps = [line for line in out.splitlines() if STEP.search(line)]
        check(sorted(STEP.search(line).group(1) for line in steps) == sorted(verbs) and
              all(shader in line for line in steps),
              f"touching {shader} re-runs its steps {verbs} alone (ran {len(steps)} steps)")
        out = must([cmake, "--build", ninja_build], "build again")
        check("no work to do" in out, f"after {shader}'s step: no work to do")

    # --- a rejected shader fails the build and leaves no output ---------------------------
    broken = os.path.join(tmp, "broken src")
    shutil.copytree(project, broken)
    with open(os.path.join(broken, "shaders", "sky.frag"), "a") as f:
        f.write("void helper() { undeclared_name = 1.0; }\n")
    with open(os.path.join(broken, "shaders", "water.fp")) as f:
        text = f.read()
    with open(os.path.join(broken, "shaders", "water.fp"), "w") as f:
        f.write(text.replace("MUL base, base, tint;", "MUL base, base, missing;"))
    broken_build = os.path.join(tmp, "broken ninja")
    must([cmake, "-S", broken, "-B", broken_build, "-G", "Ninja", f"-DCMAKE_PREFIX_PATH={prefix}"],
         "configure the broken copy")
    code, out = run([cmake, "--build", broken_build, "--", "-k", "0"])
    check(code != 0, "a rejected shader fails the build")
    check(re.search(r"sky\.frag:\d+:\d+: error: .*undeclared_name", out) is not None,
          "the build shows the GLSL diagnostic with its position")
    check(re.search(r"water\.fp:\d+:\d+: error: .*missing", out) is not None,
          "the build shows the ARB diagnostic with its position")
    check(not os.path.exists(os.path.join(broken_build, "arbiter/shaders/sky.frag.stamp")),
          "no stamp for the rejected GLSL shader")
    check(not os.path.exists(os.path.join(broken_build, "arbiter/sky.program.stamp")),
          "no stamp for the program of the rejected shader")
    check(not os.path.exists(os.path.join(broken_build, "glsl/water.frag")) and
          not os.path.exists(os.path.join(broken_build, "glsl/water.frag.bindings.json")),
          "no translation for the rejected ARB program")
    check(os.path.isfile(os.path.join(broken_build, "arbiter/shaders/sky.vert.stamp")) and
          os.path.isfile(os.path.join(broken_build, "glsl/water.vert")),
          "the accepted shaders still built (-k 0)")

    # --- examples/cmake-pipeline with Make --------------------------------------------------
    check(shutil.which("make") is not None, "make is installed (scripts/setup-deps)")
    make_build = os.path.join(tmp, "pipeline make")
    must([cmake, "-S", project, "-B", make_build, "-G", "Unix Makefiles",
          f"-DCMAKE_PREFIX_PATH={prefix}"], "configure examples/cmake-pipeline (Make)")
    out = must([cmake, "--build", make_build], "build with Make")
    ran = len(MAKE_STEP.findall(out))
    check(ran == 5, f"Make runs 5 arbiter steps (ran {ran})")
    for rel in outputs:
        check(os.path.isfile(os.path.join(make_build, rel)), f"Make build wrote {rel}")
    out = must([cmake, "--build", make_build], "second Make build")
    check(not MAKE_STEP.search(out), "second Make build runs no arbiter step")
    touch(os.path.join(project, "shaders", "sky.vert"))
    out = must([cmake, "--build", make_build], "Make build after touching sky.vert")
    steps = MAKE_STEP.findall(out)
    check(sorted(steps) == ["check", "check --link"] and "sky.vert" in out,
          f"Make: touching sky.vert re-runs its check and the program's (ran {len(steps)} steps)")

    # --- examples/api-check: the C++ libraries ----------------------------------------------
    api_build = os.path.join(tmp, "api-check")
    must([cmake, "-S", os.path.join(source_dir, "examples", "api-check"), "-B", api_build,
          "-G", "Ninja", f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={cxx}"],
         "configure examples/api-check")
    must([cmake, "--build", api_build], "build examples/api-check against the installed libraries")
    api_check = os.path.join(api_build, "api-check")
    glsl_out = os.path.join(tmp, "water.vert")
    code, out = run([api_check, os.path.join(project, "shaders", "water.vp"), glsl_out])
    check(code == 0 and "water.vp: ok" in out and "translated:" in out and
          re.search(r"^result\.position = \(", out, re.M) is not None,
          f"api-check checks, translates and runs water.vp (exit {code})")
    if os.path.isfile(glsl_out):
        with open(glsl_out) as f:
            check(f.read().startswith("#version 110"), "api-check wrote the translation")
    else:
        check(False, "api-check wrote the translation")
    code, out = run([api_check, os.path.join(broken, "shaders", "water.fp")])
    check(code == 1 and re.search(r"water\.fp:\d+:\d+: error: ", out) is not None,
          f"api-check rejects a broken program with a diagnostic (exit {code})")

    # --- examples/glstate-check: the header-only host library alone ---------------------
    gs_build = os.path.join(tmp, "glstate-check")
    must([cmake, "-S", os.path.join(source_dir, "examples", "glstate-check"), "-B", gs_build,
          "-G", "Ninja", f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={cxx}"],
         "configure examples/glstate-check")
    must([cmake, "--build", gs_build], "build examples/glstate-check against arbiter::glstate")
    glstate_check = os.path.join(gs_build, "glstate-check")
    code, out = run([glstate_check, "state.light[1].half", "state.fog.params",
                     "state.matrix.mvp.row[2]", "program.env[3]"])
    check(code == 0 and out == "state.light[1].half = 0 -0.707107 0.707107 1\n"
          "state.fog.params = 1 2 6 0.25\nstate.matrix.mvp.row[2] = 0 0 -1 2\n"
          "program.env[3] = 1 2 3 4\n", f"glstate-check computes the uniforms (exit {code})")
    code, out = run([glstate_check, "state.matrix.modelview.row[0]"])
    check(code == 1 and "not a uniform" in out,
          f"glstate-check refuses a non-canonical spelling (exit {code})")

    # --- examples/port-to-core: an ARB pair and its glsl330 translation, the same pixels ---
    port_build = os.path.join(tmp, "port-to-core")
    must([cmake, "-S", os.path.join(source_dir, "examples", "port-to-core"), "-B", port_build,
          "-G", "Ninja", f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={cxx}"],
         "configure examples/port-to-core")
    must([cmake, "--build", port_build], "build examples/port-to-core against the installed package")
    valid = os.path.join(source_dir, "corpus", "arb", "valid")
    code, out = run([os.path.join(port_build, "port-to-core"),
                     os.path.join(valid, "lit-blinn-phong.vp"),
                     os.path.join(valid, "beyond-min-env-index-24.fp")])
    check(code == 0 and "ok: the pictures match" in out,
          f"port-to-core draws the same pixels through the translation (exit {code})")
    if failures:
        print(out)
finally:
    shutil.rmtree(tmp, ignore_errors=True)

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
