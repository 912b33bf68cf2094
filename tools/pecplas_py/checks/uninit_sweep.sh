#!/usr/bin/env bash
# Uninitialised-read sweep: runs decks under valgrind memcheck with a release binary built with
# -g (doc/build.md "Uninitialised reads"). Not part of make test (minutes per deck).
#   tools/pecplas_py/checks/uninit_sweep.sh BIN_DIR LOG_DIR DECK...
# BIN_DIR holds pecplas (e.g. build/vg from
#   cmake -S . -B build/vg -DCMAKE_BUILD_TYPE=Release -DCMAKE_Fortran_FLAGS=-g -DCMAKE_C_FLAGS=-g
#   cmake --build build/vg -j1 --target pecplas pecplas-path pecplas-identify pecplas-sensitivity)
# A deck given as "path:PROGRAM" runs under that program (pecplas-path, ...) instead.
# Prints one line per deck: exit code of the run and the number of memcheck errors; the logs
# (LOG_DIR/NAME.vg) give each error's stack and the origin of the uninitialised value.
set -u
bin=$1; logs=$2; shift 2
mkdir -p "$logs"
supp="$(dirname "$0")/uninit_sweep.supp"
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for item in "$@"; do
  deck=${item%%:*}; prog=pecplas
  [[ $item == *:* ]] && prog=${item#*:}
  name=$(echo "$deck" | tr '/' '_'); name=${name%.inp}
  args=("$deck")
  [[ $prog == pecplas ]] && args+=(-o "$logs/$name.h5" --quiet)
  valgrind --tool=memcheck --track-origins=yes --error-exitcode=99 --num-callers=30 \
    --suppressions="$supp" --log-file="$logs/$name.vg" \
    "$bin/$prog" "${args[@]}" > "$logs/$name.out" 2>&1
  rc=$?
  nerr=$(grep -o 'ERROR SUMMARY: [0-9]*' "$logs/$name.vg" | awk '{print $3}')
  printf '%-60s rc=%-3s memcheck errors=%s\n' "$item" "$rc" "${nerr:-?}"
done
