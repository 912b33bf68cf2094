#!/usr/bin/env python3
"""Work-precision study of scenes S2 (pile, head load 2000 kN) and S6 (pull-out, 2.83 kN):
error of the head settlement at a fixed load against a Richardson-extrapolated reference,
versus wall time, for interface model x joint element x solver x mesh level x increments.

The decks come from the scene generators (decks/make_s2_decks.py, decks/make_s6_decks.py)
with only the studied knobs edited (bench/wp_decks.py): the loading step alone (S2: 0 ->
2000 kN; S6: 0 -> Q_FIX, a load every model reaches before its limit), its increments, the
solver method, Q4 or Q8 (GOODMAN6 / 6-node thin layer), fields written at the step end only.

Reference per interface model: Richardson extrapolation (bench/wp_analysis.py) of the Q4 mesh
series at the base increments, three finest levels it completed; the observed order p is
printed. Errors: `error` against the run's own model reference (discretisation error: the
work-precision charts), `scene_error` against the scene's reference model (S2 Mohr-Coulomb
Goodman joints, S6 MODJOIN: model + discretisation error: the advice table).

Runs are made cheapest first; a run whose estimated time would overflow the budget is skipped
(and listed), so full mode keeps to --budget seconds (default 660, plus the runs' set-up).
Every configuration runs once, on one thread (OMP_NUM_THREADS=1), with the 1-minute load
average recorded when it starts: the wall times are single runs (indicative), the errors exact.

    python3 -m pecplas_py.bench.work_precision [--quick] [--budget SECONDS] [--scenes s2,s6]
Writes doc/bench/work_precision.csv, work_precision_s2.png, work_precision_s6.png,
advice.csv and the fragments work_precision.md, advice.md.
"""
import argparse
import math
import re
import tempfile
import time
from pathlib import Path

from pecplas_py.bench import common as bc
from pecplas_py.bench import wp_decks as wd
from pecplas_py.bench.wp_analysis import relative_error, richardson
from pecplas_py.bench.wp_report import (Q_FIX, S2_LOAD, SCENE_REF, advice, label, plot,
                                        write_fragments)
from pecplas_py.decks import make_s2_decks as g2
from pecplas_py.decks import make_s6_decks as g6
from pecplas_py.scenes import s2_results
from pecplas_py.scenes import s6_results

# seconds per DOF for 10 increments, measured on this code on 2 shared cores (full mode,
# machine busy); Newton's cost grows about as sqrt(increments): fewer iterations each
RATE = {"NEWTON": 4.0e-5, "MODIFIED_NEWTON": 3.5e-4, "KATONA": 2.0e-5, "MODJOIN": 4.0e-5}
def plan(quick):
    """List of run configurations (dicts)."""
    runs = []

    def add(scene, model, element, method, level, incs, series):
        runs.append(dict(scene=scene, model=model, element=element, method=method,
                         level=level, increments=incs, series=series))
    if quick:
        lv2, lv6, mid2, mid6, incs, inc_study = (1, 2, 4, 8), (1, 2, 4), 2, 2, 10, (5, 20)
    else:
        lv2, lv6, mid2, mid6, incs, inc_study = ((3, 6, 12, 24, 48), (2, 3, 6, 12, 24), 12, 6,
                                                 10, (5, 20, 40))
    for n in lv2:
        for model in ("spring", "goodman", "ghaboussi", "mohr_coulomb", "katona"):
            if n == lv2[-1] and model not in ("mohr_coulomb", "katona"):
                continue       # the finest level only for the scene reference and Katona
            add("s2", model, "Q4", "MODIFIED_NEWTON" if model == "katona" else "NEWTON",
                n, incs, "mesh")
        if n <= lv2[1]:       # modified Newton with stiff penalty joints: hundreds of its/inc
            add("s2", "mohr_coulomb", "Q4", "MODIFIED_NEWTON", n, incs, "mesh")
        if n <= lv2[2]:
            add("s2", "katona", "Q4", "NEWTON", n, incs, "mesh")
            for model in ("mohr_coulomb", "ghaboussi"):
                add("s2", model, "Q8", "NEWTON", n, incs, "mesh")
    for n in lv6:
        add("s6", "mohr_coulomb", "Q4", "NEWTON", n, incs, "mesh")
        if n <= lv6[2]:
            add("s6", "modjoin", "Q4", "NEWTON", n, incs, "mesh")
            # the same pull under force control with arc-length (past the early local peak)
            add("s6", "modjoin_arc", "Q4", "NEWTON", n, incs, "mesh")
            add("s6", "mohr_coulomb", "Q8", "NEWTON", n, incs, "mesh")
        if n <= lv6[1]:
            add("s6", "mohr_coulomb", "Q4", "MODIFIED_NEWTON", n, incs, "mesh")
            add("s6", "modjoin", "Q4", "MODIFIED_NEWTON", n, incs, "mesh")
    for k in inc_study:
        for model in ("spring", "mohr_coulomb", "katona"):
            add("s2", model, "Q4", "MODIFIED_NEWTON" if model == "katona" else "NEWTON",
                mid2, k, "increments")
        for model in ("mohr_coulomb", "modjoin", "modjoin_arc"):
            add("s6", model, "Q4", "NEWTON", mid6, k, "increments")
    return runs


