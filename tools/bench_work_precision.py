#!/usr/bin/env python3
"""Work-precision study of scenes S2 (pile, head load 2000 kN) and S6 (pull-out, 2.83 kN):
error of the head settlement at a fixed load against a Richardson-extrapolated reference,
versus wall time, for interface model x joint element x solver x mesh level x increments.

The decks come from the scene generators (tools/make_s2_decks.py, tools/make_s6_decks.py)
with only the studied knobs edited (tools/wp_decks.py): the loading step alone (S2: 0 ->
2000 kN; S6: 0 -> Q_FIX, a load every model reaches before its limit), its increments, the
solver method, Q4 or Q8 (GOODMAN6 / 6-node thin layer), fields written at the step end only.

Reference per interface model: Richardson extrapolation (tools/wp_analysis.py) of the Q4 mesh
series at the base increments, three finest levels it completed; the observed order p is
printed. Errors: `error` against the run's own model reference (discretisation error: the
work-precision charts), `scene_error` against the scene's reference model (S2 Mohr-Coulomb
Goodman joints, S6 MODJOIN: model + discretisation error: the advice table).

Runs are made cheapest first; a run whose estimated time would overflow the budget is skipped
(and listed), so full mode keeps to --budget seconds (default 660, plus the runs' set-up).

    python3 tools/bench_work_precision.py [--quick] [--budget SECONDS] [--scenes s2,s6]
Writes doc/bench/work_precision.csv, work_precision_s2.png, work_precision_s6.png,
advice.csv and the fragments work_precision.md, advice.md.
"""
import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common as bc                      # noqa: E402
import make_s2_decks as g2                     # noqa: E402
import make_s6_decks as g6                     # noqa: E402
import s2_results                              # noqa: E402
import s6_results                              # noqa: E402
import wp_decks as wd                          # noqa: E402
from wp_analysis import cheapest_within, relative_error, richardson   # noqa: E402

S2_LOAD, Q_FIX = 2000.0, 2.83
# seconds per (DOF x increment), measured on this code (a rough guide for ordering and budget)
RATE = {"NEWTON": 2.0e-5, "MODIFIED_NEWTON": 3.0e-4, "KATONA": 7.0e-6, "MODJOIN": 4.0e-5}
SOLVER_NAME = {("NEWTON", False): "full Newton", ("MODIFIED_NEWTON", False): "modified Newton",
               ("NEWTON", True): "Katona, refactorised", ("MODIFIED_NEWTON", True):
               "Katona bordered"}
JOINT = {"goodman": "GOODMAN", "mohr_coulomb": "GOODMAN", "ghaboussi": "THIN_LAYER",
         "spring": "SPRING", "katona": "doublets", "modjoin": "GOODMAN"}
# the scene's reference model, in order of preference (the next one when it has no reference)
SCENE_REF = {"s2": ("mohr_coulomb",), "s6": ("modjoin", "mohr_coulomb")}


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
            add("s6", "mohr_coulomb", "Q8", "NEWTON", n, incs, "mesh")
        if n <= lv6[1]:
            add("s6", "mohr_coulomb", "Q4", "MODIFIED_NEWTON", n, incs, "mesh")
            add("s6", "modjoin", "Q4", "MODIFIED_NEWTON", n, incs, "mesh")
    for k in inc_study:
        for model in ("spring", "mohr_coulomb", "katona"):
            add("s2", model, "Q4", "MODIFIED_NEWTON" if model == "katona" else "NEWTON",
                mid2, k, "increments")
        for model in ("mohr_coulomb", "modjoin"):
            add("s6", model, "Q4", "NEWTON", mid6, k, "increments")
    return runs


def make_deck(r):
    """Deck text of a configuration, from the scene generator."""
    if r["scene"] == "s2":
        text = g2.deck(g2.Mesh(r["level"]), r["model"], r["level"])
        text = wd.first_step_only(text, increments=r["increments"])
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


def estimate(r):
    kind = ("KATONA" if r["model"] == "katona" else
            "MODJOIN" if r["model"] == "modjoin" and r["method"] == "NEWTON" else r["method"])
    return 0.05 + RATE[kind] * r["dofs"] * r["increments"]


def settlement(r, h5):
    """Head settlement (S2, downwards) or uplift (S6) [m] at the end of the loading step,
    None if the run did not reach the fixed load."""
    if r["scene"] == "s2":
        load, s, _ = s2_results.head_curve(h5)
        target = S2_LOAD
    else:
        load, s = s6_results.head_curve(h5)
        target = Q_FIX
    return float(s[-1]) if abs(load[-1] - target) < 1e-6 * target else None


