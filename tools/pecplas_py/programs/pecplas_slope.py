#!/usr/bin/env python3
"""pecplas-slope: limit-equilibrium factor of safety of a pecplas model (doc/theory.md, section
"Limit equilibrium of slopes"; doc/tools.md, "pecplas-slope").

    pecplas-slope INPUT [--results RESULTS.h5] [-o OUT.png] [--slices N]
                  [--grid NX NY NR] [--refine L] [--centres X0 X1 Y0 Y1]
                  [--circle XC YC R] [--phreatic X,Y X,Y ... | --ru RU] [--gamma-w GW]
                  [--increments K] [--data OUT.json] [--no-plot]

INPUT is a deck (.inp) or a results file of pecplas (.h5, which keeps the mesh and the deck).
The soil is the model's active massif element sets with their *MATERIAL: unit weight GAMMA,
cohesion C and friction angle PHI (Mohr-Coulomb, or Drucker-Prager's Mohr-Coulomb parameters);
an ELASTIC set has weight but no strength, so a circle may not cut it. Only the weight of the
soil acts (no surface loads, joints, or structures).

Circular slip surfaces, slices in vertical columns: Bishop's simplified method (moment
equilibrium, horizontal interslice forces) is minimised over a grid of centres and radii
(--grid; the radii given by the level of the circle's lowest point, the levels of the
ground's corners added), then by a pattern search from the three best circles of the grid
(the step halved --refine times); Spencer's method (force and moment equilibrium, interslice
forces of one inclination) is then solved on the same circle. --circle analyses one circle
and searches nothing.

Pore pressure at the base of a slice: below a phreatic line (--phreatic, the points of a
polyline, hydrostatic below it: u = gamma_w (y_w - y)), or r_u = u / (weight of the column
per unit area) (--ru); gamma_w from --gamma-w or from the deck's *UNITS (9.81 kN/m3).

The picture (default INPUT with .slope.png): the mesh, coloured by the magnitude of the
incremental displacement over the last K written increments of RESULTS (the finite-element
mechanism; --increments K, default 1) or by material without results, with the critical
circle's arc. Prints both factors side by side.

Needs Python 3 with NumPy (h5py for a results file, matplotlib for the picture); installed
stand-alone by `make install`. Exit codes: 0 done, 2 bad input (the message names the file,
its line and keyword), 3 no admissible circle (or no Bishop factor on the given circle).
"""
import argparse
import json
import math
import os
import sys
from pathlib import Path

import numpy as np

CORNERS = {"T3": 3, "T6": 3, "Q4": 4, "Q8": 4, "Q8R": 4, "Q9": 4}
OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7], "Q8R": [0, 4, 1, 5, 2, 6, 3, 7],
           "Q9": [0, 4, 1, 5, 2, 6, 3, 7]}
NODES_PER = {"T3": 3, "T6": 6, "Q4": 4, "Q8": 8, "Q8R": 8}
FORCE = {"N": 1000.0, "KN": 1.0, "MN": 1e-3}          # per kN
LENGTH = {"M": 1.0, "CM": 100.0, "MM": 1000.0}        # per m
GAMMA_W_KN_M3 = 9.81
GAUSS = np.polynomial.legendre.leggauss(3)


class InputError(Exception):
    """Bad input: printed as `pecplas-slope: message`, exit code 2."""


class NoCircle(Exception):
    """No admissible circle: exit code 3."""


# ------------------------------------------------------------------ the deck
class Block:
    """One keyword block: keyword, options, data lines as (fields, where)."""

    def __init__(self, keyword, options, where):
        self.keyword, self.options, self.where, self.data = keyword, options, where, []

    def err(self, msg, where=None):
        return InputError(f"{where or self.where}: [{self.keyword}] {msg}")


def deck_lines(path, seen=()):
    """(text, 'file:line') of a deck, *INCLUDE expanded."""
    path = Path(path)
    try:
        lines = path.read_text().splitlines()
    except OSError as e:
        raise InputError(f"{path}: cannot read the deck ({e.strerror})") from None
    for k, raw in enumerate(lines, 1):
        where = f"{path}:{k}"
        head = raw.split("!")[0].split("#")[0].strip()
        if head.upper().replace(" ", "").startswith("*INCLUDE"):
            opts = dict(p.partition("=")[::2] for p in
                        (q.strip() for q in head.split(",")[1:]))
            name = {k.strip().upper(): v.strip() for k, v in opts.items()}.get("FILE")
            if not name:
                raise InputError(f"{where}: [*INCLUDE] FILE= expected")
            inc = (path.parent / name).resolve()
            if inc in seen or inc == path.resolve():
                raise InputError(f"{where}: [*INCLUDE] {name} includes itself")
            if not inc.is_file():
                raise InputError(f"{where}: [*INCLUDE] no file {name}")
            yield from deck_lines(inc, (*seen, path.resolve()))
        else:
            yield raw, where


def parse_blocks(lines):
    """Blocks of (text, where) lines: the deck syntax of doc/deck.md."""
    blocks = []
    for raw, where in lines:
        line = raw.split("!")[0].split("#")[0].strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            parts = [p.strip() for p in line.split(",")]
            opts = {}
            for p in parts[1:]:
                k, _, v = p.partition("=")
                opts[k.strip().upper()] = v.strip()
            blocks.append(Block(parts[0].upper(), opts, where))
        elif blocks:
            fields = [f for f in line.replace(",", " ").split() if f]
            blocks[-1].data.append((fields, where))
    return blocks


def number(text, block, where):
    try:
        return float(text.lower().replace("d", "e"))
    except ValueError:
        raise block.err(f"'{text}' is not a number", where) from None


class Material:
    """Strength and unit weights of a *MATERIAL: GAMMA (or GAMMA_UNSAT) above the phreatic
    level, GAMMA_SAT below it (default: the same)."""

    def __init__(self, name, kind, c, phi, gamma, where, gamma_sat=None):
        self.name, self.kind, self.c, self.phi, self.gamma, self.where = \
            name, kind, c, phi, gamma, where
        self.gamma_sat = gamma if gamma_sat is None else gamma_sat

    @property
    def strength(self):
        return self.kind in ("MOHR_COULOMB", "DRUCKER_PRAGER")

    def __repr__(self):
        return f"{self.name}({self.kind}, c={self.c}, phi={self.phi}, gamma={self.gamma})"


