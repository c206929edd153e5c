#!/usr/bin/env python3
"""A plain build, as packagers and most users run it, does not turn warnings into errors.

`cmake -B DIR -DCMAKE_BUILD_TYPE=Release` with no preset: warnings are errors in the dev,
release and asan presets only (CMakePresets.json), so a compiler that warns where the project's
does not (GCC 12 at -O3 raised a false -Wrestrict inside std::string) cannot break the build.
Configures only (seconds) and reads the compile commands: no -Werror anywhere, and the presets
still set ARBITER_WERROR. Exit 0 when both hold, 1 otherwise, 2 on usage errors.

usage: plain_build_test.py SOURCE_DIR CMAKE
"""

import json
import os
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    source, cmake = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as build:
        run = subprocess.run([cmake, "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr)
            return 1
        with open(os.path.join(build, "compile_commands.json"), encoding="utf-8") as f:
            commands = json.load(f)
        werror = [c["file"] for c in commands if "-Werror" in c["command"].split()]
        if not commands:
            failures.append("no compile commands")
        if werror:
            failures.append(f"-Werror in a plain build: {len(werror)} files, e.g. {werror[0]}")
    with open(os.path.join(source, "CMakePresets.json"), encoding="utf-8") as f:
        presets = json.load(f)["configurePresets"]
    for preset in presets:
        if preset.get("cacheVariables", {}).get("ARBITER_WERROR") != "ON":
            failures.append(f"preset {preset['name']} does not set ARBITER_WERROR=ON")
    for failure in failures:
        print(failure)
    print("plain build: " + ("FAIL" if failures else "no -Werror; every preset sets it"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
