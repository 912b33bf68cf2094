#!/usr/bin/env bash
# make bench: the benchmark suite (never part of make test). Every number in doc/bench/ is
# measured by this run; every CSV row carries the commit and the machine (bench/common.py).
# The scripts are the modules pecplas_py.bench.* of tools/pecplas_py/bench/ (doc/tools.md).
#   1. program overhead vs a bare CHOLMOD solve, MODJOIN law speed   (bench/solver.py)
#   1b. CHOLMOD fill-reducing orderings on the same blocks           (bench/ordering.py)
#   2. stability maps: iterations vs K_n/E and increment size        (bench/stability.py)
#   3. scaling of an elastic-plastic mesh, 1e4 .. 1e6 DOFs            (bench/scaling.py)
#      and of a linear run (the elastic block), 1e4 .. 1e6       (bench/scaling_elastic.py)
#   3b. AMG-preconditioned CG on the footing's own tangents, 1e4 .. 1e6  (bench/amg.py)
#   4. work-precision charts S2, S6 and the "cheapest within 1 %/5 %" advice
#                                                                     (bench/work_precision.py)
#   5. adaptive refinement on the S2 pile, beside the uniform series   (bench/adapt.py)
#   6. a peer side by side: CalculiX on the same problem              (bench/peer.py)
#      and Newton's iteration count beside CalculiX's on a footing  (bench/peer_footing.py)
#      and OpenSees on the elastic block, 1e4 .. 1e6 dofs       (bench/peer_opensees.py)
#   6b. deck reading: keyword mesh against *MESH on the same mesh     (bench/deck.py)
#   6c. Katona contact against the penalty joint, by speed (S1, pile)  (bench/katona.py)
#   7. doc/bench/README.md collects the sections                      (bench/summary.py)
#   with MPI and MUMPS installed (make build-mpi): CHOLMOD vs MUMPS on 1 and 2 ranks, before 7
#                                                                     (bench/mumps.py)
# BENCH=quick runs every part in its quick mode (a few minutes in all).
set -euo pipefail
cd "$(dirname "$0")/.."
export PYTHONPATH=$PWD/tools${PYTHONPATH:+:$PYTHONPATH}
FPM=${FPM:-fpm}
PYTHON=${PYTHON:-python3}
mode=()
[[ ${BENCH:-full} == quick ]] && mode=(--quick)
$FPM build --profile release >/dev/null
# the peer (CalculiX) is needed only here, not by make run / make test
if ! command -v ccx >/dev/null; then
  if [[ $(id -u) == 0 ]]; then
    echo "== make bench: installing calculix-ccx (the peer of pecplas_py.bench.peer)"
    DEBIAN_FRONTEND=noninteractive apt-get install -y calculix-ccx >/dev/null
  else
    echo "make bench: CalculiX is missing; run as root: apt-get install calculix-ccx" >&2
    exit 1
  fi
fi
# pip_need MODULE WHAT PACKAGE...: installs the pinned PACKAGEs when MODULE is missing
pip_need() {
  local module=$1 what=$2
  shift 2
  if ! $PYTHON -c "import importlib.util as u, sys; sys.exit(u.find_spec('$module') is None)"; then
    echo "== make bench: installing $* ($what)"
    $PYTHON -m pip install --quiet "$@"
  fi
}
# the second peer (OpenSees): openseespy 3.8.0.0 needs an openseespylinux 3.8 that PyPI lacks,
# so the 3.7.1.2 pair (wrapper + 58 MB binary wheel) is pinned
pip_need openseespy "the peer of pecplas_py.bench.peer_opensees" \
  openseespy==3.7.1.2 openseespylinux==3.7.1.2
# the iterative solver tried on the footing's tangents (pyamg) is needed only here too
pip_need pyamg "the AMG of pecplas_py.bench.amg" pyamg==5.4.1
mkdir -p doc/bench
start=$(date +%s)
for part in solver ordering stability scaling scaling_elastic amg work_precision adapt peer peer_footing peer_opensees deck katona; do
  t0=$(date +%s)
  echo "== make bench: pecplas_py.bench.$part ${mode[*]}"
  $PYTHON -m "pecplas_py.bench.$part" "${mode[@]}"
  echo "== make bench: $part took $(( $(date +%s) - t0 )) s"
done
if PECPLAS_MPI=1 bash tools/install_deps.sh --check >/dev/null 2>&1; then
  t0=$(date +%s)
  echo "== make bench: MPI build and pecplas_py.bench.mumps ${mode[*]}"
  cmake -S . -B build/cmake -DPECPLAS_MPI=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/cmake -j2 --target pecplas_mpi >/dev/null
  # 1e5 and 1e6 equations by default (about 10 min); the 3e6 rows (about an hour more) with
  # BENCH_MUMPS_SIZES="1e5 1e6 3e6". Rows not rerun keep their own commit and date in the CSV.
  sizes=()
  [[ ${BENCH:-full} == quick ]] || read -r -a sizes <<< "${BENCH_MUMPS_SIZES:-1e5 1e6}"
  $PYTHON -m pecplas_py.bench.mumps "${mode[@]}" ${sizes[@]:+--sizes "${sizes[@]}"} \
    --pecplas build/cmake/mpi/pecplas
  echo "== make bench: mumps took $(( $(date +%s) - t0 )) s"
else
  echo "== make bench: no MPI/MUMPS (PECPLAS_MPI=1 tools/install_deps.sh): MUMPS part skipped"
fi
$PYTHON -m pecplas_py.bench.summary --wall $(( $(date +%s) - start ))
echo "== make bench: doc/bench/README.md ($(( $(date +%s) - start )) s in all)"
