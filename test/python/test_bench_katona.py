"""pecplas_py.bench.katona without its runs (they are `make bench`): the summary of a completed
run and the progress lines of a run stopped at the time limit are parsed into the table's
counts, the decks differ from their sources only by the solver method, and the fragment says
when the machine was loaded. pecplas_py.bench.summary --keep-header keeps the suite's header."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.bench import katona as bk
from pecplas_py.bench import summary as bench_summary

SUMMARY = """ nodes 20  elements 3  equations 20  steps 3  solver CHOLMOD / MODIFIED_NEWTON
 step  1   compress inc    1  fraction  0.2000  iter   1  residual  1.0E-12
 summary: 35 increments, 35 iterations, 0 cuts, 1 factorisations, 80 solves, 0.01 s CPU
 katona: 2 doublets, 37 state iterations (max 2 per increment), 1 flexibility builds
 status: completed  results: x.h5
"""
STOPPED = """ nodes 9  elements 4  equations 4209  steps 2  solver CHOLMOD / MODIFIED_NEWTON
 step  1   load inc    1  fraction  0.0500  iter 120  residual  9.0E-05
 step  1   load inc    2  fraction  0.1000  iter 311  residual  9.9E-05
"""


def test_completed_summary_is_parsed():
    c = bk.parse(SUMMARY)
    assert c == {"equations": 20, "status": "completed", "increments": 35, "iterations": 35,
                 "factorisations": 1, "state_iterations": 37, "state_max": 2}


def test_stopped_run_counts_its_converged_increments():
    """No summary (killed at the limit): 2 increments, 120 + 311 iterations from the progress
    lines, the factorisations unknown."""
    c = bk.parse(STOPPED)
    assert (c["increments"], c["iterations"], c["factorisations"]) == (2, 431, None)


def test_solver_line_changes_only_the_method():
    text = "*STEP, NAME=a, INCREMENTS=5\n*SOLVER, TOLERANCE=1e-4, MAX_ITERATIONS=500\n"
    new = bk.set_solver(text, "modified")
    assert "*SOLVER, METHOD=MODIFIED_NEWTON, FALLBACK=NO, TOLERANCE=1e-4, MAX_ITERATIONS=500" \
        in new and new.startswith("*STEP, NAME=a, INCREMENTS=5")
    assert bk.set_solver(text, "katona") == text


def _row(case, method, wall, load, status="completed"):
    return [case, "X", method, 20, status, 35, 35, 40, 1, None, None, f"{wall:.3f}", 1,
            f"{load:.1f}"]


def test_fragment_states_the_load_and_the_ratio():
    """Load above the core count: the fragment says the machine was shared; the Katona /
    full Newton ratio of a case is wall(Katona) / wall(full Newton) = 1 / 4."""
    rows = [_row("pile", "katona", 1.0, 99.0), _row("pile", "newton", 4.0, 99.0),
            _row("pile", "modified", 300.0, 99.0, "stopped at the 300 s limit")]
    md = bk.fragment(rows, {}, {"commit": "abc", "date": "d"}, 300)
    assert "shared with other work" in md and "pile: 0.250" in md and "> 40" in md
    quiet = bk.fragment([_row("pile", "katona", 1.0, 0.0)], {}, {"commit": "abc", "date": "d"},
                        300)
    assert "shared with other work" not in quiet


def test_summary_keeps_the_suite_header(tmp_path):
    prov = {"commit": "abc1234", "machine": "m x2", "date": "2026-01-01T00:00:00Z"}
    text = bench_summary.header(prov, 812.0)
    assert bench_summary.kept_header(text) == (prov, 812.0)
