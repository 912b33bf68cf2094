#!/usr/bin/env python3
"""Scaling: an elastic-plastic strip footing from about 1e4 to 1e6 equations.

Mesh: decks/make_default_deck.py (Q8, half model, 10 m x 5 m, footing half-width 1 m), soil
turned into Drucker-Prager fitted to Mohr-Coulomb in plane strain (E = 2e4 kPa, nu = 0.3,
c = 10 kPa, phi = psi = 30 deg: associated, so the consistent tangent is symmetric and full
Newton uses CHOLMOD). Drucker-Prager rather than Mohr-Coulomb because its smooth cone needs
fewer Newton iterations as the mesh is refined (trial with Mohr-Coulomb: 7.5 iterations per
increment at 1e4 equations, 19.5 at 1e5; Drucker-Prager 6 and 8), which keeps the 1e6 case
within the time budget. Geostatic initial stress (K0 = 0.5), then a footing pressure of
300 kPa (about half the bearing capacity: plastic zones under the footing edge) in 2
increments, results written every increment.

For each size, REPEATS runs of the release pecplas, each in its own process: wall time, peak
resident memory (bench_common.run_timed), and the phase times of the end-of-run summary
(read+setup, assembly, factorisation, solve, residual, of which law updates, output). Time
per increment = (total - read+setup) / increments. A size is reported by its median run
(median time per increment) with the spread [min - max] of the runs and the 1-minute load
average when the size started; all runs use the same thread setting (OMP_NUM_THREADS =
OPENBLAS_NUM_THREADS = --threads). The growth with the number of equations is fitted by
least squares on log-log (time ~ a N^p) over the medians, and over the fastest and the
slowest run of each size for its spread.

Writes doc/bench/scaling.csv, doc/bench/scaling.png and the fragment doc/bench/scaling.md.

    python3 -m pecplas_py.bench.scaling [--quick] [--pecplas PATH]
"""
import argparse
import os
import re
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from pecplas_py import script_cmd
from pecplas_py.bench.common import (BENCH_DIR, executable, load1, run_timed,
                                     write_csv, write_fragment)

INCREMENTS = 2
REPEATS = 3
TARGET_EXPONENT = 1.25
TIMEOUT = 480.0  # s per run; a run that takes longer is reported as 'timeout'
PHASES = ("setup", "assembly", "factorisation", "solve", "residual", "laws", "output")
HEADER = ["nx", "ny", "equations", "status", "increments", "iterations", "factorisations",
          "wall_s", "peak_mb", "time_per_increment_s", "time_per_iteration_s",
          *[f"t_{p}_s" for p in PHASES],
          "total_s", "flops", "repeats", "load1", "threads", "tpi_min_s", "tpi_max_s"]
TPI = HEADER.index("time_per_increment_s")


def equations(nx, ny):
    """Free equations of the footing mesh: Q8 nodes minus base (XY) and sides (X)."""
    nodes = (2 * nx + 1) * (2 * ny + 1) - nx * ny
    return 2 * nodes - 2 * (2 * nx + 1) - 2 * (2 * ny)


def size_for(target):
    """nx = 2 ny (square elements on the 10 m x 5 m block) closest to `target` equations."""
    ny = max(2, round((target / 6.0) ** 0.5 / 2 ** 0.5))
    return 2 * ny, ny