def make_deck(r):
    """Deck text of a configuration, from the scene generator."""
    if r["scene"] == "s2":
        text = g2.deck(g2.Mesh(r["level"]), r["model"], r["level"])
        text = wd.first_step_only(text, increments=r["increments"])
    elif r["model"] == "modjoin":
        # imposed head uplift (the pull is the reaction; make_s6_decks.py says why): the run
        # goes to 8 mm uplift (2.83 kN is carried near 5 mm) with every increment written, and
        # the uplift at Q_FIX is interpolated on the rising branch (s6_results.uplift_at)
        text = g6.deck(g6.Mesh(r["level"]), r["model"], r["level"])
        return wd.set_solver(wd.scale_steps(text, r["increments"] / 10.0, last_target=0.2,
                                            last_increments=15), r["method"],
                             5000 if r["method"] == "MODIFIED_NEWTON" else None)
    elif r["model"] == "modjoin_arc":
        text = modjoin_arc_deck(r)
    else:
        text = g6.deck(g6.Mesh(r["level"]), r["model"], r["level"])
        text = wd.first_step_only(text, factor=Q_FIX / g6.Q_END, increments=r["increments"])
    text = wd.set_output_every(text, 10**6)
    # modified Newton: the stiff joints need hundreds of iterations per increment
    text = wd.set_solver(text, r["method"],
                         5000 if r["method"] == "MODIFIED_NEWTON" else None)
    if r["element"] == "Q8":
        text = wd.to_q8(text)
    return text


def modjoin_arc_deck(r):
    """S6 MODJOIN pulled by the Mohr-Coulomb deck's head pressure to Q_FIX under arc-length
    control (doc/theory.md §4): the path passes the early local peak of the load-uplift curve
    that stops plain force control, and the step lands on Q_FIX exactly."""
    mesh = g6.Mesh(r["level"])
    text = g6.deck(mesh, "modjoin", r["level"])
    pull = re.search(r"\*LOAD, NAME=pull, TYPE=PRESSURE\nhead, [-0-9.e+]+\n",
                     g6.deck(mesh, "mohr_coulomb", r["level"])).group(0)
    i, j = text.index("*LOAD, NAME=pull, TYPE=DISPLACEMENT"), text.index("*SOLVER")
    return (text[:i] + pull + f"*STEP, NAME=pull, INCREMENTS={r['increments']}, "
            f"CONTROL=ARC_LENGTH, MAX_INCREMENTS={40 * r['increments']}\n"
            f"pull, {Q_FIX / g6.Q_END!r}\n" + text[j:])


def estimate(r):
    kind = ("KATONA" if r["model"] == "katona" else
            "MODJOIN" if r["model"] in ("modjoin", "modjoin_arc") and r["method"] == "NEWTON"
            else r["method"])
    return 0.05 + RATE[kind] * r["dofs"] * 10.0 * math.sqrt(r["increments"] / 10.0)


