"""The pure-Python pieces of the benchmark scripts (pecplas_py.bench) on synthetic data: no
benchmark is run here."""

import csv
import math
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]

from pecplas_py.bench import common as bench_common
from pecplas_py.bench import scaling as bench_scaling
from pecplas_py.bench import stability as bench_stability
from pecplas_py.bench import summary as bench_summary
from pecplas_py.decks import make_default_deck


def test_exponent_fit_recovers_a_power_law():
    # t = a N^p exactly: least squares on log-log is exact up to roundoff
    n = np.array([1e4, 3e4, 1e5, 3e5, 1e6])
    p, a = bench_scaling.fit_exponent(n, 2.5e-6 * n**1.37)
    assert p == pytest.approx(1.37, abs=1e-10)
    assert a == pytest.approx(2.5e-6, rel=1e-8)
    # +-5 % multiplicative scatter alternating in sign moves the slope by less than 0.05
    # (5 points spread over two decades)
    noisy = 2.5e-6 * n**1.37 * np.array([1.05, 0.95, 1.05, 0.95, 1.05])
    p, _ = bench_scaling.fit_exponent(n, noisy)
    assert abs(p - 1.37) < 0.05


def test_shares_add_up_to_one():
    t = {"setup": 1.0, "assembly": 2.0, "factorisation": 5.0, "solve": 0.5,
         "residual": 1.5, "laws": 1.0, "output": 0.25, "total": 11.0}
    s = bench_scaling.shares(t)
    assert sum(s.values()) == pytest.approx(1.0, abs=1e-12)
    # increment time = total - setup = 10 s
    assert s["factorisation"] == pytest.approx(0.5, abs=1e-12)
    assert s["law updates"] == pytest.approx(0.1, abs=1e-12)
    assert s["residual w/o laws"] == pytest.approx(0.05, abs=1e-12)
    assert s["other"] == pytest.approx(1.0 - 9.25 / 10.0, abs=1e-12)


def test_summary_line_is_parsed():
    # the layout written by pecplas_cmd_pecplas's summary (numbers made up)
    out = (" summary: 2 increments, 16 iterations, 0 cuts, 15 factorisations, 16 solves, "
           "9.1 s CPU\n wall time [s]: read+setup 0.556  assembly 3.790  factorisation 8.285"
           "  solve 0.382  residual 0.874 (laws 0.315)  output 0.071  total 14.015\n"
           " status: completed  results: x.h5\n")
    t, counts, status = bench_scaling.parse_summary(out)
    assert counts == (2, 16, 15)
    assert status == "completed"
    assert t["laws"] == pytest.approx(0.315, abs=1e-12)
    assert t["residual"] == pytest.approx(0.874, abs=1e-12)
    assert t["total"] == pytest.approx(14.015, abs=1e-12)


@pytest.mark.parametrize("nx,ny", [(2, 1), (6, 3), (58, 29)])
def test_equation_count_matches_the_mesh(nx, ny):
    # independent count from the generator's mesh: base nodes fixed in x and y, the two
    # vertical sides (above the base) fixed in x
    ids, nodes, _ = make_default_deck.q8_mesh(nx, ny, 10.0, 5.0)
    fixed = sum(2 if j == 0 else (1 if i in (0, 2 * nx) else 0) for (i, j) in ids)
    assert bench_scaling.equations(nx, ny) == 2 * len(nodes) - fixed