def materials_of(blocks):
    out = {}
    for b in blocks:
        if b.keyword != "*MATERIAL":
            continue
        name = b.options.get("NAME")
        if not name:
            raise b.err("NAME= expected")
        kind = b.options.get("TYPE", "ELASTIC").upper()
        props = {}
        for fields, where in b.data:
            text = " ".join(fields).replace(" = ", "=").replace("= ", "=").replace(" =", "=")
            for item in text.split():
                k, eq, v = item.partition("=")
                if eq:
                    props[k.upper()] = (number(v, b, where), where)
        first = b.data[0][1] if b.data else b.where
        gamma = props.get("GAMMA", props.get("GAMMA_UNSAT", (0.0, first)))[0]
        gamma_sat = props.get("GAMMA_SAT", (gamma, first))[0]
        c = props.get("C", (0.0, first))[0]
        phi = props.get("PHI", (0.0, first))[0]
        if gamma < 0:
            raise b.err(f"GAMMA = {gamma:g} < 0", first)
        if kind in ("MOHR_COULOMB", "DRUCKER_PRAGER"):
            if c < 0 or not 0 <= phi < 90:
                raise b.err(f"C = {c:g}, PHI = {phi:g}: C >= 0 and 0 <= PHI < 90 expected",
                            first)
            if c == 0 and phi == 0:
                raise b.err("material without strength (C = 0 and PHI = 0)", first)
        if gamma_sat < gamma:
            raise b.err(f"GAMMA_SAT = {gamma_sat:g} below GAMMA = {gamma:g}", first)
        out[name.upper()] = Material(name, kind, c, phi, gamma, b.where, gamma_sat)
    return out


def gamma_w_of(blocks):
    """The unit weight of water in the deck's *UNITS, or None without them."""
    for b in blocks:
        if b.keyword == "*UNITS" and b.data:
            words = [w.upper() for w in b.data[0][0] for w in w.replace(";", " ").split()]
            f = next((FORCE[w] for w in words if w in FORCE), None)
            length = next((LENGTH[w] for w in words if w in LENGTH), None)
            if f is not None and length is not None:
                return GAMMA_W_KN_M3 * f / length ** 3
    return None


class Soil:
    """The polygons (element corners) of the active massif sets and their materials."""

    def __init__(self, polygons, mats, sets, source, wet=None):
        self.polygons = polygons          # list of (ncorner, 2) arrays
        self.mats = mats                  # material per polygon
        self.sets = sets                  # [(set name, etype, connectivity rows, coords)]
        self.source = source
        # per polygon: False in a *DRY set (no pore pressure, no saturated weight)
        self.wet = [True] * len(polygons) if wet is None else wet


def active_sets(blocks, names):
    """Element sets active after the last step, and their materials (*ACTIVATE,
    *DEACTIVATE, *CHANGE_MATERIAL of doc/deck.md, "Phases")."""
    first = {}
    steps = []
    for b in blocks:
        if b.keyword == "*STEP":
            steps.append([])
        elif b.keyword in ("*ACTIVATE", "*DEACTIVATE", "*CHANGE_MATERIAL") and steps:
            steps[-1].append(b)
            for fields, _ in b.data:
                targets = fields[:1] if b.keyword == "*CHANGE_MATERIAL" else fields
                for t in targets:
                    first.setdefault(t.upper(), b.keyword)
    active = {n: first.get(n) != "*ACTIVATE" for n in names}
    change = {}
    for step in steps:
        for b in step:
            for fields, _ in b.data:
                if b.keyword == "*CHANGE_MATERIAL" and len(fields) >= 2:
                    change[fields[0].upper()] = fields[1].upper()
                elif b.keyword != "*CHANGE_MATERIAL":
                    for t in fields:
                        if t.upper() in active:
                            active[t.upper()] = b.keyword == "*ACTIVATE"
    return active, change


def soil_from_deck(path):
    blocks = parse_blocks(deck_lines(path))
    for b in blocks:
        if b.keyword == "*MESH":
            raise b.err("a Gmsh mesh: run pecplas on the deck and give its results file "
                        "(.h5), which holds the mesh")
    nodes = {}
    sets = {}
    section = {}
    for b in blocks:
        if b.keyword == "*NODES":
            for fields, where in b.data:
                if len(fields) != 3:
                    raise b.err("id, x, y expected", where)
                nodes[int(number(fields[0], b, where))] = (number(fields[1], b, where),
                                                          number(fields[2], b, where))
        elif b.keyword == "*ELEMENTS":
            etype = b.options.get("TYPE", "").upper()
            name = b.options.get("SET", "")
            if etype not in NODES_PER:
                raise b.err(f"TYPE={etype or '?'}: one of {', '.join(NODES_PER)} expected")
            rows = sets.setdefault(name.upper(), (name, etype, []))[2]
            for fields, where in b.data:
                if len(fields) != NODES_PER[etype] + 1:
                    raise b.err(f"id and {NODES_PER[etype]} node ids expected", where)
                rows.append(([int(number(f, b, where)) for f in fields[1:]], where, b))
        elif b.keyword == "*SECTION":
            section[b.options.get("SET", "").upper()] = (b.options.get("MATERIAL", "").upper(),
                                                         b)
    return build_soil(blocks, path, nodes, sets, section, None)


def dry_sets(blocks):
    """Names (upper case) of the element sets of *DRY: no water acts in them."""
    return {f.upper() for b in blocks if b.keyword == "*DRY" for fields, _ in b.data
            for f in fields}


def is_dry(name, dry):
    """A set named in *DRY, or a part <name>_<TYPE> of a Gmsh group named there."""
    key = name.upper()
    head, _, tail = key.rpartition("_")
    return key in dry or (tail in NODES_PER and head in dry)


def plane_strain(blocks):
    for b in blocks:
        if b.keyword == "*ANALYSIS" and b.options.get("TYPE", "").upper() == "AXISYMMETRIC":
            raise b.err("an axisymmetric model: the slices need plane strain")


def build_soil(blocks, source, nodes, sets, section, active_names):
    plane_strain(blocks)
    mats = materials_of(blocks)
    dry = dry_sets(blocks)
    wet = []
    active, change = active_sets(blocks, list(sets))
    if active_names is not None:
        active = {n: n in active_names for n in sets}
    polygons, pmats, drawn = [], [], []
    for key, (name, etype, rows) in sets.items():
        if not active.get(key, True):
            continue
        mname, sb = section.get(key, (None, None))
        mname = change.get(key, mname)
        if mname is None:
            raise InputError(f"{source}: element set {name} has no *SECTION")
        if mname not in mats:
            raise sb.err(f"no *MATERIAL {mname}") if sb else \
                InputError(f"{source}: no *MATERIAL {mname} (set {name})")
        m = mats[mname]
        conn = []
        for ids, where, b in rows:
            try:
                xy = np.array([nodes[i] for i in ids], float)
            except KeyError as e:
                raise b.err(f"no node {e.args[0]}", where) from None
            conn.append(xy)
            polygons.append(xy[:CORNERS[etype]])
            pmats.append(m)
            wet.append(not is_dry(name, dry))
        drawn.append((name, etype, conn, m))
    if not polygons:
        raise InputError(f"{source}: no active massif element set")
    return Soil(polygons, pmats, drawn, str(source), wet), blocks


