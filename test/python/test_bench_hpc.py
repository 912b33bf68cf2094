"""The pure-Python pieces of the HPC benchmark (pecplas_py.bench.mumps,
pecplas_py.bench.mumps_report) on synthetic rows: no MPI and no benchmark run here."""
import math
import re

import pytest

from pecplas_py.bench import mumps as bench_mumps
from pecplas_py.bench import mumps_report as rep

NAN = float("nan")


def row(n, solver="MUMPS", threads=1, ranks=1, problem="elastic", mb=None, **kw):
    """A completed run whose memory, fill and flops follow exact power laws of n."""
    mb = 2e-3 * n**1.1 if mb is None else mb
    r = {"problem": problem, "equations": n, "solver": solver, "threads": threads,
         "ranks": ranks, "status": "completed", "peak_mb_per_rank": mb / ranks,
         "peak_mb_total": mb, "peak_mb_ranks": "", "ordering": "metis",
         "time_per_increment_s": 1.0, "t_factorisation_s": 2.0, "factorisations": 4,
         "nnz_factor": 30.0 * n**1.1, "flops": 1e3 * n**1.5,
         "est_factor_entries": 30.0 * n**1.1, "est_flops": 1e3 * n**1.5,
         "est_mb_rank": 30.0 * n**1.1 * 12 / 1e6, "est_mb_total": 30.0 * n**1.1 * 12 / 1e6,
         "mumps_mb_rank": 30.0 * n**1.1 * 12 / 1e6, "load_run": 1.0, "final": "yes",
         "note": "", "date": "2026-11-24T05:00:00Z"}
    r.update(kw)
    return r


def test_memory_of_the_next_size_follows_the_fitted_power_law():
    # exact power law 2e-3 N^1.1 over 1e5 and 3e5: the prediction at 1e6 is exact to roundoff
    rows = [row(1e5), row(3e5)]
    need = rep.predicted_total_mb(rows, {"problem": "elastic", "equations": 1e6,
                                         "solver": "MUMPS", "threads": 1, "ranks": 1})
    assert need == pytest.approx(2e-3 * 1e6**1.1, rel=1e-8)


def test_memory_prediction_below_linear_growth_scales_the_largest_size_linearly():
    # measured DP footing, CHOLMOD 2 threads: 389.5 MB at 99 372, 2944.7 MB at 1 002 252
    # (N^0.88); the prediction at 3e6 is the largest size scaled linearly (8.6 GB), not the
    # fit's coefficient with exponent 1 (which said 48 GB and skipped a run that fits)
    rows = [row(99372, mb=389.5), row(1002252, mb=2944.7)]
    run = {"problem": "elastic", "equations": 3e6, "solver": "MUMPS", "threads": 1, "ranks": 1}
    need = rep.predicted_total_mb(rows, run)
    assert need == pytest.approx(2944.7 * 3e6 / 1002252, rel=1e-12)


def test_memory_prediction_from_one_size_or_none():
    run = {"problem": "elastic", "equations": 1e6, "solver": "MUMPS", "threads": 1, "ranks": 1}
    # one smaller size: scaled by (N / N0)^1.2 (GROWTH), a cautious exponent above 2D fill
    one = rep.predicted_total_mb([row(1e5, mb=300.0)], run)
    assert one == pytest.approx(300.0 * 10**rep.GROWTH, rel=1e-12)
    # another configuration or a larger size says nothing about this run: nan (run it)
    assert math.isnan(rep.predicted_total_mb([row(1e5, ranks=2), row(3e6)], run))