def test_stability_deck_edits():
    text = bench_stability.make_deck("s1", "newton", 1e3, 2.0, 77)
    # E1 = 1e5: K_n = 1e3 E1; steps 5, 15, 15 doubled
    assert "KN = 1e+08," in text
    # the old method alone (no fallback, no line search) beside the new chain
    assert ("*SOLVER, METHOD=NEWTON, FALLBACK=NO, LINE_SEARCH=NO, TOLERANCE=1e-4, "
            "MAX_ITERATIONS=77, MAX_CUTS=3") in text
    chain = bench_stability.make_deck("s1", "chain", 1e3, 1.0, 50)
    assert "*SOLVER, METHOD=MODIFIED_NEWTON, TOLERANCE=1e-4" in chain
    # the default method: no METHOD
    default = bench_stability.make_deck("s1", "default", 1e3, 1.0, 50)
    assert "*SOLVER, TOLERANCE=1e-4, MAX_ITERATIONS=50, MAX_CUTS=3" in default
    assert bench_stability.requested_increments(text) == 70
    k = bench_stability.make_deck("s1", "katona", 1.0, 0.2, 10)
    assert "TYPE=KATONA" in k and "TYPE=MOHR_COULOMB" not in k
    # steps of 5, 15, 15 increments times 0.2
    assert bench_stability.requested_increments(k) == 1 + 3 + 3
    # never fewer than one increment per step
    k = bench_stability.make_deck("s1", "katona", 1.0, 0.01, 10)
    assert bench_stability.requested_increments(k) == 3


def test_csv_has_provenance_columns(tmp_path):
    p = bench_common.write_csv(tmp_path / "x.csv", ["a", "b"], [[1, 2], [3, 4]])
    with open(p) as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["a", "b", "commit", "machine", "date"]
    assert len(rows) == 3
    for r in rows[1:]:
        assert len(r) == 5 and all(r[2:])


def test_summary_order_and_header(tmp_path):
    for name in ("zeta", "peer", "scaling", "alpha", "advice", "stability", "scaling_elastic",
                 "README"):
        (tmp_path / f"{name}.md").write_text(f"## {name}\n")
    order = [p.stem for p in bench_summary.ordered_fragments(tmp_path)]
    assert order == ["stability", "scaling", "scaling_elastic", "advice", "peer", "alpha", "zeta"]
    prov = {"commit": "abc1234", "machine": "host cpu x2 Linux", "date": "2026-01-01T00:00:00Z"}
    text = bench_summary.summary(tmp_path, wall=90.0, prov=prov)
    assert "abc1234" in text and "host cpu x2 Linux" in text and "90 s" in text
    pos = [text.index(f"## {n}\n") for n in order]
    assert pos == sorted(pos)
    assert "## README" not in text


def test_factorisation_flops_read_from_the_solver_line():
    # the summary line of a run (pecplas_py.bench.scaling fits the exponent of these counts)
    out = (" linear solver: CHOLMOD n=10092 nnz(factor)=673122 flops= 7.189E+07 "
           "peak_bytes= 1.162E+07 analyses=1 factorisations=11\n")
    assert bench_scaling.factorisation_flops(out) == 7.189e7
    assert math.isnan(bench_scaling.factorisation_flops("no solver line"))


def test_elastic_scaling_slopes_and_kink_verdict():
    from pecplas_py.bench import scaling_elastic as el
    # an exact power law N^1.1: every local slope is 1.1, the target (<= 1.25, no kink) is met
    n = [1e4, 1e5, 5e5, 1e6]
    t = [2e-6 * x**1.1 for x in n]
    slopes = el.local_slopes(n, t)
    assert [a for a, _, _ in slopes] == n[:-1]
    assert all(abs(s - 1.1) < 1e-12 for _, _, s in slopes)
    p, _ = bench_scaling.fit_exponent(n, t)
    assert el.verdict(p, slopes)[0]
    # the same series with the largest size 1.8x slower (the kink the benchmark looks for:
    # slope log2(1.8 * 2^1.1)/log2(2) = 1.95 between 5e5 and 1e6): not met, though the fit
    # over all sizes stays below 1.25
    t[-1] *= 1.8
    slopes = el.local_slopes(n, t)
    p, _ = bench_scaling.fit_exponent(n, t)
    assert p < 1.25 and abs(slopes[-1][2] - (1.1 + math.log(1.8) / math.log(2))) < 1e-12
    met, text = el.verdict(p, slopes)
    assert not met and "not met" in text


