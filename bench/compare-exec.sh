#!/usr/bin/env bash
# Whole-command timings of `arbiter verify` over the ARB corpus and `arbiter run` over the
# shader tests, per Mesa driver and per -j, in one go (the machines are shared: compare rows
# of one run). Usage: bench/compare-exec.sh; needs a release build (cmake --preset release &&
# cmake --build --preset release). RUNS (default 3) and EXPORT (a markdown file) as for
# compare-glsl.sh; then the peak memory of each default-driver command.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
arbiter=build/release/cli/arbiter
verify=corpus/arb/valid
tests=corpus/exec
commands=()
for driver in softpipe llvmpipe; do
  for j in 1 2; do
    commands+=(-n "verify $verify, $driver, -j $j"
               "$arbiter verify --driver $driver -j $j $verify")
  done
done
for driver in softpipe llvmpipe; do
  for j in 1 2; do
    commands+=(-n "run $tests, $driver, -j $j" "$arbiter run --driver $driver -j $j $tests")
  done
done
commands+=(-n "run $tests, softpipe, -j 2, --translate"
           "$arbiter run --translate -j 2 $tests")
hyperfine -N -i --warmup 1 --runs "${RUNS:-3}" --export-markdown "${EXPORT:-/dev/null}" \
  "${commands[@]}"
for cmd in "verify $verify" "run $tests"; do
  # shellcheck disable=SC2086 # the command is split on purpose
  /usr/bin/time -q -a -o /dev/fd/3 -f "arbiter $cmd (softpipe, -j 2): peak %M KB (largest process)" \
    "$arbiter" $cmd -j 2 3>&1 > /dev/null 2>&1 || true
done
