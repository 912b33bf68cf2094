#!/usr/bin/env python3
"""Scene S6 (thesis figs IV.4-IV.10, table IV.1): pull-out of a model pile in dense dry Hostun
sand, axisymmetric, MODJOIN (initial version, table III.1) or Mohr-Coulomb on the shaft.

Given (doc/validation.md, scene S6): pile diameter 5.5 cm, embedded length 1.62 m (points of interest at depths
0.525, 1.016, 1.581 m); sand gamma = 17 kN/m3; sand and steel elastic; interface MODJOIN
initial version with table III.1 (K0 = 80 kPa/mm, G0 = 40 kPa/mm, phi = 41, c = 0, R0 = 0.3,
beta = 9 mm, psi = 27, a_g = 0.5 /mm), and Mohr-Coulomb with the same K, G, phi and psi = 6;
23 equal increments of axial pull; table IV.1 study: G0, K0, beta, a_g each +50 %.
Assumed (not given by the thesis): tank radius 1.0 m, depth 2.0 m, rigid walls and base (outer side radially
fixed, base fixed); sand E = 3.0e4 kPa, nu = 0.3, K0 = 0.5 (geostatic initial stress, the
joints get sigma_n0 projected from it); steel E = 2.1e8 kPa, nu = 0.3. Mohr-Coulomb: pull
0 -> 6.28 kN (the thesis's last cycle peak) as a uniform upward traction on the head, 23
increments. MODJOIN: head uplift imposed, 0 -> 40 mm (the pull is the head reaction): its curve
has a local peak near 0.2 mm uplift, then rises with the dilation to a plateau, the limit load.
Further assumed here: the pile head at the sand surface; the pile starts from the same
geostatic state as the sand (GAMMA = 17 in the steel: the initial state is continuous across
the joints; its own weight, 0.3 kN, is not modelled); the same law on the shaft and under the
tip (the tip opens at once under the pull); MODJOIN "K0" is the law's
normal stiffness, not the earth pressure coefficient.

Two bodies with their own nodes (pile, sand), joined by explicit joint elements: GOODMAN4
with Lobatto integration along the shaft, Gauss under the tip. The reference mesh
(--refine 1) has 176 Q4; --refine n multiplies the element counts in each direction by n.

    python3 -m pecplas_py.decks.make_s6_decks [--refine N] [--out DIR]
"""
import argparse
import math
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.deck import Deck

A, L, H, R = 0.0275, 1.62, 2.0, 1.0
E_SAND, E_STEEL, GAMMA = 3.0e4, 2.1e8, 17.0
Q_END = 6.28        # kN, the head pull at the end of loading (factor 1)
INCREMENTS = 23
# MODJOIN runs: head uplift [m] imposed up to each u1 in increments du (fine through the early
# peak; the reaction at 40 mm is within 0.03 % of the one with half the last increment size)
UPLIFT_STEPS = ((0.0005, 0.00002), (0.002, 0.0001), (0.04, 0.0004))
U_END = UPLIFT_STEPS[-1][0]
# table III.1 (kPa and mm): the initial MODJOIN set of dense Hostun sand on steel (Plytas)
III1 = dict(K0=80.0, G0=40.0, PHI=41.0, C=0.0, R0=0.3, BETA=9.0, PSI=27.0, A_G=0.5)
# table IV.1: one parameter +50 % at a time
VARIANTS = {"": {}, "_g0": {"G0": 1.5}, "_k0": {"K0": 1.5}, "_beta": {"BETA": 1.5},
            "_ag": {"A_G": 1.5}}


def graded(x0, x1, n, ratio):
    """n intervals from x0 to x1, each `ratio` times the previous one."""
    w = [ratio**i for i in range(n)]
    s = sum(w)
    xs, x = [x0], x0
    for wi in w:
        x += (x1 - x0) * wi / s
        xs.append(x)
    xs[-1] = x1
    return xs