def text(v):
    if isinstance(v, (bytes, np.bytes_)):
        return v.decode()
    return str(v)


def soil_from_results(path):
    import h5py
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise InputError(f"{path}: not a readable results file ({e})") from None
    with f:
        if "mesh/coordinates" not in f or "mesh/sets" not in f:
            raise InputError(f"{path}: no /mesh (not a pecplas results file)")
        deck = text(f.attrs.get("deck_text", ""))
        blocks = parse_blocks((ln, f"{path} (deck_text):{k}")
                              for k, ln in enumerate(deck.splitlines(), 1))
        x = f["mesh/coordinates"][()]
        sets, section = {}, {}
        for name, s in f["mesh/sets"].items():
            etype = text(s.attrs["etype"])
            conn = s["connectivity"][()]
            sets[name.upper()] = (name, etype, [(x[row], None, None) for row in conn])
            section[name.upper()] = (text(s.attrs.get("material", "")).upper(), None)
        keys = sorted(f["increments"].keys()) if "increments" in f else []
        names = None
        if keys and "sets" in f[f"increments/{keys[-1]}"]:
            names = {n.upper() for n in f[f"increments/{keys[-1]}/sets"]}
    soil, blocks = build_soil_from_coords(blocks, path, sets, section, names)
    return soil, blocks


def build_soil_from_coords(blocks, source, sets, section, names):
    plane_strain(blocks)
    mats = materials_of(blocks)
    dry = dry_sets(blocks)
    polygons, pmats, drawn, wet = [], [], [], []
    for key, (name, etype, rows) in sets.items():
        if names is not None and key not in names:
            continue
        mname = section[key][0]
        if mname not in mats:
            raise InputError(f"{source}: set {name}: no *MATERIAL {mname} in the deck text")
        m = mats[mname]
        conn = [xy for xy, _, _ in rows]
        polygons += [xy[:CORNERS[etype]] for xy in conn]
        pmats += [m] * len(conn)
        wet += [not is_dry(name, dry)] * len(conn)
        drawn.append((name, etype, conn, m))
    if not polygons:
        raise InputError(f"{source}: no active massif element set")
    return Soil(polygons, pmats, drawn, str(source), wet), blocks


# ------------------------------------------------------------------ the soil in columns
class Profile:
    """The soil cut into vertical strips between the x of the element corners, where every
    element's top and bottom are straight: per strip, the stacked pieces (consecutive
    elements of one material merged) with their bottom and top lines and material."""

    def __init__(self, soil):
        polys = soil.polygons
        kinds = list(zip(soil.mats, soil.wet))
        self.materials = list(dict.fromkeys(kinds))      # (material, wet) pairs
        mat_index = np.array([self.materials.index(k) for k in kinds])
        xs = np.unique(np.concatenate([p[:, 0] for p in polys]))
        size = np.ptp(np.concatenate(polys), axis=0).max()
        self.tol = 1e-9 * size
        keep = np.concatenate([[True], np.diff(xs) > self.tol])
        xs = xs[keep]
        self.x_min, self.x_max = xs[0], xs[-1]
        xmin = np.array([p[:, 0].min() for p in polys])
        xmax = np.array([p[:, 0].max() for p in polys])
        strips = []
        for a, b in zip(xs[:-1], xs[1:]):
            sel = np.nonzero((xmin <= a + self.tol) & (xmax >= b - self.tol))[0]
            pieces = []
            xa, xb = a + 0.25 * (b - a), a + 0.75 * (b - a)
            for e in sel:
                lo_a, hi_a = cut(polys[e], xa)
                lo_b, hi_b = cut(polys[e], xb)
                if lo_a is None or lo_b is None:
                    continue
                pieces.append(ends(a, b, xa, xb, lo_a, lo_b) + ends(a, b, xa, xb, hi_a, hi_b)
                              + (mat_index[e],))
            strips.append((a, b, merge(pieces, self.tol)))
        strips = [s for s in strips if s[2]] if strips else []
        if not strips:
            raise InputError(f"{soil.source}: the elements enclose no area")
        strips = join_strips(strips, self.tol)
        self.kinks = np.array([s[0] for s in strips[1:]])
        self.X = np.array([s[0] for s in strips] + [strips[-1][1]])
        npmax = max(len(s[2]) for s in strips)
        shape = (len(strips), npmax)
        self.b0, self.b1, self.t0, self.t1 = (np.zeros(shape) for _ in range(4))
        self.mat = np.full(shape, -1)
        for k, (_, _, pieces) in enumerate(strips):
            for j, p in enumerate(pieces):
                self.b0[k, j], self.b1[k, j], self.t0[k, j], self.t1[k, j], self.mat[k, j] = p
        mats = [m for m, _ in self.materials]
        self.gamma = np.array([m.gamma for m in mats] + [0.0])
        # the extra weight below the phreatic level (saturated against moist), wet sets only
        self.gamma_extra = np.array([(m.gamma_sat - m.gamma) * w for m, w in self.materials]
                                    + [0.0])
        self.wet = np.array([w for _, w in self.materials] + [False])
        self.c = np.array([m.c for m in mats] + [0.0])
        self.tanphi = np.array([math.tan(math.radians(m.phi)) for m in mats] + [0.0])
        self.strong = np.array([m.strength for m in mats] + [False])
        top = np.where(self.mat >= 0, self.t0, -np.inf).max(axis=1)
        top1 = np.where(self.mat >= 0, self.t1, -np.inf).max(axis=1)
        self.s0, self.s1 = top, top1       # ground surface at the strip ends
        self.bottom = min(np.where(self.mat >= 0, self.b0, np.inf).min(),
                          np.where(self.mat >= 0, self.b1, np.inf).min())
        self.top = max(top.max(), top1.max())

    def lines(self, x):
        """Strip index, bottoms, tops (n, P) and materials of the columns at x (n,)."""
        k = np.clip(np.searchsorted(self.X, x, side="right") - 1, 0, len(self.s0) - 1)
        t = ((x - self.X[k]) / (self.X[k + 1] - self.X[k]))[:, None]
        bot = self.b0[k] + t * (self.b1[k] - self.b0[k])
        top = self.t0[k] + t * (self.t1[k] - self.t0[k])
        return k, bot, top, self.mat[k]

    def surface(self, x):
        k = np.clip(np.searchsorted(self.X, x, side="right") - 1, 0, len(self.s0) - 1)
        t = (x - self.X[k]) / (self.X[k + 1] - self.X[k])
        return self.s0[k] + t * (self.s1[k] - self.s0[k])


