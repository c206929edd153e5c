#!/usr/bin/env python3
"""The same inputs give byte-identical outputs whatever -j, the time zone, the locale,
SOURCE_DATE_EPOCH or the working directory, and paths in outputs are as given.

Each command (check, link, info, translate, exec, verify, run in their text, JSON and SARIF
forms, with the files translate and run write) runs once from the repository root with
relative paths, -j 1, LC_ALL=C, TZ=UTC, and again from temporary directories that hold copies
of the inputs under the same relative names (created in reverse order, so that directory
listings come in another order), with -j 2 and -j 8, UTF-8 locales (C.UTF-8, and de_DE.UTF-8
with its decimal comma, built with localedef when the system has none), other time zones and
another SOURCE_DATE_EPOCH. Exit codes, stdout, stderr and every file written must be equal
byte for byte. This test replaces jobs_determinism.py (-j alone): its corpora and -j values
are here.

  determinism.py ARBITER SOURCE_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

ARBITER = os.path.abspath(sys.argv[1])
ROOT = os.path.abspath(sys.argv[2])
# Files written by the commands, relative to the working directory. Under the repository
# root it is ignored by git (/build-*/); the pid keeps concurrent runs apart.
OUT = f"build-determinism-{os.getpid()}"
FAILURES = []

# The inputs the commands read, copied into the other working directories.
INPUT_TREES = ["corpus/arb", "corpus/glsl", "corpus/exec/arb-fp", "corpus/exec/arb-vp",
               "corpus/exec-deviations", "tests/golden/check", "tests/golden/link",
               "tests/golden/exec", "tests/golden/exec-glsl", "tests/golden/translate",
               "tests/golden/verify"]

VALID = "corpus/arb/valid"
VERIFY_SAMPLE = [f"{VALID}/{name}" for name in sorted(os.listdir(os.path.join(ROOT, VALID)))[::12]]
SHADER_TESTS = ["corpus/exec/arb-fp/abs.shader_test", "corpus/exec/arb-fp/kil.shader_test",
                "corpus/exec/arb-vp/lit.shader_test", "corpus/exec/arb-fp/tex-3d.shader_test",
                # Fails on Mesa (a known deviation): a FAIL message with values.
                "corpus/exec-deviations/light0-spot-cutoff-180-arb.shader_test",
                "corpus/exec/missing.shader_test"]
CHECK_FILES = ["tests/golden/check/warn-non-ascii-comment.fp",
               "tests/golden/check/bad-missing-semicolon-tab.vp",
               "tests/golden/check/ok-transform.vert", "tests/golden/check/bad-glsl-errors.vert",
               "corpus/arb/invalid/bad-address-as-source.vp", "no-such-file.vp"]

# (name, arguments, takes -j, files or directories written under OUT)
COMMANDS = []
for fmt in ("text", "json", "sarif"):
    COMMANDS += [
        (f"check arb {fmt}", ["check", "--format", fmt, "corpus/arb"], True, []),
        (f"check glsl {fmt}", ["check", "--format", fmt, "corpus/glsl"], True, []),
        (f"check files {fmt}", ["check", "--format", fmt] + CHECK_FILES, True, []),
        (f"link {fmt}", ["link", "--format", fmt, "tests/golden/link/uniforms.vs",
                         "tests/golden/link/uniforms.fs"], False, []),
    ]
for fmt in ("text", "json"):
    COMMANDS += [
        (f"info {fmt}", ["info", "--format", fmt, VALID, "corpus/glsl/types",
                         "tests/golden/check/bad-glsl-errors.vert"], False, []),
        (f"exec {fmt}", ["exec", "--format", fmt, "--engine", "all",
                         "tests/golden/exec/pair.vp", "tests/golden/exec/inputs/pair.fp"],
         False, []),
        (f"exec glsl {fmt}", ["exec", "--format", fmt, "--vectors",
                              "tests/golden/exec-glsl/inputs/pair.json",
                              "tests/golden/exec-glsl/inputs/pair.vert",
                              "tests/golden/exec-glsl/inputs/pair.frag"], False, []),
        (f"verify {fmt}", ["verify", "--format", fmt, "--vectors", "8"] + VERIFY_SAMPLE, True, []),
    ]
COMMANDS += [
    ("translate directory", ["translate", "-o", f"{OUT}/translate", "--bindings",
                             f"{OUT}/translate", VALID], True, ["translate"]),
    ("translate pair", ["translate", "--pair", "-o", f"{OUT}/pair/pair", "--bindings",
                        f"{OUT}/pair/pair.bindings.json", "tests/golden/exec/pair.vp",
                        "tests/golden/exec/inputs/pair.fp"], True, ["pair"]),
    ("translate stdout", ["translate", "tests/golden/translate/rsq-lit.vp"], True, []),
    ("verify pair", ["verify", "--format", "json", "--vectors", "8", "--pair",
                     "tests/golden/verify/pair.vp", "tests/golden/exec/inputs/pair.fp"], True, []),
    ("run json", ["run", "--format", "json", "--png", f"{OUT}/png", "--junit",
                  f"{OUT}/junit.xml"] + SHADER_TESTS, True, ["png", "junit.xml"]),
    ("run text", ["run", "--translate"] + SHADER_TESTS, True, []),
    # Two pictures of one name: the last test to finish would win; refused instead.
    ("run png clash", ["run", "--png", f"{OUT}/clash", "corpus/exec/arb-fp/abs.shader_test",
                       "corpus/exec/arb-vp/abs.shader_test"], True, []),
]


def utf8_locales(workdir):
    """[(locale, LOCPATH or None)]: C.UTF-8, then a UTF-8 locale with a decimal comma
    (de_DE) if the system lists one or localedef can build one under `workdir`, else any
    other UTF-8 locale listed: a locale-dependent number format would show."""
    try:
        listed = subprocess.run(["locale", "-a"], capture_output=True, text=True).stdout.split()
    except OSError:
        listed = []
    names = {n.lower().replace("-", ""): n for n in listed}
    found = [("C.UTF-8", None)]
    for want in ("de_de.utf8", "fr_fr.utf8", "ru_ru.utf8"):
        if want in names:
            return found + [(names[want], None)]
    locpath = os.path.join(workdir, "locales")
    os.makedirs(locpath)
    try:
        built = subprocess.run(["localedef", "-i", "de_DE", "-f", "UTF-8",
                                os.path.join(locpath, "de_DE.UTF-8")],
                               capture_output=True).returncode == 0
    except OSError:
        built = False
    if built:
        return found + [("de_DE.UTF-8", locpath)]
    others = [n for key, n in sorted(names.items())
              if key.endswith(".utf8") and not key.startswith("c.")]
    return found + [(n, None) for n in others[:1]]


def environment(locale, tz, epoch):
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("LC_") and
           k not in ("LANG", "LANGUAGE", "LOCPATH", "TZ", "SOURCE_DATE_EPOCH")}
    env.update(LC_ALL=locale[0], LANG=locale[0], TZ=tz, SOURCE_DATE_EPOCH=epoch, NO_COLOR="1")
    if locale[1]:
        env["LOCPATH"] = locale[1]
    return env


def copy_inputs(workdir):
    """The input trees under the same relative names, created in reverse order."""
    for tree in INPUT_TREES:
        for dirpath, dirnames, filenames in sorted(os.walk(os.path.join(ROOT, tree)), reverse=True):
            rel = os.path.relpath(dirpath, ROOT)
            os.makedirs(os.path.join(workdir, rel), exist_ok=True)
            for name in sorted(filenames, reverse=True):
                shutil.copyfile(os.path.join(dirpath, name), os.path.join(workdir, rel, name))


def read_tree(path):
    """{relative path: bytes} of a file or of every file under a directory."""
    if os.path.isfile(path):
        with open(path, "rb") as f:
            return {"": f.read()}
    files = {}
    for dirpath, _, filenames in os.walk(path):
        for name in filenames:
            full = os.path.join(dirpath, name)
            with open(full, "rb") as f:
                files[os.path.relpath(full, path)] = f.read()
    return files


def run_all(setting):
    """Runs every command in one setting; returns {name: (exit, stdout, stderr, files)}."""
    cwd, jobs, env = setting["cwd"], setting["jobs"], setting["env"]
    os.makedirs(os.path.join(cwd, OUT, "pair"), exist_ok=True)
    outcomes = {}
    for name, args, takes_jobs, written in COMMANDS:
        argv = args[:1] + (["-j", jobs] if takes_jobs else []) + args[1:]
        p = subprocess.run([ARBITER] + argv, cwd=cwd, env=env, capture_output=True, timeout=900)
        files = {w: read_tree(os.path.join(cwd, OUT, w)) for w in written}
        outcomes[name] = (p.returncode, p.stdout, p.stderr, files)
    return outcomes


def describe(setting):
    return (f"cwd {'the repository' if setting['cwd'] == ROOT else 'a temporary directory'}, "
            f"-j {setting['jobs']}, LC_ALL={setting['env']['LC_ALL']}, "
            f"TZ={setting['env']['TZ']}, SOURCE_DATE_EPOCH={setting['env']['SOURCE_DATE_EPOCH']}")


def first_difference(a, b):
    for i, (x, y) in enumerate(zip(a, b)):
        if x != y:
            return f"byte {i}: ...{a[max(0, i - 60):i + 60]!r} vs ...{b[max(0, i - 60):i + 60]!r}"
    return f"lengths {len(a)} and {len(b)}"


def compare(reference, other, setting):
    for name, (code, out, err, files) in reference.items():
        code2, out2, err2, files2 = other[name]
        where = f"{name} ({describe(setting)})"
        if code != code2:
            FAILURES.append(f"{where}: exit {code2}, not {code}")
        for what, a, b in (("stdout", out, out2), ("stderr", err, err2)):
            if a != b:
                FAILURES.append(f"{where}: {what} differs at {first_difference(a, b)}")
        for written, tree in files.items():
            tree2 = files2[written]
            if sorted(tree) != sorted(tree2):
                FAILURES.append(f"{where}: {written}: other files {sorted(set(tree) ^ set(tree2))}")
            for rel in sorted(set(tree) & set(tree2)):
                if tree[rel] != tree2[rel]:
                    FAILURES.append(f"{where}: {written}/{rel} differs at "
                                    f"{first_difference(tree[rel], tree2[rel])}")


def check_paths(outcomes):
    """Paths in outputs are the relative paths given, never made absolute."""
    def expect(name, condition, detail):
        if not condition:
            FAILURES.append(f"paths in {name}: {detail}")

    for name, (_, out, err, files) in outcomes.items():
        for text in [out, err] + [data for tree in files.values() for data in tree.values()]:
            expect(name, ROOT.encode() not in text, f"the absolute path {ROOT} appears")
    _, _, err, _ = outcomes["check files text"]
    expect("check text", err.startswith(b"tests/golden/check/warn-non-ascii-comment.fp:"),
           err[:100])
    doc = json.loads(outcomes["check files json"][1])
    expect("check json", [f["path"] for f in doc["files"]] == CHECK_FILES,
           [f["path"] for f in doc["files"]])
    doc = json.loads(outcomes["check files sarif"][1])
    uris = {loc["physicalLocation"]["artifactLocation"]["uri"]
            for r in doc["runs"][0]["results"] for loc in r["locations"]}
    expect("check sarif", uris == set(CHECK_FILES) - {"tests/golden/check/ok-transform.vert"},
           sorted(uris))
    doc = json.loads(outcomes["check arb json"][1])
    expect("check of a directory", all(f["path"].startswith("corpus/arb/") for f in doc["files"])
           and len(doc["files"]) > 300, len(doc["files"]))
    doc = json.loads(outcomes["info json"][1])
    first = doc["programs"][0]["path"]
    expect("info json", first.startswith(VALID + "/"), first)
    doc = json.loads(outcomes["verify json"][1])
    expect("verify json", [p["file"] for p in doc["programs"]] == VERIFY_SAMPLE,
           [p["file"] for p in doc["programs"]])
    doc = json.loads(outcomes["run json"][1])
    expect("run json", [t["file"] for t in doc["tests"]] == SHADER_TESTS,
           [t["file"] for t in doc["tests"]])
    expect("run json png", doc["tests"][0].get("png") == f"{OUT}/png/abs.png",
           doc["tests"][0].get("png"))
    expect("run json statuses", {t["status"] for t in doc["tests"]} == {"PASS", "FAIL"},
           [t["status"] for t in doc["tests"]])
    junit = outcomes["run json"][3]["junit.xml"][""]
    expect("run junit", b'classname="corpus/exec/arb-fp" name="abs.shader_test"' in junit,
           junit[:300])
    pngs = outcomes["run json"][3]["png"]
    expect("run png", "abs.png" in pngs and pngs["abs.png"].startswith(b"\x89PNG"), sorted(pngs))
    code, _, err, _ = outcomes["run png clash"]
    expect("run png clash", code == 2 and b"abs.png" in err and
           not os.path.exists(os.path.join(ROOT, OUT, "clash")), (code, err))
    translated = outcomes["translate directory"][3]["translate"]
    expect("translate", len(translated) > 300 and all(
        n.endswith((".vert", ".frag", ".bindings.json")) for n in translated), len(translated))


def main():
    work = tempfile.mkdtemp(prefix="arbiter-determinism-")
    locales = utf8_locales(work)
    settings = [
        {"cwd": ROOT, "jobs": "1", "env": environment(("C", None), "UTC", "0")},
        {"cwd": os.path.join(work, "b"), "jobs": "2",
         "env": environment(locales[0], "Asia/Kathmandu", "1700000000")},
        {"cwd": os.path.join(work, "c"), "jobs": "8",
         "env": environment(locales[-1], "America/St_Johns", "946684800")},
    ]
    try:
        for setting in settings[1:]:
            copy_inputs(setting["cwd"])
        reference = run_all(settings[0])
        check_paths(reference)
        for setting in settings[1:]:
            compare(reference, run_all(setting), setting)
        # Control: the comparison sees one changed byte of output and of a written file.
        altered = dict(reference)
        code, out, err, files = altered["run json"]
        png = dict(files["png"], **{"abs.png": files["png"]["abs.png"] + b"\0"})
        altered["run json"] = (code, out.replace(b"PASS", b"FAIL", 1), err, dict(files, png=png))
        failures = len(FAILURES)
        compare(reference, altered, settings[0])
        if len(FAILURES) != failures + 2:
            FAILURES.append(f"control: a changed output was not seen ({FAILURES[failures:]})")
        else:
            del FAILURES[failures:]
    finally:
        shutil.rmtree(os.path.join(ROOT, OUT), ignore_errors=True)
        shutil.rmtree(work, ignore_errors=True)
    for f in FAILURES:
        print("FAIL " + f)
    print(f"{len(COMMANDS)} commands in {len(settings)} settings "
          f"({', '.join(name for name, _ in locales)}): "
          f"{len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
