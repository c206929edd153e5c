#!/usr/bin/env python3
"""The examples of the user guide (docs/guide/*.md) and of README.md are what arbiter prints now.

A command block is a fenced block tagged `sh` whose lines all start with `$ `. Its commands run
one after another, each with `bash -c`, in one fresh copy of docs/guide/examples/ per page (so
a command may read what an earlier one on the same page wrote), with `arbiter` on PATH, stdout
and stderr merged, no colour. The fenced block right after it (any tag) holds their output,
byte for byte; a command that exits with status N != 0 adds the line `[exit N]` after its
output. README.md's examples run in docs/guide/examples/ too. docs/diagnostics.md is checked
the same way in a copy of docs/diagnostics/ (its examples of the command-line codes), but
never rewritten: tests/docs/diagnostics_doc_test.cpp generates it.

  guide_doc_test.py ARBITER SOURCE_DIR [--update]

--update rewrites the output blocks of the guide pages and README.md with the real output;
review the diff.
"""
import argparse
import difflib
import os
import shutil
import subprocess
import sys
import tempfile

FENCE = "```"


def blocks(lines):
    """(first content line, end line (the closing fence), tag) of every fenced block."""
    found = []
    i = 0
    while i < len(lines):
        if lines[i].startswith(FENCE):
            tag = lines[i][len(FENCE):].strip()
            j = i + 1
            while j < len(lines) and lines[j].rstrip("\n") != FENCE:
                j += 1
            if j == len(lines):
                raise ValueError(f"line {i + 1}: unclosed code block")
            found.append((i + 1, j, tag))
            i = j + 1
        else:
            i += 1
    return found


def is_command_block(lines, start, end, tag):
    body = lines[start:end]
    return tag == "sh" and body and all(line.startswith("$ ") for line in body)


def run(commands, cwd, env):
    out = ""
    for command in commands:
        p = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=300)
        text = p.stdout.decode("utf-8", "replace")
        if text and not text.endswith("\n"):
            text += "\n"
        out += text
        if p.returncode != 0:
            out += f"[exit {p.returncode}]\n"
    return out


def check_page(path, examples, env, update):
    """Returns the failures of one page (and rewrites it with --update)."""
    lines = open(path, encoding="utf-8").read().splitlines(keepends=True)
    found = blocks(lines)
    failures = []
    count = 0
    replacements = []  # (start, end, new text)
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.path.join(tmp, "examples")
        shutil.copytree(examples, cwd)
        k = 0
        while k < len(found):
            start, end, tag = found[k]
            k += 1
            if not is_command_block(lines, start, end, tag):
                continue
            count += 1
            where = f"{os.path.relpath(path)}:{start}"
            if k == len(found) or any(line.strip() for line in lines[end + 1:found[k][0] - 1]):
                failures.append(f"{where}: the command block is not followed by an output block")
                continue
            out_start, out_end, _ = found[k]
            k += 1
            commands = [line[2:].rstrip("\n") for line in lines[start:end]]
            got = run(commands, cwd, env)
            documented = "".join(lines[out_start:out_end])
            if got == documented:
                continue
            if update:
                replacements.append((out_start, out_end, got))
                continue
            diff = "".join(difflib.unified_diff(documented.splitlines(keepends=True),
                                                got.splitlines(keepends=True),
                                                "documented", "arbiter now"))
            failures.append(f"{where}: {' && '.join(commands)}\n{diff}")
    if replacements:
        for start, end, text in reversed(replacements):
            lines[start:end] = [text]
        with open(path, "w", encoding="utf-8") as f:
            f.write("".join(lines))
    return count, failures


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("arbiter")
    ap.add_argument("root")
    ap.add_argument("--update", action="store_true")
    args = ap.parse_args()
    arbiter = os.path.abspath(args.arbiter)
    guide = os.path.join(args.root, "docs", "guide")
    examples = os.path.join(guide, "examples")
    with tempfile.TemporaryDirectory() as bindir:
        # `arbiter` on PATH, whatever the build calls the binary's folder.
        os.symlink(arbiter, os.path.join(bindir, "arbiter"))
        env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""),
                   NO_COLOR="1", TERM="dumb", LC_ALL="C")
        pages = sorted(os.path.join(guide, n) for n in os.listdir(guide) if n.endswith(".md"))
        total = 0
        failures = []
        for page in pages:
            count, page_failures = check_page(page, examples, env, args.update)
            total += count
            failures += page_failures
        # README.md's examples run in docs/guide/examples/ too.
        count, page_failures = check_page(os.path.join(args.root, "README.md"), examples, env,
                                          args.update)
        total += count
        failures += page_failures
        count, page_failures = check_page(os.path.join(args.root, "docs", "diagnostics.md"),
                                          os.path.join(args.root, "docs", "diagnostics"), env,
                                          update=False)
        total += count
        failures += page_failures
    for f in failures:
        print("FAILED", f)
    print(f"guide_doc_test: {total} example(s) in {len(pages) + 2} page(s), "
          f"{len(failures)} failure(s)" + (" (pages updated)" if args.update else ""))
    if failures and not args.update:
        print("rerun with --update to rewrite the guide's output blocks, and review the diff")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
