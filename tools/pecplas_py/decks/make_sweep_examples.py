#!/usr/bin/env python3
"""The example sweeps of input/sweeps/ (doc/sweep.md), generated from the scene decks:

- s6_table_iv1: the thesis's table IV.1 study (scene S6, pile pull-out with MODJOIN, initial
  version): the reference set of table III.1 and G0, K0, beta, a_g each +50 %, one at a time.
  Template = input/s6/s6_modjoin.inp with the four values as placeholders; table.csv.
- s2_mesh: the S2 pile (Goodman interface) on the mesh refined 1, 2 and 3 times: the mesh
  part of each deck (nodes, elements, joint elements, node and edge sets) in mesh_rN.inp,
  the rest in template.inp, which includes mesh_r{{REFINE}}.inp; table.csv.

    python3 -m pecplas_py.decks.make_sweep_examples [--out input/sweeps]
"""
import argparse
import csv
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.decks import make_s2_decks
from pecplas_py.decks import make_s6_decks

MESH_KEYWORDS = ("*NODES", "*ELEMENTS", "*JOINTS", "*NSET", "*EDGES")
S2_REFINES = (1, 2, 3)
IV1 = ("K0", "G0", "BETA", "A_G")


def s6_table_iv1(out):
    out.mkdir(parents=True, exist_ok=True)
    text = (ROOT / "input/s6/s6_modjoin.inp").read_text()
    base = make_s6_decks.III1
    old = (f"K0 = {base['K0']:g}, G0 = {base['G0']:g}, PHI = {base['PHI']:g}, C = {base['C']:g}",
           f"R0 = {base['R0']:g}, BETA = {base['BETA']:g}, PSI = {base['PSI']:g}, "
           f"A_G = {base['A_G']:g}")
    new = (f"K0 = {{{{K0}}}}, G0 = {{{{G0}}}}, PHI = {base['PHI']:g}, C = {base['C']:g}",
           f"R0 = {base['R0']:g}, BETA = {{{{BETA}}}}, PSI = {base['PSI']:g}, A_G = {{{{A_G}}}}")
    for o, n in zip(old, new):
        assert text.count(o) == 1, o
        text = text.replace(o, n)
    text = text.replace("S6 pile pull-out, modjoin, refine 1",
                        "S6 pile pull-out, modjoin, table IV.1 case {{CASE_TITLE}}")
    head = ("** Template of the table IV.1 sweep (pecplas-sweep make template.inp table.csv);\n"
            "** written by tools/pecplas_py/decks/make_sweep_examples.py from "
            "input/s6/s6_modjoin.inp.\n")
    (out / "template.inp").write_text(head + text)
    with (out / "table.csv").open("w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "CASE_TITLE"] + list(IV1))
        w.writerow(["reference", "reference (table III.1)"] + [f"{base[k]:g}" for k in IV1])
        for k in IV1:
            w.writerow([f"{k.lower()}_plus50", f"{k} +50 %"]
                       + [f"{base[j] * (1.5 if j == k else 1.0):g}" for j in IV1])


def split_mesh(deck):
    """(template lines, mesh lines) of a generated S2 deck."""
    template, mesh, in_mesh, placed = [], [], False, False
    for ln in deck.splitlines():
        if ln.startswith("*") and not ln.startswith("**"):
            in_mesh = ln.upper().startswith(MESH_KEYWORDS)
            if in_mesh and not placed:
                template.append("*INCLUDE, FILE=mesh_r{{REFINE}}.inp")
                placed = True
        (mesh if in_mesh else template).append(ln)
    return template, mesh


def s2_mesh(out):
    out.mkdir(parents=True, exist_ok=True)
    template = None
    for r in S2_REFINES:
        m = make_s2_decks.Mesh(r)
        t, mesh = split_mesh(make_s2_decks.deck(m, "goodman", r))
        t = [ln.replace(f"refinement {r}", "refinement {{REFINE}}")
              .replace(f"refine {r}", "refine {{REFINE}}") for ln in t]
        assert template is None or t == template, "the non-mesh part depends on the mesh"
        template = t
        (out / f"mesh_r{r}.inp").write_text(
            f"** S2 mesh at refinement {r} ({len(m.elements)} Q4, {len(m.nodes)} nodes), "
            "included by template.inp;\n** written by "
            "tools/pecplas_py/decks/make_sweep_examples.py.\n"
            + "\n".join(mesh) + "\n")
    head = ["** Template of the S2 mesh series (pecplas-sweep make template.inp table.csv);",
            "** written by tools/pecplas_py/decks/make_sweep_examples.py from "
            "tools/pecplas_py/decks/make_s2_decks.py."]
    (out / "template.inp").write_text("\n".join(head + template) + "\n")
    (out / "table.csv").write_text("case,REFINE\n"
                                   + "".join(f"r{r},{r}\n" for r in S2_REFINES))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "input/sweeps"))
    a = ap.parse_args()
    s6_table_iv1(Path(a.out) / "s6_table_iv1")
    s2_mesh(Path(a.out) / "s2_mesh")
    print(f"written: {a.out}/s6_table_iv1, {a.out}/s2_mesh")


if __name__ == "__main__":
    main()