def test_20gb_size_solves_the_fit_and_says_when_it_is_extrapolated():
    rows = [row(n, solver="CHOLMOD") for n in (1e5, 1e6, 3e6)]
    text = "\n".join(rep.fit_table(rows))
    line = next(s for s in text.splitlines() if "| CHOLMOD | 1 × 1 |" in s)
    cells = [c.strip() for c in line.split("|")]
    assert float(cells[5]) == pytest.approx(1.1, abs=5e-3)
    n20 = float(cells[6].split()[0])
    # 2e-3 N^1.1 = 20 480 MB at N = (20480 / 2e-3)^(1 / 1.1); 3 significant digits printed
    assert n20 == pytest.approx((rep.GB20_MB / 2e-3) ** (1 / 1.1), rel=5e-3)
    # 2.35e6 equations lie within the sizes run (up to 3e6); fitted on 1e5 and 1e6 only,
    # the same size is an extrapolation
    assert "(within the sizes run)" in cells[6]
    two = "\n".join(rep.fit_table([row(n, solver="CHOLMOD") for n in (1e5, 1e6)]))
    assert "(extrapolated)" in next(s for s in two.splitlines() if "| CHOLMOD | 1 × 1 |" in s)
    # MUMPS's own estimate (12 bytes x 30 N^1.1 entries) gives the factor-only bound
    mum = "\n".join(rep.fit_table([row(n) for n in (1e5, 1e6)]))
    est = next(s for s in mum.splitlines() if "INFOG(17)" in s and "| 1 × 1 |" in s)
    assert float(est.split("|")[6].split()[0]) == pytest.approx(
        (rep.GB20_MB * 1e6 / 360.0) ** (1 / 1.1), rel=5e-3)
    # fewer than two sizes of at least 1e5: not fitted, and the table says why
    assert "not fitted" in "\n".join(rep.fit_table([row(1e4), row(1e5)]))


def test_extrapolation_reproduces_the_power_laws():
    rows = [row(n) for n in (1e5, 1e6, 3e6)]
    lines = rep.extrapolation(rows)
    assert "factor entries ~ N^1.10, flops ~ N^1.50" in lines[1]
    first = next(s for s in lines if s.startswith("| 1e+07 | ") and "| 16 |" in s)
    cells = [c.strip() for c in first.split("|")]
    # entries 30 N^1.1, flops 1e3 N^1.5 at N = 1e7 (3 significant digits printed)
    assert float(cells[2]) == pytest.approx(30.0 * 1e7**1.1, rel=5e-3)
    assert float(cells[3]) == pytest.approx(1e3 * 1e7**1.5, rel=5e-3)
    # factor share: 12 bytes per entry on 16 ranks
    assert float(cells[5]) == pytest.approx(30.0 * 1e7**1.1 * 12 / 16 / 1e9, abs=0.06)
    # time: flops / (16 ranks x rate x 50 %), rate = est_flops x 4 factorisations / 2 s at 3e6
    rate = 1e3 * 3e6**1.5 * 4 / 2.0
    assert float(cells[6]) == pytest.approx(1e3 * 1e7**1.5 / (16 * rate * 0.5), rel=5e-3)
    # the largest run had a quarter of a core (CPU 1 s over 4 s of wall time): the flop
    # rate per rank is 4 times its wall-time rate, the time a quarter
    shared = [row(n) for n in (1e5, 1e6)] + [row(3e6, cpu_s=1.0, total_s=4.0)]
    line = next(s for s in rep.extrapolation(shared) if s.startswith("| 1e+07 | ")
                and "| 16 |" in s)
    assert float(line.split("|")[6]) == pytest.approx(
        1e3 * 1e7**1.5 / (16 * 4 * rate * 0.5), rel=5e-3)
    assert "its CPU time over its wall time, 0.25" in rep.extrapolation(shared)[1]
    # fewer than two MUMPS sizes: no extrapolation is written
    assert rep.extrapolation([row(1e5)]) == []


def test_fragment_has_no_nan_and_shows_skips():
    rows = [row(1e5), row(1e6),
            {"problem": "elastic", "equations": 3e6, "solver": "MUMPS", "threads": 1,
             "ranks": 2, "status": "skipped", "final": "no",
             "note": "needs about 30.0 GB, 20.0 GB available",
             **{k: NAN for k in ("time_per_increment_s", "t_factorisation_s",
                                 "peak_mb_per_rank", "peak_mb_total", "nnz_factor", "flops",
                                 "est_factor_entries", "est_flops", "est_mb_rank",
                                 "est_mb_total", "mumps_mb_rank", "load_run")}}]
    text = rep.fragment(rows)
    assert "nan" not in text.lower()
    assert "skipped (needs about 30.0 GB, 20.0 GB available)" in text


