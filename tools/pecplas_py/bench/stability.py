#!/usr/bin/env python3
"""Stability maps: where modified Newton, full Newton and Katona stop converging.

Two scenes: S1 compression-opening-closing (input/s1/s1_open_close_kn1e5.inp, E = E1 = 1e5 kPa,
the soft block) and S2 (input/s2/s2_mohr_coulomb.inp, E = E_soil = 2e4 kPa; Katona:
s2_katona.inp). Two sweeps per scene and method:
  - K_n / E from 1 to 1e10 at the deck's number of increments (the penalty joints only;
    Katona's rigid contact has no K_n: one run, drawn as a constant row);
  - the number of increments per step (deck count times 0.1 ... 4) at a fixed K_n / E
    (S1: 1e2, S2: the deck's 1e3).
Every run is capped: *SOLVER TOLERANCE=1e-4, MAX_ITERATIONS=CAP, MAX_CUTS=3, and a wall-clock
timeout; a run that stops early (status 'diverged', 'limit load', 'failed') or times out is a
failure. Iterations per increment and status come from the results file (history/iterations,
root attribute status).

Writes doc/bench/stability.csv, stability_s1.png, stability_s2.png and the fragment
doc/bench/stability.md.

    python3 -m pecplas_py.bench.stability [--quick] [--pecplas PATH]
"""
import argparse
import re
import tempfile
import time
from pathlib import Path

import numpy as np

from pecplas_py.bench.common import (BENCH_DIR, ROOT, executable, run_timed, write_csv,
                                     write_fragment)
from pecplas_py.results import Results

SCENES = {
    "s1": {"deck": ROOT / "input/s1/s1_open_close_kn1e5.inp", "katona": None, "E": 1e5,
           "kn_inc": 1e2, "title": "S1 compression-opening-closing (E = E1)"},
    "s2": {"deck": ROOT / "input/s2/s2_mohr_coulomb.inp",
           "katona": ROOT / "input/s2/s2_katona.inp", "E": 2e4, "kn_inc": 1e3,
           "title": "S2 pile, Mohr-Coulomb interface (E = E_soil)"},
}
ABBREV = {"diverged": "D", "limit load": "L", "singular K": "S", "timeout": "T",
          "failed": "F", "error": "E"}
METHODS = ("modified_newton", "newton", "quasi_newton", "chain", "default", "katona")
# The deck's *SOLVER line of each row: the thesis's methods alone (FALLBACK=NO, no line search:
# the maps as they were), BFGS alone, the thesis's method with its chain MODIFIED_NEWTON ->
# QUASI_NEWTON -> NEWTON with line search, and the default (no METHOD: full Newton with line
# search -> QUASI_NEWTON; doc/theory.md §4).
SOLVERS = {"modified_newton": "METHOD=MODIFIED_NEWTON, FALLBACK=NO, LINE_SEARCH=NO",
           "newton": "METHOD=NEWTON, FALLBACK=NO, LINE_SEARCH=NO",
           "quasi_newton": "METHOD=QUASI_NEWTON, FALLBACK=NO",
           "chain": "METHOD=MODIFIED_NEWTON",
           "default": "",
           "katona": "METHOD=NEWTON"}
LABELS = ["modified Newton", "full Newton", "quasi-Newton (BFGS)", "modified-Newton chain",
          "default (full Newton chain)",
          "Katona (no K_n)"]
HEADER = ["scene", "sweep", "method", "kn_over_e", "increments_requested", "status",
          "timed_out", "increments_done", "iter_mean", "iter_max", "cuts",
          "katona_states_total_max", "wall_s"]


def make_deck(scene, method, ratio, scale, cap):
    """Deck text for one run: K_n = ratio E (penalty), increments per step x scale."""
    sc = SCENES[scene]
    if method == "katona":
        text = (sc["katona"] or sc["deck"]).read_text()
        text = re.sub(r"(\*INTERFACE_LAW[^\n]*TYPE=)MOHR_COULOMB", r"\1KATONA", text)
    else:
        text = sc["deck"].read_text()
        text = re.sub(r"\bKN = [^,]+,", f"KN = {ratio * sc['E']:g},", text)
    options = f"{SOLVERS[method]}, " if SOLVERS[method] else ""
    text = re.sub(r"^\*SOLVER.*$", f"*SOLVER, {options}TOLERANCE=1e-4, "
                  f"MAX_ITERATIONS={cap}, MAX_CUTS=3", text, flags=re.M)
    text = re.sub(r"(\*STEP[^\n]*INCREMENTS=)(\d+)",
                  lambda m: m.group(1) + str(max(1, round(int(m.group(2)) * scale))), text)
    return text


def requested_increments(text):
    return sum(int(n) for n in re.findall(r"\*STEP[^\n]*INCREMENTS=(\d+)", text))


