#!/usr/bin/env bash
# Everything `make test` runs, in order, each stage going on even when an earlier one failed
# so that one run shows every problem:
#   1. fpm test   (debug profile with -fcheck=all: every suite of test/main.f90)
#   2. CMake      (release build in $CMAKE_DIR, one CTest test per suite)
#   3. pytest     (test/python, the result checker's tests), when present
# then one closing line "total: N passed, M failed, K skipped" counting distinct tests (the
# Fortran tests once, from stage 1; CTest runs the same suites in another build) plus the Python
# ones; every skipped Python test prints its reason (pytest -rs, test/python/conftest.py).
# The Python tests run only binaries of this same run: after a successful CMake build this script
# writes $CMAKE_DIR/make-test.stamp (SHA-256 of each executable), removed before the build, and
# test/python/pecplas_exe.py refuses a binary that does not match it; Fortran-written files must
# be newer than build/test-logs/make-test.start. When the CMake build fails, pytest does not run.
# CTest runs with PECPLAS_REPORT set: the values the docs quote, written by the suites, are
# then read by test/python/test_validation_report.py ($PECPLAS_CTEST_REPORT, set only when
# every CTest test passed) instead of running those suites of the same binary again.
# Exits non-zero when any stage failed. The Makefile sets FPM, PYTHON, CMAKE_DIR and JOBS.
set -uo pipefail
cd "$(dirname "$0")/.."
export PYTHONPATH=$PWD/tools${PYTHONPATH:+:$PYTHONPATH}  # pecplas_py (doc/tools.md)

FPM=${FPM:-fpm}
PYTHON=${PYTHON:-python3}
CMAKE_DIR=${CMAKE_DIR:-build/cmake}
JOBS=${JOBS:-2}
FPM_TEST_FLAGS=${FPM_TEST_FLAGS:--fcheck=all}
logdir=build/test-logs
mkdir -p "$logdir"
start_stamp=$logdir/make-test.start
touch "$start_stamp"
build_stamp=$CMAKE_DIR/make-test.stamp
rm -f "$build_stamp"
cmake_built=0
report_values=$logdir/ctest-report-values.txt
rm -f "$report_values"
ctest_passed=0

passed=0
failed=0
skipped=0
summary=()
status=0

stage() { printf '\n==== %s\n' "$*"; }
note() {  # note OK|FAIL TEXT: one line of the final summary
  summary+=("$(printf '  %-4s %s' "$1" "$2")")
  [[ $1 == ok ]] || status=1
}

# ---- 1. fpm test ----
stage "fpm test --profile debug --flag '$FPM_TEST_FLAGS'"
bash tools/fpm_fresh.sh
"$FPM" test --profile debug --flag "$FPM_TEST_FLAGS" 2>&1 | tee "$logdir/fpm.log"
rc=${PIPESTATUS[0]}
line=$(grep -E '^[0-9]+ passed, [0-9]+ failed$' "$logdir/fpm.log" | tail -n 1)
if [[ -n $line ]]; then
  read -r np _ nf _ <<<"${line//,/}"
  passed=$((passed + np))
  failed=$((failed + nf))
fi
if ((rc == 0)) && [[ -n $line ]]; then
  note ok "fpm test (debug, -fcheck=all): $line"
elif [[ -n $line ]]; then
  note FAIL "fpm test (debug, -fcheck=all): $line"
else
  failed=$((failed + 1))
  note FAIL "fpm test: did not build or did not finish (exit $rc), see $logdir/fpm.log"
fi

