#!/usr/bin/env python3
"""pecplas-plot: pictures of a pecplas results file (doc/results.md, "Pictures").

    pecplas-plot RESULTS.h5 [-o OUT.png] [--field F] [--increment N] [--scale S]
                 [--range-set SET | --range LO HI | --full-range] [--no-plastic]
                 [--node ID [--dof x|y] | --set NAME] [--curve-only | --mesh-only]
                 [--data OUT.json]

writes one PNG: the deformed mesh (displacements magnified) coloured by a field, with the
plastic Gauss points marked, and beside it the load-displacement curve of the node or set
that the step is controlled by, whatever drives it.

Fields (element values): sxx, syy, szz, sxy (element mean stress, tension positive), p (mean
stress), q (von Mises), eps_p (mean equivalent plastic strain), plastic (fraction of the
element's Gauss points yielding at this increment), ux, uy, u (mean of the element's nodes).

The colour scale: by default from the 5th to the 95th percentile of the field over the whole
model's area, so that a few small, very stiff or very stressed elements (a pile in soil) do
not make the rest one colour (values beyond get the end colours, shown by the arrows of the
colour bar); `--range-set SET` the full range over one element set, `--range LO HI` given, `--full-range`
the full range over the model.

Plastic points: Mohr-Coulomb and Drucker-Prager sets store the kind of each Gauss point's last
return and its equivalent plastic strain (`state`): filled red dots where the point yields at
this increment, open grey circles where it yielded earlier and is elastic now.

The curve (from the deck kept in the file and the mesh sets):
- an arc-length step with NODE=, DOF=: that node's displacement along DOF against the
  resultant of the step's load pattern;
- a DISPLACEMENT pattern: the imposed displacement (mean over its nodes) against the sum of
  the reactions at its nodes along it (the force that imposes it);
- a FORCE or PRESSURE pattern: the displacement along the load of the node of its set that
  moves most, against the pattern's resultant (factor times its resultant at factor 1, found
  from the reactions: by equilibrium their sum is the initial part plus sum_k R_k f_k);
`--node ID [--dof x|y]` or `--set NAME` (mean over a node or edge set) choose another point.
The first point is the initial state (zero displacement and load factor); then every written
increment, up to the one drawn. `--data FILE` writes the numbers drawn (JSON).

Needs Python 3 with numpy, h5py and matplotlib; installed stand-alone by `make install`.
Exit codes: 0 written, 2 bad input (message names the file and what was expected).
"""
import argparse
import json
import os
import sys
from pathlib import Path

import h5py
import numpy as np

STRESS = {"sxx": 0, "syy": 1, "szz": 2, "sxy": 3}
ALIASES = {"xx": "sxx", "yy": "syy", "zz": "szz", "xy": "sxy"}
FIELDS = [*STRESS, "p", "q", "eps_p", "plastic", "ux", "uy", "u"]
# corner and mid-side nodes in boundary order
OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7], "Q8R": [0, 4, 1, 5, 2, 6, 3, 7],
           "Q9": [0, 4, 1, 5, 2, 6, 3, 7]}
NOT_STATED = "(not stated)"


class InputError(Exception):
    """Bad input: printed as `pecplas-plot: message`, exit code 2."""


def text(v):
    if isinstance(v, (bytes, np.bytes_)):
        return v.decode()
    if isinstance(v, np.ndarray) and v.dtype.kind in "OSU":
        return [text(x) for x in v.tolist()]
    return str(v) if isinstance(v, np.str_) else v


# ------------------------------------------------------------------ the deck kept in the file
def deck_blocks(deck):
    """[(KEYWORD, {OPTION: value}, [data lines as lists of fields])] of the deck text."""
    blocks = []
    for raw in deck.splitlines():
        line = raw.split("!")[0].strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            parts = [p.strip() for p in line.split(",")]
            opts = {}
            for p in parts[1:]:
                k, _, v = p.partition("=")
                opts[k.strip().upper()] = v.strip()
            blocks.append((parts[0].upper(), opts, []))
        elif blocks:
            blocks[-1][2].append([f.strip() for f in line.split(",")])
    return blocks


def dof_index(word):
    w = str(word).strip().upper()
    if w in ("1", "X", "R"):
        return 0
    if w in ("2", "Y", "Z"):
        return 1
    raise InputError(f"unknown dof '{word}' (1, 2, X, Y, R or Z expected)")