def cut(poly, x):
    """Lowest and highest y of the (convex) polygon on the vertical line x."""
    p, q = poly, np.roll(poly, -1, axis=0)
    dx = q[:, 0] - p[:, 0]
    on = (np.minimum(p[:, 0], q[:, 0]) <= x) & (x <= np.maximum(p[:, 0], q[:, 0])) & (dx != 0)
    if not on.any():
        return None, None
    y = p[on, 1] + (x - p[on, 0]) * (q[on, 1] - p[on, 1]) / dx[on]
    return y.min(), y.max()


def ends(a, b, xa, xb, ya, yb):
    s = (yb - ya) / (xb - xa)
    return (ya - s * (xa - a), yb + s * (b - xb))


def merge(pieces, tol):
    """Stacked pieces of one strip, consecutive ones of one material joined."""
    pieces = sorted(pieces, key=lambda p: p[0] + p[1])
    out = []
    for p in pieces:
        if out and out[-1][4] == p[4] and abs(out[-1][2] - p[0]) < tol and \
                abs(out[-1][3] - p[1]) < tol:
            out[-1] = (out[-1][0], out[-1][1], p[2], p[3], p[4])
        else:
            out.append(p)
    return out


def join_strips(strips, tol):
    """Neighbouring strips whose pieces continue each other in straight lines become one."""
    out = [strips[0]]
    for a, b, pieces in strips[1:]:
        a0, b0, prev = out[-1]
        same = len(prev) == len(pieces) and all(
            p[4] == q[4] and all(abs(p[i + 1] - q[i]) < tol and
                                 abs((p[i + 1] - p[i]) / (b0 - a0) - (q[i + 1] - q[i]) / (b - a))
                                 < tol / (b - a) for i in (0, 2))
            for p, q in zip(prev, pieces)) and abs(b0 - a) < tol
        if same:
            out[-1] = (a0, b, [(p[0], q[1], p[2], q[3], p[4]) for p, q in zip(prev, pieces)])
        else:
            out.append((a, b, pieces))
    return out


# ------------------------------------------------------------------ water
class NoWater:
    """Dry soil: no pore pressure. A water input has `pressure(x, y_base, sigma_v)` (the
    pore pressure at the base points, given the vertical total stress of their columns)
    and `breaks(circle)` (x where the pressure along the arc has a kink: the slices are cut
    there)."""
    text = "none"

    def pressure(self, x, y_base, sigma_v):
        return np.zeros_like(x)

    def breaks(self, circle):
        return np.zeros(0)


class Phreatic:
    """A phreatic line (polyline, x increasing; one point: horizontal), hydrostatic pressure
    below it: u = gamma_w (y_w(x) - y), zero above it; constant beyond its end points."""

    def __init__(self, points, gamma_w, name=None):
        pts = np.asarray(points, float)
        if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 1:
            raise InputError("--phreatic: points X,Y expected")
        if len(pts) == 1:                                  # a horizontal level
            pts = np.array([[pts[0, 0] - 1.0, pts[0, 1]], [pts[0, 0] + 1.0, pts[0, 1]]])
        if np.any(np.diff(pts[:, 0]) <= 0):
            raise InputError("--phreatic: the x of the points must increase")
        if gamma_w is None or gamma_w <= 0:
            raise InputError("--phreatic: the unit weight of water is not known: give "
                             "--gamma-w (or *UNITS in the deck)")
        self.points, self.gamma_w = pts, float(gamma_w)
        self.text = (f"phreatic line {' '.join(f'({x:g}, {y:g})' for x, y in pts)}, "
                     f"gamma_w = {gamma_w:g}" + (f" (*WATER {name} of the deck)" if name else ""))

    def level(self, x):
        return np.interp(x, self.points[:, 0], self.points[:, 1])

    def pressure(self, x, y_base, sigma_v):
        return self.gamma_w * np.maximum(0.0, self.level(x) - y_base)

    def breaks(self, circle):
        """The line's vertices and its crossings with the circle's lower arc."""
        xc, yc, r = circle
        out = list(self.points[:, 0])
        p = self.points              # the level is constant beyond its end points
        far = np.array([[min(p[0, 0], xc - r) - 1.0, p[0, 1]],
                        [max(p[-1, 0], xc + r) + 1.0, p[-1, 1]]])
        p = np.vstack([far[:1], p, far[1:]])
        for (x0, y0), (x1, y1) in zip(p[:-1], p[1:]):
            m = (y1 - y0) / (x1 - x0)
            e = y0 + m * (xc - x0) - yc
            disc = r * r * (1 + m * m) - e * e
            if disc > 0:
                for d in ((-e * m - math.sqrt(disc)) / (1 + m * m),
                          (-e * m + math.sqrt(disc)) / (1 + m * m)):
                    if x0 < xc + d < x1 and e + m * d <= 0:
                        out.append(xc + d)
        return np.array(out)


class PoreRatio:
    """Pore pressure ratio r_u: u = r_u times the vertical total stress of the column."""

    def __init__(self, ru):
        if not 0 <= ru < 1:
            raise InputError(f"--ru {ru:g}: 0 <= r_u < 1 expected")
        self.ru = float(ru)
        self.text = f"r_u = {ru:g}"

    def pressure(self, x, y_base, sigma_v):
        return self.ru * sigma_v

    def breaks(self, circle):
        return np.zeros(0)


# ------------------------------------------------------------------ one circle
def arc(x, xc, yc, r):
    return yc - np.sqrt(np.maximum(r * r - (x - xc) ** 2, 0.0))


