#!/usr/bin/env bash
# Thread scaling on a many-core node (doc/bench/threads.md). Three modes:
#
#   bash tools/bench_threads.sh pack [DIR]                 (here: what the node lacks, into DIR)
#   bash tools/bench_threads.sh device [--small] [DIR]     (on the node: every measurement)
#   bash tools/bench_threads.sh [small|full] [DIR]         (the first node run, kept as it was)
#
# pack (default DIR .device, added to .git/info/exclude): the release executables of `make
# build` and every library they load (bundle.tar.xz); when build/cmake-mpi/pecplas exists
# (`make build-mpi`; MPI_EXE= another), that MPI build with Open MPI's launcher, plug-ins and
# libraries (mpi.tar.xz: MUMPS on one node, ranks x threads); the Drucker-Prager footing decks
# of pecplas_py.bench.scaling at 1e4 and 3e5 equations. Say the sizes; one call carries 64 MiB.
#
# device: runs from the repository root with DIR = the carried pack, within BUDGET seconds
# (default 510: one device call of at most 10 minutes, the machine's start not counted), and
# writes $OUT/log.txt (OUT default /tmp/out) for pecplas_py.bench.threads_report. The cases
# run in rounds, most wanted first, each only when its time estimated from the first node
# run (threads_node16.log) still fits; a case left out is logged as SKIP with its estimate:
#   1. the elastic squares Q4 and Q8 at 1e6 equations (pecplas-bench), 1 and 16 threads, and
#      the footing at 3e5 (pecplas), 1 and 16 threads: one run each
#   2. candidates: OpenBLAS's default kernels where CORE=auto chose others (see below), on
#      the squares at 1 and 16 threads; Q8 ordered by AMD instead of the rule's METIS
#      (PECPLAS_ORDERING=AMD) on 1 and 16 threads; OMP_WAIT_POLICY=passive on Q4, 16 threads;
#      MUMPS (MPI build) on 16 ranks x 1 thread: Q8, Q4
#   3. the squares on 1 and 16 threads again (run 2 of 3)
#   4. 2, 4 and 8 threads on Q4 and Q8
#   5. the squares on 1 and 16 threads again (run 3 of 3)
#   6. the footing on 4, 8, 2 threads, and on MUMPS 16 x 1 if MUMPS beat CHOLMOD on Q8; BLAS
#      on 8 of 16 threads (PECPLAS_THREAD_PARTS=1,8,0), OMP_WAIT_POLICY=passive on Q8, MUMPS
#      4 ranks x 4 threads, Q8 AMD on 4 and 8 threads
#   7. the footing on 1 and 16 threads again, twice
# --small: the same rounds at 1e4 equations, 1 and 2 threads (2 ranks), no time estimates:
# checks the script end to end on a 2-core machine in about a minute.
set -u

# Libraries an executable loads, except the C library and the loader (the node's are used).
deps() { ldd "$@" | awk '/=>/ {print $3}' | grep '^/' |
  grep -vE '/(libc|libm|libgcc_s|libpthread|libdl|librt|libresolv)\.so|ld-linux' | sort -u; }