class Mesh:
    """Pile block (r in [0, A], z in [-L, 0]) and an L-shaped sand body around and under it."""

    def __init__(self, n):
        self.nodes, self.elements, self.nid, self.eid = [], [], 0, 0
        self.r_pile = graded(0.0, A, n, 1.0)
        self.r_out = graded(A, R, 10 * n, 1.35 ** (1.0 / n))
        self.z_pile = graded(0.0, -L, 12 * n, 1.0)
        self.z_below = graded(-L, -H, 4 * n, 1.0)
        self.r_all = self.r_pile + self.r_out[1:]
        self.z_all = self.z_pile + self.z_below[1:]
        self.P = self.grid(self.r_pile, self.z_pile, lambda i, j: True)
        npz, npr = len(self.z_pile), len(self.r_pile)
        # sand: every (r, z) except the pile's inside (r < A above the tip)
        self.S = self.grid(self.r_all, self.z_all,
                           lambda i, j: not (i < npr - 1 and j < npz - 1))
        self.block(self.P, self.r_pile, self.z_pile, "pile", lambda i, j: True)
        self.block(self.S, self.r_all, self.z_all, "sand",
                   lambda i, j: not (i < npr - 1 and j < npz - 1))

    def grid(self, rs, zs, keep):
        ids = {}
        for j, z in enumerate(zs):
            for i, r in enumerate(rs):
                if keep(i, j):
                    self.nid += 1
                    ids[i, j] = self.nid
                    self.nodes.append((self.nid, r, z))
        return ids

    def block(self, ids, rs, zs, name, keep):
        for j in range(len(zs) - 1):
            for i in range(len(rs) - 1):
                if keep(i, j):
                    self.eid += 1   # counter-clockwise in (r, z): z decreases with j
                    self.elements.append((name, self.eid, ids[i, j + 1], ids[i + 1, j + 1],
                                          ids[i + 1, j], ids[i, j]))


def interfaces(m):
    """(name, (pile node, sand node) pairs in the order of the joint tangent)."""
    npz, npr = len(m.z_pile), len(m.r_pile)
    shaft = [(m.P[npr - 1, j], m.S[npr - 1, j]) for j in range(npz)]   # t = -z, n = +r
    tip = [(m.S[i, npz - 1], m.P[i, npz - 1]) for i in range(npr)]     # t = +r, n = +z
    return [("shaft", shaft), ("tip", tip)]


def law_lines(model, factors):
    d = Deck()
    if model == "modjoin":
        p = {k: v * factors.get(k, 1.0) for k, v in III1.items()}
        # SUBSTEP 0.01 mm (default 0.001): 6x faster, limit load within 0.5 %
        items = [f"{k} = {v:g}" for k, v in p.items()] + ["SUBSTEP = 0.01"]
        d.keyword("INTERFACE_LAW", NAME="iface", TYPE="MODJOIN_INITIAL", LENGTH_UNIT="MM",
                  MODEL_UNIT="M")
        d.props(*items[:4]).props(*items[4:])
    else:
        # same K, G (kPa/mm -> kPa/m), phi; psi = 6
        d.interface_law("iface", "MOHR_COULOMB", KN=III1["K0"] * 1e3, KT=III1["G0"] * 1e3,
                        PHI=III1["PHI"], C=0, PSI=6)
    return d.lines


def joint_lines(m):
    d, jid = Deck(), 10 * m.eid
    for name, pairs in interfaces(m):
        # Lobatto on the vertical shaft (r constant: exact, no traction oscillation), Gauss
        # under the tip where the 2 pi r weight varies along the joint
        rule = "GAUSS" if name == "tip" else "LOBATTO"
        rows = [(jid + k + 1, a1, a2, b2, b1)
                for k, ((a1, b1), (a2, b2)) in enumerate(zip(pairs[:-1], pairs[1:]))]
        d.joints("GOODMAN4", name, "iface", rows, INTEGRATION=rule)
        jid += len(rows)
    return d.lines