def run_all(runs, exe, budget, workdir):
    t_start, scale, failed = time.perf_counter(), 1.0, {}
    for r in sorted(runs, key=estimate):
        used = time.perf_counter() - t_start
        est = estimate(r) * scale
        r.update(wall=float("nan"), value=None, status="skipped", peak_mb=float("nan"))
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


def label(r, short=False):
    joint = JOINT[r["model"]]
    if joint in ("GOODMAN", "THIN_LAYER"):
        joint += "6" if r["element"] == "Q8" else "4"
    solver = SOLVER_NAME[r["method"], r["model"] == "katona"]
    if short:
        return f"{r['scene']}_{r['model']}_{r['element']}_{r['method']}".lower()
    return f"{r['model']} {r['element']}/{joint}, {solver}"


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


def plot(runs, scene, path, tols=(0.01, 0.05)):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8.5, 6))
    fams = {}
    for r in runs:
        if r["scene"] == scene and r["status"] == "ok" and math.isfinite(r["error"]):
            fams.setdefault((label(r), r["series"]), []).append(r)
    for i, ((name, series), rs) in enumerate(sorted(fams.items())):
        key = "level" if series == "mesh" else "increments"
        rs.sort(key=lambda r: r[key])
        x = [r["wall"] for r in rs]
        # an error below the reference's own uncertainty is not resolved: drawn hollow at
        # that uncertainty (the finest level of a series is the reference's source)
        y = [r["error"] if r["resolved"] else r["floor"] for r in rs]
        colour = f"C{i % 10}"
        mk = "o" if series == "mesh" else "s"
        hollow = [(xi, yi) for r, xi, yi in zip(rs, x, y) if not r["resolved"]]
        if hollow:
            ax.loglog(*zip(*hollow), mk, mfc="none", color=colour, ms=7)
        ax.loglog(x, y, "-o" if series == "mesh" else "--s", color=colour, ms=4,
                  label=name + (" (mesh levels)" if series == "mesh"
                                else f" (increments, n={rs[0]['level']})"))
        for r, xi, yi in zip(rs, x, y):
            ax.annotate(str(r[key]), (xi, yi), fontsize=6, color=colour,
                        xytext=(2, 2), textcoords="offset points")
    for t in tols:
        ax.axhline(t, color="grey", lw=0.7, ls=":")
    ax.set_xlabel("wall time [s]")
    what = "head settlement at 2000 kN" if scene == "s2" else f"head uplift at {Q_FIX} kN"
    ax.set_ylabel(f"relative error of the {what}")
    ax.set_title(f"{scene.upper()} work-precision (labels: mesh refinement n or increments)")
    ax.legend(fontsize=6, loc="lower left")
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def advice(runs, scene_model, tols=(0.01, 0.05)):
    """Rows (scene, scope, tolerance, configuration, ...) of the cheapest runs."""
    rows = []
    for scene in ("s2", "s6"):
        sr = [r for r in runs if r["scene"] == scene and r["status"] == "ok"]
        scopes = [("scene", f"vs {scene_model[scene]} reference", "scene_error", sr)]
        scopes += [(m, "vs own model reference", "error", [r for r in sr if r["model"] == m])
                   for m in sorted({r["model"] for r in sr})]
        for scope, against, key, rs in scopes:
            for t in tols:
                b = cheapest_within(rs, t, error_key=key)
                none = ("none within tolerance" if any(math.isfinite(r[key]) for r in rs)
                        else "no reference (fewer than 3 mesh levels completed)")
                rows.append([scene, scope, against, t] + (
                    [label(b), b["level"], b["dofs"], b["increments"], f"{b[key]:.2e}",
                     f"{b['wall']:.3f}"] if b else [none, "", "", "", "", ""]))
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="coarse levels only (~1-2 min)")
    ap.add_argument("--budget", type=float, default=None,
                    help="seconds of runs (default 660, quick 90)")
    ap.add_argument("--scenes", default="s2,s6")
    a = ap.parse_args()
    budget = a.budget or (90.0 if a.quick else 660.0)
    scenes = a.scenes.split(",")
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
        r["scene_error"] = (r["error"] + relative_error(own["ref"], sc["ref"])
                            if own and sc else float("nan"))
    header = ["scene", "model", "element", "joint", "solver", "series", "level", "dofs",
              "increments", "status", "wall_s", "peak_mb", "value_m", "reference_m", "p",
              "error", "scene_error_bound"]
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
                     f"{r['error']:.3e}", f"{r['scene_error']:.3e}"])
    bc.write_csv(bc.BENCH_DIR / "work_precision.csv", header, rows)
    for s in scenes:
        plot(runs, s, bc.BENCH_DIR / f"work_precision_{s}.png")
    adv = advice([r for r in runs if r["scene"] in scenes], scene_model)
    ah = ["scene", "scope", "against", "tolerance", "configuration", "level", "dofs",
          "increments", "error", "wall_s"]
    bc.write_csv(bc.BENCH_DIR / "advice.csv", ah, adv)
    write_fragments(runs, refs, adv, a.quick, scenes, scene_model)