class Model:
    """What the picture needs from a results file: mesh, fields, patterns, steps."""

    def __init__(self, path):
        self.path = Path(path)
        if not self.path.is_file():
            raise InputError(f"{path}: no such file (a results file .h5 of pecplas expected)")
        try:
            self.f = h5py.File(path, "r")
        except OSError as e:
            raise InputError(f"{path}: not a readable results file ({e})") from None
        f = self.f
        if "mesh/coordinates" not in f:
            raise InputError(f"{path}: no /mesh/coordinates (not a pecplas results file)")
        self.x = f["mesh/coordinates"][()]
        self.node_ids = f["mesh/node_ids"][()]
        self.keys = sorted(f["increments"].keys()) if "increments" in f else []
        self.patterns = [text(n) for n in f["history"].attrs.get("patterns", [])] \
            if "history" in f else []
        self.axisymmetric = text(f.attrs.get("analysis", "")) == "axisymmetric"
        deck = text(f.attrs.get("deck_text", ""))
        self.blocks = deck_blocks(deck if isinstance(deck, str) else "")

    def unit(self, name):
        u = text(self.f.attrs.get(name, ""))
        return "" if u in ("", NOT_STATED) else u

    def node_row(self, node_id):
        rows = np.nonzero(self.node_ids == int(node_id))[0]
        if not len(rows):
            raise InputError(f"{self.path}: no node {node_id}")
        return int(rows[0])

    def set_nodes(self, name):
        """0-based nodes of a node set or an edge set; None when neither exists."""
        mesh = self.f["mesh"]
        if name in mesh.get("node_sets", {}):
            return np.asarray(mesh[f"node_sets/{name}/nodes"][()]).ravel()
        if name in mesh.get("edge_sets", {}):
            return np.unique(mesh[f"edge_sets/{name}/nodes"][()].ravel())
        return None

    def nodes_of(self, word):
        """A data-line node field: a node id or a node/edge set name."""
        try:
            return np.array([self.node_row(int(word))])
        except ValueError:
            nodes = self.set_nodes(word)
            if nodes is None:
                raise InputError(f"{self.path}: no node or set '{word}'") from None
            return nodes

    def load_blocks(self):
        return {o.get("NAME", ""): (o.get("TYPE", "").upper(), data)
                for k, o, data in self.blocks if k == "*LOAD"}

    def steps(self):
        return [(o, data) for k, o, data in self.blocks if k == "*STEP"]

    def field(self, key, name):
        return self.f[f"increments/{key}/{name}"][()]

    def history(self):
        h = self.f["history"]
        return {k: h[k][()] for k in h}


# ------------------------------------------------------------------ element values
def element_values(m, key, field):
    """[(set name, etype, connectivity, values per element, state, state names)]."""
    g = m.f[f"increments/{key}"]
    u = m.field(key, "displacement")
    out = []
    for name, s in m.f["mesh/sets"].items():
        etype = text(s.attrs["etype"])
        conn = s["connectivity"][()]
        fs = g["sets"][name] if "sets" in g and name in g["sets"] else None
        names = text(s.attrs.get("state_names", []))
        names = [names] if isinstance(names, str) else list(names)
        state = fs["state"][()] if fs is not None and "state" in fs else None
        mean = fs["stress_mean"][()] if fs is not None and "stress_mean" in fs else None
        n = len(conn)
        if field in STRESS:
            v = mean[:, STRESS[field]] if mean is not None else np.full(n, np.nan)
        elif field in ("p", "q"):
            if mean is None:
                v = np.full(n, np.nan)
            else:
                sx, sy, sz, txy = mean.T
                p = (sx + sy + sz) / 3.0
                v = p if field == "p" else np.sqrt(
                    0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * txy ** 2)
        elif field in ("eps_p", "plastic") and fs is None:
            v = np.full(n, np.nan)           # no set fields written (*OUTPUT, STRESSES=NO)
        elif field == "eps_p":
            # an elastic set (no plastic history) never yields
            v = state[:, :, names.index("eps_p_eq")].mean(axis=1) \
                if state is not None and "eps_p_eq" in names else np.zeros(n)
        elif field == "plastic":
            v = (state[:, :, names.index("return_kind")] > 0).mean(axis=1) \
                if state is not None and "return_kind" in names else np.zeros(n)
        else:
            un = {"ux": u[:, 0], "uy": u[:, 1], "u": np.hypot(u[:, 0], u[:, 1])}[field]
            v = un[conn].mean(axis=1)
        out.append((name, etype, conn, np.asarray(v, float), state, names))
    return out


