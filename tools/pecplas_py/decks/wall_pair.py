"""A retaining wall in the ground twice: as a continuum strip and as a plate on a line
(doc/validation.md, Structures: the wall in soil, plate against strip). Used by the test
test/python/test_wall_consistency.py and the study scenes/wall_consistency.py.

The ground: soil from x = -B to the wall's front face (excavated side, x < 0) and from its back
face to B behind, depth D, plane strain, K0 geostatic state; the soil in front of the wall is
dug to the depth H in one or more phases. The strip deck has the wall's columns (x = 0 to t,
`ncross` elements across, E_w, nu_w, the unit weight of the soil so that the geostatic state is
in equilibrium), joints on its back and front faces (SIDE=wall; a front joint set per stage,
removed with its layer); its toe is bonded to the soil below. The plate deck has the same soil
meshes, front and back meeting on the line x = 0, the plate EA = E_w t, EI = E_w t^3/12,
NU = nu_w (the plate divides both by 1 - nu_w^2: the strip's plane-strain stiffnesses; its
shear stiffness 5/6 G t is the strip's with the Timoshenko factor) and the same joints on both
faces (FACES=BOTH, EXTEND=0: the toe node is shared with the soil below, as the strip's base).

    from pecplas_py.decks.wall_pair import WallPair, deck
    text = deck(WallPair(element="Q8", ncross=2, row=0.25), plate=True)

Meshes are structured: columns graded away from the wall, rows of `row` down to the toe and
graded below; every element is a Q4 or Q8 (`element`), the plate's elements 2- or 3-node
accordingly, the joints GOODMAN4 or GOODMAN6.
"""
from dataclasses import dataclass, field

from pecplas_py.deck import Deck


@dataclass
class WallPair:
    """The data of the pair (defaults: the test's configuration)."""
    element: str = "Q8"            # Q4 or Q8 (soil and strip)
    ncross: int = 2                # strip elements across the thickness
    row: float = 0.25              # row height along the wall [m]
    t: float = 0.4                 # wall thickness [m]
    wall_l: float = 8.0            # wall length [m]
    stages: tuple = (3.0,)         # excavation depth after each phase [m]
    e_w: float = 3.0e7             # wall E [kPa]
    nu_w: float = 0.2
    soil: dict = field(default_factory=lambda: dict(E=3.0e4, NU=0.3, GAMMA=18.0))
    soil_type: str = "ELASTIC"     # or MOHR_COULOMB (then soil needs C, PHI, PSI)
    k0: float = 0.5
    kn: float = 1.0e6              # joint stiffnesses [kPa/m]
    kt: float = 3.0e4
    law: str = "ELASTIC"           # joint law type; MOHR_COULOMB adds PHI=delta, C=0, PSI=0
    delta: float = 20.0
    away: tuple = (0.4, 0.6, 0.9, 1.3, 1.8, 2.5, 3.5)     # columns from each face [m]
    below: tuple = (0.5, 1.0, 1.5, 2.0, 3.0)               # rows under the toe [m]
    increments: int = 1
    clamp_toe: bool = False        # the wall's toe held (see deck)
    tip_k: float = 0.0             # > 0: the strip's base on an elastic joint KN = KT = tip_k


def _cumulative(x0, steps, sign=1.0):
    xs = [x0]
    for h in steps:
        xs.append(xs[-1] + sign * h)
    return xs


