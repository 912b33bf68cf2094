#!/usr/bin/env python3
"""Writes the joint patch-test decks of test/data/joints/ (run from anywhere):

    python3 -m pecplas_py.decks.make_patch_decks [--out DIR]

Two blocks (2 elements wide, 1 high each) pressed together by a uniform pressure P on top,
the lower block on rollers at its base. With one elastic material for both blocks the
exact solution is a uniform uniaxial stress sigma_yy = -P in both and a uniform joint jump,
so every joint point carries sigma_n = P cos^2(a), tau = -P sin(a) cos(a) for a joint
inclined at a (tau < 0: the upper block tends to slide down the slope, towards -t).
Plane strain: x in [0, 2]; axisymmetric: annular blocks r in [1, 2]. Explicit joints use
separate coincident nodes; generated ones (EDGES=, SIDE=) start from shared nodes.
Generated plane-strain decks are laterally confined (u_x = 0 on both sides, through node
sets that name only the original interface nodes): exact only if the rule "a support on a
split node also holds its duplicate" is applied.
"""

import argparse
import math
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.deck import Deck

HERE = ROOT / "test" / "data" / "joints"
P = 100.0
E, NU = 1.0e4, 0.3
# law stiffnesses per unit length (per unit strain for the thin layer, / THICKNESS)
KN, KT = 1.0e5, 1.0e4
THICK = 0.01
ORDER = {"SPRING": None, "GOODMAN4": 1, "GOODMAN6": 2, "THIN_LAYER": None}


def grid(order, x0, width, y_bottom, y_top, ncol=2):
    """Node rows of one block: rows[k][c] = (x, y); order 1 (Q4) or 2 (Q8)."""
    nc = ncol * order
    nr = order
    rows = []
    for k in range(nr + 1):
        row = []
        for c in range(nc + 1):
            x = x0 + width * c / nc
            yb, yt = y_bottom(x), y_top(x)
            row.append((x, yb + (yt - yb) * k / nr))
        rows.append(row)
    return rows


def used(order, k, c):
    """Q8 grids have no node at (odd row, odd column)."""
    return not (order == 2 and k % 2 == 1 and c % 2 == 1)


def elements(order, ids, ncol=2):
    out = []
    for i in range(ncol):
        if order == 1:
            out.append([ids[0][i], ids[0][i + 1], ids[1][i + 1], ids[1][i]])
        else:
            c = 2 * i
            out.append([ids[0][c], ids[0][c + 2], ids[2][c + 2], ids[2][c],
                        ids[0][c + 1], ids[1][c + 2], ids[2][c + 1], ids[1][c]])
    return out


