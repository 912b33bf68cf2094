#!/usr/bin/env python3
"""Scene S2 (thesis figs II.6-II.12): an axisymmetric pile under one load cycle, with each
interface model on the same mesh, and scene S3 (fig. II.13): Mohr-Coulomb with dilatancy.

Geometry and data (doc/validation.md, scene S2): pile diameter 1 m embedded 10 m; pile and soil elastic;
interface phi = 30°, c = 0, K_t = E_soil, K_n = E_pile (per m); joints along the shaft,
horizontally under the tip and vertically below the tip down to the bottom of the mesh.
Assumed (not given by the thesis): soil E = 2e4 kPa, nu = 0.3, gamma = 18 kN/m3, K0 = 0.5 (geostatic initial
stress); pile E = 2e7 kPa, nu = 0.2; domain radius 10 m, depth 20 m, bottom fixed, outer side
radially fixed; head load 0 -> 2000 kN in 20 increments, back to 0 in 20. Further assumed here:
the pile starts from the same geostatic stress as the soil (gamma = 18, K0 = 0.5, so the
initial state is continuous across the interface); Katona contact on all the springs' node
doublets (at the tip corner three close a loop: doc/validation.md); thin layer e = 0.01 m (its unit
stiffnesses are K e); springs carry the same K_n, K_t per unit area (times their tributary
area) — with Frank's default penalty 1e5 E_ryg R_max instead, full Newton cycles between stick
and slip on unloading (doc/validation.md). Full Newton: the frictional tangent is
non-symmetric (UMFPACK); modified Newton needs hundreds of iterations per increment here.

Three bodies with their own nodes (pile P, soil column under the tip C, surrounding soil O),
joined by explicit joint elements. The reference mesh (--refine 1) has 54 Q4 (the thesis used
50); --refine n multiplies the element counts in each direction by n. At refinement 1 the
generator also writes DIR/default.inp, the deck `make run` runs: the Goodman deck under a
header saying so (kept in sync with input/s2/s2_goodman.inp by construction, and checked by
test/python/test_s2_s3.py).

    python3 -m pecplas_py.decks.make_s2_decks [--refine N] [--out DIR]
"""
import argparse
import math
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.deck import Deck

A, L, H, R = 0.5, 10.0, 20.0, 10.0
E_SOIL, E_PILE = 2.0e4, 2.0e7
THIN = 0.01
MODELS = ("goodman", "ghaboussi", "spring", "mohr_coulomb", "katona")


def graded(x0, x1, n, ratio):
    """n intervals from x0 to x1, each `ratio` times the previous one."""
    if abs(ratio - 1) < 1e-12:
        w = [1.0] * n
    else:
        w = [ratio**i for i in range(n)]
    s = sum(w)
    xs, x = [x0], x0
    for wi in w:
        x += (x1 - x0) * wi / s
        xs.append(x)
    xs[-1] = x1
    return xs


class Mesh:
    def __init__(self, n):
        self.nodes, self.elements, self.nid, self.eid = [], [], 0, 0
        self.r_pile = graded(0.0, A, n, 1.0)
        self.r_soil = graded(A, R, 5 * n, 1.6 ** (1.0 / n))
        self.z_pile = graded(0.0, -L, 5 * n, 1.0)
        self.z_below = graded(-L, -H, 4 * n, 1.3 ** (1.0 / n))
        self.P = self.block(self.r_pile, self.z_pile, "pile")
        self.C = self.block(self.r_pile, self.z_below, "column")
        self.O = self.block(self.r_soil, self.z_pile + self.z_below[1:], "soil")

    def block(self, rs, zs, name):
        ids = {}
        for j, z in enumerate(zs):
            for i, r in enumerate(rs):
                self.nid += 1
                ids[i, j] = self.nid
                self.nodes.append((self.nid, r, z))
        for j in range(len(zs) - 1):
            for i in range(len(rs) - 1):
                self.eid += 1
                # counter-clockwise in (r, z): z decreases with j
                self.elements.append((name, self.eid, ids[i, j + 1], ids[i + 1, j + 1],
                                      ids[i + 1, j], ids[i, j]))
        return ids


def interfaces(m):
    """(name, list of (face-1 node, face-2 node) pairs along the interface, in the order of
    the joint tangent) for shaft, tip and below-tip interfaces."""
    nz, nzb, nr = len(m.z_pile), len(m.z_below), len(m.r_pile)
    shaft = [(m.P[nr - 1, j], m.O[0, j]) for j in range(nz)]          # t = -z, n = +r
    tip = [(m.C[i, 0], m.P[i, nz - 1]) for i in range(nr)]            # t = +r, n = +z
    below = [(m.C[nr - 1, j], m.O[0, nz - 1 + j]) for j in range(nzb)]  # t = -z, n = +r
    return [("shaft", shaft), ("tip", tip), ("below", below)]


def law_lines(model, psi=0.0, kt=E_SOIL):
    """The interface law; `kt` (default E_soil, assumed) is changed only by the tests that
    take penalty joints to their stiff limit (test_s2_s3.py)."""
    d = Deck()
    if model == "goodman":
        d.interface_law("iface", "GOODMAN", KN=E_PILE, KT=kt, PHI=30, C=0)
    elif model == "ghaboussi":
        d.interface_law("iface", "GHABOUSSI", KN=E_PILE * THIN, KT=kt * THIN, PHI=30, C=0)
    elif model == "spring":
        d.interface_law("iface", "SPRING", KN=E_PILE, KT=kt, PHI=30, C=0)
    elif model == "katona":
        d.interface_law("iface", "KATONA", PHI=30, C=0)
    else:
        d.interface_law("iface", "MOHR_COULOMB", KN=E_PILE, KT=kt, PHI=30, C=0, PSI=psi)
    return d.lines


