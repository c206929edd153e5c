#!/usr/bin/env python3
"""Every JSON document arbiter writes matches docs/json-schema.json, and its SARIF matches the
SARIF 2.1.0 constraints of tests/cli/sarif-2.1.0-subset.schema.json with rule metadata for every
result: check and link (json, sarif), info, translate --bindings (vp, fp, --pair, a directory),
exec, verify and run on inputs from corpus/ and tests/golden/. Negative controls prove that the
schemas reject a renamed, missing or mistyped field.

  json_schema.py ARBITER SOURCE_DIR
"""
import copy
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import jsonschema

ARBITER = os.path.abspath(sys.argv[1])
ROOT = os.path.abspath(sys.argv[2])
ENV = dict(os.environ, NO_COLOR="1", LC_ALL="C")
FAILURES = []
CHECKED = {"documents": 0}


def load(path):
    with open(os.path.join(ROOT, path), encoding="utf-8") as f:
        return json.load(f)


SCHEMA = load("docs/json-schema.json")
SARIF_SCHEMA = load("tests/cli/sarif-2.1.0-subset.schema.json")
jsonschema.Draft202012Validator.check_schema(SCHEMA)
jsonschema.Draft202012Validator.check_schema(SARIF_SCHEMA)
KINDS = sorted(SCHEMA["$defs"].keys() & {"check", "info", "bindings", "exec", "verify", "run"})
assert KINDS == ["bindings", "check", "exec", "info", "run", "verify"], KINDS


def validator(kind):
    """The sub-schema of one document kind, as docs/json-output.md says to select it."""
    schema = {k: v for k, v in SCHEMA.items() if k != "oneOf"}
    schema["$ref"] = "#/$defs/" + kind
    return jsonschema.Draft202012Validator(schema)


VALIDATORS = {kind: validator(kind) for kind in KINDS}
ROOT_VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)
SARIF_VALIDATOR = jsonschema.Draft202012Validator(SARIF_SCHEMA)


def fail(name, detail):
    FAILURES.append(f"{name}: {detail}")


def errors_of(validator_, doc):
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message[:300]}"
            for e in validator_.iter_errors(doc)]


def run(args, cwd=ROOT, codes=(0, 1)):
    p = subprocess.run([ARBITER] + args, cwd=cwd, capture_output=True, env=ENV, timeout=600)
    if p.returncode not in codes:
        fail(" ".join(args), f"exit {p.returncode}, stderr:\n{p.stderr.decode()[:2000]}")
        return None
    return p.stdout.decode("utf-8")


def expect_valid(kind, name, doc):
    """Validates against the kind's sub-schema, and against the root: exactly that kind."""
    CHECKED["documents"] += 1
    errors = errors_of(VALIDATORS[kind], doc)
    if errors:
        fail(f"{name} ({kind})", "\n  ".join(errors[:10]))
        return
    others = [k for k in KINDS if k != kind and VALIDATORS[k].is_valid(doc)]
    if others or not ROOT_VALIDATOR.is_valid(doc):
        fail(f"{name} ({kind})", f"the root schema does not single it out (also {others})")


def check_json(kind, args, cwd=ROOT, codes=(0, 1)):
    out = run(args, cwd, codes)
    if out is None:
        return None
    try:
        doc = json.loads(out)
    except json.JSONDecodeError as e:
        fail(" ".join(args), f"not JSON: {e}")
        return None
    expect_valid(kind, " ".join(args), doc)
    return doc


# ---- SARIF: the subset schema, then what JSON Schema cannot say -------------------------

def documented_entries():
    """code -> the first line of its docs/diagnostics.md entry ("**error**: summary. Spec: X.")."""
    with open(os.path.join(ROOT, "docs/diagnostics.md"), encoding="utf-8") as f:
        text = f.read()
    return dict(re.findall(r"^## (\S+)\n\n(\*\*\w+\*\*: .*)$", text, re.M))


DOCUMENTED = documented_entries()


def unescape(markdown):
    """Markdown without its backslash escapes (CommonMark: any ASCII punctuation)."""
    return re.sub(r"\\([!-/:-@\[-`{-~])", r"\1", markdown)


