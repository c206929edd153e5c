#!/usr/bin/env bash
# Whole-process comparison of `arbiter check` on ARB programs with Mesa loading the same
# programs (bench/mesa_load_arb.cpp: one OSMesa softpipe context, glProgramStringARB per
# program), in one hyperfine run; then peak memory. Usage: bench/compare-arb.sh [DIR]
# (default corpus/arb); needs a release build (cmake --preset release && cmake --build
# --preset release; BUILD names another build folder). RUNS (default 20) and EXPORT (a
# markdown file) as for compare-glsl.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
dir=${1:-corpus/arb}
build=${BUILD:-build/release}
arbiter=$build/cli/arbiter
mesa=$build/bench/mesa_load_arb
mapfile -t files < <(find "$dir" -type f \( -name '*.vp' -o -name '*.fp' \) | LC_ALL=C sort)
(( ${#files[@]} > 0 )) || { echo "no ARB programs under $dir" >&2; exit 1; }
one=${ONE:-corpus/arb/valid/skinning-four-bones.vp}
echo "${#files[@]} programs under $dir; single file: $one"
hyperfine -N -i --warmup 3 --runs "${RUNS:-20}" --export-markdown "${EXPORT:-/dev/null}" \
  -n "arbiter check (all files)" "$arbiter check ${files[*]}" \
  -n "arbiter check -j 1 (all files)" "$arbiter check -j 1 ${files[*]}" \
  -n "read_files (all files: what reading them costs)" "$build/bench/read_files ${files[*]}" \
  -n "mesa_load_arb (all files)" "$mesa ${files[*]}" \
  -n "arbiter check (one file)" "$arbiter check $one" \
  -n "mesa_load_arb (one file)" "$mesa $one" \
  -n "/bin/true" "/bin/true"
for args in "${files[*]}" "$one"; do
  # shellcheck disable=SC2086 # the file list is split on purpose
  /usr/bin/time -q -a -o /dev/fd/3 -f "arbiter check, $(wc -w <<< "$args") file(s): peak %M KB" \
    "$arbiter" check $args 3>&1 > /dev/null 2>&1 || true
done