def polygon_areas(x, conn, etype):
    """Area of each element's outline (shoelace over its boundary nodes)."""
    ring = x[conn[:, OUTLINE.get(etype, list(range(conn.shape[1])))]]      # (nel, nb, 2)
    xs, ys = ring[..., 0], ring[..., 1]
    return 0.5 * np.abs((xs * np.roll(ys, -1, axis=1) - np.roll(xs, -1, axis=1) * ys)
                        .sum(axis=1))


def weighted_percentiles(values, weights, qs):
    """Percentiles (qs in [0, 1]) of `values` where each counts with its weight: the value
    below which the fraction q of the total weight lies (linear between midpoints)."""
    order = np.argsort(values)
    v, w = values[order], weights[order]
    cum = (np.cumsum(w) - 0.5 * w) / w.sum()
    return np.interp(qs, cum, v)


def colour_range(sets, how, range_set=None, given=None, x=None):
    """(lo, hi, text) of the colour scale; `how` default | set | given | full. The default
    spans 5 to 95 % of the model's drawn area (with `x`, else of its elements)."""
    finite = [(v, (polygon_areas(x, conn, etype) if x is not None else np.ones(len(v))))
              for _, etype, conn, v, _, _ in sets]
    every = np.concatenate([v for v, _ in finite]) if finite else np.zeros(0)
    area = np.concatenate([a for _, a in finite]) if finite else np.zeros(0)
    ok = np.isfinite(every) & (area > 0)
    every, area = every[ok], area[ok]
    if how == "given":
        lo, hi = given
        what = "given"
    elif how == "set":
        chosen = [v for name, _, _, v, _, _ in sets if name == range_set]
        if not chosen:
            raise InputError(f"no element set '{range_set}' (sets: "
                             f"{', '.join(s[0] for s in sets)})")
        v = chosen[0][np.isfinite(chosen[0])]
        lo, hi = (v.min(), v.max()) if len(v) else (0.0, 1.0)
        what = f"full range of set {range_set}"
    elif how == "full" or len(every) < 3:
        lo, hi = (every.min(), every.max()) if len(every) else (0.0, 1.0)
        what = "full range of the model"
    else:
        lo, hi = weighted_percentiles(every, area, [0.05, 0.95])
        what = "5-95 % of the model's area"
    if not hi > lo:
        pad = max(abs(lo), 1.0) * 1e-6
        lo, hi = lo - pad, hi + pad
    return float(lo), float(hi), what


# ------------------------------------------------------------------ the curve
def pattern_resultants(m, keys, rows, factors):
    """Resultant (2,) of each pattern at factor 1, from the reactions of the written
    increments (least squares on sum(reactions) = R0 + sum_k R_k f_k); a pattern the
    increments cannot tell apart from the others gets None."""
    reac = np.array([m.field(k, "reaction").sum(axis=0) for k in keys])
    if m.axisymmetric:
        reac[:, 0] = 0.0          # radial ring reactions are balanced by hoop stresses
    design = np.column_stack([np.ones(len(rows)), factors[rows]])
    coef, *_ = np.linalg.lstsq(design, reac, rcond=None)
    out = []
    for k in range(factors.shape[1]):
        others = np.delete(design, 1 + k, axis=1)
        col = design[:, 1 + k]
        fit = others @ np.linalg.lstsq(others, col, rcond=None)[0] if others.size else 0 * col
        ok = np.linalg.norm(col - fit) > 1e-9 * max(np.linalg.norm(col), 1e-300)
        # the load opposes its reactions
        out.append(-coef[1 + k] if ok else None)
    return out


