#!/usr/bin/env python3
"""GLSL Mesa agreement: arbiter and Mesa must give every corpus GLSL shader the same verdict.

For every shader under the corpus (recursive; .vert .vs .frag .fs), one mesa_glsl_compile run
prints both verdicts per file: Mesa's (OSMesa, softpipe by default) and arbiter's
(glsl::CheckShader in the same process), each judged as the GLSL corpus test judges the file:
compile only, or compile and link when its `// [config]` block says `check_link: true`.
A mismatch passes only when glsl-intentional-differences.md lists the file with both verdicts;
a listed file that no longer differs (or no longer exists) fails as a stale entry. Files whose
`require_extensions` Mesa does not meet are skipped; a missing or empty corpus passes with a
note. Prints each failure with both tools' messages and which verdict the file's
`expect_result` asks for, then `N passed, N failed, N skipped`.
Exit 0 when nothing failed, 1 otherwise, 2 on usage errors.
"""

import argparse
import json
import os
import re
import subprocess
import sys

from differences import parse_differences, verdict_name

EXTENSIONS = (".vert", ".vs", ".frag", ".fs")


def find_shaders(corpus):
    """Every GLSL shader under `corpus`, as sorted paths relative to it (with '/')."""
    found = []
    for root, dirs, files in os.walk(corpus):
        dirs.sort()
        for name in files:
            if name.endswith(EXTENSIONS):
                path = os.path.join(root, name)
                found.append(os.path.relpath(path, corpus).replace(os.sep, "/"))
    return sorted(found)


def run_tool(tool, driver, paths):
    """The JSON object mesa_glsl_compile printed per absolute path, or {"crash": message} for a
    file on which it crashed or hung (the run then goes on with the files after it)."""
    results = {}
    remaining = list(paths)
    while remaining:
        cmd = [tool, "--driver", driver, "--"] + remaining
        try:
            proc = subprocess.run(cmd, capture_output=True, timeout=600, check=False)
            stdout, stderr, rc = proc.stdout, proc.stderr, proc.returncode
        except subprocess.TimeoutExpired as e:
            stdout, stderr, rc = e.stdout or b"", e.stderr or b"", "timeout"
        except OSError as e:
            for path in remaining:
                results[path] = {"crash": f"cannot run {tool}: {e}"}
            break
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
        if rc in (2, 3) and done == 0:
            # A usage or context error: nothing will work; report it once for every file.
            detail = stderr.decode("utf-8", "replace").strip()[-2000:]
            for path in remaining:
                results[path] = {"crash": f"mesa_glsl_compile exit {rc}: {detail}"}
            break
        # The tool stopped before printing a result for remaining[0].
        detail = stderr.decode("utf-8", "replace").strip()[-2000:]
        results[remaining[0]] = {"crash": f"mesa_glsl_compile exit {rc} on this file: {detail}"}
        remaining = remaining[1:]
    return results


