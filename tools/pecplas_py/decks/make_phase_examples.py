#!/usr/bin/env python3
"""Writes the staged-construction examples of input/examples/ (doc/deck.md, Phases;
doc/validation.md, Staged construction):

- excavation_cantilever.inp: a cantilever sheet-pile wall in dry sand, plane strain. The wall
  is a thin continuum strip (Q8, two elements across its thickness t = 0.4 m, E chosen so that
  E t^3/12 is the bending stiffness of a steel sheet pile), 8 m long, with Goodman joints
  (GOODMAN6, Mohr-Coulomb law, wall friction delta = 2/3 phi) on both faces and under its
  tip; Mohr-Coulomb sand (phi = 30 deg, c = 0, psi = 0) in the K0 state (K0 = 1 - sin phi);
  the soil in front of the wall is excavated in three stages of 1 m (final retained height
  3 m, embedment 5 m). Each stage removes one layer and the joints beside it.
- excavation_cantilever_plate.inp: the same wall as a plate on its axis (EA = E t,
  EI = E t^3/12, the strip's nu), the same joint law on both faces (FACES=BOTH), the same
  soil meshes without the wall's columns and the same stages (doc/validation.md: the plate's
  head displacement and moment beside the strip's).
- pile_wished_in_place.inp: the S2 pile (input/s2/s2_goodman.inp, the same mesh and data)
  installed into the K0 ground: the pile and its joints are inactive in the initial state
  and activated "wished in place" by a nil step (the pile with the initial stress of the
  ground it replaces, the joints from the soil stresses beside them), then loaded
  0 -> 2000 kN -> 0 as in S2: nothing moves at installation, and the curve is S2's.
- embankment_stages.inp: a 3 m embankment (slopes 1V:2H, crest half-width 5 m, half model by
  symmetry) built in three 1 m lifts on soft Mohr-Coulomb clay in the K0 state; each lift is
  activated stress-free and its weight applied over its phase by a GRAVITY pattern of its
  own; a final nil step restores equilibrium.

    python3 -m pecplas_py.decks.make_phase_examples [--out DIR]

Meshes are structured Q8 (excavation, embankment); nodes are shared by coordinates.
"""
import argparse
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.deck import Deck
from pecplas_py.decks import make_s2_decks

# ---- excavation: geometry and data (also read by scenes/excavation_report.py)
WALL_T = 0.4          # wall strip thickness [m]
WALL_L = 8.0          # wall length [m]
STAGES = (1.0, 2.0, 3.0)   # excavation depth after each stage [m]
SAND = dict(E=3.0e4, NU=0.3, GAMMA=18.0, C=0.0, PHI=30.0, PSI=0.0)
K0_SAND = 0.5         # 1 - sin 30 deg
# plane-strain bending stiffness of an AZ 18-type sheet pile, about 8e4 kN m2/m:
# E t^3 / 12 with t = 0.4 m
WALL_E, WALL_NU = 1.5e7, 0.2
WALL_DELTA = 20.0     # wall friction angle, 2/3 phi
JOINT_KN, JOINT_KT = 1.0e6, 3.0e4


