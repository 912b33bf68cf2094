"""Names, chart, advice table and summary fragments of the work-precision study
(bench/work_precision.py)."""
import math
import os

from pecplas_py.bench import common as bc
from pecplas_py.bench.wp_analysis import cheapest_within

S2_LOAD, Q_FIX = 2000.0, 2.83
SOLVER_NAME = {("NEWTON", False): "full Newton", ("MODIFIED_NEWTON", False): "modified Newton",
               ("NEWTON", True): "Katona, refactorised", ("MODIFIED_NEWTON", True):
               "Katona bordered"}
JOINT = {"goodman": "GOODMAN", "mohr_coulomb": "GOODMAN", "ghaboussi": "THIN_LAYER",
         "spring": "SPRING", "katona": "doublets", "modjoin": "GOODMAN",
         "modjoin_arc": "GOODMAN"}
# the scene's reference model, in order of preference (the next one when it has no reference)
SCENE_REF = {"s2": ("mohr_coulomb",), "s6": ("modjoin", "mohr_coulomb")}


def timing_text(loads):
    """What the wall times of the study are: single runs on one thread, the load range when
    they started; the errors do not depend on them."""
    t = ("Every configuration runs once, on one thread (OMP_NUM_THREADS=1); 1-minute load "
         f"average {bc.load_range(loads)} when the runs started, on {os.cpu_count()} cores. "
         "The wall times are single runs, so they are indicative (a rerun moves them by the "
         "machine's run-to-run spread, more on a loaded machine); the errors are exact: a "
         "rerun gives the same values whatever the machine or its load.")
    known = [x for x in loads if x is not None and math.isfinite(x)]
    if known and max(known) > (os.cpu_count() or 1):
        t += (f" **Wall times not final: load average up to {max(known):.1f} on "
              f"{os.cpu_count()} cores** (other programs were running).")
    return t


def label(r, short=False):
    joint = JOINT[r["model"]]
    if joint in ("GOODMAN", "THIN_LAYER"):
        joint += "6" if r["element"] == "Q8" else "4"
    solver = SOLVER_NAME[r["method"], r["model"] == "katona"]
    if short:
        return f"{r['scene']}_{r['model']}_{r['element']}_{r['method']}".lower()
    return f"{r['model']} {r['element']}/{joint}, {solver}"


def plot(runs, scene, path, tols=(0.01, 0.05)):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8.5, 6))
    fams = {}
    for r in runs:
        if r["scene"] == scene and r["status"] == "ok" and math.isfinite(r["error"]):
            name = label(r) if r["scene"] in ("s2", "s6") else f"{r['model']} {r['element']}"
            fams.setdefault((name, r["series"]), []).append(r)
    for i, ((name, series), rs) in enumerate(sorted(fams.items())):
        key = "increments" if series == "increments" else "level"
        rs.sort(key=lambda r: r[key])
        x = [r["wall"] for r in rs]
        # an error below the reference's own uncertainty is not resolved: drawn hollow at
        # that uncertainty (the finest level of a series is the reference's source)
        y = [r["error"] if r["resolved"] else r["floor"] for r in rs]
        colour = plt.cm.tab20(i % 20)   # up to 20 families with their own colour
        mk = {"mesh": "o", "increments": "s", "adaptive": "^"}[series]
        hollow = [(xi, yi) for r, xi, yi in zip(rs, x, y) if not r["resolved"]]
        if hollow:
            ax.loglog(*zip(*hollow), mk, mfc="none", color=colour, ms=7)
        style = {"mesh": "-o", "increments": "--s", "adaptive": "-.^"}[series]
        ax.loglog(x, y, style, color=colour, ms=4, lw=1.8 if series == "adaptive" else 1.0,
                  label=name + {"mesh": " (mesh levels)", "adaptive": " (adaptive levels)"}.get(
                      series, f" (increments, n={rs[0]['level']})"))
        for r, xi, yi in zip(rs, x, y):
            ax.annotate(str(r[key]), (xi, yi), fontsize=6, color=colour,
                        xytext=(2, 2), textcoords="offset points")
    for t in tols:
        ax.axhline(t, color="grey", lw=0.7, ls=":")
    ax.set_xlabel("wall time [s]")
    what = {"s2": "head settlement at 2000 kN", "footing": "footing settlement"}.get(
        scene, f"head uplift at {Q_FIX} kN")
    ax.set_ylabel(f"relative error of the {what}")
    ax.set_title(f"{'Strip footing' if scene == 'footing' else scene.upper()} work-precision "
                 "(labels: mesh n, adaptive level or increments)")
    ax.legend(fontsize=6, loc="lower left")
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def advice(runs, scene_model, tols=(0.01, 0.05)):
    """Rows (scene, scope, tolerance, configuration, ...) of the cheapest runs."""
    rows = []
    for scene in sorted({r["scene"] for r in runs}):
        sr = [r for r in runs if r["scene"] == scene and r["status"] == "ok"]
        scopes = [("scene", f"vs {scene_model[scene]} reference", "scene_error", sr)]
        scopes += [(m, "vs own model reference", "error_bound",
                    [r for r in sr if r["model"] == m])
                   for m in sorted({r["model"] for r in sr})]
        for scope, against, key, rs in scopes:
            for t in tols:
                b = cheapest_within(rs, t, error_key=key)
                none = ("none within tolerance" if any(math.isfinite(r[key]) for r in rs)
                        else "no reference (fewer than 3 mesh levels completed)")
                rows.append([scene, scope, against, t] + (
                    [label(b), b["level"], b["dofs"], b["increments"], f"{b[key]:.2e}",
                     f"{b['wall']:.3f}", f"{b.get('load1', math.nan):.2f}"] if b else
                    [none, "", "", "", "", "", ""]))
    return rows


