#!/usr/bin/env python3
"""Adaptive refinement beside uniform refinement (make bench), error of a goal against wall time.

S2 pile (goal: head settlement at 2000 kN): `pecplas DECK --target-error 1% --goal node:1:y`
from the coarsest deck of the work-precision series (decks/make_s2_decks.py, level 3, first
loading step, 5 increments, full Newton), for the Mohr-Coulomb interface (Q4/GOODMAN4 and
Q8/GOODMAN6) and Katona contact (Q4); the uniform series and the Richardson references are those
of doc/bench/work_precision.csv (bench/work_precision.py, not rerun here).

Strip footing (goal: settlement of the footing centre at 150 kPa): the Drucker-Prager footing of
bench/scaling.py (Q8, 10 m x 5 m half model, geostatic stress, 150 kPa in 2 increments); uniform
series nx x nx/2 for nx = 10 .. 80 run here (Richardson reference over the three finest), and the
adaptive sequence from nx = 10 (target 0.2 %).

Every level the program prints is a point of the adaptive series, at the wall time of the levels
up to it (what reaching that mesh adaptively costs). Every run is made once, on one thread
(OMP_NUM_THREADS=1), with the 1-minute load average recorded when it starts (CSV column load1):
the wall times are single runs (indicative), the errors and DOF counts exact.

Writes doc/bench/adapt.csv (one row per level), work_precision_s2.png (redrawn from
work_precision.csv with the adaptive series), work_precision_footing.png and the fragment
adapt.md with the table of the cheapest configuration within 1 % / 5 %, uniform and adaptive
rows together.
"""
import argparse
import csv
import math
import os
import re
import tempfile
from pathlib import Path

from pecplas_py.bench import common as bc
from pecplas_py.bench import scaling as bsc
from pecplas_py.bench import wp_decks as wd
from pecplas_py.bench.wp_analysis import cheapest_within, relative_error, richardson
from pecplas_py.bench.wp_report import label, plot
from pecplas_py.decks import make_s2_decks as g2
from pecplas_py.results import Results