class Q8Mesh:
    """Quadratic quadrangles whose nodes are shared by coordinates."""

    def __init__(self, eid0=1):
        self.ids, self.xy, self.sets, self.eid = {}, [], {}, eid0 - 1

    def node(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.ids:
            self.xy.append((x, y))
            self.ids[key] = len(self.xy)
        return self.ids[key]

    def quad(self, set_name, corners):
        """A Q8 of corners counter-clockwise [(x, y) * 4], straight sides."""
        c = [self.node(*p) for p in corners]
        mids = [self.node((corners[i][0] + corners[(i + 1) % 4][0]) / 2,
                          (corners[i][1] + corners[(i + 1) % 4][1]) / 2) for i in range(4)]
        self.eid += 1
        self.sets.setdefault(set_name, []).append((self.eid, *c, *mids))
        return self.eid

    def edge(self, a, b):
        """(end, end, mid) node ids of the straight edge a-b (existing nodes)."""
        m = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        return tuple(self.ids[(round(p[0], 9), round(p[1], 9))] for p in (a, b, m))

    def nodes_where(self, test):
        return [i for (x, y), i in sorted(self.ids.items(), key=lambda kv: kv[1])
                if test(x, y)]

    def node_list(self):
        return [(i + 1, x, y) for i, (x, y) in enumerate(self.xy)]


def cumulative(x0, steps, sign=1.0):
    xs = [x0]
    for h in steps:
        xs.append(xs[-1] + sign * h)
    return xs


def excavation_geometry():
    """Grid lines: x of the back soil, wall and front soil; y from the surface down."""
    away = [0.4, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 3.2]            # 12 m from each face
    x_back = cumulative(0.0, away, -1.0)[::-1]                 # -12 .. 0
    x_wall = [0.0, WALL_T / 2, WALL_T]
    x_front = cumulative(WALL_T, away)                         # 0.4 .. 12.4
    ys = cumulative(0.0, [0.5] * 6 + [1.0] * 5 + [1.0, 1.5, 2.5, 3.0], -1.0)   # 0 .. -16
    return x_back, x_wall, x_front, ys


def grid_mesh(xs, ys, set_of):
    """Q8 mesh of the grid xs x ys (ys from the surface down), each element in the set
    set_of(x, y) of its centre."""
    m = Q8Mesh()
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            x0, x1, y0, y1 = xs[i], xs[i + 1], ys[j + 1], ys[j]
            m.quad(set_of((x0 + x1) / 2, (y0 + y1) / 2), [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
    return m


def excavation_set(xc, yc, strip):
    """The element set of the cantilever decks' element centred at (xc, yc): the back soil
    (x < 0), the wall strip (strip deck only, 0 < x < WALL_T, above its tip), the layers
    exc_k excavated at stage k, the front soil."""
    if xc < 0:
        return "back"
    if strip and xc < WALL_T:
        return "wall" if yc > -WALL_L else "front"
    for k, depth in enumerate(STAGES):
        if yc > -depth:
            return f"exc_{k + 1}"
    return "front"


def excavation_stages(d, m, xs, ys, joints):
    """The supports, K0 state, stages and solver shared by both cantilever decks: stage k
    removes the layer exc_k and the joint set {joints}_k beside it. Returns the deck text."""
    xmin, xmax, ymin = min(xs), max(xs), min(ys)
    d.nset("left", m.nodes_where(lambda x, y: abs(x - xmin) < 1e-9), per_line=16)
    d.nset("right", m.nodes_where(lambda x, y: abs(x - xmax) < 1e-9), per_line=16)
    d.nset("bottom", m.nodes_where(lambda x, y: abs(y - ymin) < 1e-9), per_line=16)
    d.boundary("left, X", "right, X", "bottom, XY")
    d.initial_stress("GEOSTATIC", f"ALL, 0.0, {K0_SAND}")
    for k in range(len(STAGES)):
        d.keyword("STEP", NAME=f"excavate_{k + 1}", INCREMENTS=5)
        d.keyword("DEACTIVATE").data(f"exc_{k + 1}", f"{joints}_{k + 1}")
        d.keyword("END STEP")
    d.solver(METHOD="NEWTON", MAX_ITERATIONS=50, MAX_CUTS=6).output(EVERY=1)
    return d.text()


def excavation_deck():
    x_back, x_wall, x_front, ys = excavation_geometry()
    xs = x_back[:-1] + x_wall + x_front[1:]
    m = grid_mesh(xs, ys, lambda xc, yc: excavation_set(xc, yc, strip=True))
    wall_ys = [y for y in ys if y >= -WALL_L - 1e-9]
    # edges: face 1 is the soil (the body that is not SIDE=wall)
    back = [m.edge((0.0, wall_ys[j + 1]), (0.0, wall_ys[j])) for j in range(len(wall_ys) - 1)]
    fronts = {}
    tops = [0.0, *[-d for d in STAGES]]
    for j in range(len(wall_ys) - 1):
        yc = (wall_ys[j] + wall_ys[j + 1]) / 2
        name = "front_deep"
        for k in range(len(STAGES)):
            if tops[k + 1] < yc < tops[k]:
                name = f"front_{k + 1}"
        fronts.setdefault(name, []).append(m.edge((WALL_T, wall_ys[j + 1]), (WALL_T, wall_ys[j])))
    tip = [m.edge((x_wall[i], -WALL_L), (x_wall[i + 1], -WALL_L)) for i in range(2)]
    E_wall_bending = WALL_E * WALL_T**3 / 12 / (1 - WALL_NU**2)
    d = Deck(fmt=".10g")
    d.comment("Cantilever sheet-pile wall in dry sand, excavated in front in three stages.",
              "",
              f"The wall is a thin continuum strip: Q8, two elements across its thickness "
              f"t = {WALL_T} m,",
              f"{WALL_L} m long, E = {WALL_E:g} kPa, nu = {WALL_NU} (plane-strain bending "
              f"stiffness E t^3/12/(1-nu^2) = {E_wall_bending:.3g} kN m2/m,",
              "a steel sheet pile's), with the unit weight of the sand it replaces. Goodman "
              "joints (GOODMAN6, Mohr-Coulomb",
              f"law, delta = {WALL_DELTA:g} deg, c = 0, K_n = {JOINT_KN:g}, K_t = "
              f"{JOINT_KT:g} kPa/m) on the back face, the front face",
              "(one joint set per excavation stage, removed with its layer) and under the tip.",
              f"Dry sand: Mohr-Coulomb E = {SAND['E']:g} kPa, nu = {SAND['NU']}, gamma = "
              f"{SAND['GAMMA']:g} kN/m3, phi = {SAND['PHI']:g} deg, c = 0, psi = 0,",
              f"K0 = {K0_SAND} (1 - sin phi) geostatic state. Domain 12 m behind the back "
              "face and in front of the front face,",
              "16 m deep; sides fixed horizontally, bottom fixed. Stages: the sand in front "
              "is removed to 1, 2 and 3 m",
              "(the layers exc_1, exc_2, exc_3 and the front joints beside them), 5 increments "
              "each, no load.",
              "Post-processing: python3 -m pecplas_py.scenes.excavation_report "
              "(doc/validation.md, Staged construction).",
              "",
              "Generated by tools/pecplas_py/decks/make_phase_examples.py.")
    d.title("Cantilever wall, three excavation stages")
    d.units("kN, m, kPa")
    d.analysis("PLANE_STRAIN")
    d.nodes(m.node_list())
    for name in ["back", "wall", "front", *[f"exc_{k + 1}" for k in range(len(STAGES))]]:
        d.elements("Q8", name, m.sets[name])
    d.material("sand", type="MOHR_COULOMB", **SAND)
    d.material("steel_strip", E=WALL_E, NU=WALL_NU, GAMMA=SAND["GAMMA"])
    for name in ["back", "front", *[f"exc_{k + 1}" for k in range(len(STAGES))]]:
        d.section(name, "sand")
    d.section("wall", "steel_strip")
    d.interface_law("wall_friction", "MOHR_COULOMB", KN=JOINT_KN, KT=JOINT_KT, PHI=WALL_DELTA,
                    PSI=0.0, C=0.0)
    d.edges("back_face", back)
    for name in sorted(fronts):
        d.edges(f"{name}_face", fronts[name])
    d.edges("tip_face", tip)
    d.keyword("JOINTS", TYPE="GOODMAN6", SET="j_back", LAW="wall_friction",
              INTEGRATION="LOBATTO", EDGES="back_face", SIDE="wall")
    for name in sorted(fronts):
        d.keyword("JOINTS", TYPE="GOODMAN6", SET=f"j_{name}", LAW="wall_friction",
                  INTEGRATION="LOBATTO", EDGES=f"{name}_face", SIDE="wall")
    d.keyword("JOINTS", TYPE="GOODMAN6", SET="j_tip", LAW="wall_friction",
              INTEGRATION="GAUSS", EDGES="tip_face", SIDE="wall")
    return excavation_stages(d, m, xs, ys, "j_front")


def excavation_plate_deck():
    """The cantilever of excavation_deck with the wall as a plate on the line x = 0: the same
    soil meshes (the back soil's and the front soil's faces meet on the line), EA = E t,
    EI = E t^3/12, NU = the strip's (the plate divides both by 1 - nu^2: the strip's
    plane-strain stiffnesses), the same joint law on both faces (FACES=BOTH; the toe node
    shared with the soil below)."""
    x_back, _, x_front, ys = excavation_geometry()
    xs = x_back + [x - WALL_T for x in x_front[1:]]
    m = grid_mesh(xs, ys, lambda xc, yc: excavation_set(xc, yc, strip=False))
    wall_ys = [y for y in ys if y >= -WALL_L - 1e-9]
    line = [m.edge((0.0, wall_ys[j]), (0.0, wall_ys[j + 1])) for j in range(len(wall_ys) - 1)]
    ea, ei = WALL_E * WALL_T, WALL_E * WALL_T**3 / 12
    d = Deck(fmt=".10g")
    d.comment("Cantilever sheet-pile wall in dry sand as a plate, excavated in front in three "
              "stages:",
              "excavation_cantilever.inp with the wall strip replaced by a plate on its axis.",
              "",
              f"Plate EA = E t = {ea:g} kN/m, EI = E t^3/12 = {ei:g} kN m2/m, NU = {WALL_NU} "
              f"(E = {WALL_E:g} kPa, t = {WALL_T} m: the strip's",
              "plane-strain stiffnesses), weightless; Goodman joints (GOODMAN6, the strip's "
              "law) on both faces",
              "(FACES=BOTH; one joint set per body: wif_exc_k removed with its layer). The "
              "same sand, K0 state,",
              "boundaries and stages as the strip deck; the soil meshes are the strip deck's "
              "without the wall's columns.",
              "Post-processing: doc/validation.md, Staged construction.",
              "",
              "Generated by tools/pecplas_py/decks/make_phase_examples.py.")
    d.title("Cantilever wall as a plate, three excavation stages")
    d.units("kN, m, kPa")
    d.analysis("PLANE_STRAIN")
    d.nodes(m.node_list())
    for name in ["back", "front", *[f"exc_{k + 1}" for k in range(len(STAGES))]]:
        d.elements("Q8", name, m.sets[name])
    d.material("sand", type="MOHR_COULOMB", **SAND)
    for name in ["back", "front", *[f"exc_{k + 1}" for k in range(len(STAGES))]]:
        d.section(name, "sand")
    d.interface_law("wall_friction", "MOHR_COULOMB", KN=JOINT_KN, KT=JOINT_KT, PHI=WALL_DELTA,
                    PSI=0.0, C=0.0)
    d.edges("wall_line", line)
    d.keyword("PLATE", SET="wall", EDGES="wall_line", EA=ea, EI=ei, NU=WALL_NU)
    d.keyword("JOINTS", TYPE="GOODMAN6", SET="wif", LAW="wall_friction",
              INTEGRATION="LOBATTO", EDGES="wall_line", FACES="BOTH")
    return excavation_stages(d, m, xs, ys, "wif_exc")


# ---- pile wished in place
def pile_deck():
    """The S2 Goodman deck with an installation phase before its load steps."""
    base = make_s2_decks.deck(make_s2_decks.Mesh(1), "goodman", 1)
    lines = base.splitlines()
    head = ["** The S2 pile (input/s2/s2_goodman.inp: same mesh, materials, joints, load) "
            "installed into the K0 ground.",
            "** The pile and its joints are first mentioned by *ACTIVATE: they are not in "
            "the initial state (the",
            "** ground with the geostatic stress everywhere, the pile's place included). The "
            "nil step `install`",
            "** activates the pile wished in place (with the initial stress of the ground it "
            "replaces) and the",
            "** joints from the soil stresses beside them: nothing moves. Then the S2 load "
            "cycle; its head",
            "** load-settlement curve is S2's (doc/validation.md, Staged construction).",
            "** Generated by tools/pecplas_py/decks/make_phase_examples.py from "
            "make_s2_decks.py.",
            "**"]
    out = head[:]
    for line in lines:
        if line.startswith("*STEP, NAME=load"):
            out += ["*STEP, NAME=install, INCREMENTS=1",
                    "*ACTIVATE, STRESS=WISHED_IN_PLACE",
                    "pile",
                    "*ACTIVATE",
                    "shaft, tip, below",
                    "*END STEP"]
        if line == "S2 pile, goodman interface, refine 1":
            line = "S2 pile wished in place, goodman interface, refine 1"
        out.append(line)
    return "\n".join(out) + "\n"


# ---- embankment
EMB_H, EMB_CREST, EMB_SLOPE, EMB_LIFTS = 3.0, 5.0, 2.0, 3
CLAY = dict(E=5.0e3, NU=0.3, GAMMA=17.0, C=15.0, PHI=20.0, PSI=0.0)
FILL = dict(E=2.0e4, NU=0.3, GAMMA=20.0, C=5.0, PHI=32.0, PSI=0.0)
K0_CLAY = 0.6


def embankment_deck():
    base = EMB_CREST + EMB_SLOPE * EMB_H                  # half-width at the base: 11 m
    ncol = 8
    x_under = [base * i / ncol for i in range(ncol + 1)]
    xs = x_under + cumulative(base, [1.5, 2.0, 2.5, 3.0, 4.0, 6.0])[1:]   # .. 30 m
    ys = cumulative(0.0, [1.0, 1.0, 1.5, 2.0, 2.0, 2.5], -1.0)            # 0 .. -10
    m = grid_mesh(xs, ys, lambda xc, yc: "clay")
    lift = EMB_H / EMB_LIFTS

    def half(y):
        return base - EMB_SLOPE * y

    for k in range(EMB_LIFTS):
        y0, y1 = k * lift, (k + 1) * lift
        for i in range(ncol):
            b0, b1 = half(y0), half(y1)
            m.quad(f"lift_{k + 1}", [(b0 * i / ncol, y0), (b0 * (i + 1) / ncol, y0),
                                     (b1 * (i + 1) / ncol, y1), (b1 * i / ncol, y1)])
    d = Deck(fmt=".10g")
    d.comment("An embankment built in three lifts on soft ground, plane strain, half model.",
              "",
              f"Embankment {EMB_H:g} m high, crest half-width {EMB_CREST:g} m, slopes 1V:"
              f"{EMB_SLOPE:g}H, three lifts of {lift:g} m",
              f"(element sets lift_1..3, Q8). Fill: Mohr-Coulomb E = {FILL['E']:g} kPa, "
              f"nu = {FILL['NU']}, gamma = {FILL['GAMMA']:g},",
              f"c = {FILL['C']:g} kPa, phi = {FILL['PHI']:g} deg, psi = 0. Soft clay 10 m "
              f"deep: Mohr-Coulomb E = {CLAY['E']:g} kPa, nu = {CLAY['NU']},",
              f"gamma = {CLAY['GAMMA']:g}, c = {CLAY['C']:g} kPa, phi = {CLAY['PHI']:g} deg, "
              f"psi = 0, geostatic K0 = {K0_CLAY}. Axis and far side (30 m)",
              "fixed horizontally, bottom fixed. Each lift is activated stress-free (first "
              "mentioned by *ACTIVATE:",
              "not in the initial state) and its weight applied over its phase by its own "
              "GRAVITY pattern; a final",
              "nil step (no pattern, no change) checks the equilibrium at the end of "
              "construction.",
              "",
              "Generated by tools/pecplas_py/decks/make_phase_examples.py.")
    d.title("Embankment built in three lifts on soft clay")
    d.units("kN, m, kPa")
    d.analysis("PLANE_STRAIN")
    d.nodes(m.node_list())
    for name in ["clay", *[f"lift_{k + 1}" for k in range(EMB_LIFTS)]]:
        d.elements("Q8", name, m.sets[name])
    d.material("clay", type="MOHR_COULOMB", **CLAY)
    d.material("fill", type="MOHR_COULOMB", **FILL)
    d.section("clay", "clay")
    for k in range(EMB_LIFTS):
        d.section(f"lift_{k + 1}", "fill")
    xmax, ymin = max(xs), min(ys)
    d.nset("axis", m.nodes_where(lambda x, y: abs(x) < 1e-9 and y <= 1e-9), per_line=16)
    for k in range(EMB_LIFTS):
        d.nset(f"axis_lift_{k + 1}", m.nodes_where(
            lambda x, y, k=k: abs(x) < 1e-9 and k * lift + 1e-9 < y <= (k + 1) * lift + 1e-9))
    d.nset("far", m.nodes_where(lambda x, y: abs(x - xmax) < 1e-9), per_line=16)
    d.nset("bottom", m.nodes_where(lambda x, y: abs(y - ymin) < 1e-9), per_line=16)
    d.boundary("axis, X", *[f"axis_lift_{k + 1}, X" for k in range(EMB_LIFTS)], "far, X",
               "bottom, XY")
    d.initial_stress("GEOSTATIC", f"clay, 0.0, {K0_CLAY}")
    for k in range(EMB_LIFTS):
        d.load(f"fill_{k + 1}", "GRAVITY", f"lift_{k + 1}")
    for k in range(EMB_LIFTS):
        d.keyword("STEP", NAME=f"lift_{k + 1}", INCREMENTS=5)
        d.data(f"fill_{k + 1}", 1.0)
        d.keyword("ACTIVATE").data(f"lift_{k + 1}")
        d.keyword("END STEP")
    d.keyword("STEP", NAME="equilibrium", INCREMENTS=1)
    d.keyword("END STEP")
    d.solver(METHOD="NEWTON", MAX_ITERATIONS=50, MAX_CUTS=6).output(EVERY=1)
    return d.text()


DECKS = {"excavation_cantilever.inp": excavation_deck,
         "excavation_cantilever_plate.inp": excavation_plate_deck,
         "pile_wished_in_place.inp": pile_deck,
         "embankment_stages.inp": embankment_deck}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "input" / "examples"))
    a = ap.parse_args(argv)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    for name, make in DECKS.items():
        p = out / name
        p.write_text(make())
        print(p)


if __name__ == "__main__":
    main()