def describe(rel, result):
    """The lines printed under a failing file: both tools' verdicts and messages."""
    lines = []
    expect = result.get("expect")
    if expect in ("pass", "fail"):
        lines.append(f"  corpus expects {expect} ({'accept' if expect == 'pass' else 'reject'})"
                     f"{', with link' if result.get('link') else ', compile only'}")
    arbiter = result.get("arbiter", {})
    lines.append(f"  arbiter ({verdict_name(bool(arbiter.get('accepted')))}):")
    for d in arbiter.get("diagnostics") or ["(no diagnostics)"]:
        lines.append(f"    {d}")
    mesa = result.get("mesa", {})
    lines.append(f"  mesa ({verdict_name(bool(mesa.get('accepted')))}):")
    log = [l for l in (mesa.get("log") or "").splitlines() if l.strip()]
    for l in log[:10] or ["(empty info log)"]:
        lines.append(f"    {l.strip()}")
    if mesa.get("failure"):
        lines.append(f"    GL call failed: {mesa['failure']}")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tool", required=True, help="the mesa_glsl_compile binary")
    parser.add_argument("--corpus", required=True, help="corpus/glsl")
    parser.add_argument("--differences", required=True, help="glsl-intentional-differences.md")
    parser.add_argument("--driver", default="softpipe", choices=("softpipe", "llvmpipe"))
    parser.add_argument("--known-gaps", default=None,
                        help="tests/glsl/known-gaps.txt: shaders where arbiter is known to "
                             "miss the spec's verdict (a difference there is expected)")
    args = parser.parse_args()
    known_gaps = set()
    if args.known_gaps:
        with open(args.known_gaps) as f:
            for line in f:
                path = line.split("#", 1)[0].strip()
                if path:
                    known_gaps.add(path)

    if not os.access(args.tool, os.X_OK):
        print(f"glsl_agreement: mesa_glsl_compile binary '{args.tool}' is missing or not "
              f"executable")
        return 1
    entries, problems = parse_differences(args.differences, EXTENSIONS)
    shaders = find_shaders(args.corpus) if os.path.isdir(args.corpus) else []
    if not shaders:
        print(f"glsl_agreement: note: no GLSL shaders under {args.corpus}: nothing to compare")

    absolute = {rel: os.path.abspath(os.path.join(args.corpus, rel)) for rel in shaders}
    results = run_tool(args.tool, args.driver, [absolute[rel] for rel in shaders])

    passed, failures, skipped = 0, [], []
    for rel in shaders:
        r = results.get(absolute[rel], {"crash": "no result"})
        entry = entries.get(rel)
        if "skip" in r:
            skipped.append((rel, r["skip"]))
            continue
        for key in ("crash", "io_error", "config_error"):
            if key in r:
                failures.append((rel, f"{key.replace('_', ' ')}: {r[key]}", None))
                break
        else:
            if r.get("mesa", {}).get("failure"):
                failures.append((rel, f"a GL call failed: {r['mesa']['failure']}", r))
                continue
            a_ok = bool(r["arbiter"]["accepted"])
            m_ok = bool(r["mesa"]["accepted"])
            if a_ok == m_ok:
                if entry is None:
                    passed += 1
                else:
                    failures.append((rel, f"stale entry ({args.differences} line {entry[2]}): "
                                     f"both tools now {verdict_name(a_ok)}", r))
            elif entry is None and rel in known_gaps:
                passed += 1  # arbiter's known gap (tests/glsl/known-gaps.txt), Mesa right
            elif entry is None:
                failures.append((rel, f"arbiter: {verdict_name(a_ok)}, mesa: "
                                 f"{verdict_name(m_ok)}", r))
            elif entry[:2] != (a_ok, m_ok):
                failures.append((rel, f"listed as arbiter {verdict_name(entry[0])} / mesa "
                                 f"{verdict_name(entry[1])} (line {entry[2]}), now arbiter "
                                 f"{verdict_name(a_ok)} / mesa {verdict_name(m_ok)}", r))
            else:
                passed += 1  # an intentional difference

    skipped_rels = {rel for rel, _ in skipped}
    for rel, (_, _, line) in sorted(entries.items()):
        if rel not in absolute:
            problems.append(f"{args.differences}:{line}: stale entry: '{rel}' is not a corpus "
                            f"shader")
        elif rel in skipped_rels:
            pass  # Mesa lacks what it needs here: neither confirmed nor stale

    for rel, why, r in failures:
        print(f"FAIL {rel}: {why}")
        if r is not None:
            for line in describe(rel, r):
                print(line)
    for problem in problems:
        print(f"FAIL {problem}")
    for rel, why in skipped:
        print(f"SKIP {rel}: {why}")
    failed = len(failures) + len(problems)
    print(f"mesa_glsl_agreement: {passed} passed, {failed} failed, {len(skipped)} skipped")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