def mass_extent(prof, xc, yc, r):
    """[(x_entry, x_exit)] of the stretches where the circle's lower arc is below the
    ground, or a reason why the circle is not admissible (str)."""
    X, s0, s1 = prof.X, prof.s0, prof.s1
    a = np.maximum(X[:-1], xc - r)
    b = np.minimum(X[1:], xc + r)
    ok = b > a
    if not ok.any():
        return "misses the model"
    w = X[1:] - X[:-1]
    m = (s1 - s0) / w

    def g(x):
        return s0 + m * (x - X[:-1]) - arc(x, xc, yc, r)

    ga, gb = g(a), g(b)
    xs = np.clip(xc + m * r / np.sqrt(1 + m * m), a, b)
    gs = g(xs)
    e = s0 + m * (xc - X[:-1]) - yc
    disc = r * r * (1 + m * m) - e * e
    sq = np.sqrt(np.maximum(disc, 0.0))
    left = np.where(ga > 0, a, xc + (-e * m - sq) / (1 + m * m))
    right = np.where(gb > 0, b, xc + (-e * m + sq) / (1 + m * m))
    inside = ok & ((ga > 0) | (gb > 0) | (gs > 0))
    idx = np.nonzero(inside)[0]
    if not len(idx):
        return "above the ground"
    spans = []
    for k in idx:
        lo, hi = max(left[k], a[k]), min(right[k], b[k])
        if hi - lo <= prof.tol:
            continue
        if spans and lo - spans[-1][1] <= prof.tol:
            spans[-1][1] = hi
        else:
            spans.append([lo, hi])
    if not spans:
        return "above the ground"
    for lo, hi in spans:
        if lo <= prof.x_min + prof.tol or hi >= prof.x_max - prof.tol:
            return "leaves the model through its side"
        if lo <= xc - r + prof.tol or hi >= xc + r - prof.tol:
            return "centre below the ground"
    return [tuple(sp) for sp in spans]


def slices(prof, circle, n, water, span):
    """The slices of the mass above a circle between x = span[0] and span[1]: dict of arrays
    (width b, weight W, base angle alpha with the sign of the sliding direction, c, tan phi,
    pore pressure u at the base), or a str saying why the circle is not admissible."""
    xc, yc, r = circle
    lo, hi = span
    edges = np.linspace(lo, hi, n + 1)
    # the slices are also cut where the ground, a layer or the pore pressure has a kink
    cuts = np.concatenate([prof.kinks, water.breaks(circle)])
    inner = cuts[(cuts > lo + prof.tol) & (cuts < hi - prof.tol)]
    if len(inner):
        edges = np.unique(np.concatenate([edges, inner]))
        edges = edges[np.concatenate([[True], np.diff(edges) > prof.tol])]
    bw = np.diff(edges)
    mid = 0.5 * (edges[:-1] + edges[1:])
    gx, gw = GAUSS
    xq = (mid[:, None] + 0.5 * bw[:, None] * gx[None, :]).ravel()
    _, bot, top, mat = prof.lines(xq)
    yq = arc(xq, xc, yc, r)
    if np.any(yq < np.where(mat >= 0, bot, np.inf).min(axis=1) - prof.tol):
        return "goes below the model"
    col = column_weight(prof, water, xq, yq, bot, top, mat)
    weight = (col.reshape(-1, len(gx)) * gw).sum(axis=1) * 0.5 * bw
    _, bot, top, mat = prof.lines(mid)
    ym = arc(mid, xc, yc, r)
    at = (bot <= ym[:, None] + prof.tol) & (ym[:, None] <= top + prof.tol) & (mat >= 0)
    if not at.any(axis=1).all():
        return "base outside the soil"
    base = mat[np.arange(len(mid)), at.argmax(axis=1)]
    if not prof.strong[base].all():
        return "cuts a material without strength"
    sigma = column_weight(prof, water, mid, ym, bot, top, mat)
    alpha = np.arcsin(np.clip((mid - xc) / r, -1.0, 1.0))
    drive = (weight * np.sin(alpha)).sum()
    if drive == 0:
        return "no driving moment"
    alpha = alpha * np.sign(drive)
    return {"x": mid, "b": bw, "W": weight, "alpha": alpha, "c": prof.c[base],
            "tanphi": prof.tanphi[base],
            "u": water.pressure(mid, ym, sigma) * prof.wet[base],
            "entry": lo, "exit": hi, "edges": edges}


def column_weight(prof, water, x, y, bot, top, mat):
    """Weight per unit width of the columns above y at x: GAMMA, and GAMMA_SAT below the
    phreatic level in wet sets."""
    h = np.clip(top - np.maximum(bot, y[:, None]), 0.0, None)
    w = (h * prof.gamma[mat]).sum(axis=1)
    level = getattr(water, "level", None)
    if level is not None:
        yw = level(x)[:, None]
        below = np.clip(np.minimum(top, yw) - np.maximum(bot, y[:, None]), 0.0, None)
        w = w + (below * prof.gamma_extra[mat]).sum(axis=1)
    return w


def bishop(s, tol=1e-12):
    """Bishop's simplified factor of the slices, or None (no factor with m_alpha > 0)."""
    b, w, a, c, t, u = s["b"], s["W"], s["alpha"], s["c"], s["tanphi"], s["u"]
    drive = (w * np.sin(a)).sum()
    num = c * b + np.maximum(w - u * b, 0.0) * t
    ca, sa = np.cos(a), np.sin(a)

    def rhs(f):
        return (num / (ca + sa * t / f)).sum() / drive

    f = 1.0
    for _ in range(200):
        m = ca + sa * t / f
        if np.any(m <= 0):
            break
        fn = rhs(f)
        if not np.isfinite(fn) or fn <= 0:
            break
        if abs(fn - f) <= tol * fn:
            f = fn
            return f if np.all(ca + sa * t / f > 0) else None
        f = fn
    # fixed point failed: bisection on h(F) = F - rhs(F) where all m_alpha > 0
    neg = sa * t < 0
    f_lo = max(1e-6, (-(sa * t)[neg] / ca[neg]).max() * (1 + 1e-9)) if neg.any() else 1e-6
    f_hi = 1e6
    h_lo, h_hi = f_lo - rhs(f_lo), f_hi - rhs(f_hi)
    if not (h_lo < 0 < h_hi):
        return None
    for _ in range(200):
        fm = math.sqrt(f_lo * f_hi)
        if fm - rhs(fm) < 0:
            f_lo = fm
        else:
            f_hi = fm
        if f_hi - f_lo <= tol * f_hi:
            break
    return 0.5 * (f_lo + f_hi)


def spencer_q(s, f, theta):
    """Resultant interslice force of each slice (Spencer 1967), at inclination theta."""
    b, w, a, c, t, u = s["b"], s["W"], s["alpha"], s["c"], s["tanphi"], s["u"]
    l = b / np.cos(a)
    resist = (c * l + (w * np.cos(a) - u * l) * t) / f
    den = np.cos(a - theta) + np.sin(a - theta) * t / f
    return (w * np.sin(a) - resist) / den, den


