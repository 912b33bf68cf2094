#!/usr/bin/env python3
"""Smooth rigid strip footing on a weightless soil, our deck and its CalculiX twin.

The textbook collapse problem: a footing of half-width B = 1 m on x in [0, 1] at y = 0,
pushed down by an imposed settlement of its nodes (20 equal increments, 0.05 m for the von
Mises soil), plane strain, half model 6 m x 5 m, symmetry axis and far side on rollers, base
fixed. Soil: E = 1e5 kPa, nu = 0.3 and
  vm  von Mises / Tresca with c_u = 100 kPa (Drucker-Prager with phi = 0, which is von Mises;
      CalculiX: *PLASTIC with the yield stress sqrt(3) c_u), closed form (2 + pi) c_u,
  mc  Mohr-Coulomb c = 100 kPa, phi = psi = 30 deg (no CalculiX twin),
  dp  Drucker-Prager matched to the same c, phi in plane strain (no CalculiX twin).
drive = settle: the footing nodes carry the settlement; drive = springs: they are pushed
through stiff normal springs (no shear: a smooth footing) by driver nodes that carry it.

The mesh is graded towards the footing edge and the surface; `refine` m splits every element
side of the base mesh (m = 1, about 2 000 equations) into m equal parts. Q4 meshes use every
node line of the quadratic mesh as element corners (4 Q4 per Q8). Equations: Q4 2 675 m = 1,
24 400 m = 3, 97 500 m = 6; Q8 and Q8R 2 003 m = 1, 18 300 m = 3, 99 500 m = 7.

    python3 -m pecplas_py.decks.make_footing_peer_decks OUTDIR [--element Q8R] [--refine 1]
        [--material vm] [--drive settle] [--increments 20] [--settle S] [--no-ccx]
writes OUTDIR/footing_<material>_<element>_m<refine>[_springs].inp (and .ccx.inp for vm with
the settle drive).
"""
import argparse
import math
from pathlib import Path

# corner lines of the base mesh (element sides of the quadratic mesh at m = 1)
X_BASE = [0.0, 0.26667488, 0.436736, 0.5942, 0.74, 0.875, 1.0, 1.125, 1.26, 1.4058,
          1.563264, 1.73332512, 1.9169911296, 2.11535041997, 2.32957845357, 2.56094472985,
          2.81082030824, 3.0806859329, 3.5, 4.08703969394, 4.90889526546, 6.0]
Y_BASE = [-5.0, -3.88150554238, -3.15475283851, -2.63564376432, -2.26485156847, -2.0,
          -1.81082030824, -1.56094472985, -1.32957845357, -1.11535041997, -0.9169911296,
          -0.73332512, -0.563264, -0.4058, -0.26, -0.125, 0.0]
B = 1.0
E, NU, C = 1.0e5, 0.3, 100.0
CCX_ELEMENT = {"Q4": "CPE4", "Q8": "CPE8", "Q8R": "CPE8R"}
SETTLE = {"vm": 0.05, "mc": 0.2, "dp": 0.2}


def lines(base, m):
    """The base lines with every interval split into m equal parts."""
    out = [base[0]]
    for a, b in zip(base[:-1], base[1:]):
        out += [a + (b - a) * k / m for k in range(1, m + 1)]
    return out


def mesh(element, m):
    """Nodes [(x, y)], elements [node ids], and the node grid {(i, j): id} (i along x)."""
    xc, yc = lines(X_BASE, m), lines(Y_BASE, m)
    # all node lines: corners and mid-sides of the quadratic mesh
    xs = [v for a, b in zip(xc[:-1], xc[1:]) for v in (a, 0.5 * (a + b))] + [xc[-1]]
    ys = [v for a, b in zip(yc[:-1], yc[1:]) for v in (a, 0.5 * (a + b))] + [yc[-1]]
    ids, nodes = {}, []
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            if element != "Q4" and i % 2 == 1 and j % 2 == 1:
                continue  # no centre node in Q8
            nodes.append((x, y))
            ids[(i, j)] = len(nodes)
    els = []
    if element == "Q4":
        for j in range(len(ys) - 1):
            for i in range(len(xs) - 1):
                els.append([ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]])
    else:
        for j in range(0, len(ys) - 1, 2):
            for i in range(0, len(xs) - 1, 2):
                els.append([ids[(i, j)], ids[(i + 2, j)], ids[(i + 2, j + 2)], ids[(i, j + 2)],
                            ids[(i + 1, j)], ids[(i + 2, j + 1)], ids[(i + 1, j + 2)],
                            ids[(i, j + 1)]])
    return nodes, els, ids, len(xs), len(ys)


def node_sets(nodes, ids, nx, ny):
    top = ny - 1
    return {
        "footing": [ids[(i, top)] for i in range(nx) if nodes[ids[(i, top)] - 1][0] <= B + 1e-9],
        "axis": [ids[(0, j)] for j in range(ny) if (0, j) in ids],
        "far": [ids[(nx - 1, j)] for j in range(ny) if (nx - 1, j) in ids],
        "base": [ids[(i, 0)] for i in range(nx) if (i, 0) in ids],
    }


def rows(values, per=10, comma=False):
    """Data lines of `per` values; `comma`: every line but the last ends with a comma
    (CalculiX continues a set on the next line only then)."""
    out = [", ".join(map(str, values[k:k + per])) for k in range(0, len(values), per)]
    return [v + ("," if comma and k < len(out) - 1 else "") for k, v in enumerate(out)]