pack() {
  local dir=${1:-.device} tmp exe e list=()
  mkdir -p "$dir"
  local ex; ex=$(git rev-parse --git-path info/exclude 2>/dev/null) &&
    { grep -qx "/$(basename "$dir")/" "$ex" 2>/dev/null || echo "/$(basename "$dir")/" >> "$ex"; }
  tmp=$(mktemp -d); trap 'rm -rf "$tmp"' RETURN
  local all; all=$(fpm run --profile release --all --runner echo 2>/dev/null | grep '^build/')
  for e in pecplas pecplas-bench pecplas-bench-threads pecplas-bench-bare; do
    exe=$(echo "$all" | tr ' ' '\n' | grep "/$e\$" | head -1)
    [ -n "$exe" ] || { echo "pack: no release $e (make build)" >&2; return 2; }
    list+=("$exe")
  done
  mkdir -p "$tmp/b/lib"
  cp "${list[@]}" "$tmp/b/lib/"
  deps "${list[@]}" | xargs cp -Lu -t "$tmp/b/lib/"
  tar -C "$tmp/b" -cf - lib | xz -T0 -6 > "$dir/bundle.tar.xz"
  local mpi=${MPI_EXE:-build/cmake-mpi/pecplas}
  rm -f "$dir/mpi.tar.xz"
  if [ -x "$mpi" ]; then
    local m=$tmp/m P=/usr/lib/x86_64-linux-gnu
    mkdir -p "$m/lib" "$m/ompi/openmpi3" "$m/ompi/pmix" "$m/share"
    cp "$mpi" "$m/lib/pecplas-mpi"
    cp "$(command -v orterun)" "$(command -v orted)" "$m/lib/"
    cp $P/openmpi/lib/openmpi3/*.so "$m/ompi/openmpi3/"
    cp $P/pmix2/lib/pmix/*.so "$m/ompi/pmix/"
    cp -r /usr/share/openmpi "$m/share/"
    # plug-ins for networks a single node does not use (InfiniBand, UCX, OFI, PSM) would
    # need their libraries too: left out
    for f in "$m"/ompi/*/*.so; do
      ldd "$f" | grep -qiE 'ucx|ucp|ucs|fabric|verbs|psm|cuda' && rm -f "$f"
    done
    deps "$m/lib/pecplas-mpi" "$m/lib/orterun" "$m/lib/orted" "$m"/ompi/*/*.so |
      xargs cp -Lu -t "$m/lib/"
    tar -C "$m" -cf - . | xz -T0 -6 > "$dir/mpi.tar.xz"
  else
    echo "pack: no MPI build at $mpi (make build-mpi): MUMPS cases will be skipped" >&2
  fi
  local t n
  for t in 10000 300000; do
    [ -f "$dir/footing_$t.inp.xz" ] && continue
    PYTHONPATH=tools python3 -c "
import sys; from pathlib import Path
from pecplas_py.bench.scaling import make_deck, size_for
nx, ny = size_for($t); make_deck(nx, ny, Path(sys.argv[1]))" "$tmp/footing_$t.inp" || return 2
    xz -T0 -c "$tmp/footing_$t.inp" > "$dir/footing_$t.inp.xz"
  done
  du -ch "$dir"/bundle.tar.xz "$dir"/mpi.tar.xz "$dir"/footing_*.inp.xz 2>/dev/null
  n=$(du -cb "$dir"/* | tail -1 | cut -f1)
  [ "$n" -lt $((60 * 1048576)) ] || echo "pack: $dir holds over 60 MiB: too much for one call" >&2
}

device() {
  local SMALL=0
  if [ "${1:-}" = --small ]; then SMALL=1; shift; fi
  D=$(cd "${1:-.device}" && pwd) || return 3
  OUT=${OUT:-/tmp/out}; mkdir -p "$OUT"
  T0=$(date +%s); BUDGET=${BUDGET:-510}
  LOG=$OUT/log.txt
  B=${BENCH_TMP:-/tmp/b}; W=$B/w
  rm -rf "$B"; mkdir -p "$W"
  tar -C "$B" -xJf "$D/bundle.tar.xz" || return 3
  HAVE_MPI=0
  if [ -f "$D/mpi.tar.xz" ] && tar -C "$B" -xJf "$D/mpi.tar.xz"; then HAVE_MPI=1; fi
  export LD_LIBRARY_PATH=$B/lib PATH=$B/lib:$PATH
  # Open MPI and PMIx from the pack, not from where they were built
  export OPAL_PREFIX=$B OPAL_PKGLIBDIR=$B/ompi/openmpi3 OPAL_PKGDATADIR=$B/share/openmpi \
    OPAL_BINDIR=$B/lib OPAL_LIBDIR=$B/lib PMIX_PREFIX=$B PMIX_PKGLIBDIR=$B/ompi/pmix \
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader \
    OMPI_MCA_pml=ob1 OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_backing_directory=/tmp
  local T FOOTN
  if [ $SMALL = 1 ]; then Q4=70; Q8=41; FOOTN=10000; NMAX=2; MID=""
  else Q4=707; Q8=408; FOOTN=300000; NMAX=16; MID="2 4 8"; fi
  FOOT=$W/footing.inp
  xz -dc "$D/footing_$FOOTN.inp.xz" > "$FOOT" || return 3
  say "=== machine: $(nproc) cpus; $(grep -m1 'model name' /proc/cpuinfo); $(free -g | awk '/Mem/ {print $2" GB"}'); $(uname -r)"
  say "=== load: $(cat /proc/loadavg); mode device$([ $SMALL = 1 ] && echo ' --small'); budget $BUDGET s; MPI pack: $HAVE_MPI"
  for e in pecplas pecplas-bench; do
    ldd "$B/lib/$e" | grep -q 'not found' && say "=== $e: $(ldd "$B/lib/$e" | grep 'not found' | tr '\n' ' ')"
  done
  TIMEFORMAT='%R %U %S'
  # OpenBLAS picks its kernels from the CPU model; a model it does not know (0.3.21: Intel
  # family 6 model 207 here) gets the SSE3 kernels of `Prescott` even on a CPU with AVX-512.
  # CORE=auto (default): then every run gets OPENBLAS_CORETYPE=SkylakeX (AVX-512) or Haswell
  # (AVX2), and round 2 compares the default kernels; CORE=none: leave OpenBLAS alone;
  # CORE=NAME: that core for every run.
  local flags dflt core=${CORE:-auto}
  flags=$(grep -m1 '^flags' /proc/cpuinfo)
  dflt=$(env -u OPENBLAS_CORETYPE OPENBLAS_VERBOSE=2 pecplas-bench-threads 2>&1 | sed -n 's/^Core: //p' | head -1)
  if [ "$core" = auto ]; then core=none
    if [ "$dflt" = Prescott ]; then
      case " $flags " in *" avx512f "*) core=SkylakeX ;; *" avx2 "*) core=Haswell ;; esac
    fi
  fi
  [ "$core" != none ] && export OPENBLAS_CORETYPE=$core
  say "=== cpu: $(grep -m1 '^cpu family' /proc/cpuinfo | tr -s '\t ' ' '), $(grep -m1 '^model\s' /proc/cpuinfo | tr -s '\t ' ' '); avx2: $(case " $flags " in *" avx2 "*) echo yes ;; *) echo no ;; esac), avx512f: $(case " $flags " in *" avx512f "*) echo yes ;; *) echo no ;; esac)"
  say "=== OpenBLAS kernels: ${dflt:-unknown} by default; every run below: $(OPENBLAS_VERBOSE=2 pecplas-bench-threads 2>&1 | sed -n 's/^Core: //p' | head -1) (OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-unset})"

  # round 1: the ends of the scale, one run each
  sq rule 1 Q4; sq rule $NMAX Q4; sq rule 1 Q8; sq rule $NMAX Q8
  ft rule 1; ft rule $NMAX
  say "=== left after round 1: $(left) s"
  # round 2: candidates at the ends
  if [ "$core" != none ]; then  # OpenBLAS's default kernels (the program would set the
    # same ones as CORE=auto by itself: PECPLAS_BLAS_CORE=keep stops it)
    local keep="-u OPENBLAS_CORETYPE PECPLAS_BLAS_CORE=keep"
    sq blasdefault 1 Q4 $keep; sq blasdefault $NMAX Q4 $keep
    sq blasdefault 1 Q8 $keep; sq blasdefault $NMAX Q8 $keep
  fi
  sq amd 1 Q8 PECPLAS_ORDERING=AMD; sq amd $NMAX Q8 PECPLAS_ORDERING=AMD
  # the OpenMP team of the element loops sleeps at once when idle instead of spinning (a
  # 2-thread profile spent 17 % of its CPU samples in libgomp)
  sq passive $NMAX Q4 OMP_WAIT_POLICY=passive
  mp mumps $NMAX 1 Q8; mp mumps $NMAX 1 Q4
  say "=== left after round 2: $(left) s"
  # round 3: the squares' ends again (run 2 of 3)
  sq rule 1 Q4; sq rule $NMAX Q4; sq rule 1 Q8; sq rule $NMAX Q8
  say "=== left after round 3: $(left) s"
  # round 4: between the ends
  for T in $MID; do sq rule $T Q4; done
  for T in $MID; do sq rule $T Q8; done
  say "=== left after round 4: $(left) s"
  # round 5: the squares' ends, run 3 of 3
  sq rule 1 Q4; sq rule $NMAX Q4; sq rule 1 Q8; sq rule $NMAX Q8
  say "=== left after round 5: $(left) s"
  # round 6: the footing between the ends and on MUMPS (only if MUMPS beat CHOLMOD on Q8,
  # both whole runs on 16 threads); more candidates
  for T in 4 8 2; do [ $SMALL = 1 ] && [ $T != 2 ] && continue; ft rule $T; done
  local tm tc; tm=$(last_total "^MPI mumps case=Q8 ranks=$NMAX threads=1 ")
  tc=$(last_total "^RUN rule threads=$NMAX .* Q8 ")
  if [ $SMALL = 1 ] || { [ -n "$tm" ] && [ -n "$tc" ] && awk "BEGIN {exit !($tm < $tc)}"; }; then
    mp mumps $NMAX 1 FOOT  # (--small: always, to check it)
  else say "SKIP mumps FOOT ranks=$NMAX (MUMPS on Q8: ${tm:-none} s, CHOLMOD: ${tc:-none} s)"; fi
  sq blas8 $NMAX Q4 PECPLAS_THREAD_PARTS=1,$((NMAX / 2)),0
  sq blas8 $NMAX Q8 PECPLAS_THREAD_PARTS=1,$((NMAX / 2)),0
  sq passive $NMAX Q8 OMP_WAIT_POLICY=passive
  if [ $SMALL = 1 ]; then mp mumps 1 2 Q8; else mp mumps 4 4 Q8; fi
  for T in 4 8; do [ $SMALL = 1 ] || sq amd $T Q8 PECPLAS_ORDERING=AMD; done
  say "=== left after round 6: $(left) s"
  # round 7: the footing's spread
  for T in 2 3; do ft rule 1; ft rule $NMAX; done
  say "=== done, left $(left) s; load $(cat /proc/loadavg)"
}

# the run total [s] of the last log line matching a pattern (RUN: the bench line's total; MPI:
# the summary's), empty when none
last_total() { grep -E "$1" "$LOG" | tail -1 | awk '/^RUN/ {print $14; exit}
  { if (match($0, /total [0-9.]+/)) print substr($0, RSTART + 6, RLENGTH - 6) }'; }
left() { echo $(( BUDGET - ($(date +%s) - T0) )); }
say() { echo "$*" | tee -a "$LOG"; }
# Seconds one run took on the first 16-core node (threads_node16.log; MUMPS and AMD guessed
# from the 2-core runs of doc/bench/mumps.md and ordering.md): case threads -> seconds.
# The seconds a case's last run took replace the estimate once it has run.
declare -A MEAS=()
estimate() {
  [ "$SMALL" = 1 ] && { echo 1; return; }
  [ -n "${MEAS["${3:-} $1 $2"]:-}" ] && { echo "${MEAS["${3:-} $1 $2"]}"; return; }
  case "$1 $2" in
    "Q4 1") echo 13 ;; "Q4 2") echo 11 ;; "Q4 "*) echo 9 ;;
    "Q8 1") echo 29 ;; "Q8 2") echo 24 ;; "Q8 4") echo 21 ;; "Q8 "*) echo 20 ;;
    "Q8amd 1") echo 26 ;; "Q8amd "*) echo 16 ;;
    "FOOT 1") echo 48 ;; "FOOT 2") echo 40 ;; "FOOT "*) echo 32 ;;
    "mumpsQ4 "*) echo 25 ;; "mumpsQ8 "*) echo 35 ;; "mumpsFOOT "*) echo 70 ;;
    *) echo 30 ;;
  esac
}
# true when a run of `estimate` seconds still fits (30 % margin), else logs a SKIP line
fits() { local e; e=$(estimate "$1" "$2" "$3")
  [ "$SMALL" = 1 ] && return 0
  [ $(( e * 13 / 10 )) -le "$(left)" ] && return 0
  say "SKIP $3 $1 threads=$2 (about $e s, $(left) s left)"; return 1; }
# elastic square through the whole program: tag threads element [env arguments...]
sq() { local tag=$1 n=$2 el=$3 sz line key=$3; shift 3
  [ "$el" = Q4 ] && sz=$Q4 || sz=$Q8
  [ "$tag" = amd ] && key=${el}amd
  fits "$key" "$n" "$tag" || return 0
  local t0; t0=$(date +%s)
  line=$(env "$@" OMP_NUM_THREADS=$n PECPLAS_BENCH_MATRIX=0 timeout $(( $(estimate "$key" "$n") * 3 + 30 )) \
    pecplas-bench $el $sz $W 2>>"$OUT/err.txt") || { say "FAIL $tag $el threads=$n"; return 0; }
  MEAS["$tag $key $n"]=$(( $(date +%s) - t0 + 1 ))
  say "RUN $tag threads=$n load=$(cut -d' ' -f1 /proc/loadavg) $line"; }
# the footing through the program: tag threads [env...]
ft() { local tag=$1 n=$2; shift 2
  fits FOOT "$n" "$tag" || return 0
  local t0; t0=$(date +%s)
  { time env OMP_NUM_THREADS=$n "$@" timeout $(( $(estimate FOOT "$n") * 3 + 30 )) \
      pecplas "$FOOT" -o $W/f.h5 > $W/f.log 2>&1 ; } 2> $W/f.time
  MEAS["$tag FOOT $n"]=$(( $(date +%s) - t0 + 1 ))
  say "FOOT $tag threads=$n time=$(tail -1 $W/f.time) | $(grep -E 'wall time|summary:|threads:|linear solver:|status:' $W/f.log | tr '\n' '|')"; }
# MUMPS, the MPI build on R ranks of T threads each: tag ranks threads Q4|Q8|FOOT
mp() { local tag=$1 r=$2 t=$3 c=$4 deck
  [ "$HAVE_MPI" = 1 ] || { say "SKIP $tag $c ranks=$r threads=$t (no MPI pack)"; return 0; }
  fits "mumps$c" "$r" "$tag" || return 0
  if [ "$c" = FOOT ]; then deck=$W/footing_mumps.inp
    sed 's/^\*SOLVER, LINEAR=[A-Z]*/*SOLVER, LINEAR=MUMPS/' "$FOOT" > "$deck"
  else local sz; [ "$c" = Q4 ] && sz=$Q4 || sz=$Q8
    deck=$W/square_mumps_$c.inp
    [ -f "$W/square_${c}_$sz.msh" ] || { say "SKIP $tag $c (no mesh from pecplas-bench)"; return 0; }
    sed 's/^\*STEP/*SOLVER, LINEAR=MUMPS\n*STEP/' "$W/square_${c}_$sz.inp" > "$deck"
  fi
  local t0; t0=$(date +%s)
  { time env OMP_NUM_THREADS=$t timeout $(( $(estimate "mumps$c" "$r") * 3 + 30 )) \
      orterun -np $r --bind-to none -x OMP_NUM_THREADS -x LD_LIBRARY_PATH \
      ${OPENBLAS_CORETYPE:+-x OPENBLAS_CORETYPE} \
      pecplas-mpi "$deck" -o $W/m.h5 > $W/m.log 2>&1 ; } 2> $W/m.time
  MEAS["$tag mumps$c $r"]=$(( $(date +%s) - t0 + 1 ))
  say "MPI $tag case=$c ranks=$r threads=$t time=$(tail -1 $W/m.time) | $(grep -E 'wall time|summary:|threads:|linear solver:|status:' $W/m.log | tr '\n' '|')"; }

case ${1:-full} in
  pack) shift; pack "$@"; exit ;;
  device) shift; device "$@"; exit ;;
esac
# the first node run (2026-11-27): 
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