def test_solver_overhead_lines_add_up():
    import re
    from pecplas_py.bench import solver as bench_solver
    # one 1e6 row: total 6.0, bare 4.0; the named parts and the rest add up to total - bare
    d = {c: 0.0 for c in bench_solver.COLUMNS + bench_solver.EXTRA}
    d.update(element="Q4", equations=999698, read_setup_s=0.4, assembly_s=0.5,
             factorisation_s=3.8, solve_s=0.25, residual_s=0.15, output_s=0.45, total_s=6.0,
             bare_cholmod_s=4.0, threads=1)
    row = [d[c] for c in bench_solver.COLUMNS + bench_solver.EXTRA]
    small = list(row)
    small[bench_solver.COLUMNS.index("equations")] = 99458
    lines = bench_solver.overhead_lines([small, row])
    assert len(lines) == 3 and lines[2].startswith("- Q4 at 1e6, 1 thread(s): total - bare = 2.00 s")
    nums = [float(x) for x in re.findall(r"[-+]?\d+\.\d+", lines[2].split("=", 2)[2])]
    assert abs(sum(nums) - 2.0) < 1e-9   # 0.40 + 0.50 + 0.15 + 0.45 + 0.45 + 0.05


def _scaling_run(neq, tpi, status="completed"):
    """A row of bench_scaling.HEADER up to `flops` with time per increment `tpi`."""
    row = [0, 0, neq, status] + [0.0] * (bench_scaling.HEADER.index("flops") - 3)
    row[bench_scaling.TPI] = tpi
    return row


def test_scaling_reports_the_median_run_and_its_spread():
    runs = [_scaling_run(100, t) for t in (3.0, 1.0, 2.0)]
    row, lo, hi = bench_scaling.median_run(runs)
    assert row[bench_scaling.TPI] == 2.0 and (lo, hi) == (1.0, 3.0)
    # a failed run is the size's result, whatever the others did
    runs.append(_scaling_run(100, float("nan"), "timeout"))
    row, lo, hi = bench_scaling.median_run(runs)
    assert row[3] == "timeout" and math.isnan(lo) and math.isnan(hi)


def test_scaling_exponents_of_medians_fastest_and_slowest_runs():
    # medians N^1.2 (target N^<=1.25 met); fastest runs 0.9x (same exponent); slowest 1.1x
    # at the small sizes and 2x at the largest (their fit is steeper). Then the largest
    # median doubled (a kink): local slope between the two largest sizes
    # log10(2 * 10^1.2) = 1.5, not met
    n = [1e4, 1e5, 1e6]
    rows = []
    for k, x in enumerate(n):
        t = 1e-6 * x**1.2
        r = _scaling_run(int(x), t)
        rows.append(r + [3, 0.1, 1, 0.9 * t, (2.0 if k == 2 else 1.1) * t])
    p, lo, hi, last = bench_scaling.exponents(rows)
    assert p == pytest.approx(1.2, abs=1e-9) and lo == pytest.approx(1.2, abs=1e-9)
    assert last == pytest.approx(1.2, abs=1e-9)
    assert hi > 1.2 + 0.1
    assert p <= bench_scaling.TARGET_EXPONENT
    text = bench_scaling.fragment(rows, p, 1.2, 10.0, False)
    assert "median of 3 runs per size" in text and "load average 0.1" in text
    assert "threads 1" in text and "not met" not in text
    rows[-1][bench_scaling.TPI] *= 2.0
    p, _, _, last = bench_scaling.exponents(rows)
    assert last == pytest.approx(1.2 + math.log10(2.0), abs=1e-9)
    assert "not met" in bench_scaling.fragment(rows, p, 1.2, 10.0, False)


def test_load_range_of_known_loads():
    assert bench_common.load_range([0.52, float("nan"), "1.26", "", None]) == "0.5 - 1.3"
    assert bench_common.load_range([0.81, 0.84]) == "0.8"
    assert bench_common.load_range([float("nan"), ""]) == "unknown"