def make_deck(nx, ny, path):
    subprocess.run([*script_cmd("decks.make_default_deck"), "--nx",
                    str(nx), "--ny", str(ny), "--width", "10", "--depth", "5", "--footing", "1",
                    "-o", str(path)], check=True)
    text = path.read_text()
    text = re.sub(r"\*MATERIAL, NAME=clay, TYPE=ELASTIC\n[^\n]*",
                  "*MATERIAL, NAME=clay, TYPE=DRUCKER_PRAGER\n"
                  "E = 2.0e4, NU = 0.3, GAMMA = 18.0, C = 10, PHI = 30, PSI = 30", text)
    text = re.sub(r"footing, 100.0[^\n]*", "footing, 300.0", text)
    text = re.sub(r"\*SOLVER[^\n]*", "*SOLVER, LINEAR=AUTO, METHOD=NEWTON, TOLERANCE=1e-4, "
                  "MAX_ITERATIONS=30, MAX_CUTS=3", text)
    # geostatic initial stress (K0 = 0.5) instead of a gravity step: every increment timed
    # is a plastic one
    text = re.sub(r"\*LOAD, NAME=weight[^\n]*\n[^\n]*\n", "", text)
    text = re.sub(r"\*STEP, NAME=geostatic[^*]*\*END STEP\n", "", text)
    text = re.sub(r"\*BOUNDARY", "*INITIAL_STRESS, TYPE=GEOSTATIC\nALL, 0.0, 0.5\n*BOUNDARY",
                  text)
    text = re.sub(r"(\*STEP, NAME=loading, INCREMENTS=)\d+", rf"\g<1>{INCREMENTS}", text)
    text = re.sub(r"footing_load, 1.0[^\n]*", "footing_load, 1.0", text)
    text = text.replace("on elastic soil", "on Drucker-Prager soil")
    path.write_text(text)


def parse_summary(out):
    """Phase times, increments, iterations, factorisations from the end-of-run summary."""
    t = {}
    m = re.search(r"wall time \[s\]:(.*)", out)
    if m:
        line = m.group(1)
        for key, name in (("read\\+setup", "setup"), ("assembly", "assembly"),
                          ("factorisation", "factorisation"), ("solve", "solve"),
                          ("residual", "residual"), ("\\(laws", "laws"), ("output", "output"),
                          ("total", "total")):
            mm = re.search(key + r" ([0-9.]+)", line)
            t[name] = float(mm.group(1)) if mm else float("nan")
    m = re.search(r"summary: (\d+) increments, (\d+) iterations, \d+ cuts, (\d+) factoris", out)
    counts = tuple(int(g) for g in m.groups()) if m else (0, 0, 0)
    st = re.search(r"status: (\S+(?: load)?)", out)
    return t, counts, st.group(1) if st else "failed"


def factorisation_flops(out):
    """Flop count of one factorisation, from CHOLMOD's analysis as the run summary's
    'linear solver:' line prints it (nan when absent)."""
    m = re.search(r"linear solver: .*?flops= *([0-9.Ee+-]+)", out)
    return float(m.group(1)) if m else float("nan")


def fit_exponent(n, t):
    """Least-squares fit of log t = log a + p log n: returns (p, a)."""
    p, loga = np.polyfit(np.log(np.asarray(n, float)), np.log(np.asarray(t, float)), 1)
    return p, float(np.exp(loga))


def shares(t):
    """Shares of the increment time (total - setup): factorisation, law updates, assembly,
    output, solve and the rest of the residual (B^T sigma), and anything not timed."""
    run = t["total"] - t["setup"]
    parts = {"factorisation": t["factorisation"], "law updates": t["laws"],
             "assembly": t["assembly"], "output": t["output"], "solve": t["solve"],
             "residual w/o laws": t["residual"] - t["laws"]}
    parts["other"] = max(0.0, run - sum(parts.values()))
    return {k: v / run for k, v in parts.items()} if run > 0 else {k: 0.0 for k in parts}