def settlement(r, h5):
    """Head settlement (S2, downwards) or uplift (S6) [m] at the end of the loading step,
    None if the run did not reach the fixed load."""
    if r["scene"] == "s2":
        load, s, _ = s2_results.head_curve(h5)
        target = S2_LOAD
    elif r["model"] == "modjoin":
        u = s6_results.uplift_at(h5, Q_FIX)
        return None if math.isnan(u) else float(u)
    else:
        load, s = s6_results.head_curve(h5)
        target = Q_FIX
    return float(s[-1]) if abs(load[-1] - target) < 1e-6 * target else None


def run_all(runs, exe, budget, workdir):
    t_start, scale, failed = time.perf_counter(), 1.0, {}
    for r in sorted(runs, key=estimate):
        used = time.perf_counter() - t_start
        est = estimate(r) * scale
        r.update(wall=float("nan"), value=None, status="skipped", peak_mb=float("nan"),
                 load1=float("nan"))
        key = (r["scene"], r["model"], r["element"], r["method"])
        if r["level"] >= failed.get(key, math.inf):
            r["status"] = "skipped (coarser level failed)"
            print(f"  skip {label(r)} n={r['level']} inc={r['increments']}: failed at "
                  f"n={failed[key]}")
            r.pop("text")
            continue
        if used + est > budget:
            print(f"  skip {label(r)} n={r['level']} inc={r['increments']}: estimated "
                  f"{est:.0f} s, {budget - used:.0f} s left")
            r.pop("text")
            continue
        deck = Path(workdir) / f"{label(r, short=True)}_{r['level']}_{r['increments']}.inp"
        deck.write_text(r.pop("text"))
        h5 = deck.with_suffix(".h5")
        timeout = max(10.0, min(4.0 * est, budget - used))
        r["load1"] = bc.load1()
        res = bc.run_timed([exe, deck, "-o", h5, "--quiet"], timeout=timeout)
        r.update(wall=res["wall"], peak_mb=res["peak_mb"])
        if res["rc"] == 0:
            r["value"] = settlement(r, h5)
        r["status"] = ("ok" if r["value"] is not None else
                       "timeout" if res["rc"] is None else f"failed rc={res['rc']}")
        if r["status"] != "ok":
            failed[key] = min(failed.get(key, math.inf), r["level"])
        if r["status"] == "ok" and res["wall"] > 1.0:   # learn the machine's speed
            scale = 0.5 * scale + 0.5 * res["wall"] / estimate(r)
        print(f"  {res['wall']:7.2f} s  {label(r):42s} n={r['level']:<3d} dofs={r['dofs']:<7d}"
              f" inc={r['increments']:<3d} {r['status']:8s} "
              + (f"{r['value']:.6e}" if r["value"] is not None else ""), flush=True)
        for p in (deck, h5, h5.with_suffix(".xdmf")):
            p.unlink(missing_ok=True)


