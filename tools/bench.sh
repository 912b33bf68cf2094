#!/usr/bin/env bash
# make bench: elastic plane-strain squares (Q4 and Q8) at about 1e4, 1e5 and 1e6 equations,
# each in its own process (so peak memory belongs to the case). Every line: phase wall times
# of the whole program (read+setup, assembly incl. COO->CSC, factorisation incl. analysis,
# solve, residual, output), its total, a bare CHOLMOD analyse+factorise+solve of the SAME
# matrix measured in the same run, their ratio, and peak resident memory.
# SIZES=small skips the 1e6 cases (a minute each). First: the MODJOIN law speed
# (bench/laws/bench_laws.f90).
set -euo pipefail
cd "$(dirname "$0")/.."
FPM=${FPM:-fpm}
$FPM build --profile release >/dev/null
# interface-law speed (MODJOIN: updates/s incl. tangent, 8000-increment CNL path), seconds
$FPM run --profile release --target pecplas-bench-laws 2>/dev/null
echo
exe=$($FPM run --profile release --target pecplas-bench --runner echo 2>/dev/null | tail -n 1)
cases=("Q4 70" "Q8 41" "Q4 223" "Q8 129")
[[ ${SIZES:-all} == small ]] || cases+=("Q4 707" "Q8 408")
printf '%-3s %8s %9s %8s %8s %8s %8s %8s %8s %8s %8s %7s %8s %9s\n' el N equations \
  read+set assembly factor solve residual output total bare ratio peakMB 'nnz(L)'
for c in "${cases[@]}"; do
  "$exe" $c build/bench
done
echo "times in seconds (wall); ratio = total / bare CHOLMOD (analyse + factorise + solve)"