def plot(rows, p, a, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ok = [r for r in rows if r[3] == "completed"]
    n = np.array([r[2] for r in ok], float)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.2))
    ax1.loglog(n, [r[TPI] for r in ok], "o-", label="time per increment (median)")
    lo = np.array([col(r, "tpi_min_s") for r in ok], float)
    hi = np.array([col(r, "tpi_max_s") for r in ok], float)
    if np.all(np.isfinite(lo)):
        ax1.fill_between(n, lo, hi, color="tab:blue", alpha=0.2, lw=0, label="spread of runs")
    ax1.loglog(n, a * n**p, "k--", lw=1, label=f"fit ~ N^{p:.2f}")
    ax1.loglog(n, [r[TPI + 1] for r in ok], "^-", color="tab:green", label="time per iteration")
    ax1.set_xlabel("equations N")
    ax1.set_ylabel("wall time [s]")
    ax3 = ax1.twinx()
    ax3.loglog(n, [r[8] for r in ok], "s:", color="tab:red", label="peak memory")
    ax3.set_ylabel("peak resident memory [MB]", color="tab:red")
    h1, l1 = ax1.get_legend_handles_labels()
    h3, l3 = ax3.get_legend_handles_labels()
    ax1.legend(h1 + h3, l1 + l3, loc="upper left", fontsize=8)
    ax1.grid(True, which="both", alpha=0.3)
    names = list(shares(dict(zip(("total", *PHASES), [1.0] + [0.0] * len(PHASES)))).keys())
    bottom = np.zeros(len(ok))
    x = np.arange(len(ok))
    for k in names:
        v = np.array([shares(row_times(r))[k] for r in ok]) * 100
        ax2.bar(x, v, bottom=bottom, label=k)
        bottom += v
    ax2.set_xticks(x)
    ax2.set_xticklabels([f"{int(v):.1e}".replace("e+0", "e") for v in n], fontsize=8)
    ax2.set_xlabel("equations N")
    ax2.set_ylabel("share of increment time [%]")
    ax2.legend(fontsize=7, bbox_to_anchor=(1.01, 1.0), loc="upper left")
    fig.suptitle("Strip footing, Drucker-Prager soil, full Newton (CHOLMOD), 2 increments",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def row_times(r):
    i = HEADER.index("t_setup_s")
    t = dict(zip(PHASES, r[i:i + len(PHASES)]))
    t["total"] = r[HEADER.index("total_s")]
    return t


def col(r, name):
    return r[HEADER.index(name)]


def median_run(runs):
    """The row of a size from its repeated runs (rows of HEADER without the last five
    columns): the run with the median time per increment among the completed ones, with
    the spread (min, max) of their times per increment; a size with a failed run is
    reported by that run (its status), so a failure is never hidden by the others."""
    bad = [r for r in runs if r[3] != "completed"]
    if bad:
        return list(bad[0]), float("nan"), float("nan")
    ranked = sorted(runs, key=lambda r: r[TPI])
    t = [r[TPI] for r in ranked]
    return list(ranked[(len(ranked) - 1) // 2]), t[0], t[-1]


def exponents(rows):
    """Exponent of the time per increment over the completed sizes: fitted on the medians,
    on each size's fastest run and on its slowest run (nan below two sizes); and the local
    slope between the two largest sizes (the kink test)."""
    ok = [r for r in rows if r[3] == "completed"]
    nan = float("nan")
    if len(ok) < 2:
        return nan, nan, nan, nan
    n = [r[2] for r in ok]
    p = fit_exponent(n, [r[TPI] for r in ok])[0]
    lo = fit_exponent(n, [col(r, "tpi_min_s") for r in ok])[0]
    hi = fit_exponent(n, [col(r, "tpi_max_s") for r in ok])[0]
    a, b = ok[-2], ok[-1]
    last = float(np.log(b[TPI] / a[TPI]) / np.log(b[2] / a[2]))
    return p, lo, hi, last


def spread_text(lo, hi):
    """The exponents over the fastest and slowest runs, when the sizes were repeated."""
    if not (np.isfinite(lo) and np.isfinite(hi)):
        return ""
    return f", medians; N^{lo:.2f} over each size's fastest run, N^{hi:.2f} over its slowest"


def fragment(rows, p, q, wall, quick):
    ok = [r for r in rows if r[3] == "completed"]
    _, lo, hi, last = exponents(rows)
    loads = [col(r, "load1") for r in rows if col(r, "load1") == col(r, "load1")]
    reps = sorted({int(col(r, "repeats")) for r in rows if col(r, "repeats") == col(r, "repeats")})
    threads = sorted({int(col(r, "threads")) for r in rows if col(r, "threads") == col(r, "threads")})
    load_text = (f"1-minute load average {min(loads):.1f}–{max(loads):.1f} when the sizes "
                 f"started (on {os.cpu_count()} cores)" if loads else "load not recorded")
    rep_text = ("median of " + "/".join(str(k) for k in reps) + " runs per size, spread "
                "[min – max]" if reps else "one run per size")
    th_text = ("/".join(str(k) for k in threads) if threads
               else os.environ.get("OPENBLAS_NUM_THREADS", "?"))
    L = ["## Scaling (`tools/pecplas_py/bench/scaling.py`)", "",
         "Strip footing (Q8, Drucker–Prager matched to Mohr–Coulomb in plane strain, "
         "c = 10 kPa, φ = ψ = 30°), geostatic initial "
         "stress (K0 = 0.5), then 300 kPa in 2 increments, full Newton with CHOLMOD, results "
         "every increment. Time per "
         "increment = (total − read+setup) / increments; "
         f"{rep_text}; threads {th_text} (OMP_NUM_THREADS = OPENBLAS_NUM_THREADS: CHOLMOD's "
         f"team and the BLAS); {load_text}. "
         f"{'Quick mode (small sizes only). ' if quick else ''}"
         f"Wall time of the benchmark {wall:.0f} s. Data: `scaling.csv`.", "",
         f"**Time per increment grows as N^{p:.2f}** (least squares on log–log over "
         f"{len(ok)} sizes{spread_text(lo, hi)}); local slope between the two largest sizes "
         f"N^{last:.2f}: target N^<={TARGET_EXPONENT} with no kink "
         f"{'met' if p <= TARGET_EXPONENT and last <= TARGET_EXPONENT else 'not met'} on this "
         f"run. Time per Newton iteration as N^{q:.2f}.", "",
         "| equations | status | load | increments | iterations | time/increment [s] "
         "| time/iteration [s] "
         "| peak memory [MB] | factorisation | law updates | assembly | output | solve "
         "| residual w/o laws | other |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if r[3] == "completed":
            s = shares(row_times(r))
            sh = " | ".join(f"{100 * s[k]:.0f} %" for k in s)
        else:
            sh = " | ".join(["-"] * 7)
        spread = (f" [{col(r, 'tpi_min_s'):.3g} – {col(r, 'tpi_max_s'):.3g}]"
                  if col(r, "tpi_min_s") == col(r, "tpi_min_s") else "")
        ld = f"{col(r, 'load1'):.1f}" if col(r, "load1") == col(r, "load1") else "-"
        L.append(f"| {r[2]} | {r[3]} | {ld} | {r[4]} | {r[5]} | {r[TPI]:.3g}{spread} "
                 f"| {r[TPI + 1]:.3g} | {r[8]:.0f} | {sh} |")
    fl = [r for r in ok if col(r, "flops") == col(r, "flops") and col(r, "flops") > 0]
    if len(fl) >= 2:
        f, _ = fit_exponent([r[2] for r in fl], [col(r, "flops") for r in fl])
        i = HEADER.index("t_factorisation_s")
        g, _ = fit_exponent([r[2] for r in fl], [r[i] / r[4] for r in fl])
        h, _ = fit_exponent([r[2] for r in fl], [r[TPI] - r[i] / r[4] for r in fl])
        L += ["", f"The flop count of one factorisation (CHOLMOD's analysis, independent of "
              f"the machine) grows as N^{f:.2f}, near the N^1.5 of nested dissection on a 2-D "
              f"mesh, the least any ordering achieves; the factorisation time per increment "
              f"as N^{g:.2f} (the iterations grow too), the rest of the increment as "
              f"N^{h:.2f}. The exponent of the whole increment rises towards the "
              "factorisation's as it takes over: a time per increment growing as N^1.25 or "
              "less up to 1e6 equations would need a linear solver whose cost grows more "
              "slowly than a sparse factorisation's, and Newton iterations that do not grow. "
              "Whether an iterative solver's would, on this footing's own tangents, is "
              "measured in the section on AMG-preconditioned CG below."]
    L += ["", "Shares are of the increment time (median run); the law updates are the stress "
          "integration at the Gauss points (the part of the residual timer inside the material "
          "updates).", "", "![scaling](scaling.png)", ""]
    return "\n".join(L)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="1e4, 3e4 and 1e5 equations only")
    ap.add_argument("--pecplas", default=None)
    ap.add_argument("--threads", type=int, default=1,
                    help="BLAS/OpenMP threads of the runs (default 1: a core each, so that "
                    "the exponent does not depend on how busy the other core is)")
    ap.add_argument("--sizes", type=float, nargs="+", default=None,
                    help="target equation counts (default 1e4 3e4 1e5 3e5 1e6, quick: 1e4 3e4 1e5)")
    ap.add_argument("--repeats", type=int, default=REPEATS,
                    help=f"runs per size (default {REPEATS}; the median is reported)")
    ap.add_argument("--render", action="store_true",
                    help="only write the fragment and figure again from doc/bench/scaling.csv")
    a = ap.parse_args()
    if a.render:
        render()
        return
    exe = a.pecplas or executable("pecplas")
    for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"):
        os.environ[var] = str(a.threads)
    targets = a.sizes or ([1e4, 3e4, 1e5] if a.quick else [1e4, 3e4, 1e5, 3e5, 1e6])
    rows = []
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        for target in targets:
            nx, ny = size_for(target)
            deck = tmp / f"footing_{nx}x{ny}.inp"
            make_deck(nx, ny, deck)
            out = deck.with_suffix(".h5")
            load = load1()
            runs = []
            for _ in range(a.repeats):
                runs.append(one_run(exe, deck, out, nx, ny))
                print(*runs[-1], sep="\t", flush=True)
                if runs[-1][3] != "completed":
                    break
            row, lo, hi = median_run(runs)
            rows.append(row + [len(runs), load, a.threads, lo, hi])
            for f in tmp.glob(deck.stem + "*"):
                f.unlink()
    wall = time.perf_counter() - t0
    finish(rows, wall, a.quick)


def one_run(exe, deck, out, nx, ny):
    """One run of the deck: a row of HEADER up to `flops`."""
    r = run_timed([exe, deck, "-o", out], timeout=TIMEOUT)
    tm, (inc, its, fac), status = parse_summary(r["stdout"])
    if r["rc"] is None:
        status = "timeout"
    tpi = (tm["total"] - tm["setup"]) / inc if inc and tm else float("nan")
    m = re.search(r"equations (\d+)", r["stdout"])
    neq = int(m.group(1)) if m else equations(nx, ny)
    return [nx, ny, neq, status, inc, its, fac, round(r["wall"], 3), round(r["peak_mb"], 1),
            round(tpi, 4), round(tpi * inc / its, 5) if its else float("nan"),
            *[tm.get(k, float("nan")) for k in PHASES], tm.get("total", float("nan")),
            factorisation_flops(r["stdout"])]


def render():
    """The fragment and figure from doc/bench/scaling.csv (its wall time is not stored: the
    one in the current fragment is kept)."""
    import csv
    with open(BENCH_DIR / "scaling.csv") as f:
        recs = list(csv.reader(f))[1:]
    with open(BENCH_DIR / "scaling.csv") as f:
        names = next(csv.reader(f))
    k = len(HEADER) if "tpi_max_s" in names else HEADER.index("flops") + 1
    rows = [[int(r[0]), int(r[1]), int(r[2]), r[3]] + [float(x) for x in r[4:k]]
            + [float("nan")] * (len(HEADER) - k) for r in recs]
    for r in rows:
        r[4], r[5], r[6] = int(r[4]), int(r[5]), int(r[6])
    old = (BENCH_DIR / "scaling.md").read_text()
    m = re.search(r"Wall time of the benchmark (\d+) s", old)
    b = re.search(r"BLAS threads (\d+)\.", old)
    if b:
        os.environ["OPENBLAS_NUM_THREADS"] = b.group(1)
    finish(rows, float(m.group(1)) if m else float("nan"), False, rewrite_csv=False)


def finish(rows, wall, quick, rewrite_csv=True):
    """CSV (unless rendering from it: its rows keep their own commit and date), figure and
    fragment."""
    ok = [r for r in rows if r[3] == "completed"]
    nan = (float("nan"), float("nan"))
    p, a_ = fit_exponent([r[2] for r in ok], [r[TPI] for r in ok]) if len(ok) >= 2 else nan
    q, _ = fit_exponent([r[2] for r in ok], [r[TPI + 1] for r in ok]) if len(ok) >= 2 else nan
    if rewrite_csv:
        write_csv(BENCH_DIR / "scaling.csv", HEADER, rows)
    plot(rows, p, a_, BENCH_DIR / "scaling.png")
    write_fragment("scaling", fragment(rows, p, q, wall, quick))
    print(f"scaling: exponent per increment {p:.3f}, per iteration {q:.3f}, {wall:.1f} s")


if __name__ == "__main__":
    main()
