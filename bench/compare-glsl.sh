#!/usr/bin/env bash
# Whole-process comparison of `arbiter check` with glslangValidator on the same GLSL files,
# in one hyperfine run: one process for all files (both tools; arbiter with -j 1 and 2), then
# one glslangValidator process per file. Usage: bench/compare-glsl.sh [DIR] (default corpus/glsl); needs a
# release build (cmake --preset release && cmake --build --preset release).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
dir=${1:-corpus/glsl}
arbiter=build/release/cli/arbiter
mapfile -t files < <(find "$dir" -type f \( -name '*.vert' -o -name '*.frag' \) | LC_ALL=C sort)
(( ${#files[@]} > 0 )) || { echo "no GLSL files under $dir" >&2; exit 1; }
list=$(mktemp)
trap 'rm -f "$list"' EXIT
printf '%s\n' "${files[@]}" > "$list"
echo "${#files[@]} files under $dir"
# -d: a shader without #version is desktop 1.10, as arbiter takes it. -l is not given:
# glslangValidator would link all files into one program; arbiter links each shader alone,
# so the closest comparison is compile-only for glslangValidator (arbiter does more work).
hyperfine -N -i --warmup 2 --runs "${RUNS:-10}" --export-markdown "${EXPORT:-/dev/null}" \
  -n "arbiter check -j 1 (all files)" "$arbiter check -j 1 ${files[*]}" \
  -n "arbiter check -j 2 (all files)" "$arbiter check -j 2 ${files[*]}" \
  -n "glslangValidator -d (all files)" "glslangValidator -d ${files[*]}"
# One process per file takes about 40 s a run: fewer runs.
hyperfine -N -i --runs "${PER_FILE_RUNS:-3}" \
  -n "glslangValidator -d (one process per file)" \
  "bash -c 'while read -r f; do glslangValidator -d \"\$f\" >/dev/null; done < $list'"