def run_one(exe, scene, sweep, method, ratio, scale, cap, timeout, tmp):
    text = make_deck(scene, method, ratio, scale, cap)
    deck = tmp / f"{scene}_{method}_{ratio:g}_{scale:g}.inp"
    deck.write_text(text)
    out = deck.with_suffix(".h5")
    r = run_timed([exe, deck, "-o", out], timeout=timeout)
    timed_out = r["rc"] is None
    status, it = "timeout", np.zeros(0, int)
    if not timed_out:
        try:
            with Results(out) as res:
                status = res.status
                it = res.history("iterations")
        except (OSError, KeyError):
            # no results file: the deck was refused before the first increment
            status = "singular K" if "singular" in r["stderr"] else "error"
    m = re.search(r"(\d+) cuts", r["stdout"])
    cuts = int(m.group(1)) if m else -1
    m = re.search(r"(\d+) state iterations \(max (\d+)", r["stdout"])
    states = f"{m.group(1)}/{m.group(2)}" if m else ""
    out.unlink(missing_ok=True)
    for p in tmp.glob(deck.stem + "*"):
        p.unlink()
    return [scene, sweep, method, "" if method == "katona" else f"{ratio:g}",
            requested_increments(text), status, int(timed_out), len(it),
            f"{it.mean():.2f}" if len(it) else "", int(it.max()) if len(it) else "",
            cuts, states, f"{r['wall']:.3f}"]


def state_mean(row):
    """Katona contact-state iterations per increment (each a solve with the flexibility)."""
    if not row[11] or not row[7]:
        return float("nan")
    return int(row[11].split("/")[0]) / int(row[7])


def converged(row):
    return row[5] == "completed"


def plot(scene, rows, ratios, scales, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm
    fig, axes = plt.subplots(1, 2, figsize=(13, 3.8), gridspec_kw={"width_ratios": [1.6, 1]})
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("0.85")
    vals = [float(r[8]) for r in rows if r[0] == scene and r[8] != ""]
    norm = LogNorm(vmin=1, vmax=max(10.0, max(vals) if vals else 10.0))
    for ax, sweep, xs in ((axes[0], "kn", ratios), (axes[1], "increments", scales)):
        grid = np.full((len(METHODS), len(xs)), np.nan)
        marks, xlabels = [], None
        sub = [r for r in rows if r[0] == scene and r[1] == sweep]
        if sweep == "increments":
            xlabels = [str(r[4]) for r in sub if r[2] == METHODS[0]]
        for i, meth in enumerate(METHODS):
            mrows = [r for r in sub if r[2] == meth]
            for j in range(len(xs)):
                r = mrows[0] if (meth == "katona" and sweep == "kn") else mrows[j]
                if r[8] != "":
                    grid[i, j] = float(r[8])
                if not converged(r):
                    marks.append((j, i, r[5]))
        im = ax.imshow(np.ma.masked_invalid(grid), cmap=cmap, norm=norm, aspect="auto",
                       origin="lower")
        for j, i, st in marks:
            ax.plot(j, i, "x", color="red", ms=14, mew=2.5)
            ax.text(j, i - 0.32, ABBREV.get(st, st), ha="center", va="center", fontsize=8,
                    color="red", weight="bold")
        failed = {(a, b) for a, b, _ in marks}
        for i, meth in enumerate(METHODS):
            mrows = [r for r in sub if r[2] == meth]
            for j in range(len(xs)):
                if not np.isfinite(grid[i, j]) or (j, i) in failed:
                    continue
                label = f"{grid[i, j]:.3g}"
                if meth == "katona" and sweep == "kn":
                    # one run (no K_n): one label across the row
                    if j == len(xs) // 2:
                        ax.text(j, i, f"K_n not used: {label} Newton it/inc, "
                                f"{state_mean(mrows[0]):.2g} contact-state it/inc",
                                ha="center", va="center", fontsize=8, color="w")
                    continue
                if meth == "katona":
                    label += f"\n{state_mean(mrows[j]):.2g} st."
                ax.text(j, i, label, ha="center", va="center", fontsize=7,
                        color="w" if grid[i, j] < norm.vmax ** 0.5 else "k")
        ax.set_yticks(range(len(METHODS)))
        ax.set_yticklabels(LABELS
                           if sweep == "kn" else [])
        ax.set_xticks(range(len(xs)))
        if sweep == "kn":
            ax.set_xticklabels([f"1e{int(round(np.log10(x)))}" for x in xs])
            ax.set_xlabel("K_n / E (log)")
            ax.set_title("deck increments")
        else:
            ax.set_xticklabels(xlabels)
            ax.set_xlabel("increments requested (all steps)")
            ax.set_title(f"K_n / E = {SCENES[scene]['kn_inc']:g}")
    fig.colorbar(im, ax=axes, label="mean iterations per increment", shrink=0.9)
    fig.suptitle(SCENES[scene]["title"] + ": red x = no convergence (" +
                 ", ".join(f"{v} {k}" for k, v in ABBREV.items()) +
                 "); st. = Katona contact-state it/inc", fontsize=9)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)