S2_CASES = [("mohr_coulomb", "Q4"), ("katona", "Q4"), ("mohr_coulomb", "Q8")]
FOOTING_NX = (10, 20, 40, 80)
# footing pressure [kPa]: plastic zones under the footing edge, well below the collapse load;
# nx a multiple of 10 so that the footing half-width is 1 m on every mesh
PRESSURE = 150.0
LEVEL = re.compile(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$")
TOLS = (0.01, 0.05)


def s2_deck(model, element):
    text = g2.deck(g2.Mesh(3), model, 3)
    text = wd.first_step_only(text, increments=5)
    text = wd.set_output_every(text, 10**6)
    text = wd.set_solver(text, "NEWTON")
    return wd.to_q8(text) if element == "Q8" else text


def footing_deck(nx, path):
    """The Drucker-Prager footing deck and the id of its footing-centre node (0, 0)."""
    bsc.make_deck(nx, nx // 2, path)
    text = re.sub(r"footing, 300.0", f"footing, {PRESSURE!r}", path.read_text())
    path.write_text(text)
    nodes = re.search(r"\*NODES\n(.*?)\n\*", text, re.S).group(1)
    for line in nodes.splitlines():
        if line.startswith("**"):
            continue
        i, x, y = (float(v) for v in line.split(","))
        if abs(x) < 1e-12 and abs(y) < 1e-12:
            return int(i)
    raise RuntimeError("no node at the footing centre")


def csv_runs(scene="s2"):
    """The work-precision runs of a scene from work_precision.csv, as the chart wants them."""
    runs = []
    with open(bc.BENCH_DIR / "work_precision.csv") as f:
        for r in csv.DictReader(f):
            if r["scene"] != scene:
                continue
            method = "MODIFIED_NEWTON" if r["solver"] in ("modified Newton", "Katona bordered") \
                else "NEWTON"
            ref = float(r["reference_m"]) if r["reference_m"] else float("nan")
            value = float(r["value_m"]) if r["value_m"] else None
            err = relative_error(value, ref)
            runs.append(dict(scene=scene, model=r["model"], element=r["element"],
                             method=method, series=r["series"], level=int(r["level"]),
                             increments=int(r["increments"]), dofs=int(r["dofs"]),
                             status=r["status"], wall=float(r["wall_s"]), value=value,
                             error=err, ref=ref, load1=_float(r.get("load1"))))
    return runs


def _float(text):
    """A CSV number; nan when empty or missing (a file written before the column existed)."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def adaptive(exe, deck_text, goal, name, target, max_dofs):
    """Levels (dofs, goal value, estimate, cumulative wall, load average at the run's start)
    of one adaptive run."""
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / f"{name}.inp"
        deck.write_text(deck_text)
        load = bc.load1()
        r = bc.run_timed([exe, str(deck), "--target-error", target, "--goal", goal,
                          "--max-dofs", str(max_dofs), "-o", str(Path(tmp) / "a.h5")])
    out, cum = [], 0.0
    for g in (m.groups() for m in map(LEVEL.match, r["stdout"].splitlines()) if m):
        cum += float(g[6])
        out.append(dict(level=int(g[0]), dofs=int(g[1]), value=float(g[4]),
                        estimate=g[5], wall=cum, load1=load))
    print(f"  {name}: {len(out)} levels, exit {r['rc']}, {r['wall']:.1f} s", flush=True)
    return out, r["rc"] == 0


def run_footing(exe):
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        for nx in FOOTING_NX:
            deck = Path(tmp) / f"footing_{nx}.inp"
            node = footing_deck(nx, deck)
            h5 = deck.with_suffix(".h5")
            load = bc.load1()
            r = bc.run_timed([exe, str(deck), "-o", str(h5), "--quiet"], timeout=600)
            value = None
            if r["rc"] == 0:
                with Results(h5) as res:
                    u = res.field(res.last_key(), "displacement")
                    value = -float(u[res.node_index(node), 1])
            runs.append(dict(scene="footing", model="drucker_prager", element="Q8",
                             method="NEWTON", series="mesh", level=nx, increments=2,
                             dofs=bsc.equations(nx, nx // 2), wall=r["wall"], value=value,
                             status="ok" if value is not None else f"failed rc={r['rc']}",
                             load1=load))
            print(f"  footing uniform nx={nx}: {r['wall']:.2f} s, {value}", flush=True)
        deck = Path(tmp) / "footing_adapt.inp"
        node = footing_deck(FOOTING_NX[0], deck)
        text = deck.read_text()
    ok = [r for r in runs if r["value"] is not None]
    rich = richardson([1.0 / r["level"] for r in ok], [r["value"] for r in ok])
    levels, met = adaptive(exe, text, f"node:{node}:y", "footing", "0.2%", 40000)
    for lv in levels:
        lv["value"] = -lv["value"]
    return runs, rich, levels, met


def finish(runs, ref, floor):
    for r in runs:
        r["error"] = relative_error(r["value"], ref)
        r["floor"] = floor
        r["resolved"] = math.isfinite(r["error"]) and r["error"] > floor
        r["error_bound"] = max(r["error"], floor) if math.isfinite(r["error"]) else r["error"]


def adaptive_runs(scene, model, element, levels):
    return [dict(scene=scene, model=model, element=element, method="NEWTON", series="adaptive",
                 level=lv["level"], increments=5 if scene == "s2" else 2, dofs=lv["dofs"],
                 wall=lv["wall"], value=lv["value"], status="ok", estimate=lv["estimate"],
                 load1=lv["load1"])
            for lv in levels]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="the Q8 S2 case and the footing")
    ap.add_argument("--max-dofs", type=int, default=20000)
    args = ap.parse_args()
    bc.one_thread()
    exe = bc.executable()
    prov = bc.provenance()
    wp = csv_runs()
    refs = {}
    for r in wp:
        if math.isfinite(r["ref"]):
            refs[r["model"]] = r["ref"]
    # the reference uncertainty of each model, from the finest three Q4 levels (as the
    # work-precision study computes it)
    floors = {}
    for model in refs:
        pts = sorted({(r["level"], r["value"]) for r in wp if r["model"] == model and
                      r["element"] == "Q4" and r["series"] == "mesh" and r["increments"] == 10
                      and r["value"] is not None and r["status"] == "ok"})
        rich = richardson([1.0 / n for n, _ in pts], [v for _, v in pts])
        floors[model] = rich["uncertainty"] / abs(refs[model])
    ada = []
    for model, element in S2_CASES[2:] if args.quick else S2_CASES:
        levels, met = adaptive(exe, s2_deck(model, element), "node:1:y", f"s2_{model}_{element}",
                               "1%", args.max_dofs)
        for lv in levels:
            lv["value"] = -lv["value"]
        ada += adaptive_runs("s2", model, element, levels)
    for r in wp + ada:
        ref = refs.get(r["model"], float("nan"))
        r["ref"] = ref
        r["error"] = relative_error(r["value"], ref)
        r["floor"] = floors.get(r["model"], float("nan"))
        r["resolved"] = math.isfinite(r["error"]) and r["error"] > r["floor"]
        r["error_bound"] = max(r["error"], r["floor"])
    plot([r for r in wp + ada if r["status"] == "ok"], "s2", bc.BENCH_DIR / "work_precision_s2.png")
    fruns, frich, flevels, fmet = run_footing(exe)
    fada = adaptive_runs("footing", "drucker_prager", "Q8", flevels)
    finish(fruns + fada, frich["ref"], frich["uncertainty"] / abs(frich["ref"]))
    plot([r for r in fruns + fada if r["status"] == "ok"], "footing",
         bc.BENCH_DIR / "work_precision_footing.png")
    header = ["scene", "model", "element", "series", "level", "dofs", "value_m", "reference_m",
              "error", "wall_s", "estimate_pct", "load1"]
    rows = [[r["scene"], r["model"], r["element"], r["series"], r["level"], r["dofs"],
             f"{r['value']:.9e}" if r["value"] is not None else "", f"{r['ref']:.9e}"
             if "ref" in r else f"{frich['ref']:.9e}", f"{r['error']:.3e}", f"{r['wall']:.4f}",
             r.get("estimate", ""), f"{r['load1']:.2f}"] for r in ada + fruns + fada]
    bc.write_csv(bc.BENCH_DIR / "adapt.csv", header, rows)
    write_fragment(prov, wp, ada, fruns, fada, frich, args.quick)


def table(groups):
    """Markdown rows: cheapest within each tolerance among uniform and adaptive runs."""
    out = []
    for name, rs in groups:
        for t in TOLS:
            ok = [r for r in rs if r["status"] == "ok"]
            for kind in ("uniform", "adaptive", "either"):
                pool = [r for r in ok if kind == "either" or
                        (r["series"] == "adaptive") == (kind == "adaptive")]
                b = cheapest_within(pool, t, error_key="error_bound")
                if b is None:
                    out.append(f"| {name} | {t:.0%} | {kind} | none within tolerance | | | | |")
                    continue
                conf = ("adaptive level" if b["series"] == "adaptive" else
                        "uniform n =" if b["scene"] == "s2" else "uniform nx =")
                out.append(f"| {name} | {t:.0%} | {kind} | {label_of(b)}, {conf} {b['level']}, "
                           f"{b['increments']} increments | {b['dofs']} | {b['error_bound']:.2e} "
                           f"| {b['wall']:.3f} | |")
    return out


def label_of(r):
    if r["scene"] == "footing":
        return "Drucker-Prager Q8, full Newton"
    return label(r)


def timing_text(runs, wp):
    """Thread setting and load of this run's timings (`runs`) and of the work-precision run's
    (`wp`, the S2 uniform series)."""
    loads = [r.get("load1", math.nan) for r in runs]
    t = ("Every run here is made once, on one thread (OMP_NUM_THREADS=1); 1-minute load "
         f"average {bc.load_range(loads)} when the runs started, on {os.cpu_count()} cores: "
         "the wall times are single runs and indicative, the errors and DOF counts exact.")
    known = [x for x in loads if math.isfinite(x)]
    if known and max(known) > (os.cpu_count() or 1):
        t += (f" **Wall times not final: load average up to {max(known):.1f} on "
              f"{os.cpu_count()} cores** (other programs were running).")
    wp_load = bc.load_range([r.get("load1", math.nan) for r in wp])
    t += (" S2 uniform wall times are those of the work-precision run (its own commit and "
          + ("load" if wp_load == "unknown" else
             f"load: single runs, one thread, load average {wp_load}")
          + "), the adaptive ones of this run.")
    return t


def write_fragment(prov, wp, ada, fruns, fada, frich, quick):
    lines = ["## Adaptive refinement beside uniform refinement (S2, strip footing)", "",
             f"`python3 -m pecplas_py.bench.adapt{' --quick' if quick else ''}` (commit "
             f"{prov['commit']}, {prov['date']}). " + timing_text(ada + fruns + fada, wp)
             + " Adaptive series: "
             "`pecplas DECK --target-error 1% --goal node:N:y` (footing: 0.2 %), every level a point at the "
             "wall time of the levels up to it. S2: head settlement at 2000 kN from the coarsest "
             "deck of the work-precision series (n = 3, 5 increments, full Newton); error against "
             "the model's Richardson reference of the work-precision table. Strip footing "
             "(Drucker-Prager, Q8, 10 m x 5 m half model, "
             f"{PRESSURE:g} kPa in 2 increments after a "
             "geostatic state): settlement of the footing centre; uniform series nx = "
             f"{', '.join(map(str, FOOTING_NX))} (nx x nx/2 elements), Richardson reference "
             f"{1e3 * frich['ref']:.4f} mm (observed order "
             f"{'none' if frich['p'] is None else format(frich['p'], '.2f')}, uncertainty "
             f"{frich['uncertainty'] / abs(frich['ref']):.1e}), adaptive from nx = 10. "
             "The wall times of the two kinds are not measured alike: an adaptive level's is "
             "the program's own time for that level (solve, estimate, results written), a "
             "uniform run's the whole process (start, deck read, solve, results) timed by the "
             "script; together with the different loads this makes the 'either' rows "
             "indicative only, while the DOF counts compare exactly. "
             "Data: `adapt.csv`.", "",
             "| scene | model | element | levels (DOFs) | value [mm] | error | estimate | "
             "wall [s] |", "|---|---|---|---|---|---|---|---|"]
    for scene, model, element, rs in _adaptive_groups(ada + fada):
        last = rs[-1]
        lines.append(f"| {scene} | {model} | {element} | "
                     f"{' '.join(str(r['dofs']) for r in rs)} | {1e3 * last['value']:.3f} | "
                     f"{100 * last['error']:.3f} % | {last['estimate']} % | {last['wall']:.1f} |")
    lines += ["", "Cheapest configuration within 1 % / 5 % (error: against the reference, never "
              "below the reference's own uncertainty; wall: the run, or for an adaptive level the "
              "levels up to it), among the uniform runs, the adaptive levels, and either:", "",
              "| case | tolerance | among | configuration | DOFs | error | wall [s] | |",
              "|---|---|---|---|---|---|---|---|"]
    groups = [(f"S2 {m} {e}", [r for r in wp + ada if (r["model"], r["element"]) == (m, e)
                                and r["method"] == "NEWTON" and r["series"] != "increments"])
              for m, e in S2_CASES if any((r["model"], r["element"]) == (m, e) for r in ada)]
    groups.append(("strip footing", fruns + fada))
    lines += table(groups)
    lines += ["", "![s2 work-precision with adaptive series](work_precision_s2.png)",
              "![strip footing work-precision](work_precision_footing.png)"]
    bc.write_fragment("adapt", "\n".join(lines))


def _adaptive_groups(rs):
    out = {}
    for r in rs:
        out.setdefault((r["scene"], r["model"], r["element"]), []).append(r)
    return [(*k, v) for k, v in out.items()]


if __name__ == "__main__":
    main()