def ours(element, m, material, drive, increments, settle):
    nodes, els, ids, nx, ny = mesh(element, m)
    sets = node_sets(nodes, ids, nx, ny)
    out = [f"** strip footing, {material}, {element}, refine {m}, drive {drive}",
           f"*TITLE\nfooting {material} {element} m{m} {drive}", "*UNITS\nkN, m, kPa",
           "*ANALYSIS, TYPE=PLANE_STRAIN", "*NODES"]
    out += [f"{k}, {x:.12g}, {y:.12g}" for k, (x, y) in enumerate(nodes, 1)]
    driver = []
    if drive == "springs":
        driver = list(range(len(nodes) + 1, len(nodes) + 1 + len(sets["footing"])))
        out += [f"{d}, {nodes[n - 1][0]:.12g}, {nodes[n - 1][1]:.12g}"
                for d, n in zip(driver, sets["footing"])]
    out.append(f"*ELEMENTS, TYPE={element}, SET=soil")
    out += [f"{k}, " + ", ".join(map(str, e)) for k, e in enumerate(els, 1)]
    if material == "vm":
        out.append(f"*MATERIAL, NAME=soil, TYPE=DRUCKER_PRAGER\n"
                   f"E = {E:g}, NU = {NU:g}, C = {C:g}, PHI = 0, PSI = 0, MATCH = 3")
    elif material == "mc":
        out.append(f"*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB\n"
                   f"E = {E:g}, NU = {NU:g}, C = {C:g}, PHI = 30, PSI = 30")
    else:
        out.append(f"*MATERIAL, NAME=soil, TYPE=DRUCKER_PRAGER\n"
                   f"E = {E:g}, NU = {NU:g}, C = {C:g}, PHI = 30, PSI = 30, MATCH = 3")
    out.append("*SECTION, SET=soil, MATERIAL=soil")
    if drive == "springs":
        sets["driver"] = driver
    for name, lst in sets.items():
        out.append(f"*NSET, NAME={name}")
        out += rows(lst)
    if drive == "springs":
        # normal springs 1e4 times stiffer than the soil under a 1 m footing, no shear
        out.append(f"*INTERFACE_LAW, NAME=push, TYPE=SPRING\nKN = {1e4 * E:g}, KT = 0, "
                   "PHI = 0, C = 0")
        out.append("*JOINTS, TYPE=SPRING, SET=pushers, LAW=push, ANGLE=0")
        first = len(els) + 1
        out += [f"{first + k}, {n}, {d}" for k, (n, d) in enumerate(zip(sets["footing"], driver))]
    out.append("*BOUNDARY\naxis, X\nfar, X\nbase, XY")
    if drive == "springs":
        out.append("driver, X")
    moved = "driver" if drive == "springs" else "footing"
    out.append(f"*LOAD, NAME=settle, TYPE=DISPLACEMENT\n{moved}, Y, -1.0")
    out.append(f"*STEP, NAME=push, INCREMENTS={increments}\nsettle, {settle:g}")
    out.append("*SOLVER, TOLERANCE=0.0001")  # the default method: full Newton
    out.append("*OUTPUT, STRESSES=NO, STRAINS=NO")
    return "\n".join(out) + "\n"


def ccx(element, m, increments, settle):
    nodes, els, ids, nx, ny = mesh(element, m)
    sets = node_sets(nodes, ids, nx, ny)
    out = [f"** strip footing, vm, {CCX_ELEMENT[element]}, refine {m}", "*HEADING",
           "footing", "*NODE, NSET=Nall"]
    out += [f"{k}, {x:.12g}, {y:.12g}, 0" for k, (x, y) in enumerate(nodes, 1)]
    out.append(f"*ELEMENT, TYPE={CCX_ELEMENT[element]}, ELSET=soil")
    out += [f"{k}, " + ", ".join(map(str, e)) for k, e in enumerate(els, 1)]
    for name, lst in sets.items():
        out.append(f"*NSET, NSET={name}")
        out += rows(lst, 8, comma=True)
    out += ["*MATERIAL, NAME=soil", "*ELASTIC", f"{E:g}, {NU:g}", "*PLASTIC",
            f"{math.sqrt(3.0) * C:.8g}, 0.", "*SOLID SECTION, ELSET=soil, MATERIAL=soil", "1.",
            "*BOUNDARY", "axis, 1", "far, 1", "base, 1, 2",
            "*STEP, INC=10000", "*STATIC", f"{1.0 / increments:g}, 1., 1e-8, {1.0 / increments:g}",
            "*BOUNDARY", f"footing, 2, 2, {-settle:g}",
            "*NODE PRINT, NSET=footing, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--element", default="Q8R", choices=sorted(CCX_ELEMENT))
    ap.add_argument("--refine", type=int, default=1)
    ap.add_argument("--material", default="vm", choices=sorted(SETTLE))
    ap.add_argument("--drive", default="settle", choices=["settle", "springs"])
    ap.add_argument("--increments", type=int, default=20)
    ap.add_argument("--settle", type=float, default=None)
    ap.add_argument("--no-ccx", action="store_true")
    a = ap.parse_args()
    settle = SETTLE[a.material] if a.settle is None else a.settle
    out = Path(a.outdir)
    out.mkdir(parents=True, exist_ok=True)
    stem = f"footing_{a.material}_{a.element}_m{a.refine}" + \
        ("_springs" if a.drive == "springs" else "")
    (out / f"{stem}.inp").write_text(ours(a.element, a.refine, a.material, a.drive,
                                          a.increments, settle))
    print(out / f"{stem}.inp")
    if a.material == "vm" and a.drive == "settle" and not a.no_ccx:
        (out / f"{stem}.ccx.inp").write_text(ccx(a.element, a.refine, a.increments, settle))
        print(out / f"{stem}.ccx.inp")


if __name__ == "__main__":
    main()