def sarif_problems(log):
    problems = errors_of(SARIF_VALIDATOR, log)
    if problems:
        return problems
    run_ = log["runs"][0]
    rules = run_["tool"]["driver"]["rules"]
    ids = [r["id"] for r in rules]
    if len(set(ids)) != len(ids):
        problems.append(f"duplicate rules: {ids}")
    used = []
    for i, result in enumerate(run_["results"]):
        index = result["ruleIndex"]
        if index >= len(rules) or rules[index]["id"] != result["ruleId"]:
            problems.append(f"results/{i}: ruleIndex {index} is not rule '{result['ruleId']}'")
        if result["ruleId"] not in used:
            used.append(result["ruleId"])
    # The rules are those of the codes present, in first-use order (docs/json-output.md).
    if ids != used:
        problems.append(f"rules {ids} are not the codes used {used}")
    for rule in rules:
        code = rule["id"]
        if not rule["helpUri"].endswith("#" + code):
            problems.append(f"{code}: helpUri {rule['helpUri']}")
        if not rule["help"]["markdown"].endswith("(" + rule["helpUri"] + ")"):
            problems.append(f"{code}: help.markdown does not link helpUri")
        if rule["defaultConfiguration"]["level"] not in ("error", "warning", "note"):
            problems.append(f"{code}: level {rule['defaultConfiguration']['level']}")
        # Codes of the diagnostic tables: help says what docs/diagnostics.md says.
        if code.startswith(("arb-", "glsl-")):
            entry = DOCUMENTED.get(code)
            if entry is None:
                problems.append(f"{code}: not in docs/diagnostics.md")
            elif not unescape(rule["help"]["markdown"]).startswith(unescape(entry) + "\n\n"):
                problems.append(f"{code}: help.markdown {rule['help']['markdown']!r} is not the "
                                f"documented {entry!r}")
            elif not entry.startswith(f"**{rule['defaultConfiguration']['level']}**"):
                problems.append(f"{code}: defaultConfiguration differs from the docs")
    return problems


def check_sarif(args, cwd=ROOT, expect_results=True):
    out = run(args, cwd)
    if out is None:
        return None
    CHECKED["documents"] += 1
    log = json.loads(out)
    problems = sarif_problems(log)
    if problems:
        fail(" ".join(args), "\n  ".join(problems[:10]))
    elif expect_results and not log["runs"][0]["results"]:
        fail(" ".join(args), "no results: the case does not test rules")
    return log


# ---- Negative controls: each mutation must be rejected ----------------------------------

def expect_rejected(name, validator_, doc, mutate):
    bad = copy.deepcopy(doc)
    mutate(bad)
    if validator_.is_valid(bad):
        fail("negative control", f"{name}: the schema accepts the mutated document")


def rename(obj, old, new):
    obj[new] = obj.pop(old)


