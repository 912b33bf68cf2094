#!/usr/bin/env python3
"""Adaptive refinement on the S2 pile (make bench): `pecplas DECK --target-error 1%
--goal node:1:y` from the coarsest deck of the work-precision series (tools/make_s2_decks.py,
level 3, first loading step to 2000 kN, full Newton), for the Mohr-Coulomb interface
(Q4/GOODMAN4 and Q8/GOODMAN6) and Katona contact (Q4). Each adaptive level is printed by the
program; this script compares the last level's head settlement with the model's Richardson
reference of doc/bench/work_precision.csv and finds the DOFs the uniform mesh series of that
file needs for the same error. Writes doc/bench/adapt.csv and the fragment adapt.md.
"""
import argparse
import csv
import re
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_common as bc                        # noqa: E402
import make_s2_decks as g2                       # noqa: E402
import wp_decks as wd                            # noqa: E402

CASES = [("mohr_coulomb", "Q4"), ("katona", "Q4"), ("mohr_coulomb", "Q8")]
LEVEL = re.compile(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$")


def deck_text(model, element):
    text = g2.deck(g2.Mesh(3), model, 3)
    text = wd.first_step_only(text, increments=5)
    text = wd.set_output_every(text, 10**6)
    text = wd.set_solver(text, "NEWTON")
    return wd.to_q8(text) if element == "Q8" else text


def uniform_rows(model, element):
    """(dofs, error) of the uniform mesh series of work_precision.csv, and the reference."""
    rows, ref = [], None
    with open(bc.BENCH_DIR / "work_precision.csv") as f:
        for r in csv.DictReader(f):
            if (r["scene"], r["model"], r["element"], r["series"]) != ("s2", model, element,
                                                                     "mesh"):
                continue
            if r["status"] != "ok" or "modified" in r["solver"]:
                continue
            rows.append((int(r["dofs"]), float(r["error"])))
            ref = float(r["reference_m"])
    return sorted(rows), ref


def run_case(exe, model, element, target, max_dofs):
    with tempfile.TemporaryDirectory() as tmp:
        deck = Path(tmp) / f"s2_{model}_{element}.inp"
        deck.write_text(deck_text(model, element))
        r = bc.run_timed([exe, str(deck), "--target-error", target, "--goal", "node:1:y",
                          "--max-dofs", str(max_dofs), "-o", str(Path(tmp) / "a.h5")])
    levels = [m.groups() for m in map(LEVEL.match, r["stdout"].splitlines()) if m]
    return r, [(int(g[1]), -float(g[4]), g[5], float(g[6])) for g in levels]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="the Q8 case only")
    ap.add_argument("--max-dofs", type=int, default=20000)
    args = ap.parse_args()
    exe = bc.executable()
    prov = bc.provenance()
    out = []
    for model, element in CASES[2:] if args.quick else CASES:
        r, levels = run_case(exe, model, element, "1%", args.max_dofs)
        uni, ref = uniform_rows(model, element)
        if not levels or ref is None:
            print(f"bench_adapt: {model} {element}: no levels or no reference", file=sys.stderr)
            continue
        dofs, value, est, _ = levels[-1]
        err = abs(value - ref) / ref
        need = next((d for d, e in uni if e <= err), None)
        need1 = next((d for d, e in uni if e <= 0.01), None)
        out.append(dict(model=model, element=element, levels=len(levels), dofs=dofs,
                        value_mm=1e3 * value, reference_mm=1e3 * ref, error=err,
                        estimate=est, met=r["rc"] == 0, wall_s=r["wall"],
                        uniform_dofs_same_error=need, uniform_dofs_1pct=need1,
                        sequence=" ".join(str(lv[0]) for lv in levels), **prov))
        print(f"{model} {element}: {len(levels)} levels, {dofs} DOFs, {1e3 * value:.3f} mm, "
              f"error {100 * err:.3f} % (uniform: {need} DOFs for it, {need1} for 1 %)")
    with open(bc.BENCH_DIR / "adapt.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out[0]))
        w.writeheader()
        w.writerows(out)
    lines = ["## Adaptive refinement (S2)", "",
             f"`python3 tools/bench_adapt.py` (commit {prov['commit']}, {prov['date']}): "
             "`pecplas DECK --target-error 1% --goal node:1:y` from the coarsest mesh of the "
             "work-precision series (n = 3), first loading step to 2000 kN; error of the head "
             "settlement against the model's Richardson reference (work-precision table above); "
             "uniform DOFs: the first level of the uniform series with an error no larger "
             "(none: no level of the series reaches it). Data: `adapt.csv`.", "",
             "| model | element | levels (DOFs) | settlement [mm] | reference [mm] | error | "
             "estimate | wall [s] | uniform DOFs, same error | uniform DOFs, 1 % |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for o in out:
        lines.append(f"| {o['model']} | {o['element']} | {o['sequence']} | "
                     f"{o['value_mm']:.3f} | {o['reference_mm']:.3f} | "
                     f"{100 * o['error']:.3f} % | {o['estimate']} % | {o['wall_s']:.1f} | "
                     f"{o['uniform_dofs_same_error'] or 'none'} | {o['uniform_dofs_1pct']} |")
    bc.write_fragment("adapt", "\n".join(lines))


if __name__ == "__main__":
    main()