def _peer_rows(walls, timing=True):
    """Synthetic peer.csv rows: one pile mesh and the block, every code with the wall times
    {code: (median, min, max)}; timing=False: the 11 columns written before the spread."""
    from pecplas_py.bench import peer as bench_peer
    codes = ["ours, Mohr-Coulomb penalty", bench_peer.TIED, "ours, Katona", "CalculiX"]
    rows = []
    for scene, cs in (("S2 pile r1", codes), ("CGS-4 block", codes[:1] + codes[2:])):
        for k, code in enumerate(cs):
            med, lo, hi = walls[code]
            row = [scene, code, 54, 164, f"{med:.3f}", "20.0", 0, "0.717", f"{90 + k}.000",
                   "0.412371" if scene.startswith("CGS") else "70.00", "900"]
            if timing:
                row += [f"{lo:.3f}", f"{hi:.3f}", 3, f"{0.4 + 0.2 * k:.2f}", 1]
            rows.append(row)
    return rows


def test_peer_median_spread_and_ratio_range():
    from pecplas_py.bench import peer as bench_peer
    assert bench_peer.spread([1.3, 0.9, 1.1]) == (1.1, 0.9, 1.3)
    # CalculiX 1.0 [0.8 - 1.2] against ours 0.2 [0.1 - 0.4]: 5 [0.8/0.4 = 2, 1.2/0.1 = 12]
    assert bench_peer.ratio_spread((1.0, 0.8, 1.2), (0.2, 0.1, 0.4)) == pytest.approx(
        (5.0, 2.0, 12.0))


def test_peer_fragment_states_median_load_and_threads():
    from pecplas_py.bench import peer as bench_peer
    walls = {c: (0.2, 0.1, 0.4) for c in ("ours, Mohr-Coulomb penalty", bench_peer.TIED,
                                           "ours, Katona")}
    walls["CalculiX"] = (1.0, 0.8, 1.2)
    text = bench_peer.fragment(_peer_rows(walls), "2.20")
    assert "Median of 3 runs per case" in text and "one thread" in text
    assert "Load (1-minute load average when each case started): 0.4 - 1.0," in text
    assert "| 0.200 [0.100 - 0.400] | 5.0 [2.0 - 12.0] |" in text
    assert "| CalculiX | 1.000 [0.800 - 1.200] |  |" in text
    assert "best of" not in text
    # rows written before the spread was recorded: one run each, load unknown, no crash
    old = _peer_rows(walls, timing=False)
    assert bench_peer.timing_of(old[0])[:4] == (0.2, 0.2, 0.2, 1)
    text = bench_peer.fragment(old, "2.20", quick=True)
    assert "One run per case (quick mode)" in text and "load average when each case " \
        "started): unknown" in text
    assert "| 0.200 | 5.0 |" in text


def test_summary_lists_the_run_of_each_section(tmp_path):
    # two sections with data (written by bench_common.write_csv, which adds commit, machine
    # and date to every row), one rerun over two commits; a fragment without CSV is not listed
    (tmp_path / "scaling.md").write_text("## scaling\n")
    (tmp_path / "peer.md").write_text("## peer\n")
    (tmp_path / "notes.md").write_text("## notes\n")
    bench_common.write_csv(tmp_path / "scaling.csv", ["a"], [[1]])
    with open(tmp_path / "peer.csv", "w") as f:
        f.write("a,commit,machine,date\n1,abc1234,m,2026-01-01T10:00:00Z\n"
                "2,def5678,m,2026-01-02T11:00:00Z\n")
    runs = bench_summary.section_runs(tmp_path)
    assert [r[0] for r in runs] == ["scaling", "peer"]
    assert runs[1] == ("peer", ["abc1234", "def5678"], "2026-01-01T10:00:00Z",
                       "2026-01-02T11:00:00Z")
    text = bench_summary.summary(tmp_path, prov={"commit": "x", "machine": "m", "date": "d"})
    assert "- peer: commit `abc1234`, `def5678`, 2026-01-01T10:00:00Z – 2026-01-02T11:00:00Z" in text
    assert "- notes:" not in text
    assert text.index("- scaling: commit") < text.index("## scaling")