def load_curve(m, upto, node=None, dof=None, set_name=None):
    """The load-displacement curve of the drawn step: dict with label, units, the key of
    each point (None: the initial state), displacement and load arrays."""
    h = m.history()
    rows = np.nonzero(h["fields"])[0]
    if len(rows) != len(m.keys) or not len(rows):
        return None
    nkeep = m.keys.index(upto) + 1
    keys, rows = m.keys[:nkeep], rows[:nkeep]
    factors = h["pattern_factors"]
    if factors.ndim == 1:
        factors = factors[:, None]
    step = int(h["step"][rows[-1]])
    steps = m.steps()
    opts, data = steps[step - 1] if step - 1 < len(steps) else ({}, [])
    loads = m.load_blocks()
    driven = [d[0] for d in data if d and d[0] in m.patterns]
    if not driven:
        return None
    # the pattern that drives the step: the first named one whose factor changes in it
    in_step = rows[h["step"][rows] == step]
    k = next((m.patterns.index(p) for p in driven
              if np.ptp(factors[in_step, m.patterns.index(p)]) > 0), m.patterns.index(driven[0]))
    name = m.patterns[k]
    kind, pdata = loads.get(name, ("", []))
    length, force = m.unit("length_unit"), m.unit("force_unit")
    u = np.array([m.field(key, "displacement") for key in keys])     # (n, nnode, 2)
    direction = None
    how = ""
    if kind == "DISPLACEMENT" and node is None and set_name is None:
        # the imposed displacement and the reactions that impose it
        nodes, dofs, values = [], [], []
        for d in pdata:
            if len(d) < 3:
                continue
            for n in m.nodes_of(d[0]):
                nodes.append(n)
                dofs.append(dof_index(d[1]))
                values.append(float(d[2]))
        if not nodes:
            return None
        nodes, dofs, values = map(np.asarray, (nodes, dofs, values))
        main_dof = int(np.bincount(dofs, weights=np.abs(values)).argmax())
        sel = dofs == main_dof
        sign = np.sign(values[sel].mean()) or 1.0
        disp = u[:, nodes[sel], main_dof].mean(axis=1) * sign
        reac = np.array([m.field(key, "reaction")[nodes[sel], main_dof].sum() for key in keys])
        load = reac * sign
        label = (f"imposed displacement '{name}' ({dof_name(m, main_dof)}, mean of "
                 f"{int(sel.sum())} nodes)")
        ylabel = f"force imposing it (sum of reactions) [{force}]"
        how = "displacement pattern"
    else:
        resultants = pattern_resultants(m, keys, rows, factors)
        r = resultants[k]
        if r is not None and np.linalg.norm(r) > 0:
            load = factors[rows, k] * np.linalg.norm(r)
            direction = r / np.linalg.norm(r)
            ylabel = f"resultant of '{name}' [{force}]"
        else:
            load = factors[rows, k]
            ylabel = f"factor of '{name}'"
        if node is not None or set_name is not None:
            nodes = np.array([m.node_row(node)]) if node is not None else m.set_nodes(set_name)
            if nodes is None:
                raise InputError(f"{m.path}: no node or edge set '{set_name}'")
            where = f"node {node}" if node is not None else f"mean of set '{set_name}'"
            how = "chosen"
        elif opts.get("CONTROL", "").upper() == "ARC_LENGTH" and opts.get("NODE"):
            nodes = m.nodes_of(opts["NODE"])[:1]
            dof = dof if dof is not None else ("xy"[dof_index(opts.get("DOF", "2"))])
            where = f"stop node {int(m.node_ids[nodes[0]])}"
            how = "arc-length stop node"
        else:
            sets = [d[0] for d in pdata if d] or [name]
            cand = np.unique(np.concatenate([m.nodes_of(s) for s in sets]))
            along = direction if direction is not None else np.array([0.0, -1.0])
            moved = np.abs(u[-1, cand] @ along)
            nodes = cand[[int(moved.argmax())]]
            where = f"node {int(m.node_ids[nodes[0]])} of '{sets[0]}', the one moving most"
            how = "loaded set"
        if dof is not None:
            comp = dof_index(dof)
            along = np.eye(2)[comp]
            if direction is not None and direction @ along < 0:
                along = -along
            dtext = f"{dof_name(m, comp)}, along the load" if direction is not None and \
                abs(direction[comp]) > 0 else dof_name(m, comp)
        else:
            along = direction if direction is not None else np.array([0.0, -1.0])
            dtext = "along the load"
        disp = (u[:, nodes] @ along).mean(axis=1)
        label = f"{where} ({dtext})"
    return {"label": label, "ylabel": ylabel, "xlabel": f"displacement [{length}]",
            "pattern": name, "kind": kind or "?", "how": how,
            "keys": [None, *keys], "displacement": [0.0, *map(float, disp)],
            "load": [0.0, *map(float, load)]}