def deck(jtype, axi=False, generated=False, order=1, angle=0.0, integration=None, method=None,
         law=None, extra="", note=None):
    x0, width = (1.0, 1.0) if axi else (0.0, 2.0)
    xc = x0 + 0.5 * width
    tan = math.tan(math.radians(angle))
    joint = lambda x: 1.0 + (x - xc) * tan
    top = 2.0 + 0.5 * width * tan
    lower = grid(order, x0, width, lambda x: 0.0, joint)
    upper = grid(order, x0, width, joint, lambda x: top)
    nid = 0
    nodes = []
    lid, uid = [], []
    for rows, out, block in ((lower, lid, "lower"), (upper, uid, "upper")):
        for k, row in enumerate(rows):
            ids = []
            for c, xy in enumerate(row):
                if block == "upper" and k == 0 and generated:
                    ids.append(lid[-1][c])
                    continue
                if not used(order, k, c):
                    ids.append(None)
                    continue
                nid += 1
                nodes.append((nid, xy))
                ids.append(nid)
            out.append(ids)
    le, ue = elements(order, lid), elements(order, uid)
    etype = "Q4" if order == 1 else "Q8"
    name = jtype.lower()
    title = f"joint patch test, {jtype}, {'axisymmetric' if axi else 'plane strain'}"
    if generated:
        title += ", generated doublets"
    if angle:
        title += f", joint inclined at {angle:g} deg"
    d = Deck(fmt=".15g")
    d.comment("Written by make_patch_decks.py (see its docstring for the exact solution).")
    if note:
        d.comment(note)
    d.title(title).units("kN, m, kPa")
    if axi:
        d.analysis("AXISYMMETRIC")
    d.nodes(nodes)
    d.elements(etype, "lower", [(k + 1, *e) for k, e in enumerate(le)])
    d.elements(etype, "upper", [(k + 11, *e) for k, e in enumerate(ue)])
    d.material("soil", E=E, NU=NU).section("lower", "soil").section("upper", "soil")
    kn, kt = (KN * THICK, KT * THICK) if jtype == "THIN_LAYER" else (KN, KT)
    if law:
        d.line(*law)
    else:
        d.interface_law("contact", "ELASTIC", KN=kn, KT=kt)
    opts = f"*JOINTS, TYPE={jtype}, SET=joint, LAW=contact" + extra
    if integration:
        opts += f", INTEGRATION={integration}"
    if jtype == "THIN_LAYER":
        opts += f", THICKNESS={THICK:g}"
    face1 = lid[-1]
    face2 = uid[0]
    if generated:
        edges = []
        for i in range(2):
            if order == 1:
                edges.append([face1[i], face1[i + 1]])
            else:
                edges.append([face1[2 * i], face1[2 * i + 2], face1[2 * i + 1]])
        d.edges("interface", edges).line(opts + ", EDGES=interface, SIDE=upper")
    else:
        d.line(opts)
        if jtype == "SPRING":
            d.rows([(101 + c, face1[c], face2[c]) for c in range(len(face1))])
        else:
            for i in range(2):
                if order == 1:
                    conn = [face1[i], face1[i + 1], face2[i + 1], face2[i]]
                else:
                    c = 2 * i
                    conn = [face1[c], face1[c + 2], face2[c + 2], face2[c], face1[c + 1],
                            face2[c + 1]]
                d.data(101 + i, *conn)
    d.nset("base", [i for i in lid[0] if i]).boundary("base, Z" if axi else "base, Y")
    if generated and not axi:
        sides = [row[0] for row in lid + uid if row[0]] + [row[-1] for row in lid + uid if row[-1]]
        d.nset("sides", sorted(set(sides))).boundary("sides, X")
    elif not axi:
        d.line(f"{lid[0][0]}, X")
    t = uid[-1]
    top_edges = []
    for i in range(2):
        if order == 1:
            top_edges.append([t[i], t[i + 1]])
        else:
            top_edges.append([t[2 * i], t[2 * i + 2], t[2 * i + 1]])
    d.edges("top", top_edges).load("p", "PRESSURE", f"top, {P:g}")
    if method:
        d.solver(METHOD=method)
    d.step("press", 2, "p, 1")
    return d.text()


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(HERE), help=f"directory (default {HERE})")
    return ap.parse_args()


def main():
    cases = []
    for jtype in ["SPRING", "GOODMAN4", "GOODMAN6", "THIN_LAYER"]:
        for axi in (False, True):
            for generated in (False, True):
                order = 2 if jtype == "GOODMAN6" or (generated and ORDER[jtype] is None) else 1
                tag = ("axi" if axi else "plane") + ("_gen" if generated else "")
                cases.append((f"patch_{jtype.lower()}_{tag}.inp",
                              deck(jtype, axi, generated, order)))
    for jtype, order in [("GOODMAN4", 1), ("GOODMAN6", 2)]:
        cases.append((f"patch_{jtype.lower()}_plane_lobatto.inp",
                      deck(jtype, order=order, integration="LOBATTO")))
    for jtype, order in [("SPRING", 1), ("GOODMAN4", 1), ("GOODMAN6", 2), ("THIN_LAYER", 1)]:
        cases.append((f"patch_{jtype.lower()}_inclined.inp", deck(jtype, order=order, angle=30.0)))
    cases.append(("patch_goodman6_newton.inp", deck("GOODMAN6", generated=True, order=2,
                                                    method="NEWTON")))
    cases.append(("patch_spring_inclined_angle.inp", deck(
        "SPRING", angle=30.0, extra=", ANGLE=30",
        note="Spring direction given (ANGLE=30) instead of taken from the joint edges.")))
    cases.append(("penalty_spring_plane.inp", deck(
        "SPRING", law=["*INTERFACE_LAW, NAME=contact, TYPE=SPRING", "PHI = 30, E_RYG = 0.5"],
        note="Spring (Frank) law without KN, KT: default penalty 1e5 E_RYG R_max / (mean "
             "tributary) at set-up, R_max = 2 (D11 + G) / 3 here.")))
    out = Path(parse_args().out)
    out.mkdir(parents=True, exist_ok=True)
    for name, text in cases:
        (out / name).write_text(text)
        print("wrote", out / name)


if __name__ == "__main__":
    main()
