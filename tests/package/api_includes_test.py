#!/usr/bin/env python3
"""The C++ API is the installed public headers (docs/api.md): the CLI includes nothing else of
arbiter (every quoted #include in cli/ is a cli-local header or an `arbiter/<lib>/...` public
header), and the public headers include only public headers, so that an installed header never
needs a private one (<lib>/src/...).

It also checks that docs/api.md quotes examples/api-check/main.cpp, the example that the test
package_install builds against the installed package, as it is.

Usage: api_includes_test.py SOURCE_DIR
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1])
LIBS = ("compiler", "glstate", "arbvp", "glsl", "targets", "runtime")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
public = {p.relative_to(root / lib / "include").as_posix()
          for lib in LIBS for p in (root / lib / "include").rglob("*") if p.is_file()}
problems = []


def check_file(path, local_dir):
    for kind, name in INCLUDE.findall(path.read_text(encoding="utf-8")):
        close = ">" if kind == "<" else '"'
        where = f"{path.relative_to(root)}: #include {kind}{name}{close}"
        if name.startswith("arbiter/"):
            if name not in public:
                problems.append(f"{where}: not an installed public header")
        elif kind == '"' and not (local_dir and (local_dir / name).is_file()):
            problems.append(f"{where}: neither a cli-local header nor arbiter/<lib>/...")


cli = sorted((root / "cli").glob("*.cpp")) + sorted((root / "cli").glob("*.h"))
for path in cli:
    check_file(path, root / "cli")
headers = sorted(p for lib in LIBS for p in (root / lib / "include").rglob("*.h"))
for path in headers:
    check_file(path, None)  # public headers: arbiter/... or system headers only

example = (root / "examples/api-check/main.cpp").read_text(encoding="utf-8")
if f"```cpp\n{example}```" not in (root / "docs/api.md").read_text(encoding="utf-8"):
    problems.append("docs/api.md does not quote examples/api-check/main.cpp as it is")

if not cli or not headers:
    problems.append(f"no sources found under {root}")
for p in problems:
    print("FAIL " + p)
print(f"{len(cli)} cli files and {len(headers)} public headers checked, {len(problems)} problems")
sys.exit(1 if problems else 0)
