#!/usr/bin/env bash
# precommit.sh: the checks to pass before a commit: clang-format on changed lines, the dev build,
# the unit and golden tests, and clang-tidy on changed sources.
#   ARBITER_SKIP_TIDY=1   skip clang-tidy (it is the slowest step)
# Changed = against the merge-base with origin/main when that exists, else HEAD, plus untracked
# files. Exit status: 0 when every check passed, 1 otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/setup-deps
jobs=$(nproc)
status=0

if git rev-parse --verify -q origin/main >/dev/null; then
  base=$(git merge-base HEAD origin/main)
else
  base=HEAD
fi
cxx_ext='cpp,cc,h,hpp'
is_cxx() { [[ "$1" =~ \.(cpp|cc|h|hpp)$ ]]; }

mapfile -t changed < <(git diff --name-only --diff-filter=d "$base" -- ; git ls-files --others --exclude-standard)
cxx_changed=()
for f in "${changed[@]}"; do
  if is_cxx "$f" && [[ -f "$f" ]]; then
    cxx_changed+=("$f")
  fi
done
mapfile -t untracked < <(git ls-files --others --exclude-standard)

echo "=== precommit: clang-format (changed lines since ${base:0:12})"
format_rc=0
git clang-format --diff --extensions "$cxx_ext" "$base" -- || format_rc=$?
# git clang-format sees tracked files only; new files are checked whole.
for f in "${untracked[@]}"; do
  if is_cxx "$f"; then
    if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
      echo "needs clang-format: $f (new file)"
      format_rc=1
    fi
  fi
done
if ((format_rc != 0)); then
  echo "precommit: formatting differs (fix: git clang-format $base; clang-format -i NEW_FILES)"
  status=1
fi

echo "=== precommit: build (dev)"
cmake --preset dev >/dev/null
cmake --build --preset dev -j "$jobs"

echo "=== precommit: ctest -L 'unit|golden' (dev)"
ctest --preset dev -j "$jobs" -L 'unit|golden' || status=1

if [[ "${ARBITER_SKIP_TIDY:-0}" != 1 ]] && command -v clang-tidy >/dev/null; then
  echo "=== precommit: clang-tidy (changed sources)"
  sources=()
  for f in "${cxx_changed[@]}"; do
    # Only files with a compile command (headers are checked through them).
    if [[ "$f" =~ \.(cpp|cc)$ ]] && grep -q "\"file\": \".*/$f\"" build/dev/compile_commands.json; then
      sources+=("$f")
    fi
  done
  if ((${#sources[@]} > 0)); then
    clang-tidy -p build/dev --quiet "${sources[@]}" || status=1
  else
    echo "no changed sources"
  fi
fi

if ((status != 0)); then
  echo "precommit: FAILED"
else
  echo "precommit: all checks passed"
fi
exit "$status"