def root_f(fun, f0):
    """The root in F of a sum that is negative for small F and positive for large F,
    searched around f0 by bracketing (factor 1.25 steps) then bisection; None if none."""
    lo = hi = f0
    vlo = vhi = fun(f0)
    if vlo is None:
        return None
    for _ in range(60):
        if vlo < 0 < vhi or vlo > 0 > vhi:
            break
        if vlo >= 0:
            lo /= 1.25
            vlo = fun(lo)
        if vhi <= 0:
            hi *= 1.25
            vhi = fun(hi)
        if vlo is None or vhi is None:
            return None
    else:
        return None
    if not (vlo < 0 < vhi):
        return None
    for _ in range(200):
        fm = 0.5 * (lo + hi)
        v = fun(fm)
        if v is None:
            return None
        if v < 0:
            lo = fm
        else:
            hi = fm
        if hi - lo <= 1e-13 * hi:
            break
    return 0.5 * (lo + hi)


def spencer(s, f0):
    """Spencer's factor and interslice inclination (F, theta in radians) of the slices:
    force equilibrium sum Q = 0 and moment equilibrium about the centre
    sum Q cos(alpha - theta) = 0 both hold; None if no inclination in (-45, 60) degrees
    makes the two factors equal."""

    def fm(theta):
        def g(f):
            q, den = spencer_q(s, f, theta)
            return None if np.any(den <= 0) else (q * np.cos(s["alpha"] - theta)).sum()
        return root_f(g, f0)

    def ff(theta):
        def g(f):
            q, den = spencer_q(s, f, theta)
            return None if np.any(den <= 0) else q.sum()
        return root_f(g, f0)

    def d(theta):
        a, b = fm(theta), ff(theta)
        return None if a is None or b is None else (a - b, a)

    grid = np.radians(np.arange(-45.0, 61.0, 3.0))
    vals = [d(th) for th in grid]
    start = next((i for i, v in enumerate(vals) if v is not None and
                  abs(np.degrees(grid[i])) < 1e-9), None)
    order = sorted(range(len(grid) - 1), key=lambda i: abs(grid[i]))
    for i in order:
        v0, v1 = vals[i], vals[i + 1]
        if v0 is None or v1 is None or v0[0] * v1[0] > 0:
            continue
        lo, hi = grid[i], grid[i + 1]
        dlo = v0[0]
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            v = d(mid)
            if v is None:
                return None
            if (v[0] < 0) == (dlo < 0):
                lo, dlo = mid, v[0]
            else:
                hi = mid
            if hi - lo < 1e-12:
                break
        v = d(0.5 * (lo + hi))
        return (v[1], 0.5 * (lo + hi)) if v is not None else None
    del start
    return None


def bishop_circle(prof, circle, n, water):
    """(Bishop's factor, the slices) of a circle, or (None, why not). A circle below the
    ground on several stretches cuts several bodies, each rotating on its own: the factor
    is the least of theirs (e.g. a toe circle whose arc dips below the ground in front of
    the toe moves the body above the toe)."""
    spans = mass_extent(prof, *circle)
    if isinstance(spans, str):
        return None, spans
    best = (None, "no driving moment")
    for span in spans:
        s = slices(prof, circle, n, water, span)
        if isinstance(s, str):
            if s != "no driving moment":
                return None, s
            continue
        f = bishop(s)
        if f is None:
            return None, "no Bishop factor (m_alpha <= 0)"
        if best[0] is None or f < best[0]:
            best = (f, s)
    return best


# ------------------------------------------------------------------ the search
def default_box(prof):
    h = max(prof.top - prof.bottom, 1e-9)
    return (prof.x_min, prof.x_max, prof.top, prof.top + 2.0 * h)


def search(prof, n, water, grid=(12, 12, 12), refine=6, box=None, starts=3):
    """The circle of least Bishop factor. A coarse grid: centres (x, y) on NX x NY points of
    the box, and for each NR levels of the circle's lowest point between the model's bottom
    and top, plus the levels of the ground's corners (a toe circle's lowest point is often
    at the toe). Then from each of the `starts` best coarse circles that are more than one
    grid step apart, a pattern search: the 3 x 3 x 3 circles around the best one (centre x,
    y and lowest level) at the current step, moving to the best, the step halved when the
    best stays in the middle, `refine` halvings in all."""
    x0, x1, y0, y1 = box or default_box(prof)
    if not (x1 > x0 and y1 > y0):
        raise InputError(f"--centres {x0:g} {x1:g} {y0:g} {y1:g}: X0 < X1 and Y0 < Y1 "
                         "expected")
    nx, ny, nr = grid
    xs = np.linspace(x0, x1, nx)
    ys = np.linspace(y0, y1, ny)
    zs = np.linspace(prof.bottom, prof.top, nr + 2)[1:-1]   # lowest point of the circle
    corners = np.concatenate([prof.s0, prof.s1])
    corners = corners[(corners > prof.bottom + prof.tol) & (corners < prof.top - prof.tol)]
    zs = np.unique(np.concatenate([zs, corners]))
    tried = valid = 0
    reasons = {}
    seen = {}

    def factor(xc, yc, z):
        nonlocal tried, valid
        key = (round(xc / prof.tol), round(yc / prof.tol), round(z / prof.tol))
        if key in seen:
            return seen[key]
        r = yc - z
        f = None
        if r > 0:
            tried += 1
            f, why = bishop_circle(prof, (xc, yc, r), n, water)
            if f is None:
                reasons[why] = reasons.get(why, 0) + 1
            else:
                valid += 1
        seen[key] = np.inf if f is None else f
        return seen[key]

    coarse = sorted((factor(x, y, z), (x, y, z)) for x in xs for y in ys for z in zs)
    coarse = [c for c in coarse if np.isfinite(c[0])]
    if not coarse:
        raise NoCircle("no admissible circle in the search box (centres x " +
                       f"{x0:g} .. {x1:g}, y {y0:g} .. {y1:g}): " +
                       ", ".join(f"{k}: {v}" for k, v in sorted(reasons.items())))
    step0 = np.array([(x1 - x0) / max(nx - 1, 1), (y1 - y0) / max(ny - 1, 1),
                      (prof.top - prof.bottom) / (nr + 1)])
    picked = []
    for f, p in coarse:
        if all(np.any(np.abs(np.subtract(p, q)) > step0 * 1.01) for _, q in picked):
            picked.append((f, p))
        if len(picked) == starts:
            break
    best = picked[0]
    offsets = [np.array((i, j, k)) for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)]
    for f, p in picked:
        p, h, halvings = np.array(p, float), step0 / 2, 0
        for _ in range(40 * (refine + 1)):
            if halvings >= refine:
                break
            cand = min((factor(*(p + o * h)), tuple(o)) for o in offsets)
            if cand[0] < f and any(cand[1]):
                f, p = cand[0], p + np.array(cand[1]) * h
            else:
                h, halvings = h / 2, halvings + 1
        if f < best[0]:
            best = (f, tuple(p))
    xb, yb, zb = best[1]
    return best[0], (xb, yb, yb - zb), tried, valid, (x0, x1, y0, y1)


