#!/usr/bin/env bash
# Thread scaling on a many-core node (doc/bench/threads.md), within a time budget of BUDGET
# seconds (default 400): the elastic squares at 1e6 equations (Q4, Q8) through the whole
# program on 1, 2, 4, 8, 16 threads (pecplas-bench); configurations of CHOLMOD's
# factorisation on the assembled matrices (pecplas-bench-threads: threads of CHOLMOD's OpenMP
# regions, BLAS threads, flops per BLAS thread); the Drucker-Prager strip footing of
# pecplas_py.bench.scaling at 3e5 equations (pecplas). Writes OUT/log.txt (OUT default
# /tmp/out); pecplas_py.bench.threads_report turns the log into doc/bench/threads.csv and .png.
#
#   bash tools/bench_threads.sh [small|full] [DIR]
#
# DIR holds what the node lacks: bundle.tar.xz of ../shared/tools/device_bundle.sh (the
# release executables and their libraries; else they are taken from PATH), optionally
# pecplas-bench-bare-old in it (an earlier program's bare factorisation, compared), and
# ompblas.tar.xz (the libraries of Debian's libopenblas0-openmp, to compare OpenBLAS's OpenMP
# build with its pthreads build), footing_10000.inp and footing_300000.inp(.xz) (decks of
# pecplas_py.bench.scaling make_deck). `small` checks the script in seconds on any machine.
set -u
MODE=${1:-full}
D=$(cd "${2:-$(dirname "$0")}" && pwd)
OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"
T0=$(date +%s); BUDGET=${BUDGET:-400}
LOG=$OUT/log.txt
left() { echo $(( BUDGET - ($(date +%s) - T0) )); }
say() { echo "$*" | tee -a "$LOG"; }
if [ -f "$D/bundle.tar.xz" ]; then
  mkdir -p /tmp/b && tar -C /tmp/b -xJf "$D/bundle.tar.xz" || exit 3
  export LD_LIBRARY_PATH=/tmp/b/lib PATH=/tmp/b/lib:$PATH
fi
OMPLIB=/tmp/b/ompblas
if [ -f "$D/ompblas.tar.xz" ]; then mkdir -p $OMPLIB && tar -C $OMPLIB -xJf "$D/ompblas.tar.xz"; fi
W=/tmp/w; rm -rf $W; mkdir -p $W
for f in footing_10000 footing_300000; do
  if [ -f $D/$f.inp ]; then cp $D/$f.inp $W/; elif [ -f $D/$f.inp.xz ]; then xz -dc $D/$f.inp.xz > $W/$f.inp; fi
done
say "=== machine: $(nproc) cpus; $(grep -m1 'model name' /proc/cpuinfo); $(free -g | awk '/Mem/ {print $2" GB"}'); $(uname -r)"
say "=== load: $(cat /proc/loadavg); time: $(command -v /usr/bin/time || echo none)"
if [ "$MODE" = small ]; then Q4=70; Q8=41; FOOT=footing_10000.inp; NMAX=2; TS="1 2"
else Q4=707; Q8=408; FOOT=footing_300000.inp; NMAX=16; TS="1 2 4 8 16"; fi
TIMEFORMAT='%R %U %S'

# one pecplas-bench run: tag, threads, element, n, [env...]
bench() { local tag=$1 n=$2 el=$3 sz=$4; shift 4
  local line; line=$(env OMP_NUM_THREADS=$n "$@" timeout 120 pecplas-bench $el $sz $W 2>>"$OUT/err.txt")
  say "RUN $tag threads=$n load=$(cut -d' ' -f1 /proc/loadavg) $line"; }
# pecplas-bench-threads on a matrix: tag, OMP_NUM_THREADS, matrix, configs...
sweep() { local tag=$1 n=$2 m=$3; shift 3
  say "SWEEP $tag OMP=$n load=$(cut -d' ' -f1 /proc/loadavg)"
  env OMP_NUM_THREADS=$n ${SWEEP_ENV:-} timeout 150 pecplas-bench-threads $m "$@" 2>>"$OUT/err.txt" | sed "s/^/S $tag /" | tee -a "$LOG"; }