def test_scaling_render_keeps_the_csv_rows_and_their_provenance(tmp_path, monkeypatch):
    # --render rewrites the fragment and figure from the CSV; the CSV's rows keep the commit
    # and date of the run that measured them (it rewrote them with the current commit); the
    # fragment is rendered afresh into tmp_path (it once went to doc/bench/scaling.md)
    import shutil
    for name in ("scaling.csv", "scaling.md"):
        shutil.copy(ROOT / "doc" / "bench" / name, tmp_path / name)
    before = (tmp_path / "scaling.csv").read_bytes()
    monkeypatch.setattr(bench_scaling, "BENCH_DIR", tmp_path)
    monkeypatch.setattr(bench_common, "BENCH_DIR", tmp_path)   # write_fragment's scaling.md
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "1")
    bench_scaling.render()
    assert (tmp_path / "scaling.csv").read_bytes() == before
    assert "Time per increment grows as N^" in (tmp_path / "scaling.md").read_text()


def _solver_row(run_user, run_sys, equations=999698):
    """A 1e6 solver row (median and [min, max] of the run's user and system times)."""
    from pecplas_py.bench import solver as bench_solver
    d = {c: 0.0 for c in bench_solver.COLUMNS + bench_solver.EXTRA}
    d.update(element="Q4", equations=equations, threads=1, run_user_s=run_user[1],
             run_user_min_s=run_user[0], run_user_max_s=run_user[2], run_sys_s=run_sys[1],
             run_sys_min_s=run_sys[0], run_sys_max_s=run_sys[2], bare_user_s=3.1,
             bare_sys_s=1.4, bare_sys_min_s=1.3, bare_sys_max_s=1.5)
    return [d[c] for c in bench_solver.COLUMNS + bench_solver.EXTRA]


def test_solver_cpu_lines_say_where_the_spread_is():
    from pecplas_py.bench import solver as bench_solver
    # user time steady (4.0-4.1), system time spread (1.4-3.2): the sentence is made
    lines = bench_solver.cpu_lines([_solver_row((4.0, 4.05, 4.1), (1.4, 2.0, 3.2)),
                                    _solver_row((0.1, 0.1, 0.1), (0.1, 0.1, 0.1), 99458)])
    assert any(line.startswith(
        "- Q4 at 1e6, 1 thread(s): the run user 4.05 [4.00-4.10], system 2.00 "
        "[1.40-3.20]; the bare user 3.10, system 1.40 [1.30-1.50]; total - bare ")
        for line in lines)
    assert sum(line.startswith("- Q4") for line in lines) == 1   # the 1e6 row only
    assert any("varies less than its system time" in line for line in lines)
    # user time spread wider than system time: no such claim
    lines = bench_solver.cpu_lines([_solver_row((3.5, 4.0, 4.6), (1.4, 1.5, 1.6))])
    assert not any("varies less" in line for line in lines)


def test_solver_overhead_split_adds_up_to_total_minus_bare():
    # one thread: the user, system and no-CPU parts are each the run's minus the bare's, so
    # they add up to total - bare; the user-time ratio is the run's over the bare's
    from pecplas_py.bench import solver as bench_solver
    names = bench_solver.COLUMNS + bench_solver.EXTRA
    d = dict(zip(names, _solver_row((4.0, 4.4, 4.5), (1.0, 2.0, 3.0))))
    d.update(total_s=7.0, bare_cholmod_s=4.6)   # bare: user 3.1, system 1.4, no CPU 0.1
    text = bench_solver.split_text(d)
    assert "total - bare 2.40 s = user +1.30, system +0.60, on no CPU +0.50" in text
    assert text.endswith("user time run / bare 1.42")
    parts = [float(x) for x in re.findall(r"[-+]\d+\.\d+", text.split("=")[1])[:3]]
    assert sum(parts) == pytest.approx(7.0 - 4.6, abs=0.015)
    # with two threads CPU time is not a part of the wall time: no split
    d["threads"] = 2
    assert bench_solver.split_text(d) == ""