# ------------------------------------------------------------------ the picture
def mechanism(results, k):
    """Magnitude of the finite-element mechanism per node and what it is: the incremental
    displacements of a safety step's last increments (/safety/mechanism) when the file has
    one, else the displacement over the last k written increments."""
    import h5py
    with h5py.File(results, "r") as f:
        x = f["mesh/coordinates"][()]
        g = f.get("safety")
        if g is not None and "mechanism" in g:
            m = np.asarray(g["mechanism"][()], float)
            m = m.T if m.shape[0] == 2 and m.shape[1] != 2 else m
            return x, np.hypot(m[:, 0], m[:, 1]), "safety step's mechanism"
        keys = sorted(f["increments"].keys()) if "increments" in f else []
        if not keys:
            raise InputError(f"{results}: no increment with fields")
        last = f[f"increments/{keys[-1]}/displacement"][()]
        if len(keys) > k:
            prev = f[f"increments/{keys[-1 - k]}/displacement"][()]
            first = keys[-1 - k]
        else:
            prev, first = np.zeros_like(last), "start"
    return x, np.hypot(*(last - prev).T), f"increments {first} to {keys[-1]}"


def fe_factor(results):
    """The strength-reduction factor a safety step wrote (/safety: factor, kind,
    resolution), or None."""
    import h5py
    with h5py.File(results, "r") as f:
        g = f.get("safety")
        if g is None or "factor" not in g.attrs:
            return None
        return {"factor": float(g.attrs["factor"]), "kind": text(g.attrs.get("kind", "")),
                "resolution": float(g.attrs.get("resolution", float("nan")))}


def draw(soil, prof, circle, s, out, title, results=None, k=1):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    fig, ax = plt.subplots(figsize=(10, 6))
    polys, values = [], []
    if results:
        x, du, what = mechanism(results, k)
        import h5py
        with h5py.File(results, "r") as f:
            for name, g in f["mesh/sets"].items():
                etype = text(g.attrs["etype"])
                conn = g["connectivity"][()]
                ring = OUTLINE.get(etype, list(range(conn.shape[1])))
                for row in conn:
                    polys.append(x[row[ring]])
                    values.append(du[row].mean())
        pc = PolyCollection(polys, array=np.asarray(values), cmap="viridis",
                            edgecolors="0.4", linewidths=0.2)
        ax.add_collection(pc)
        fig.colorbar(pc, ax=ax, label=f"|incremental displacement| (finite elements, {what})")
    else:
        names = list(dict.fromkeys(m.name for *_, m in soil.sets))
        cmap = plt.get_cmap("tab10")
        for name, etype, conn, m in soil.sets:
            ring = OUTLINE.get(etype, list(range(len(conn[0]) if conn else 0)))
            for xy in conn:
                polys.append(xy[ring])
                values.append(names.index(m.name))
        pc = PolyCollection(polys, facecolors=[cmap(v % 10) for v in values],
                            edgecolors="0.4", linewidths=0.2, alpha=0.6)
        ax.add_collection(pc)
        for i, nm in enumerate(names):
            ax.plot([], [], "s", color=cmap(i % 10), label=nm)
        ax.legend(loc="lower left", fontsize=8, title="materials", title_fontsize=8)
    xc, yc, r = circle
    xa = np.linspace(s["entry"], s["exit"], 200)
    ax.plot(xa, arc(xa, xc, yc, r), "r-", lw=2, label="critical circle")
    ax.plot([s["entry"], xc, s["exit"]], [arc(np.array([s["entry"]]), xc, yc, r)[0], yc,
                                          arc(np.array([s["exit"]]), xc, yc, r)[0]],
            "r--", lw=0.8)
    ax.plot([xc], [yc], "r+", ms=10)
    ax.autoscale()
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    tmp = out.with_name(f".{out.name}.{os.getpid()}.tmp")
    try:
        fig.savefig(tmp, format="png", dpi=120, bbox_inches="tight")
        os.replace(tmp, out)
    finally:
        if tmp.exists():
            tmp.unlink()
    plt.close(fig)


# ------------------------------------------------------------------ the command
def point(textp):
    try:
        x, y = (float(v) for v in textp.split(","))
    except ValueError:
        raise InputError(f"--phreatic: '{textp}' is not a point X,Y") from None
    return x, y


def load(path):
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{path}: no such file (a deck .inp or a results file .h5 "
                         "expected)")
    with open(p, "rb") as fh:
        head = fh.read(8)
    if head == b"\x89HDF\r\n\x1a\n":
        return soil_from_results(p)
    return soil_from_deck(p)


def deck_water(blocks):
    """The phreatic level of the deck in force after its last step (*WATER, NAME=,
    GAMMA_W=, LEVEL=y or data lines x, y: the first one from the start; *CHANGE_WATER,
    LEVEL=name|NONE in a step), or None."""
    levels = {}
    current = None
    for b in blocks:
        if b.keyword == "*WATER":
            name = b.options.get("NAME", "")
            gw = number(b.options.get("GAMMA_W", "nan"), b, b.where)
            if not gw > 0:
                raise b.err("GAMMA_W= expected (a positive number)")
            if "LEVEL" in b.options:
                pts = [(0.0, number(b.options["LEVEL"], b, b.where))]
            else:
                pts = [(number(f[0], b, w), number(f[1], b, w)) for f, w in b.data
                       if len(f) >= 2]
            try:
                levels[name.upper()] = Phreatic(pts, gw, name)
            except InputError as e:
                raise b.err(str(e).replace("--phreatic: ", "")) from None
            if current is None:
                current = name.upper()
        elif b.keyword == "*CHANGE_WATER" and "LEVEL" in b.options:
            current = b.options["LEVEL"].upper()
    if current in (None, "NONE"):
        return None
    if current not in levels:
        raise InputError(f"*CHANGE_WATER, LEVEL={current}: no *WATER of that name")
    return levels[current]