def write_fragments(runs, refs, adv, quick, scenes, scene_model):
    prov = bc.provenance()
    ok = [r for r in runs if r["status"] == "ok"]
    timing = timing_text([r.get("load1", math.nan) for r in runs
                          if not r["status"].startswith("skipped")])
    md = ["## Work-precision (S2, S6)", "",
          f"`python3 -m pecplas_py.bench.work_precision{' --quick' if quick else ''}` (commit "
          f"{prov['commit']}, {prov['date']}): {len(ok)} of {len(runs)} runs completed, "
          f"{sum(r['wall'] for r in ok):.0f} s of runs. S2: head settlement at 2000 kN (end of "
          f"loading, unloading not run); S6: head uplift at {Q_FIX} kN (a load below every "
          "model's limit). Error: against the model's own Richardson reference (Q4 mesh "
          "series, three finest levels, 10 increments); hollow markers: error below the "
          "reference's own uncertainty, drawn at that uncertainty. " + timing, "",
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
          "tolerance; where two configurations' wall times differ by less than the machine's "
          "run-to-run spread, the pick between them is indicative. " + timing +
          " Scope `scene`: against the scene's reference model (" +
          ", ".join(f"{s.upper()}: {m}" for s, m in ref_of.items()) + "), as the bound "
          "discretisation error + the distance between the model's and the scene model's "
          "references, so another model qualifies only if its own limit is close; scope = a "
          "model: against that model's own reference (discretisation only). The error used is "
          "never below the reference's own uncertainty (an error the reference cannot resolve "
          "is not claimed), so a model whose reference is uncertain by more than the "
          "tolerance has no configuration within it.", ""]
    for s in scenes:
        if SCENE_REF[s][0] != scene_model[s]:
            ad.append(f"- {s.upper()}: the preferred scene model {SCENE_REF[s][0]} has no "
                      f"reference (fewer than three mesh levels completed), "
                      f"{scene_model[s]} stands in.")
    ad += ["", "| scene | scope | tolerance | configuration | n | DOFs | increments | error | "
           "wall [s] |", "|---|---|---|---|---|---|---|---|---|"]
    for s, scope, _, t, conf, n, dofs, inc, err, wall, _ in adv:
        ad.append(f"| {s} | {scope} | {t:.0%} | {conf} | {n} | {dofs} | {inc} | {err} | "
                  f"{wall} |")
    bc.write_fragment("advice", "\n".join(ad))


def _groups(runs, series):
    out = {}
    for r in sorted(runs, key=lambda r: r["increments"]):
        if r["series"] == series:
            out.setdefault((r["scene"], r["model"], r["element"], r["method"]), []).append(r)
    return out