def references(runs, base_incs):
    """Per (scene, model): Richardson over the Q4 mesh series (the solver reaching the finest
    level), and a check series (Q8) where present."""
    refs = {}
    for scene in ("s2", "s6"):
        for model in sorted({r["model"] for r in runs if r["scene"] == scene}):
            best = None
            for el in ("Q4", "Q8"):
                for method in ("NEWTON", "MODIFIED_NEWTON"):
                    pts = {r["level"]: r["value"] for r in runs
                           if (r["scene"], r["model"], r["element"], r["method"]) ==
                           (scene, model, el, method) and r["series"] == "mesh"
                           and r["value"] is not None and r["increments"] == base_incs}
                    if len(pts) < 3:
                        continue
                    lv = sorted(pts)
                    rich = richardson([1.0 / n for n in lv], [pts[n] for n in lv])
                    rich.update(element=el, method=method, finest=lv[-1])
                    p = f"{rich['p']:.2f}" if rich["p"] is not None else "n/a (non-monotone)"
                    print(f"  {scene} {model:13s} {el} {method:16s} levels {lv[-3:]}: "
                          f"ref {rich['ref']:.6e} m, p = {p}, uncertainty "
                          f"{rich['uncertainty'] / abs(rich['ref']):.2e}")
                    if el == "Q4" and (best is None or lv[-1] > best["finest"]):
                        best = rich
            if best is not None:
                refs[scene, model] = best
    return refs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="coarse levels only (~1-2 min)")
    ap.add_argument("--budget", type=float, default=None,
                    help="seconds of runs (default 660, quick 90)")
    ap.add_argument("--scenes", default="s2,s6")
    a = ap.parse_args()
    budget = a.budget or (90.0 if a.quick else 660.0)
    scenes = a.scenes.split(",")
    bc.one_thread()
    exe = bc.executable("pecplas")
    runs = [r for r in plan(a.quick) if r["scene"] in scenes]
    for r in runs:
        r["text"] = make_deck(r)
        r["dofs"] = wd.count_dofs(r["text"])
    total = sum(estimate(r) for r in runs)
    print(f"work-precision: {len(runs)} runs, estimated {total:.0f} s at the nominal speed "
          f"(budget {budget:.0f} s: runs that would overflow it are skipped)", flush=True)
    with tempfile.TemporaryDirectory() as wdir:
        run_all(runs, exe, budget, wdir)
    base = 10
    print("references (Richardson over the three finest levels):")
    refs = references(runs, base)
    scene_model = {s: next((m for m in SCENE_REF[s] if (s, m) in refs), None)
                   for s in ("s2", "s6")}
    for r in runs:
        own = refs.get((r["scene"], r["model"]))
        sc = refs.get((r["scene"], scene_model[r["scene"]]))
        r["error"] = relative_error(r["value"], own["ref"]) if own else float("nan")
        r["floor"] = own["uncertainty"] / abs(own["ref"]) if own else float("nan")
        r["resolved"] = own is not None and r["error"] > own["uncertainty"] / abs(own["ref"])
        # against the scene's model: a bound, discretisation error + the model's offset (the
        # distance between the two references), so that a coarse run of another model does
        # not qualify by crossing the reference on its way to its own limit
        # the advice never claims an error below what the reference resolves: the bound is
        # max(error, the reference's own uncertainty)
        r["error_bound"] = max(r["error"], r["floor"]) if own else float("nan")
        r["scene_error"] = (r["error_bound"] + relative_error(own["ref"], sc["ref"])
                            if own and sc else float("nan"))
    header = ["scene", "model", "element", "joint", "solver", "series", "level", "dofs",
              "increments", "status", "wall_s", "peak_mb", "value_m", "reference_m", "p",
              "error", "scene_error_bound", "load1"]
    rows = []
    for r in sorted(runs, key=lambda r: (r["scene"], label(r), r["series"], r["level"],
                                         r["increments"])):
        ref = refs.get((r["scene"], r["model"]))
        rows.append([r["scene"], r["model"], r["element"], label(r).split("/")[1].split(",")[0],
                     label(r).split(", ", 1)[1], r["series"], r["level"], r["dofs"],
                     r["increments"], r["status"], f"{r['wall']:.4f}", f"{r['peak_mb']:.1f}",
                     "" if r["value"] is None else f"{r['value']:.9e}",
                     f"{ref['ref']:.9e}" if ref else "",
                     f"{ref['p']:.3f}" if ref and ref["p"] is not None else "",
                     f"{r['error']:.3e}", f"{r['scene_error']:.3e}", f"{r['load1']:.2f}"])
    bc.write_csv(bc.BENCH_DIR / "work_precision.csv", header, rows)
    for s in scenes:
        plot(runs, s, bc.BENCH_DIR / f"work_precision_{s}.png")
    adv = advice([r for r in runs if r["scene"] in scenes], scene_model)
    ah = ["scene", "scope", "against", "tolerance", "configuration", "level", "dofs",
          "increments", "error", "wall_s", "load1"]
    bc.write_csv(bc.BENCH_DIR / "advice.csv", ah, adv)
    write_fragments(runs, refs, adv, a.quick, scenes, scene_model)


if __name__ == "__main__":
    main()
