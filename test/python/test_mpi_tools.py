"""The pure-Python pieces of the MPI check and benchmark (pecplas_py.checks.mpi_check,
pecplas_py.bench.mumps) on synthetic data: no MPI needed."""

import numpy as np
import pytest

from pecplas_py.bench import mumps as bench_mumps
from pecplas_py.checks import mpi_check


def test_mumps_deck_replaces_the_solver_choice():
    text = "*NODES\n1, 0, 0\n*SOLVER, LINEAR=CHOLMOD, METHOD=NEWTON\n*STEP, NAME=a\n"
    out = mpi_check.mumps_deck(text)
    assert "*SOLVER, LINEAR=MUMPS, METHOD=NEWTON" in out
    assert "CHOLMOD" not in out


def test_mumps_deck_adds_a_solver_line_before_the_first_step():
    out = mpi_check.mumps_deck("*NODES\n1, 0, 0\n*STEP, NAME=a\n*STEP, NAME=b\n")
    lines = out.splitlines()
    assert lines.index("*SOLVER, LINEAR=MUMPS") == lines.index("*STEP, NAME=a") - 1
    assert out.count("*SOLVER") == 1


def test_mumps_deck_without_steps_is_refused():
    with pytest.raises(ValueError):
        mpi_check.mumps_deck("*NODES\n1, 0, 0\n")


def test_power_fit_recovers_exponent_and_20gb_size():
    # memory = 2e-3 N^1.1 MB: the fit returns p = 1.1 (to roundoff) and solving for 20 GB
    # gives back the N of that memory
    n = np.array([1e4, 3e4, 1e5, 3e5])
    p, a = bench_mumps.fit(n, 2e-3 * n**1.1)
    assert p == pytest.approx(1.1, rel=1e-10)
    n20 = (bench_mumps.GB20_MB / a) ** (1 / p)
    assert 2e-3 * n20**1.1 == pytest.approx(bench_mumps.GB20_MB, rel=1e-8)


def test_power_fit_needs_two_valid_points():
    assert bench_mumps.fit([1e4, 2e4], [5.0, float("nan")]) is None


def test_summary_numbers_are_read():
    line = (" linear solver: MUMPS n=30000 nnz(factor)=5318710 flops= 8.564E+08 ranks=2 "
            "est_factor_entries=5318710 est_flops= 8.564E+08 est_mb_rank=71 mb_rank=62")
    assert bench_mumps.number(r"est_flops=\s*([0-9.E+-]+)", line) == 8.564e8
    assert bench_mumps.number(r" mb_rank=(\d+)", line) == 62
    assert np.isnan(bench_mumps.number(r"absent=(\d+)", line))


def test_assembly_split_read_from_the_summary():
    out = (" wall time [s]: read+setup 0.456  assembly 3.346\n"
           " ranks: 2, each assembles the stiffness of its own elements: wall 3.049 to 3.102 s,"
           " CPU 0.676 to 0.681 s\n")
    assert mpi_check.assembly_split(out) == (2, 0.676, 0.681)
    assert mpi_check.assembly_split(" wall time [s]: assembly 1.0\n") is None


def test_unit_runs_pass_only_when_every_rank_passed():
    both = "6 passed, 0 failed\n6 passed, 0 failed\n"
    assert mpi_check.unit_passed(0, both, 2)
    assert not mpi_check.unit_passed(0, both, 1)  # a rank too many: not the run asked for
    assert not mpi_check.unit_passed(0, "6 passed, 0 failed\n", 2)  # a rank said nothing
    assert not mpi_check.unit_passed(0, "6 passed, 0 failed\n5 passed, 1 failed\n", 2)
    assert not mpi_check.unit_passed(1, both, 2)  # mpirun's exit status counts
    assert not mpi_check.unit_passed(0, "0 passed, 0 failed\n", 1)  # nothing ran


def _results(path, rows, status, fields):
    """A minimal results file: history rows (iterations, residual) and increment groups
    {global increment: (displacement, joint relative displacement)} in metres."""
    import h5py
    with h5py.File(path, "w") as f:
        f.attrs["status"] = status
        f.attrs["created"] = str(path)  # a time stamp: not compared
        f["history/step"] = np.ones(len(rows), dtype=np.int32)
        f["history/iterations"] = np.array([r[0] for r in rows], dtype=np.int32)
        f["history/residual"] = np.array([r[1] for r in rows])
        f["history/cpu_time"] = np.random.default_rng().random(len(rows))
        for g, (u, z) in fields.items():
            grp = f.create_group(f"increments/{g:06d}")
            grp.attrs["global_increment"] = g
            for name, v in (("displacement", u), ("joints/tip/relative_displacement", z)):
                grp[name] = np.asarray(v, dtype=float)
                grp[name].attrs["units"] = "m"


def test_restart_differences_within_the_scatter_of_several_ranks(tmp_path):
    """A restarted run on several ranks equals the uninterrupted one when its iteration
    counts are the same and every dataset lies within EXACT_TOL of the largest value of its
    units in the increment: a closed joint's relative displacements (1e-19, noise around
    zero) are measured against the displacements, not against themselves; another iteration
    count or a difference above the tolerance is reported."""
    full, part, rest = (tmp_path / f"{k}.h5" for k in ("full", "part", "rest"))
    u = np.array([1.0e-2, -3.0e-3])
    _results(full, [(2, 1e-5), (3, 2e-6), (2, 7e-13)], "completed",
             {2: (u, [1e-19]), 3: (2 * u, [4e-19])})
    _results(part, [(2, 1e-5)], "interrupted", {1: (u / 2, [0.0])})
    _results(rest, [(3, 2e-6), (2, 4e-13)], "completed",
             {2: (u * (1 + 1e-14), [-3e-19]), 3: (2 * u, [1e-18])})
    assert mpi_check.restart_differences(full, part, rest, 1) == []
    _results(rest, [(2, 2e-6), (2, 4e-13)], "completed",
             {2: (u + [0.0, 1e-8], [0.0]), 3: (2 * u, [0.0])})
    assert mpi_check.restart_differences(full, part, rest, 1) == [
        "history/iterations", "increment 2: displacement"]