def deck(m, model, refine, variant=""):
    nr, nall, nz = len(m.r_pile), len(m.r_all), len(m.z_all)
    npz = len(m.z_pile)
    head = [m.P[i, 0] for i in range(nr)]
    axis = [m.P[0, j] for j in range(npz)] + [m.S[0, j] for j in range(npz - 1, nz)]
    bottom = [m.S[i, nz - 1] for i in range(nall)]
    outer = [m.S[nall - 1, j] for j in range(nz)]
    what = model + (f", table IV.1 variant {variant[1:]} +50 %" if variant else "")
    d = Deck(fmt=".12g")
    d.comment(f"S6 model pile pull-out, interface: {what}, refinement {refine}")
    d.line(*("** " + line for line in __doc__.strip().splitlines()[2:24]))
    d.comment("Generated by tools/pecplas_py/decks/make_s6_decks.py.")
    d.title(f"S6 pile pull-out, {what}, refine {refine}").units("kN, m, kPa")
    d.analysis("AXISYMMETRIC").nodes(m.nodes)
    for name in ("pile", "sand"):
        d.elements("Q4", name, [e[1:] for e in m.elements if e[0] == name])
    d.material("steel", f"E = {E_STEEL:g}, NU = 0.3, GAMMA = {GAMMA:g}")
    d.material("sand", f"E = {E_SAND:g}, NU = 0.3, GAMMA = {GAMMA:g}")
    d.section("pile", "steel").section("sand", "sand")
    d.line(*law_lines(model, VARIANTS[variant]), *joint_lines(m))
    d.nset("axis", axis).nset("bottom", bottom).nset("outer", outer)
    d.boundary("axis, R", "outer, R", "bottom, XY")
    if model != "modjoin":  # the pressure's edges (MODJOIN's runs impose the uplift on nodes)
        d.edges("head", [(head[i + 1], head[i]) for i in range(nr - 1)])
    d.initial_stress("GEOSTATIC", "ALL, 0.0, 0.5")
    if model == "modjoin":
        # head uplift imposed (the pull is the head reaction): MODJOIN's load-uplift curve
        # has a local peak at ~0.2 mm (the contraction phase lowers sigma_n and opens the top
        # of the shaft) that a force-controlled run cannot pass when it is deep (K0, beta
        # +50 %), then rises again with the dilation to a plateau (the limit load)
        d.nset("head_nodes", head)
        d.load("pull", "DISPLACEMENT", f"head_nodes, Y, {U_END:g}")
        u0 = 0.0
        for k, (u1, du) in enumerate(UPLIFT_STEPS):
            d.step(f"pull{k + 1}", round((u1 - u0) / du), ("pull", u1 / U_END))
            u0 = u1
    else:
        d.comment(f"{Q_END:g} kN upward on the head (total over pi a^2; negative pressure pulls)")
        d.load("pull", "PRESSURE", ("head", -Q_END / (math.pi * A * A)))
        d.step("pull", INCREMENTS, "pull, 1")
    d.solver(METHOD="NEWTON", MAX_ITERATIONS=25, MAX_CUTS=5).output(EVERY=1)
    return d.text()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--refine", type=int, default=1)
    ap.add_argument("--out", default=str(ROOT / "input"))
    a = ap.parse_args()
    m = Mesh(a.refine)
    tag = "" if a.refine == 1 else f"_r{a.refine}"
    out = Path(a.out) / "s6"
    out.mkdir(parents=True, exist_ok=True)
    for variant in VARIANTS:
        p = out / f"s6_modjoin{variant}{tag}.inp"
        p.write_text(deck(m, "modjoin", a.refine, variant))
        print(p)
    p = out / f"s6_mohr_coulomb{tag}.inp"
    p.write_text(deck(m, "mohr_coulomb", a.refine))
    print(p)
    print(f"{len(m.elements)} Q4, {len(m.nodes)} nodes")


if __name__ == "__main__":
    main()