def negative_controls(docs, sarif_log):
    check = VALIDATORS["check"]
    d = docs["check"]
    expect_rejected("check: diagnostic severity renamed", check, d,
                    lambda x: rename(x["files"][0]["diagnostics"][0], "severity", "level"))
    expect_rejected("check: unknown severity", check, d,
                    lambda x: x["files"][0]["diagnostics"][0].update(severity="fatal"))
    expect_rejected("check: summary missing", check, d, lambda x: x.pop("summary"))
    expect_rejected("check: line 0", check, d,
                    lambda x: x["files"][0]["diagnostics"][0].update(line=0))
    expect_rejected("check: errors as a string", check, d,
                    lambda x: x["files"][0].update(errors="1"))
    expect_rejected("check: a field added to a file", check, d,
                    lambda x: x["files"][0].update(status="rejected"))
    expect_rejected("info: stats field renamed", VALIDATORS["info"], docs["info"],
                    lambda x: rename(x["programs"][0]["stats"], "tex_indirections", "indirections"))
    expect_rejected("bindings: glsl renamed", VALIDATORS["bindings"], docs["bindings"],
                    lambda x: rename(x["inputs"][0], "glsl", "expression"))
    expect_rejected("exec: three components", VALIDATORS["exec"], docs["exec"],
                    lambda x: x["results"]["ref"][0]["outputs"][0]["value"].pop())
    expect_rejected("exec: NaN spelled NaN", VALIDATORS["exec"], docs["exec"],
                    lambda x: x["results"]["ref"][0]["outputs"][0]["value"].__setitem__(0, "NaN"))
    expect_rejected("verify: unknown verdict", VALIDATORS["verify"], docs["verify"],
                    lambda x: x["programs"][0].update(verdict="pass"))
    expect_rejected("verify: error verdict without its error", VALIDATORS["verify"],
                    docs["verify"], lambda x: x["programs"][0].update(verdict="error"))
    expect_rejected("run: lower-case status", VALIDATORS["run"], docs["run"],
                    lambda x: x["tests"][0].update(status="pass"))
    expect_rejected("run: counts missing", VALIDATORS["run"], docs["run"],
                    lambda x: x.pop("failed"))
    # SARIF: the schema, then the checks beyond it.
    for name, mutate in [
        ("rule help removed", lambda x: x["runs"][0]["tool"]["driver"]["rules"][0].pop("help")),
        ("help without markdown",
         lambda x: x["runs"][0]["tool"]["driver"]["rules"][0]["help"].pop("markdown")),
        ("version 2.0.0", lambda x: x.update(version="2.0.0")),
        ("startLine 0", lambda x: x["runs"][0]["results"][0]["locations"][0]["physicalLocation"]
         ["region"].update(startLine=0)),
        ("level fatal", lambda x: x["runs"][0]["results"][0].update(level="fatal")),
        ("ruleIndex off by one", lambda x: x["runs"][0]["results"][0].update(
            ruleIndex=x["runs"][0]["results"][0]["ruleIndex"] + 1)),
        ("a rule no result uses", lambda x: x["runs"][0]["tool"]["driver"]["rules"].append(
            copy.deepcopy(x["runs"][0]["tool"]["driver"]["rules"][0]) | {"id": "arb-unused"})),
        ("help not the documented text", lambda x: x["runs"][0]["tool"]["driver"]["rules"][0]
         ["help"].update(markdown="**error**: something else.\n\n(" +
                         x["runs"][0]["tool"]["driver"]["rules"][0]["helpUri"] + ")")),
    ]:
        bad = copy.deepcopy(sarif_log)
        mutate(bad)
        if not sarif_problems(bad):
            fail("negative control", f"SARIF {name}: accepted")


SHADER_TESTS = {
    # A [require] Mesa does not meet, and a malformed file: SKIP and FAIL with a message.
    "skip.shader_test": "[require]\nGL_ARB_no_such_extension\n\n[test]\nclear\n",
    "bad-command.shader_test": "[require]\nGL >= 1.3\nGL_ARB_fragment_program\n\n"
                               "[fragment program]\n!!ARBfp1.0\nMOV result.color, {1.0};\nEND\n\n"
                               "[test]\nfrobnicate 1 2 3\n",
}


def non_utf8_paths(tmp):
    """A file name that is not UTF-8 is written with U+FFFD: still valid JSON, no crash."""
    folder = os.path.join(tmp, "bytes")
    os.makedirs(folder)
    program = os.path.join(folder.encode(), b"a\xff.fp")
    test = os.path.join(folder.encode(), b"a\xff.shader_test")
    shutil.copyfile(os.path.join(ROOT, "corpus/arb/valid/alias.fp").encode(), program)
    shutil.copyfile(os.path.join(ROOT, "corpus/exec/arb-fp/abs.shader_test").encode(), test)
    for kind, args in (("check", ["check", "--format", "json"]),
                       ("info", ["info", "--format", "json"]),
                       ("exec", ["exec", "--format", "json"]),
                       ("verify", ["verify", "--format", "json", "--vectors", "1"]),
                       ("run", ["run", "--format", "json"])):
        target = test if kind == "run" else program
        argv = [ARBITER.encode()] + [a.encode() for a in args] + [os.path.basename(target)]
        p = subprocess.run(argv, cwd=folder, capture_output=True, env=ENV, timeout=600)
        name = f"{kind} of a non-UTF-8 path"
        try:
            doc = json.loads(p.stdout.decode("utf-8"))
        except (UnicodeDecodeError, json.JSONDecodeError) as e:
            fail(name, f"exit {p.returncode}, {e}, stderr {p.stderr[:300]!r}")
            continue
        expect_valid(kind, name, doc)
        if "a\ufffd." not in json.dumps(doc, ensure_ascii=False):
            fail(name, "the path is not written with U+FFFD")