def dof_name(m, d):
    return ("u_r", "u_z")[d] if m.axisymmetric else ("u_x", "u_y")[d]


# ------------------------------------------------------------------ the picture
def draw(m, a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    if not m.keys:
        raise InputError(f"{m.path}: no increment with fields")
    key = m.keys[-1]
    if a.increment is not None:
        key = f"{a.increment:06d}"
        if key not in m.keys:
            raise InputError(f"{m.path}: no fields at increment {a.increment} (written: "
                             f"{int(m.keys[0])} ... {int(m.keys[-1])})")
    field = ALIASES.get(a.field, a.field)
    if field is None:
        g = m.f[f"increments/{key}"]
        field = "syy" if "sets" in g and all("stress_mean" in g["sets"][n]
                                             for n in g["sets"]) else "u"
    data = {"results": str(m.path), "increment": int(key), "field": field}
    curve = None if a.mesh_only else load_curve(m, key, a.node, a.dof, a.set)
    show_mesh = not a.curve_only
    if a.curve_only and curve is None:
        raise InputError(f"{m.path}: no load-displacement curve (no step drives a pattern "
                         "with written increments)")
    if show_mesh and curve:
        fig, (ax, axc) = plt.subplots(1, 2, figsize=(13, 5.5),
                                      gridspec_kw={"width_ratios": [1.4, 1]})
    elif show_mesh:
        fig, ax = plt.subplots(figsize=(7.5, 5.5))
        axc = None
    else:
        fig, axc = plt.subplots(figsize=(6.5, 5))
        ax = None
    if show_mesh:
        sets = element_values(m, key, field)
        how = "given" if a.range else "set" if a.range_set else "full" if a.full_range \
            else "default"
        lo, hi, what = colour_range(sets, how, a.range_set, a.range, m.x)
        u = m.field(key, "displacement")
        size = np.ptp(m.x, axis=0).max()
        umax = np.abs(u).max()
        scale = a.scale if a.scale is not None else (0.1 * size / umax if umax > 0 else 1.0)
        xd = m.x + scale * u
        polys, values = [], []
        yielding, yielded = [], []
        for name, etype, conn, v, state, names in sets:
            ring = OUTLINE.get(etype, list(range(conn.shape[1])))
            for e, nodes in enumerate(conn):
                polys.append(xd[nodes[ring]])
            values.append(v)
            if state is not None and "return_kind" in names and not a.no_plastic:
                gp = m.f[f"mesh/sets/{name}/gauss_coordinates"][()]         # (nel, ng, 2)
                shift = scale * u[conn].mean(axis=1)                        # (nel, 2)
                where = gp + shift[:, None, :]
                now = state[:, :, names.index("return_kind")] > 0
                yielding.append(where[now])
                if "eps_p_eq" in names:
                    yielded.append(where[(~now) & (state[:, :, names.index("eps_p_eq")] > 0)])
        values = np.concatenate(values) if values else np.zeros(0)
        if not np.isfinite(values).any():
            raise InputError(f"{m.path}: no values of field {field} at increment {int(key)} "
                             "(the deck's *OUTPUT wrote no element fields: STRESSES=NO?); "
                             "--curve-only draws the curve alone")
        below, above = bool(np.nanmin(values) < lo), bool(np.nanmax(values) > hi)
        extend = {(False, False): "neither", (True, False): "min", (False, True): "max",
                  (True, True): "both"}[(below, above)]
        pc = PolyCollection(polys, array=np.ma.masked_invalid(values), cmap="viridis",
                            edgecolors="k", linewidths=0.3)
        pc.set_clim(lo, hi)
        ax.add_collection(pc)
        ax.autoscale()
        ax.set_aspect("equal")
        unit = m.unit("stress_unit") if field in (*STRESS, "p", "q") else \
            m.unit("length_unit") if field in ("ux", "uy", "u") else "1"
        title = {"p": "mean stress p", "q": "von Mises q", "eps_p": "equivalent plastic strain",
                 "plastic": "fraction of yielding Gauss points", "ux": "u_x", "uy": "u_y",
                 "u": "|u|"}.get(field, f"sigma_{field[1:]} (tension +)")
        fig.colorbar(pc, ax=ax, extend=extend, label=f"{title} [{unit}]  ({what})")
        nyield = sum(len(p) for p in yielding)
        nyielded = sum(len(p) for p in yielded)
        if nyielded:
            pts = np.concatenate(yielded)
            ax.plot(pts[:, 0], pts[:, 1], "o", mfc="none", mec="0.5", ms=3,
                    label=f"yielded earlier ({nyielded})")
        if nyield:
            pts = np.concatenate(yielding)
            ax.plot(pts[:, 0], pts[:, 1], "o", color="red", ms=3,
                    label=f"yielding now ({nyield})")
        if nyield or nyielded:
            ax.legend(loc="lower right", fontsize=8, title="plastic Gauss points",
                      title_fontsize=8)
        g = m.f[f"increments/{key}"]
        ax.set_title(f"{text(m.f.attrs.get('title', ''))}\nincrement {int(key)} (step "
                     f"{int(g.attrs.get('step', 0))}), displacements x{scale:.3g}", fontsize=10)
        data.update({"colour_range": [lo, hi], "colour_range_of": what, "scale": scale,
                     "values": {name: [float(x) for x in v] for name, _, _, v, _, _ in sets},
                     "yielding_points": nyield, "yielded_points": nyielded})
    if curve:
        axc.plot(curve["displacement"], curve["load"], "o-", ms=3)
        axc.set_xlabel(f"{curve['label']}\n{curve['xlabel']}", fontsize=9)
        axc.set_ylabel(curve["ylabel"])
        axc.set_title(f"load-displacement, pattern '{curve['pattern']}' ({curve['kind'].lower()})",
                      fontsize=10)
        axc.grid(alpha=0.3)
        data["curve"] = curve
    fig.tight_layout()
    out = Path(a.output) if a.output else m.path.with_suffix(".png")
    tmp = out.with_name(f".{out.name}.{os.getpid()}.tmp")
    try:
        fig.savefig(tmp, format="png", dpi=a.dpi, bbox_inches="tight")
        os.replace(tmp, out)
    finally:
        if tmp.exists():
            tmp.unlink()
    plt.close(fig)
    if a.data:
        Path(a.data).write_text(json.dumps(data, indent=1))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(prog="pecplas-plot", description=__doc__.split("\n\n")[0])
    ap.add_argument("results", help="a results file of pecplas (.h5)")
    ap.add_argument("-o", "--output", help="PNG file (default: RESULTS with .png)")
    ap.add_argument("--field", choices=[*FIELDS, *ALIASES],
                    help="the colour field (default syy, or u where no stress was written)")
    ap.add_argument("--component", dest="field", choices=[*ALIASES, *STRESS],
                    help=argparse.SUPPRESS)
    ap.add_argument("--increment", type=int, help="global increment (default: the last)")
    ap.add_argument("--scale", type=float, help="displacement magnification (default: "
                    "the largest displacement drawn as 1/10 of the model)")
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--range-set", metavar="SET", help="colour scale over this element set")
    g.add_argument("--range", type=float, nargs=2, metavar=("LO", "HI"))
    g.add_argument("--full-range", action="store_true", help="full range of the model")
    ap.add_argument("--no-plastic", action="store_true", help="no plastic points")
    ap.add_argument("--node", type=int, help="curve of this node (user id)")
    ap.add_argument("--dof", choices=["x", "y", "r", "z", "1", "2"],
                    help="curve displacement component (default: along the load)")
    ap.add_argument("--set", help="curve of the mean over this node or edge set")
    g = ap.add_mutually_exclusive_group()
    g.add_argument("--curve-only", action="store_true")
    g.add_argument("--mesh-only", action="store_true")
    ap.add_argument("--dpi", type=int, default=120)
    ap.add_argument("--data", help="also write the numbers drawn to this JSON file")
    a = ap.parse_args(argv)
    if a.node is not None and a.set:
        ap.error("--node and --set exclude each other")
    try:
        m = Model(a.results)
        try:
            out = draw(m, a)
        finally:
            m.f.close()
    except InputError as e:
        print(f"pecplas-plot: {e}", file=sys.stderr)
        return 2
    print(f"pecplas-plot: {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