# ---- 2. CMake route ----
stage "cmake -B $CMAKE_DIR -DCMAKE_BUILD_TYPE=Release && cmake --build $CMAKE_DIR -j$JOBS"
ctest_args=(--test-dir "$CMAKE_DIR" --output-on-failure)
# pytest runs below on its own; CTest's python_results test would only repeat it.
[[ -d test/python ]] && ctest_args+=(--label-exclude python)
# Run from `make`, the inner make of `cmake --build` would print every directory change.
unset MAKEFLAGS MFLAGS MAKELEVEL
cmake -B "$CMAKE_DIR" -DCMAKE_BUILD_TYPE=Release 2>&1 | tee "$logdir/cmake-configure.log"
rc=${PIPESTATUS[0]}
if ((rc == 0)); then
  cmake --build "$CMAKE_DIR" -j"$JOBS" 2>&1 | tee "$logdir/cmake-build.log"
  rc=${PIPESTATUS[0]}
  if ((rc == 0)); then
    cmake_built=1
    {
      echo "# written by tools/test_all.sh after the CMake build of $(date -u +%FT%TZ)"
      find "$CMAKE_DIR" -maxdepth 1 -type f -perm -u+x -name 'pecplas*' -exec sha256sum {} +
    } >"$build_stamp.tmp" && mv "$build_stamp.tmp" "$build_stamp"
    stage "ctest ${ctest_args[*]}"
    # The suites write the values the docs quote (test/doc_report.f90) into $report_values;
    # test/python/test_validation_report.py reads them instead of running those suites of
    # the same binary a second time (only when every CTest test passed).
    rm -f "$report_values"
    PECPLAS_REPORT=$PWD/$report_values ctest "${ctest_args[@]}" 2>&1 | tee "$logdir/ctest.log"
    rc=${PIPESTATUS[0]}
    line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$logdir/ctest.log" | tail -n 1)
    if ((rc == 0)) && [[ -n $line ]]; then
      ctest_passed=1
      note ok "ctest (CMake release build): $line"
    else
      failed=$((failed + 1))
      note FAIL "ctest (CMake release build): ${line:-exit $rc}, see $logdir/ctest.log"
    fi
  else
    failed=$((failed + 1))
    note FAIL "cmake --build failed (exit $rc), see $logdir/cmake-build.log"
  fi
else
  failed=$((failed + 1))
  note FAIL "cmake configure failed (exit $rc), see $logdir/cmake-configure.log"
fi

# ---- 3. pytest ----
if ! compgen -G 'test/python/test_*.py' >/dev/null; then
  note ok "pytest: no test/python/test_*.py yet"
elif ((cmake_built == 0)); then
  failed=$((failed + 1))
  note FAIL "pytest test/python: not run, the CMake build failed (no fresh binaries to test)"
else
  stage "$PYTHON -m pytest test/python"
  export PECPLAS_BIN=$PWD/$CMAKE_DIR/pecplas
  export PECPLAS_STAMP=$PWD/$build_stamp
  export PECPLAS_TEST_START=$PWD/$start_stamp
  if ((ctest_passed == 1)) && [[ -s $report_values ]]; then
    export PECPLAS_CTEST_REPORT=$PWD/$report_values
  fi
  # The test files are shared among $JOBS pytest-xdist workers when it is installed (an
  # optional package of tools/install_deps.sh), whole files to one worker (--dist loadfile:
  # a module's fixtures run once); the programs they start run one thread each.
  pytest_par=()
  if ((JOBS > 1)) && "$PYTHON" -c 'import xdist' 2>/dev/null; then
    pytest_par=(-n "$JOBS" --dist loadfile)
  else
    echo "(pytest-xdist not installed or JOBS=1: the Python tests run one at a time)"
  fi
  "$PYTHON" -m pytest -q -rs -p no:cacheprovider "${pytest_par[@]}" test/python 2>&1 \
    | tee "$logdir/pytest.log"
  rc=${PIPESTATUS[0]}
  line=$(grep -E '[0-9]+ (passed|failed|skipped|errors?)( |,|$)' "$logdir/pytest.log" | tail -n 1)
  np=0 nf=0 ns=0
  [[ $line =~ ([0-9]+)\ passed ]] && np=${BASH_REMATCH[1]}
  [[ $line =~ ([0-9]+)\ failed ]] && nf=${BASH_REMATCH[1]}
  [[ $line =~ ([0-9]+)\ skipped ]] && ns=${BASH_REMATCH[1]}
  [[ $line =~ ([0-9]+)\ errors? ]] && nf=$((nf + BASH_REMATCH[1]))
  passed=$((passed + np))
  skipped=$((skipped + ns))
  if ((rc == 0)); then
    note ok "pytest test/python: $np passed, $ns skipped"
  elif ((rc == 5)); then
    note ok "pytest test/python: no tests collected"
  else
    ((nf > 0)) || nf=1
    failed=$((failed + nf))
    note FAIL "pytest test/python: exit $rc, ${line:-no summary}"
  fi
fi

stage "summary"
printf '%s\n' "${summary[@]}"
if ((status != 0)); then
  echo "make test: FAILED (logs in $logdir)"
fi
if ((skipped > 0)); then
  echo "skipped (reasons):"
  grep -E '^SKIPPED' "$logdir/pytest.log" | sed 's/^/  /'
fi
echo "total: $passed passed, $failed failed, $skipped skipped"
exit "$status"