def main():
    docs = {}
    arb_invalid = "corpus/arb/invalid"
    # check and link: whole corpora (every diagnostic family), an error limit, a missing file,
    # two strings of one shader, a link pair. Rejections exit 1.
    docs["check"] = check_json("check", ["check", "--format", "json", arb_invalid])
    for args in (["corpus/arb/valid"], ["corpus/glsl"],
                 ["--error-limit", "2", "tests/golden/check/bad-error-limit.fp"],
                 ["tests/golden/check/warn-non-ascii-comment.fp",
                  "tests/golden/check/ok-transform.vp"],
                 ["--stage", "frag", "tests/golden/check/part1.glsl",
                  "tests/golden/check/part2.glsl"]):
        check_json("check", ["check", "--format", "json"] + args)
    missing = check_json("check", ["check", "--format", "json", "no-such-file.vp"], codes=(3,))
    if missing and missing["files"][0]["diagnostics"][0]["line"] is not None:
        fail("check missing file", "a file-less diagnostic has a line")
    link = "tests/golden/link"
    for pair in (["ok.vs", "ok.fs"], ["uniforms.vs", "uniforms.fs"],
                 ["varyings.vs", "varyings.fs"]):
        check_json("check", ["link", "--format", "json"] + pair, cwd=os.path.join(ROOT, link))
        check_sarif(["link", "--format", "sarif"] + pair, cwd=os.path.join(ROOT, link),
                    expect_results=pair[0] != "ok.vs")
    sarif_log = check_sarif(["check", "--format", "sarif", arb_invalid])
    for args in (["corpus/glsl"], ["corpus/arb/valid"],
                 ["--error-limit", "2", "tests/golden/check/bad-error-limit.fp"]):
        check_sarif(["check", "--format", "sarif"] + args)
    empty = check_sarif(["check", "--format", "sarif", "tests/golden/check/ok-transform.vp"],
                        expect_results=False)
    if empty and empty["runs"][0]["tool"]["driver"]["rules"]:
        fail("sarif of a valid program", "rules without results")

    # info: ARB and GLSL corpora (rejected inputs go to stderr as text), a two-string shader.
    docs["info"] = check_json("info", ["info", "--format", "json", "corpus/arb/valid"])
    check_json("info", ["info", "--format", "json", "corpus/glsl"])
    strings = check_json("info", ["info", "--format", "json", "--stage", "frag",
                                  "tests/golden/link/strings.fs", "tests/golden/link/common.glsl"])
    if strings and strings["programs"] and "strings" not in strings["programs"][0]:
        fail("info --stage frag", "a shader of two files does not list its strings")

    with tempfile.TemporaryDirectory() as tmp:
        # translate --bindings: a vertex program, a fragment program, a pair, a directory.
        maps = []
        for name, args in (("vp", ["tests/golden/translate/rsq-lit.vp"]),
                           ("fp", ["tests/golden/translate/no-comments.fp"]),
                           ("pair", ["--pair", "tests/golden/exec/pair.vp",
                                     "tests/golden/exec/inputs/pair.fp"])):
            path = os.path.join(tmp, name + ".bindings.json")
            if run(["translate", "-o", os.path.join(tmp, name), "--bindings", path] + args,
                   codes=(0,)) is not None:
                maps.append(path)
        outdir = os.path.join(tmp, "all")
        run(["translate", "-o", outdir, "--bindings", outdir, "corpus/arb/valid"], codes=(0,))
        maps += sorted(os.path.join(outdir, f) for f in os.listdir(outdir)
                       if f.endswith(".bindings.json"))
        if len(maps) < 100:
            fail("translate --bindings", f"only {len(maps)} binding maps written")
        for path in maps:
            with open(path, encoding="utf-8") as f:
                doc = json.load(f)
            expect_valid("bindings", os.path.relpath(path, tmp), doc)
            if doc["inputs"] and "bindings" not in docs:
                docs["bindings"] = doc

        # exec: one engine and both, a vertex and a fragment program, a pair.
        exec_dir = os.path.join(ROOT, "tests/golden/exec")
        docs["exec"] = check_json("exec", ["exec", "--format", "json", "--engine", "all",
                                           "lit.vp"], cwd=exec_dir)
        check_json("exec", ["exec", "--format", "json", "--vectors", "kil.json", "kil.fp"],
                   cwd=exec_dir)
        check_json("exec", ["exec", "--format", "json", "--engine", "all", "pair.vp",
                            "inputs/pair.fp"], cwd=exec_dir)
        # exec of GLSL shaders: a vertex shader, a fragment shader with a discard, a pair, a
        # rejected shader.
        glsl_dir = os.path.join(ROOT, "tests/golden/exec-glsl")
        check_json("exec", ["exec", "--format", "json", "--uniform", "weights=1,2,3",
                            "inputs/lit.vert"], cwd=glsl_dir)
        check_json("exec", ["exec", "--format", "json", "--vectors", "inputs/mrt.json",
                            "inputs/mrt.frag"], cwd=glsl_dir)
        check_json("exec", ["exec", "--format", "json", "inputs/pair.vert", "inputs/pair.frag"],
                   cwd=glsl_dir)
        check_json("exec", ["exec", "--format", "json", "inputs/rejected.vert"], cwd=glsl_dir)

        # verify: agreement, a disagreement (an injected translator bug), undefined results,
        # a pair.
        verify_dir = os.path.join(ROOT, "tests/golden/verify")
        docs["verify"] = check_json("verify", ["verify", "--format", "json", "-j", "2",
                                               "--vectors", "4", "agree.fp", "undefined.vp"],
                                    cwd=verify_dir)
        bad = check_json("verify", ["verify", "--format", "json", "--vectors", "4",
                                    "--engines", "ref,mesa-glsl", "--mutation",
                                    "lrp-operand-order", "mutation.fp"], cwd=verify_dir)
        if bad and bad["programs"][0]["verdict"] != "disagree":
            fail("verify --mutation", "no disagreement: the case does not test them")
        check_json("verify", ["verify", "--format", "json", "--vectors", "4", "--pair",
                              "pair.vp", "../exec/inputs/pair.fp"], cwd=verify_dir)

        # run: passing tests, a failing one (a known Mesa deviation), a skip, a malformed file.
        for name, text in SHADER_TESTS.items():
            with open(os.path.join(tmp, name), "w", encoding="utf-8") as f:
                f.write(text)
        docs["run"] = check_json("run", [
            "run", "--format", "json", "-j", "2", "--png", os.path.join(tmp, "png"),
            "corpus/exec/arb-fp/abs.shader_test", "corpus/exec/arb-vp/lit.shader_test",
            "corpus/exec-deviations/light0-spot-cutoff-180-glsl.shader_test",
            os.path.join(tmp, "skip.shader_test"), os.path.join(tmp, "bad-command.shader_test")])
        if docs["run"]:
            statuses = sorted({t["status"] for t in docs["run"]["tests"]})
            if statuses != ["FAIL", "PASS", "SKIP"]:
                fail("run", f"statuses {statuses}: the cases do not cover PASS, FAIL and SKIP")
        check_json("run", ["run", "--format", "json", "--translate",
                           "corpus/exec/arb-fp/kil.shader_test"])

        non_utf8_paths(tmp)

    if sarif_log and all(docs.get(k) for k in KINDS):
        negative_controls(docs, sarif_log)
    else:
        fail("negative controls", f"missing documents: {[k for k in KINDS if not docs.get(k)]}")

    for f in FAILURES:
        print("FAIL " + f)
    print(f"{CHECKED['documents']} documents validated, {len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