def water_of(a, blocks):
    """The water input: --phreatic or --ru, else the deck's phreatic level in force after
    its last step (--no-water: none), else dry."""
    gw = a.gamma_w if a.gamma_w is not None else gamma_w_of(blocks)
    if a.phreatic:
        return Phreatic([point(p) for p in a.phreatic], gw)
    if a.ru is not None:
        return PoreRatio(a.ru)
    if not a.no_water:
        w = deck_water(blocks)
        if w is not None:
            return w
    return NoWater()


def analyse(soil, blocks, water, n=50, grid=(12, 12, 12), refine=6, box=None, circle=None):
    """Bishop (searched or on the given circle) and Spencer on the critical circle."""
    if n < 1:
        raise InputError(f"--slices {n}: at least 1 expected")
    prof = Profile(soil)
    if circle is not None:
        if circle[2] <= 0:
            raise InputError(f"--circle: radius {circle[2]:g} <= 0")
        f, s = bishop_circle(prof, circle, n, water)
        if f is None:
            raise NoCircle(f"circle ({circle[0]:g}, {circle[1]:g}) R = {circle[2]:g}: {s}")
        tried = valid = 1
        box = None
    else:
        f, circle, tried, valid, box = search(prof, n, water, grid, refine, box)
        s = bishop_circle(prof, circle, n, water)[1]
    sp = spencer(s, f)
    return {"bishop": f, "spencer": sp[0] if sp else None,
            "theta_deg": math.degrees(sp[1]) if sp else None,
            "circle": [float(v) for v in circle], "entry": float(s["entry"]),
            "exit": float(s["exit"]), "slices": int(len(s["b"])), "circles_tried": tried,
            "circles_admissible": valid, "box": box, "water": water.text,
            "_s": s, "_prof": prof}


def main(argv=None):
    ap = argparse.ArgumentParser(prog="pecplas-slope", description=__doc__.split("\n\n")[0])
    ap.add_argument("input", help="a deck (.inp) or a results file of pecplas (.h5)")
    ap.add_argument("--results", help="results file whose last increments give the "
                    "mechanism drawn (default: INPUT when it is a results file)")
    ap.add_argument("-o", "--output", help="PNG file (default: INPUT with .slope.png)")
    ap.add_argument("--slices", type=int, default=50, help="slices per circle (default 50; "
                    "the slices are also cut at the kinks of the ground and layers)")
    ap.add_argument("--grid", type=int, nargs=3, default=[12, 12, 12],
                    metavar=("NX", "NY", "NR"), help="search grid: centres NX x NY, NR "
                    "levels of the circle's lowest point (default 12 12 12)")
    ap.add_argument("--refine", type=int, default=6, help="halvings of the step of the "
                    "pattern search from the best coarse circles (default 6)")
    ap.add_argument("--centres", type=float, nargs=4, metavar=("X0", "X1", "Y0", "Y1"),
                    help="search box of the centres (default: the model's width, from "
                    "its top to two heights above)")
    ap.add_argument("--circle", type=float, nargs=3, metavar=("XC", "YC", "R"),
                    help="analyse this circle only (no search)")
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--phreatic", nargs="+", metavar="X,Y", help="phreatic line points")
    g.add_argument("--ru", type=float, help="pore pressure ratio r_u")
    g.add_argument("--no-water", action="store_true", help="ignore the deck's *WATER")
    ap.add_argument("--gamma-w", type=float, help="unit weight of water (default from "
                    "*UNITS: 9.81 kN/m3)")
    ap.add_argument("--increments", type=int, default=1, help="the mechanism is the "
                    "displacement over the last K written increments (default 1)")
    ap.add_argument("--data", help="also write the numbers (JSON)")
    ap.add_argument("--no-plot", action="store_true", help="no picture")
    a = ap.parse_args(argv)
    try:
        if any(v < 1 for v in a.grid) or a.refine < 0 or a.increments < 1:
            raise InputError("--grid needs 1 or more per direction, --refine 0 or more, "
                             "--increments 1 or more")
        soil, blocks = load(a.input)
        water = water_of(a, blocks)
        results = a.results
        if results is None and Path(a.input).read_bytes()[:4] == b"\x89HDF":
            results = a.input
        if results and not Path(results).is_file():
            raise InputError(f"{results}: no such file")
        r = analyse(soil, blocks, water, a.slices, tuple(a.grid), a.refine,
                    tuple(a.centres) if a.centres else None, a.circle)
    except InputError as e:
        print(f"pecplas-slope: {e}", file=sys.stderr)
        return 2
    except NoCircle as e:
        print(f"pecplas-slope: {e}", file=sys.stderr)
        return 3
    xc, yc, rad = r["circle"]
    print(f"pecplas-slope: {a.input}")
    print(f"  water: {r['water']}")
    if a.circle is None:
        print(f"  search: {r['circles_admissible']} admissible circles of "
              f"{r['circles_tried']} tried")
    print(f"  critical circle: centre ({xc:.4g}, {yc:.4g}), radius {rad:.4g}, ground "
          f"from x = {r['entry']:.4g} to {r['exit']:.4g}, {r['slices']} slices")
    sp = f"{r['spencer']:.4f}" if r["spencer"] is not None else \
        "no solution (no interslice inclination from -45 to 60 deg balances both forces " \
        "and moments on this circle)"
    th = f" (interslice inclination {r['theta_deg']:.2f} deg)" if r["spencer"] else ""
    print(f"  factor of safety:  Bishop simplified {r['bishop']:.4f}   Spencer {sp}{th}")
    fe = fe_factor(results) if results else None
    if fe:
        r["finite_elements"] = fe
        print(f"  finite elements (strength reduction): {fe['factor']:.4f} ({fe['kind']}, "
              f"resolution {fe['resolution']:.2g})")
    if not a.no_plot:
        out = Path(a.output) if a.output else Path(a.input).with_suffix(".slope.png")
        spt = sp if r["spencer"] is not None else "no solution"
        title = (f"{Path(a.input).name}: Bishop F = {r['bishop']:.3f}, Spencer F = {spt}; "
                 f"circle ({xc:.3g}, {yc:.3g}), R = {rad:.3g}")
        try:
            draw(soil, r["_prof"], r["circle"], r["_s"], out, title, results, a.increments)
        except InputError as e:
            print(f"pecplas-slope: {e}", file=sys.stderr)
            return 2
        print(f"  picture: {out}")
    if a.data:
        Path(a.data).write_text(json.dumps({k: v for k, v in r.items()
                                            if not k.startswith("_")}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