class _Mesh:
    """Q4 or Q8 quadrangles whose nodes are shared by coordinates."""

    def __init__(self, element):
        self.element, self.ids, self.xy, self.sets, self.eid = element, {}, [], {}, 0

    def node(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.ids:
            self.xy.append((x, y))
            self.ids[key] = len(self.xy)
        return self.ids[key]

    def quad(self, set_name, x0, x1, y0, y1):
        corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
        c = [self.node(*p) for p in corners]
        if self.element == "Q8":
            c += [self.node((corners[i][0] + corners[(i + 1) % 4][0]) / 2,
                            (corners[i][1] + corners[(i + 1) % 4][1]) / 2) for i in range(4)]
        self.eid += 1
        self.sets.setdefault(set_name, []).append((self.eid, *c))

    def edge(self, a, b):
        """(end, end[, mid]) node ids of the straight edge a-b."""
        pts = [a, b] + ([((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)] if self.element == "Q8" else [])
        return tuple(self.ids[(round(p[0], 9), round(p[1], 9))] for p in pts)

    def nodes_where(self, test):
        return [i for (x, y), i in sorted(self.ids.items(), key=lambda kv: kv[1]) if test(x, y)]


def geometry(p, plate):
    """Grid lines (xs, ys) of the deck and the wall's x range (x0, x1; x0 == x1 for the plate)."""
    t = 0.0 if plate else p.t
    front = _cumulative(0.0, p.away, -1.0)[::-1]
    if plate:
        wall = [0.0]
    else:
        n = p.ncross
        wall = [t * k / n for k in range(n + 1)]
    back = _cumulative(t, p.away)
    nrow = round(p.wall_l / p.row)
    ys = [-p.row * j for j in range(nrow + 1)] + \
        _cumulative(-p.wall_l, p.below, -1.0)[1:]
    return front[:-1] + wall + back[1:], ys, 0.0, t


def stage_of(p, yc):
    """Phase (1, 2, ...) that digs a front cell of centre depth yc; 0 below the last."""
    top = 0.0
    for k, d in enumerate(p.stages, 1):
        if -d < yc < -top:
            return k
        top = d
    return 0


def deck(p, plate):
    """The deck text of the pair `p` (a WallPair): the plate variant or the strip."""
    xs, ys, x0, x1 = geometry(p, plate)
    m = _Mesh(p.element)
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            xa, xb, ya, yb = xs[i], xs[i + 1], ys[j + 1], ys[j]
            xc, yc = (xa + xb) / 2, (ya + yb) / 2
            if x0 < xc < x1 and yc > -p.wall_l:
                name = "wall"
            elif xc < x0 and stage_of(p, yc):
                name = f"exc_{stage_of(p, yc)}"
            else:
                name = "soil"
            m.quad(name, xa, xb, ya, yb)
    wall_ys = [y for y in ys if y >= -p.wall_l - 1e-9]
    d = Deck(fmt=".10g")
    what = "a plate" if plate else f"a continuum strip ({p.ncross} {p.element} across)"
    d.comment(f"A cantilever wall in {p.soil_type.lower()} soil as {what}: "
              "pecplas_py.decks.wall_pair (doc/validation.md, Structures).")
    d.title(f"Wall in soil as {what}")
    d.units("kN, m, kPa")
    d.analysis("PLANE_STRAIN")
    d.nodes([(i + 1, x, y) for i, (x, y) in enumerate(m.xy)])
    names = ["soil"] + [f"exc_{k + 1}" for k in range(len(p.stages))] + ([] if plate else ["wall"])
    for name in names:
        d.elements(p.element, name, m.sets[name])
    if p.soil_type == "ELASTIC":
        d.material("soil", **p.soil)
    else:
        d.material("soil", type=p.soil_type, **p.soil)
    for name in names[:-1] if not plate else names:
        d.section(name, "soil")
    law = dict(KN=p.kn, KT=p.kt)
    if p.law != "ELASTIC":
        law.update(PHI=p.delta, PSI=0.0, C=0.0)
    d.interface_law("wall_face", p.law, **law)
    jtype = "GOODMAN6" if p.element == "Q8" else "GOODMAN4"
    integ = dict(INTEGRATION="LOBATTO") if p.element == "Q8" else {}
    tops = [0.0, *[-s for s in p.stages]]

    def front_name(yc):
        for k in range(len(p.stages)):
            if tops[k + 1] < yc < tops[k]:
                return f"front_{k + 1}"
        return "front_deep"

    if plate:
        d.edges("wall_line", [m.edge((0.0, wall_ys[j]), (0.0, wall_ys[j + 1]))
                              for j in range(len(wall_ys) - 1)])
        d.keyword("PLATE", SET="wall", EDGES="wall_line", EA=p.e_w * p.t,
                  EI=p.e_w * p.t ** 3 / 12, NU=p.nu_w)
        d.keyword("JOINTS", TYPE=jtype, SET="wif", LAW="wall_face", EDGES="wall_line",
                  FACES="BOTH", **integ)
    else:
        d.material("wall", E=p.e_w, NU=p.nu_w, GAMMA=p.soil["GAMMA"])
        d.section("wall", "wall")
        d.edges("back_face", [m.edge((x1, wall_ys[j + 1]), (x1, wall_ys[j]))
                              for j in range(len(wall_ys) - 1)])
        fronts = {}
        for j in range(len(wall_ys) - 1):
            yc = (wall_ys[j] + wall_ys[j + 1]) / 2
            fronts.setdefault(front_name(yc), []).append(
                m.edge((x0, wall_ys[j + 1]), (x0, wall_ys[j])))
        d.edges("front_deep", fronts["front_deep"])
        for k in range(len(p.stages)):
            d.edges(f"front_{k + 1}", fronts[f"front_{k + 1}"])
        if p.tip_k > 0:
            d.interface_law("tip", "ELASTIC", KN=p.tip_k, KT=p.tip_k)
            wx = [x for x in xs if x0 - 1e-9 <= x <= x1 + 1e-9]
            d.edges("tip_face", [m.edge((wx[i], -p.wall_l), (wx[i + 1], -p.wall_l))
                                 for i in range(len(wx) - 1)])
            d.keyword("JOINTS", TYPE=jtype, SET="j_tip", LAW="tip", EDGES="tip_face",
                      SIDE="wall")
        d.keyword("JOINTS", TYPE=jtype, SET="j_back", LAW="wall_face", EDGES="back_face",
                  SIDE="wall", **integ)
        for name in ["front_deep", *[f"front_{k + 1}" for k in range(len(p.stages))]]:
            d.keyword("JOINTS", TYPE=jtype, SET=f"j_{name}", LAW="wall_face", EDGES=name,
                      SIDE="wall", **integ)
    xmin, xmax, ymin = min(xs), max(xs), min(ys)
    d.nset("sides", m.nodes_where(lambda x, y: abs(x - xmin) < 1e-9 or abs(x - xmax) < 1e-9),
           per_line=16)
    d.nset("bottom", m.nodes_where(lambda x, y: abs(y - ymin) < 1e-9), per_line=16)
    rows = ["sides, X", "bottom, XY"]
    if p.clamp_toe:
        # the wall's toe held: the plate's toe node in x, y and rotation, the strip's base
        # (its nodes across the thickness) in x and y
        d.nset("toe", m.nodes_where(lambda x, y: x0 - 1e-9 <= x <= x1 + 1e-9 and
                                    abs(y + p.wall_l) < 1e-9))
        rows.append("toe, ALL" if plate else "toe, XY")
    d.boundary(*rows)
    d.initial_stress("GEOSTATIC", f"ALL, 0.0, {p.k0:g}")
    for k in range(len(p.stages)):
        joint = f"wif_exc_{k + 1}" if plate else f"j_front_{k + 1}"
        d.keyword("STEP", NAME=f"excavate_{k + 1}", INCREMENTS=p.increments)
        d.keyword("DEACTIVATE").data(f"exc_{k + 1}", joint)
        d.keyword("END STEP")
    d.solver(METHOD="NEWTON", MAX_ITERATIONS=50, MAX_CUTS=6, TOLERANCE=1e-9).output(EVERY=1)
    return d.text()