def converging_range(rows, scene, method):
    """(lowest, highest) K_n/E of the converged runs, and the failed ratios."""
    sub = [r for r in rows if r[0] == scene and r[1] == "kn" and r[2] == method]
    ok = [float(r[3]) for r in sub if converged(r)]
    bad = [float(r[3]) for r in sub if not converged(r)]
    return ok, bad


def fragment(rows, cap, timeout, wall, quick):
    L = ["## Stability maps (`tools/pecplas_py/bench/stability.py`)", "",
         f"Mean iterations per converged increment; a run fails when an increment does not "
         f"converge within {cap} iterations after 3 halvings, or after {timeout:g} s "
         f"(timeout): 'converges' means within this budget (S1 modified Newton at "
         f"K_n/E = 1e3 completes with a 10 000-iteration cap, doc/validation.md). Tolerance "
         f"1e-4. Rows: the thesis's methods alone (modified Newton, full Newton: FALLBACK=NO, "
         f"no line search), quasi-Newton (BFGS) alone, the thesis's method with its chain "
         f"(METHOD=MODIFIED_NEWTON: modified -> quasi- -> full Newton with line search) and the "
         f"default (no METHOD: full Newton with line search -> quasi-Newton; doc/theory.md §4). Status as the program "
         f"reports it: an increment no method converges is 'diverged' (a 'limit load' only when "
         f"the arc-length probe finds a maximum; the pile has none at 2000 kN); 'singular K' = "
         f"the first factorisation of the "
         f"penalty-stiffened matrix is refused (pivot ratio test), before any increment. "
         f"Katona's Newton iterations are 1 per increment here (elastic bodies: the contact "
         f"nonlinearity is taken by the contact-state iterations, given apart). "
         f"{'Quick mode (coarse sweep). ' if quick else ''}"
         f"Wall time of the sweep {wall:.0f} s. Data: `stability.csv`.", ""]
    for scene in SCENES:
        L += [f"**{SCENES[scene]['title']}**", "",
              "| method | converges for K_n/E in | fails at K_n/E | increments sweep "
              f"(K_n/E = {SCENES[scene]['kn_inc']:g}): converges / fails |", "|---|---|---|---|"]
        for meth in METHODS:
            inc = [r for r in rows if r[0] == scene and r[1] == "increments" and r[2] == meth]
            inc_ok = ", ".join(str(r[4]) for r in inc if converged(r)) or "none"
            inc_bad = ", ".join(f"{r[4]} ({r[5]})" for r in inc if not converged(r)) or "none"
            if meth == "katona":
                k = [r for r in rows if r[0] == scene and r[1] == "kn" and r[2] == meth][0]
                rng = (f"all (no K_n): {k[5]}, {k[8] or '-'} Newton it/inc, "
                       f"{state_mean(k):.2f} contact-state it/inc (max {k[11].split('/')[-1]})")
                bad = "-"
            else:
                ok, badl = converging_range(rows, scene, meth)
                rng = (f"1e{np.log10(min(ok)):.0f} … 1e{np.log10(max(ok)):.0f}" if ok
                       else "none")
                bad = ", ".join(f"1e{np.log10(b):.0f}" for b in badl) or "none"
            L.append(f"| {meth.replace('_', ' ')} | {rng} | {bad} | {inc_ok} / {inc_bad} |")
        L += ["", f"![stability {scene}](stability_{scene}.png)", ""]
    return "\n".join(L)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="coarse sweep (about a minute)")
    ap.add_argument("--pecplas", default=None)
    a = ap.parse_args()
    exe = a.pecplas or executable("pecplas")
    if a.quick:
        ratios = [10.0**e for e in (0, 2, 4, 6, 8, 10)]
        scales = [0.25, 1.0, 2.0]
        cap, timeout = 300, 20.0
    else:
        ratios = [10.0**e for e in range(0, 11)]
        scales = [0.1, 0.25, 0.5, 1.0, 2.0, 4.0]
        cap, timeout = 1000, 40.0
    rows = []
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        for scene in SCENES:
            for meth in METHODS:
                for ratio in ([1.0] if meth == "katona" else ratios):
                    rows.append(run_one(exe, scene, "kn", meth, ratio, 1.0, cap, timeout, tmp))
                    print(*rows[-1], sep="\t", flush=True)
                for s in scales:
                    rows.append(run_one(exe, scene, "increments", meth,
                                        SCENES[scene]["kn_inc"], s, cap, timeout, tmp))
                    print(*rows[-1], sep="\t", flush=True)
    wall = time.perf_counter() - t0
    write_csv(BENCH_DIR / "stability.csv", HEADER, rows)
    for scene in SCENES:
        plot(scene, rows, ratios, scales, BENCH_DIR / f"stability_{scene}.png")
    write_fragment("stability", fragment(rows, cap, timeout, wall, a.quick))
    print(f"stability sweep: {len(rows)} runs, {wall:.1f} s")


if __name__ == "__main__":
    main()