def joint_lines(m, model):
    d, jid = Deck(), 10 * m.eid
    for name, pairs in interfaces(m):
        if model in ("spring", "katona"):
            rows = [(jid + k + 1, a, b) for k, (a, b) in enumerate(pairs)]
            d.joints("SPRING", name, "iface", rows)
        else:
            # Lobatto (points on the doublets) on the vertical joints removes the traction
            # oscillations of these stiff joints and is exact there (r constant); Gauss under
            # the tip, where the 2 pi r weight varies along the joint
            rule = "GAUSS" if name == "tip" else "LOBATTO"
            rows = [(jid + k + 1, a1, a2, b2, b1)
                    for k, ((a1, b1), (a2, b2)) in enumerate(zip(pairs[:-1], pairs[1:]))]
            d.joints("THIN_LAYER" if model == "ghaboussi" else "GOODMAN4", name, "iface", rows,
                     INTEGRATION=rule, THICKNESS=THIN if model == "ghaboussi" else None)
        jid += len(rows)
    return d.lines


def deck(m, model, refine, psi=0.0, title=None, kt=E_SOIL, unload=True):
    """Deck text of `model` on mesh m; unload=False keeps the loading step only."""
    nz, nzb, nr, nrs = len(m.z_pile), len(m.z_below), len(m.r_pile), len(m.r_soil)
    head = [m.P[i, 0] for i in range(nr)]
    axis = [m.P[0, j] for j in range(nz)] + [m.C[0, j] for j in range(nzb)]
    bottom = [m.C[i, nzb - 1] for i in range(nr)] + [m.O[i, nz + nzb - 2] for i in range(nrs)]
    outer = [m.O[nrs - 1, j] for j in range(nz + nzb - 1)]
    d = Deck(fmt=".12g")
    d.comment(f"S2 pile under one load cycle, interface model: {model}"
              + (f", psi = {psi:g}" if model == "mohr_coulomb" else "") + f", refinement {refine}")
    d.line(*("** " + line for line in __doc__.strip().splitlines()[2:17]))
    d.comment("Generated by tools/pecplas_py/decks/make_s2_decks.py.")
    d.title(title or f"S2 pile, {model} interface, refine {refine}").units("kN, m, kPa")
    d.analysis("AXISYMMETRIC").nodes(m.nodes)
    for name in ("pile", "column", "soil"):
        d.elements("Q4", name, [e[1:] for e in m.elements if e[0] == name])
    d.material("concrete", f"E = {E_PILE:g}, NU = 0.2, GAMMA = 18")
    d.material("sand", f"E = {E_SOIL:g}, NU = 0.3, GAMMA = 18")
    d.section("pile", "concrete").section("column", "sand").section("soil", "sand")
    d.line(*law_lines(model, psi, kt), *joint_lines(m, model))
    d.nset("axis", axis).nset("bottom", bottom).nset("outer", outer)
    d.boundary("axis, R", "outer, R", "bottom, XY")
    d.edges("head", [(head[i + 1], head[i]) for i in range(nr - 1)])
    d.initial_stress("GEOSTATIC", "ALL, 0.0, 0.5")
    d.comment("2000 kN on the head (ring total over pi a^2)")
    d.load("head", "PRESSURE", ("head", 2000.0 / (math.pi * A * A)))
    d.step("load", 20, "head, 1")
    if unload:
        d.step("unload", 20, "head, 0")
    d.solver(METHOD="NEWTON", MAX_ITERATIONS=50, MAX_CUTS=6).output(EVERY=1)
    return d.text()


def default_deck(m):
    """The Goodman deck at refinement 1 with a header naming it `make run`'s default."""
    head = ["** input/default.inp: the deck `make run` runs (-> output/default.h5, .xmf and",
            "** the head load-settlement picture output/default.png). It is scene S2 "
            "(doc/validation.md)",
            "** with the Goodman interface at refinement 1, identical to input/s2/s2_goodman.inp",
            "** below this header: a 1 m pile, 10 m long, loaded 0 -> 2000 kN -> 0; runs in about",
            "** a second.",
            "** Written by tools/pecplas_py/decks/make_s2_decks.py (do not edit: regenerate). "
            "Other decks:",
            "** input/examples/ (strip footing), input/s1 ... input/s6 (the thesis scenes).",
            "**"]
    return "\n".join(head) + "\n" + deck(m, "goodman", 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--refine", type=int, default=1)
    ap.add_argument("--out", default=str(ROOT / "input"))
    a = ap.parse_args()
    m = Mesh(a.refine)
    tag = "" if a.refine == 1 else f"_r{a.refine}"
    s2, s3 = Path(a.out) / "s2", Path(a.out) / "s3"
    s2.mkdir(parents=True, exist_ok=True)
    s3.mkdir(parents=True, exist_ok=True)
    for model in MODELS:
        p = s2 / f"s2_{model}{tag}.inp"
        p.write_text(deck(m, model, a.refine))
        print(p)
    for psi in (0, 1, 5, 15, 30):
        p = s3 / f"s3_psi{psi}{tag}.inp"
        p.write_text(deck(m, "mohr_coulomb", a.refine, psi,
                          f"S3 pile, Mohr-Coulomb interface, psi = {psi}, refine {a.refine}"))
        print(p)
    if a.refine == 1:
        p = Path(a.out) / "default.inp"
        p.write_text(default_deck(m))
        print(p)
    print(f"{len(m.elements)} Q4, {len(m.nodes)} nodes")


if __name__ == "__main__":
    main()
