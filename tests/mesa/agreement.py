#!/usr/bin/env python3
"""Mesa agreement: arbiter and Mesa must give every corpus ARB program the same verdict.

For every ARB program under the corpus (recursive; .vp .fp .arbvp .arbfp, and .txt files with
a `!!ARB` header), Mesa's verdict comes from one mesa_arb_load run over all files (OSMesa,
softpipe by default) and arbiter's from `arbiter check --limits mesa --format json FILE`
(exit 0 accepted, 1 rejected). A mismatch passes only when intentional-differences.md lists
the file with both verdicts; a listed file that no longer differs (or no longer exists) fails
as a stale entry. Files whose `# REQUIRE <extension>` names an extension Mesa lacks are
skipped. Prints each failure with both tools' messages, then `N passed, N failed, N skipped`.
Exit 0 when nothing failed, 1 otherwise, 2 on usage errors.
"""

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys

from differences import parse_differences, verdict_name

EXTENSIONS = (".vp", ".fp", ".arbvp", ".arbfp", ".txt")
REQUIRE_RE = re.compile(rb"#\s*REQUIRE\s+(\S+)")


def find_programs(corpus):
    """Every ARB program under `corpus`, as sorted paths relative to it (with '/')."""
    found = []
    for root, dirs, files in os.walk(corpus):
        dirs.sort()
        for name in files:
            if not name.endswith(EXTENSIONS):
                continue
            path = os.path.join(root, name)
            if name.endswith(".txt"):
                with open(path, "rb") as f:
                    if b"!!ARB" not in f.read(256):
                        continue
            found.append(os.path.relpath(path, corpus).replace(os.sep, "/"))
    return sorted(found)


def mesa_extensions(mesa_load, env):
    """The extensions Mesa advertises, or None if they cannot be queried."""
    try:
        proc = subprocess.run([mesa_load, "--extensions"], capture_output=True, env=env,
                              timeout=120, check=False)
        if proc.returncode != 0:
            return None
        return set(json.loads(proc.stdout)["extensions"])
    except (OSError, ValueError, KeyError, subprocess.TimeoutExpired):
        return None


def mesa_verdicts(mesa_load, paths, env):
    """Mesa's result per absolute path: the JSON object mesa_arb_load printed, or
    {"crash": message} when Mesa crashed or hung on that file (the run then goes on with the
    files after it)."""
    results = {}
    remaining = list(paths)
    while remaining:
        try:
            proc = subprocess.run([mesa_load, "--"] + remaining, capture_output=True, env=env,
                                  timeout=600, check=False)
            stdout, stderr, rc = proc.stdout, proc.stderr, proc.returncode
        except subprocess.TimeoutExpired as e:
            stdout, stderr, rc = e.stdout or b"", e.stderr or b"", "timeout"
        done = 0
        for line in stdout.decode("utf-8", "replace").splitlines():
            try:
                obj = json.loads(line)
            except ValueError:
                continue
            if done < len(remaining) and obj.get("path") == remaining[done]:
                results[remaining[done]] = obj
                done += 1
        remaining = remaining[done:]
        if not remaining:
            break
        # mesa_arb_load stopped before printing a result for remaining[0].
        detail = stderr.decode("utf-8", "replace").strip()[-2000:]
        results[remaining[0]] = {"crash": f"mesa_arb_load exit {rc} on this file: {detail}"}
        remaining = remaining[1:]
    return results