def test_fresh_memory_rate_is_measured():
    # a real measurement of this machine (8 MB, fast): positive and finite, and far below
    # what a memory-less copy could claim (no machine fills fresh pages at 1000 GB/s)
    from pecplas_py.bench import common as bench_common
    rate = bench_common.fresh_memory_gbs(mb=8, repeats=3)
    assert 0.0 < rate < 1000.0


def test_solver_csv_of_an_earlier_version_renders_without_cpu_lines(tmp_path):
    # a solver.csv written before the CPU-time columns (its header as the earlier
    # bench_solver wrote it): they read as nan, and the fragment has no CPU lines rather
    # than wrong ones; the committed CSV, with them, renders them
    from pecplas_py.bench import solver as bench_solver
    cpu = {"run_user_s", "run_sys_s", "bare_user_s", "bare_sys_s", "run_user_min_s",
           "run_user_max_s", "run_sys_min_s", "run_sys_max_s", "bare_sys_min_s",
           "bare_sys_max_s"}
    names = bench_solver.COLUMNS + bench_solver.EXTRA
    old = [c for c in names if c not in cpu | {"fresh_gbs"}]
    row = dict(zip(names, _solver_row((4.0, 4.05, 4.1), (1.4, 2.0, 3.2))), n=707)
    with open(tmp_path / "solver.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(old + ["commit", "machine", "date"])
        w.writerow([row[c] for c in old] + ["abc1234", "vm", "2026-11-24T00:00:00Z"])
    rows = bench_solver.read_rows(tmp_path / "solver.csv")
    assert len(rows) == 1 and len(rows[0]) == len(names)
    assert math.isnan(rows[0][names.index("run_sys_s")])
    text = bench_solver.solver_fragment(rows)
    assert "Target total / bare <= 1.2 at 1e6, Q4" in text
    assert "CPU time of the run" not in text
    # nor a fresh-memory rate: its column reads "-"
    assert math.isnan(rows[0][names.index("fresh_gbs")])
    assert "| Q4 | 999698 | 1 | 0.0 | - | " in text
    committed = bench_solver.read_rows(ROOT / "doc" / "bench" / "solver.csv")
    assert "CPU time of the run" in bench_solver.solver_fragment(committed)


def test_solver_case_maps_the_two_programs_lines_to_the_columns(monkeypatch, tmp_path):
    # the run's line (pecplas-bench) and the bare's line (pecplas-bench-bare, a process of
    # its own) as the programs print them; each number must land in its own column and the
    # ratio be total / bare
    from pecplas_py.bench import solver as bench_solver
    lines = {"bench": " Q4      707    999698    0.540    0.510    3.738    0.232    0.133    0.199"
                      "    5.775   1792.8    4.080    1.700\n",
             "bare": "    0.700    2.850    0.244    3.794  1.05E+08    3.050    0.750\n"}
    calls = []

    def fake_run(cmd, **kw):
        calls.append(cmd)
        return {"rc": 0, "stdout": lines["bare" if "bare" in cmd[0] else "bench"],
                "stderr": ""}
    monkeypatch.setattr(bench_solver, "run_timed", fake_run)
    monkeypatch.setattr(bench_solver.os, "sync", lambda: None)
    row = bench_solver.one_case("pecplas-bench", "pecplas-bench-bare", "Q4", 707, str(tmp_path))
    d = dict(zip(bench_solver.COLUMNS, row))
    assert (d["element"], d["n"], d["equations"]) == ("Q4", 707, 999698)
    assert (d["read_setup_s"], d["output_s"], d["total_s"], d["peak_mb"]) == \
        (0.54, 0.199, 5.775, 1792.8)
    assert (d["run_user_s"], d["run_sys_s"], d["bare_user_s"], d["bare_sys_s"]) == \
        (4.08, 1.7, 3.05, 0.75)
    assert d["bare_cholmod_s"] == 3.794 and d["nnz_L"] == 1.05e8
    assert d["ratio"] == pytest.approx(5.775 / 3.794, rel=1e-12)
    # the bare reads the matrix file the run wrote
    assert calls[1][1] == str(tmp_path / "square_Q4_707.matrix.h5")
    # a failed program is an error, not a row
    lines["bare"] = "\n"
    with pytest.raises(RuntimeError, match="pecplas-bench-bare Q4 707 failed"):
        bench_solver.one_case("pecplas-bench", "pecplas-bench-bare", "Q4", 707, str(tmp_path))


def test_footing_peer_ccx_counts_and_plateau():
    """CalculiX's .sta: a cut attempt (number ending in U) counts its iterations and a cut,
    not an increment; the plateau is the last 'total force' block's -RF_y per unit width."""
    from pecplas_py.bench import peer_footing as bf
    sta = ("SUMMARY OF JOB INFORMATION\n"
           "  STEP      INC     ATT  ITRS     TOT TIME     STEP TIME      INC TIME\n"
           "     1          1     1     6  0.5E-01  0.5E-01  0.5E-01\n"
           "     1          2     1U    4  0.1E+00  0.1E+00  0.5E-01\n"
           "     1          2     2     5  0.1E+00  0.1E+00  0.25E-01\n")
    assert bf.ccx_counts(sta) == (2, 15, 1)
    dat = ("\n total force (fx,fy,fz) for set FOOTING and time  0.95E+00\n\n"
           "        6.7E+00 -5.257025E+02 -7.6E-14\n"
           "\n total force (fx,fy,fz) for set FOOTING and time  0.1E+01\n\n"
           "        6.8E+00 -5.258250E+02  1.0E-13\n")
    assert bf.ccx_plateau(dat) == pytest.approx(525.825, abs=1e-9)


def test_footing_peer_fragment_ratios():
    """The footing table: iterations per increment and the ratio to CalculiX's count on the
    same mesh and element, the plateau's relative difference; rows of other soils or drives
    go to the second table."""
    from pecplas_py.bench import peer_footing as bf
    rows = [["2k", "ours", "Q8R", "vm", "settle", 2003, 20, 76, 0, "1.19", "525.8", 0, "0.5", 1],
            ["2k", "CalculiX", "Q8R", "vm", "settle", 2003, 20, 60, 0, "23.47", "525.8", 0,
             "0.5", 1],
            ["2k", "ours", "Q8R", "mc", "settle", 2003, 20, 105, 0, "2.01", "3068.2", 0,
             "0.5", 1]]
    text = bf.fragment(rows)
    assert "| 2k | Q8R | 2003 | ours | 20 | 76 | 3.8 | 1.27 | 0 | 1.19 | 525.8 | +0.00% |" in text
    assert "| 2k | Q8R | mc | settle | 2003 | 20 | 105 | 0 | 2.01 | 3068.2 |" in text


def test_footing_decks_reproduce_the_base_mesh():
    """refine 1 is the 2 000-equation mesh: 22 x 17 corner lines of the quadratic mesh,
    21 x 16 Q8 (1 083 nodes) or 42 x 32 Q4 (1 419 nodes); refine m splits every side in m."""
    from pecplas_py.decks import make_footing_peer_decks as fd
    nodes, els, *_ = fd.mesh("Q8", 1)
    assert (len(nodes), len(els)) == (1083, 336)
    nodes, els, *_ = fd.mesh("Q4", 1)
    assert (len(nodes), len(els)) == (1419, 1344)
    nodes, els, *_ = fd.mesh("Q8", 3)
    assert len(els) == 336 * 9