def test_run_output_is_parsed():
    out = (" linear solver: MUMPS n=99372 nnz(factor)=9876543 flops= 1.234E+10 peak_bytes= "
           "1.0E+08 analyses=1 factorisations=15 solves=16 ordering=metis (LDL^T) ranks=2 "
           "est_factor_entries=9876543 est_flops= 1.234E+10 est_mb_rank=150 est_mb_total=290 "
           "mb_rank=140 mb_total=270\n"
           " summary: 2 increments, 16 iterations, 0 cuts, 15 factorisations, 16 solves, 9 s CPU\n"
           " wall time [s]: read+setup 0.5  assembly 3.7  factorisation 8.25  solve 0.38  "
           "residual 0.87 (laws 0.31)  output 0.07  total 14.5\n status: completed  results: x\n")
    r = bench_mumps.parse_run(out)
    assert (r["increments"], r["iterations"], r["factorisations"]) == (2, 16, 15)
    assert r["time_per_increment_s"] == pytest.approx((14.5 - 0.5) / 2, abs=1e-12)
    assert r["t_factorisation_s"] == 8.25
    assert (r["cpu_s"], r["total_s"]) == (9.0, 14.5)
    assert (r["est_mb_rank"], r["est_mb_total"], r["mumps_mb_rank"]) == (150, 290, 140)
    assert r["est_flops"] == 1.234e10 and r["flops"] == 1.234e10
    assert r["ordering"] == "metis (LDL^T)" and r["status"] == "completed"


def test_load_excludes_the_reader_and_merge_replaces_a_rerun():
    assert bench_mumps.runnable_tasks("0.5 0.4 0.3 3/170 999") == 2
    assert bench_mumps.runnable_tasks("0.5 0.4 0.3 1/170 999") == 0
    old = [row(1e5), row(1e6), row(1e5, solver="CHOLMOD")]
    new = [row(1e6, t_factorisation_s=9.0)]
    merged = bench_mumps.merge(old, new)
    assert len(merged) == 3
    assert [r["t_factorisation_s"] for r in merged if r["equations"] == 1e6] == [9.0]
    # ordered by problem, size, then configuration (CHOLMOD before MUMPS)
    assert [(r["equations"], r["solver"]) for r in merged][:2] == [(1e5, "CHOLMOD"),
                                                                 (1e5, "MUMPS")]


def test_csv_round_trip_keeps_each_rows_provenance(tmp_path):
    rows = [row(1e5, commit="abc1234", machine="m", date="2026-11-24T05:00:00Z"),
            row(1e6, commit="def5678", machine="m", date="2026-11-24T06:00:00Z")]
    p = tmp_path / "m.csv"
    bench_mumps.write_rows(p, rows)
    back = bench_mumps.read_rows(p)
    assert [r["commit"] for r in back] == ["abc1234", "def5678"]
    assert back[1]["equations"] == 1000000 and back[1]["ranks"] == 1
    assert back[1]["est_flops"] == pytest.approx(1e3 * 1e6**1.5, rel=1e-12)
    assert re.match(r"\d{4}-", back[0]["date"])


def test_configuration_names_are_checked():
    assert bench_mumps.parse_config("mumps:1:2") == ("MUMPS", 1, 2)
    with pytest.raises(SystemExit, match="known: CHOLMOD:1:1"):
        bench_mumps.parse_config("MUMPS:4:4")


def test_configurations_not_run_are_listed():
    rows = [row(1e5, problem="elastic", solver=s, threads=th, ranks=k)
            for s, th, k in rep.CONFIGS] + [row(1e5, problem="dp_footing", solver="CHOLMOD")]
    rows += [row(3e6, problem="elastic", solver="CHOLMOD")]
    text = rep.fragment(rows)
    assert ("Not run in this series: elastic at 3000000.0 equations: CHOLMOD 2 × 1, MUMPS 1 × 1, "
            "MUMPS 1 × 2; dp_footing at 100000.0 equations: CHOLMOD 2 × 1, MUMPS 1 × 1, MUMPS "
            "1 × 2; dp_footing at 3000000.0 equations: all four.") in text