def arbiter_verdict(arbiter, path):
    """(accepted or None on a tool error, message lines) from `arbiter check`."""
    cmd = [arbiter, "check", "--limits", "mesa", "--format", "json", path]
    try:
        proc = subprocess.run(cmd, capture_output=True, timeout=60, check=False)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, [f"cannot run {' '.join(cmd)}: {e}"]
    stdout = proc.stdout.decode("utf-8", "replace")
    stderr = proc.stderr.decode("utf-8", "replace")
    messages = []
    try:
        doc = json.loads(stdout)
        for report in doc.get("files", []):
            for d in report.get("diagnostics", []):
                messages.append(f"{d.get('line', '?')}:{d.get('column', '?')}: "
                                f"{d.get('severity', '?')}: {d.get('message', '')} "
                                f"[{d.get('code', '?')}]")
    except (ValueError, AttributeError):
        if stdout.strip():
            messages.append("(output is not JSON) " + stdout.strip()[:2000])
    if stderr.strip():
        messages.append("stderr: " + stderr.strip()[:2000])
    if proc.returncode in (0, 1):
        return proc.returncode == 0, messages
    return None, [f"exit code {proc.returncode} (0 accept / 1 reject expected)"] + messages


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--arbiter", required=True, help="the arbiter binary")
    parser.add_argument("--mesa-load", required=True, help="the mesa_arb_load binary")
    parser.add_argument("--corpus", required=True, help="corpus/arb")
    parser.add_argument("--differences", required=True, help="intentional-differences.md")
    parser.add_argument("--driver", default="softpipe", choices=("softpipe", "llvmpipe"))
    parser.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()

    for what, path in (("arbiter", args.arbiter), ("mesa_arb_load", args.mesa_load)):
        if not os.access(path, os.X_OK):
            print(f"agreement: {what} binary '{path}' is missing or not executable")
            return 1
    if not os.path.isdir(args.corpus):
        print(f"agreement: corpus directory '{args.corpus}' does not exist")
        return 1

    entries, problems = parse_differences(args.differences, EXTENSIONS)
    programs = find_programs(args.corpus)
    if not programs:
        print(f"agreement: note: no ARB programs under {args.corpus}")

    env = dict(os.environ, GALLIUM_DRIVER=args.driver, MESA_SHADER_CACHE_DISABLE="true")
    extensions = mesa_extensions(args.mesa_load, env)
    if extensions is None:
        problems.append(f"{args.mesa_load} --extensions failed: cannot honour # REQUIRE lines")
        extensions = set()

    checked, skipped = [], []
    for rel in programs:
        with open(os.path.join(args.corpus, rel), "rb") as f:
            required = [r.decode("ascii", "replace") for r in REQUIRE_RE.findall(f.read())]
        missing = [r for r in required if r not in extensions]
        if missing:
            skipped.append((rel, missing))
        else:
            checked.append(rel)

    absolute = {rel: os.path.abspath(os.path.join(args.corpus, rel)) for rel in checked}
    mesa = mesa_verdicts(args.mesa_load, [absolute[rel] for rel in checked], env)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        arb = dict(zip(checked, pool.map(lambda rel: arbiter_verdict(args.arbiter, absolute[rel]),
                                         checked)))

    passed, failures = 0, []
    for rel in checked:
        m = mesa[absolute[rel]]
        a_ok, a_msgs = arb[rel]
        entry = entries.get(rel)
        if "crash" in m or a_ok is None:
            failures.append((rel, "a tool failed", a_ok, a_msgs, m))
            continue
        m_ok = bool(m.get("accepted"))
        if a_ok == m_ok:
            if entry is None:
                passed += 1
            else:
                failures.append((rel, f"stale entry (intentional-differences.md line "
                                 f"{entry[2]}): both tools now {verdict_name(a_ok)}",
                                 a_ok, a_msgs, m))
        elif entry is None:
            failures.append((rel, f"arbiter: {verdict_name(a_ok)}, mesa: {verdict_name(m_ok)}",
                             a_ok, a_msgs, m))
        elif entry[:2] != (a_ok, m_ok):
            failures.append((rel, f"listed as arbiter {verdict_name(entry[0])} / mesa "
                             f"{verdict_name(entry[1])} (line {entry[2]}), now arbiter "
                             f"{verdict_name(a_ok)} / mesa {verdict_name(m_ok)}", a_ok, a_msgs, m))
        else:
            passed += 1  # an intentional difference

    skipped_rels = {rel for rel, _ in skipped}
    for rel, (_, _, line) in sorted(entries.items()):
        if rel not in absolute and rel not in skipped_rels:
            problems.append(f"{args.differences}:{line}: stale entry: '{rel}' is not a corpus "
                            f"program")

    for rel, why, a_ok, a_msgs, m in failures:
        print(f"FAIL {rel}: {why}")
        verdict = "error" if a_ok is None else verdict_name(a_ok)
        print(f"  arbiter ({verdict}):")
        for line in a_msgs or ["(no diagnostics)"]:
            print(f"    {line}")
        if "crash" in m:
            print(f"  mesa (error): {m['crash']}")
        else:
            print(f"  mesa ({verdict_name(bool(m.get('accepted')))}):")
            text = (m.get("error_string") or "").strip() or "(no message)"
            print(f"    {text} (GL_PROGRAM_ERROR_POSITION_ARB {m.get('error_position')})")
    for problem in problems:
        print(f"FAIL {problem}")
    for rel, missing in skipped:
        print(f"SKIP {rel}: Mesa lacks {', '.join(missing)}")
    failed = len(failures) + len(problems)
    print(f"mesa_agreement: {passed} passed, {failed} failed, {len(skipped)} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
