"""The thread benchmark's pieces that run without a many-core node: the report of
tools/bench_threads.sh's log (pecplas_py.bench.threads_report) on a synthetic log, the script's
syntax, and the benchmark switch PECPLAS_ORDERING of the release pecplas."""

import os
import subprocess
from pathlib import Path

import pytest

from pecplas_exe import pecplas_cmd
from pecplas_py.bench import scaling as bench_scaling
from pecplas_py.bench import threads_report

ROOT = Path(__file__).resolve().parents[2]

# bench line: element n equations setup assembly factorisation solve residual output total
# peak_mb user sys
LOG = """=== machine: 16 cpus; model name : Test CPU; 125 GB; 6.1
RUN rule threads=1 load=0.1  Q4  707  999698  0.7 0.8  9.0 0.3 0.2 0.2 12.0 1690.8 10.0 1.0
RUN rule threads=1 load=0.1  Q4  707  999698  0.7 0.8  8.0 0.3 0.2 0.2 11.0 1690.8 10.0 1.0
RUN rule threads=1 load=0.1  Q4  707  999698  0.7 0.8 10.0 0.3 0.2 0.2 13.0 1690.8 10.0 1.0
RUN rule threads=16 load=0.1 Q4  707  999698  0.5 0.3  3.0 0.3 0.1 0.2  4.0 1764.0 30.0 30.0
RUN rule threads=16 load=0.1 Q4  707  999698  0.5 0.3  4.0 0.3 0.1 0.2  5.0 1764.0 30.0 30.0
RUN amd threads=16 load=0.1  Q8  408  998784  0.5 0.4  9.0 0.4 0.1 0.2 10.0 2200.5 50.0 60.0
RUN rule threads=1 load=0.1  Q8  408  998784  0.5 0.9 24.0 0.4 0.3 0.2 27.0 2127.6 24.6 2.1
FOOT rule threads=1 time=47.1 45.9 1.2 |  summary: 2 increments| wall time [s]: read+setup 0.3  assembly 2.8  factorisation 38.9  solve 1.8  residual 2.5 (laws 1.5)  output 0.2  total 47.0| linear solver: CHOLMOD n=299568 nnz(factor)=1 flops= 1 ordering=METIS|
MPI mumps case=Q8 ranks=16 threads=1 time=15.0 200.0 10.0 |  summary: 1 increments| wall time [s]: read+setup 0.5  assembly 0.1  factorisation 9.0  solve 0.5  residual 0.1 (laws 0.0)  output 0.2  total 13.5| linear solver: MUMPS n=998784 nnz(factor)=1 ranks=16|
SKIP rule FOOT threads=16 (about 32 s, 20 s left)
"""


def test_report_takes_the_median_of_repeats_and_labels_candidates():
    rows, machine = threads_report.parse(LOG)
    assert "Test CPU" in machine
    runs = [r for r in rows if r["section"] == "run"]
    assert {r["case"] for r in runs} == {"Q4 1e6", "Q8 1e6, amd", "Q8 1e6",
                                         "footing 3e5", "Q8 1e6, mumps 16x1"}
    mpi = next(r for r in runs if r["tag"] == "mumps")
    assert (mpi["threads"], mpi["ranks"], mpi["total_s"]) == (16, 16, 13.5)
    table = threads_report.summary(rows).splitlines()
    q4_1 = next(x for x in table if x.startswith("| Q4 1e6 | 1 |"))
    q4_16 = next(x for x in table if x.startswith("| Q4 1e6 | 16 |"))
    # 3 runs: median 12.0 of 11, 12, 13; 2 runs: median 4.5, speed-up 12 / 4.5 = 2.67
    assert "| 3 | 12.00 [11.00 - 13.00] |" in q4_1
    assert "| 2 | 4.50 [4.00 - 5.00] |" in q4_16 and "| 2.67 | 2.67 |" in q4_16
    # a candidate without a 1-thread run is compared with the program's: 27 / 13.5 = 2.00
    mumps = next(x for x in table if x.startswith("| Q8 1e6, mumps 16x1 | 16 |"))
    assert "| - | 2.00 |" in mumps


def test_report_reads_the_first_node_log_as_before():
    rows, _ = threads_report.parse((ROOT / "doc/bench/threads_node16.log").read_text())
    # 6 program runs of Q4 and Q8, 2 of the footing, 22 factorisation configurations, 3 bare
    assert len(rows) == 34
    assert {r["case"] for r in rows if r["section"] == "run"} == {"Q4 1e6", "Q8 1e6",
                                                                   "footing 3e5"}


def test_the_script_parses():
    r = subprocess.run(["bash", "-n", str(ROOT / "tools/bench_threads.sh")],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("value, used", [("METIS", "METIS"), ("AMD", "AMD"), ("", "AMD"),
                                         ("metis", "AMD")])
def test_pecplas_ordering_switch(tmp_path, value, used):
    # the Drucker-Prager footing of the scaling benchmark on 16 x 8 Q8 elements (associated:
    # symmetric, CHOLMOD): its rule orders it by AMD (few flops per entry of L); the switch
    # names AMD or METIS exactly, any other value leaves the rule
    deck = tmp_path / "footing.inp"
    bench_scaling.make_deck(16, 8, deck)
    env = dict(os.environ, PECPLAS_ORDERING=value, OMP_NUM_THREADS="1")
    r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(tmp_path / "d.h5")],
                       capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    line = next(x for x in r.stdout.splitlines() if "linear solver:" in x)
    assert f"ordering={used}" in line, line