# the program on the footing deck: tag, threads, [env...]
foot() { local tag=$1 n=$2; shift 2
  local t0=$(date +%s.%N)

  { time env OMP_NUM_THREADS=$n "$@" timeout 150 pecplas $W/$FOOT -o $W/f.h5 > $W/f.log 2>&1 ; } 2> $W/f.time
  say "FOOT $tag threads=$n time=$(cat $W/f.time) | $(grep -E 'wall time|summary:|threads:' $W/f.log | tr '\n' '|')"; }

# A. elastic Q4 at 1e6: one run per thread count (new configuration), matrix from the first
M4=$W/square_Q4_$Q4.matrix.h5; M8=$W/square_Q8_$Q8.matrix.h5
bench new 1 Q4 $Q4
cp $M4 $W/q4.matrix.h5; M4=$W/q4.matrix.h5
# B. configurations of the factorisation on that matrix (R regions, B BLAS, W flops/thread)
sweep q4 $NMAX $M4 1,1,0 1,$NMAX,1e6 1,$NMAX,1e5 1,$NMAX,1e7 1,$NMAX,1e8 4,$NMAX,1e6 \
  1,8,1e6 1,4,1e6 1,2,1e6 1,$NMAX,1e6 1,1,0 1,$NMAX,0
for n in $TS; do [ $n -gt 1 ] && bench new $n Q4 $Q4; done
# the old program's bare factorisation (dynamic team of 4 regions, BLAS n for every call)
command -v pecplas-bench-bare-old >/dev/null &&
  say "OLD bare Q4 16: $(OMP_NUM_THREADS=$NMAX timeout 70 pecplas-bench-bare-old $M4 2>&1)"
say "NEW bare Q4 16: $(OMP_NUM_THREADS=$NMAX timeout 70 pecplas-bench-bare $M4 2>&1)"
say "NEW bare Q4 1: $(OMP_NUM_THREADS=1 timeout 70 pecplas-bench-bare $M4 2>&1)"
# OpenBLAS's OpenMP build instead of its pthreads build
if [ -d $OMPLIB ] && [ $(left) -gt 200 ]; then
  SWEEP_ENV="LD_LIBRARY_PATH=$OMPLIB:/tmp/b/lib" sweep q4omp $NMAX $M4 1,1,0 1,$NMAX,1e6 1,$NMAX,1e7 1,$NMAX,0
fi
say "=== left after A/B: $(left) s"
# C. Q8 at 1e6
if [ $(left) -gt 170 ]; then
  bench new $NMAX Q8 $Q8
  cp $M8 $W/q8.matrix.h5; M8=$W/q8.matrix.h5
  sweep q8 $NMAX $M8 1,1,0 1,$NMAX,1e6 1,$NMAX,1e7 1,8,1e6 4,$NMAX,1e6 1,$NMAX,0
  bench new 1 Q8 $Q8
fi
say "=== left after C: $(left) s"
# D. Drucker-Prager footing (Newton: assembly, law updates, factorisations)
if [ $(left) -gt 90 ]; then
  for n in 1 4 $NMAX; do [ $(left) -gt 40 ] && foot new $n; done
fi
say "=== left after D: $(left) s"
# E. what the old program's bare factorisation does with the OpenMP wait policy passive
OLD=$(command -v pecplas-bench-bare-old)
if [ -n "$OLD" ] && [ $(left) -gt 70 ]; then
  say "OLD bare Q4 16 passive: $(OMP_NUM_THREADS=$NMAX OMP_WAIT_POLICY=passive timeout 60 pecplas-bench-bare-old $M4 2>&1)"
fi
if [ -n "$OLD" ] && [ $(left) -gt 50 ]; then
  say "OLD bare Q4 16 again: $(OMP_NUM_THREADS=$NMAX timeout 45 pecplas-bench-bare-old $M4 2>&1)"
fi
if [ $(left) -gt 30 ]; then sweep q4rep $NMAX $M4 1,$NMAX,1e6 1,$NMAX,1e7 1,1,0; fi
say "=== done, left $(left) s; load $(cat /proc/loadavg)"
