#!/usr/bin/env python3
"""Every document the project's files cite exists in the repository.

Comments, scripts, tests and docs cite design documents by name ("architecture.md, Execution
design", "docs/verify.md"). A citation of a name ending in .md must resolve: as a path from
the repository root, from the citing file's folder, or as a file of docs/ or docs/design/.
Exit 0 when every citation resolves, 1 otherwise (each unresolved one printed as
file:line: name), 2 on usage errors.
"""

import os
import re
import subprocess
import sys

CITATION = re.compile(r"(?<![\w./-])((?:[\w.-]+/)*[\w-]+\.md)\b")
# Names that are not citations of a document of this project: other projects' files that
# docs/design/style.md quotes, and a file name that a CLI test creates.
FOREIGN = {"CONTRIBUTING.md", "test/README.md", "top/readme.md"}
SHARED = re.compile(r"shared/(design|specs)/")
TEXT_SUFFIXES = (".cpp", ".h", ".py", ".txt", ".cmake", ".md", ".sh", ".shader_test", ".supp",
                 ".def", ".json", ".1", "")


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files"], capture_output=True, text=True,
                         check=True).stdout
    return [line for line in out.splitlines() if line]


def resolves(root, citing, name):
    candidates = [name, os.path.join(os.path.dirname(citing), name),
                  os.path.join("docs", name), os.path.join("docs", "design", name)]
    # A path into the shared folder names a document outside the project.
    if name.startswith(("/", "shared")) or "/shared/" in name:
        return False
    return any(os.path.isfile(os.path.join(root, c)) for c in candidates)


def main():
    if len(sys.argv) != 2:
        print("usage: references_test.py REPO_ROOT", file=sys.stderr)
        return 2
    root = sys.argv[1]
    missing = []
    for path in tracked_files(root):
        if path == "tests/docs/references_test.py":
            continue
        if not path.endswith(TEXT_SUFFIXES) or path.startswith(("corpus/glsl/", "build/")):
            continue
        full = os.path.join(root, path)
        try:
            with open(full, encoding="utf-8") as f:
                lines = f.readlines()
        except (UnicodeDecodeError, IsADirectoryError, FileNotFoundError):
            continue
        for number, line in enumerate(lines, 1):
            if SHARED.search(line):
                missing.append(f"{path}:{number}: cites the shared folder, not part of the "
                               f"project: {line.strip()}")
            for match in CITATION.finditer(line):
                name = match.group(1)
                if name in FOREIGN or name.startswith("http"):
                    continue
                if not resolves(root, path, name):
                    missing.append(f"{path}:{number}: {name}")
    for m in missing:
        print(m)
    print(f"{len(missing)} unresolved citation(s)")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