def write_fragments(runs, refs, adv, quick, scenes, scene_model):
    prov = bc.provenance()
    ok = [r for r in runs if r["status"] == "ok"]
    md = ["## Work-precision (S2, S6)", "",
          f"`python3 tools/bench_work_precision.py{' --quick' if quick else ''}` (commit "
          f"{prov['commit']}, {prov['date']}): {len(ok)} of {len(runs)} runs completed, "
          f"{sum(r['wall'] for r in ok):.0f} s of runs. S2: head settlement at 2000 kN (end of "
          f"loading, unloading not run); S6: head uplift at {Q_FIX} kN (a load below every "
          "model's limit). Error: against the model's own Richardson reference (Q4 mesh "
          "series, three finest levels, 10 increments); hollow markers: error below the "
          "reference's own uncertainty, drawn at that uncertainty.", "",
          "| scene | model | element | reference [mm] | observed order p | levels (n) | "
          "uncertainty |", "|---|---|---|---|---|---|---|"]
    for (scene, model), ref in sorted(refs.items()):
        lv = ", ".join(f"{1 / h:.0f}" for h in ref["levels"])
        p = f"{ref['p']:.2f}" if ref["p"] is not None else "none (non-monotone): finest used"
        md.append(f"| {scene} | {model} | {ref['element']} | {ref['ref'] * 1e3:.4f} | {p} | "
                  f"{lv} | {ref['uncertainty'] / abs(ref['ref']):.1e} |")
    md.append("")
    for (scene, model, el, method), rs in sorted(_groups(ok, "increments").items()):
        v = [r["value"] for r in rs]
        spread = (max(v) - min(v)) / abs(v[-1])
        md.append(f"- Increments ({scene}, {model}, {el}, {method}, n = {rs[0]['level']}): "
                  f"{', '.join(str(r['increments']) for r in rs)} increments change the "
                  f"value by at most {spread:.1e} (relative).")
    bad = [r for r in runs if r["status"] != "ok"]
    if bad:
        md += ["", "Not completed: " + "; ".join(
            f"{label(r)} n={r['level']} inc={r['increments']} ({r['status']})" for r in bad)]
    md += ["", *(f"![{s} work-precision](work_precision_{s}.png)" for s in scenes)]
    bc.write_fragment("work_precision", "\n".join(md))
    ref_of = {s: scene_model[s] or "none" for s in scenes}
    ad = ["## Model no more than a scene needs", "",
          "Cheapest completed run (wall time, measured in the run) whose error is below the "
          "tolerance. Scope `scene`: against the scene's reference model (" +
          ", ".join(f"{s.upper()}: {m}" for s, m in ref_of.items()) + "), as the bound "
          "discretisation error + the distance between the model's and the scene model's "
          "references, so another model qualifies only if its own limit is close; scope = a "
          "model: against that model's own reference (discretisation only).", ""]
    for s in scenes:
        if SCENE_REF[s][0] != scene_model[s]:
            ad.append(f"- {s.upper()}: the preferred scene model {SCENE_REF[s][0]} has no "
                      f"reference (fewer than three mesh levels completed), "
                      f"{scene_model[s]} stands in.")
    ad += ["", "| scene | scope | tolerance | configuration | n | DOFs | increments | error | "
           "wall [s] |", "|---|---|---|---|---|---|---|---|---|"]
    for s, scope, _, t, conf, n, dofs, inc, err, wall in adv:
        ad.append(f"| {s} | {scope} | {t:.0%} | {conf} | {n} | {dofs} | {inc} | {err} | "
                  f"{wall} |")
    bc.write_fragment("advice", "\n".join(ad))


def _groups(runs, series):
    out = {}
    for r in sorted(runs, key=lambda r: r["increments"]):
        if r["series"] == series:
            out.setdefault((r["scene"], r["model"], r["element"], r["method"]), []).append(r)
    return out


if __name__ == "__main__":
    main()
