#!/usr/bin/env python3
"""Picture of a PECPLAS results file: the deformed mesh (magnified) coloured by a stress
component at the last written increment (element average of the Gauss-point values) and,
when a load pattern acts on an edge or node set of its own name (e.g. the pile head `head`
of the default deck), the load-displacement curve of its loaded node beside it.

    python3 -m pecplas_py.plots.plot_results output/default.h5 [-o out.png] [--component yy]
                                                 [--increment N] [--scale S]
Components: xx, yy, zz, xy (tension positive).

The load of a pattern is its resultant, taken from the support reactions: by equilibrium the
sum of the reactions is the initial part plus sum_k F_k f_k (pattern resultant F_k times its
factor f_k), so a least-squares fit over the written increments gives F_k without knowing how
the pattern was defined. The loaded node is the node of the set that moves most at the
largest load factor (the pile head's axis node in the default deck). In axisymmetry only
the axial reactions add up to a force (radial ones are balanced by the hoop stresses)."""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.results import Results, text

COMPONENTS = {"xx": 0, "yy": 1, "zz": 2, "xy": 3}
# corner nodes in boundary order; quadratic elements walk corner, mid, corner, ...
OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7], "Q8R": [0, 4, 1, 5, 2, 6, 3, 7]}


def load_curve(r):
    """(label, load [force units], displacement of the loaded node along the load [length])
    for the first pattern acting on an edge or node set of its own name, else None."""
    names = r.patterns if "history" in r.file else []
    mesh = r.file["mesh"]
    sets = {**dict(mesh.get("edge_sets", {}).items()), **dict(mesh.get("node_sets", {}).items())}
    hit = [k for k, n in enumerate(names) if n in sets]
    if not hit:
        return None
    k = hit[0]
    rows = r.field_rows()
    factors = r.pattern_factors(rows)
    keys = r.keys
    if len(keys) != len(rows) or len(keys) < 2:
        return None
    reac = r.fields("reaction").sum(axis=1)
    if r.attr("analysis", "") == "axisymmetric":
        reac[:, 0] = 0.0      # radial reactions of rings do not add up to a force
    design = np.column_stack([np.ones(len(keys)), factors])
    coef = np.linalg.lstsq(design, reac, rcond=None)[0]        # (1 + npattern, 2)
    resultant = coef[1 + k]                                    # reaction of pattern k at f = 1
    if np.linalg.norm(resultant) < 1e-300:
        return None
    direction = -resultant / np.linalg.norm(resultant)         # the load opposes its reactions
    nodes = np.unique(sets[names[k]]["nodes"][:].ravel())
    peak = keys[int(np.argmax(np.abs(factors[:, k])))]
    u_peak = r.field(peak, "displacement")[nodes] @ direction
    node = nodes[int(np.argmax(np.abs(u_peak)))]
    u = np.array([r.field(key, "displacement")[node] @ direction for key in keys])
    load = factors[:, k] * np.linalg.norm(resultant)

    def unit(name):  # the units read from *UNITS; "" when the deck did not state them
        text = str(r.attr(name, ""))
        return "" if text == "(not stated)" else text
    force, length = unit("force_unit"), unit("length_unit")
    label = (f"'{names[k]}' (node {int(r.node_ids[node])})", force.strip(), length.strip())
    return label, np.r_[0.0, load], np.r_[0.0, u]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output")
    ap.add_argument("--component", default="yy", choices=COMPONENTS)
    ap.add_argument("--increment", type=int)
    ap.add_argument("--scale", type=float, help="displacement magnification (auto)")
    a = ap.parse_args()
    out = Path(a.output) if a.output else Path(a.h5).with_suffix(".png")
    with Results(a.h5) as r:
        x = r.coordinates
        incs = r.keys
        if not incs:
            sys.exit(f"{a.h5}: no increment with fields")
        key = f"{a.increment:06d}" if a.increment else incs[-1]
        g = r.increment(key)
        u = r.field(key, "displacement")
        size = np.ptp(x, axis=0).max()
        scale = a.scale or (0.1 * size / max(np.abs(u).max(), 1e-300))
        polys, values = [], []
        for name, s in r.file["mesh/sets"].items():
            etype = text(s.attrs["etype"])
            conn = s["connectivity"][:]
            stress = g["sets"][name]["stress_mean"][:] if name in g.get("sets", {}) else None
            for e, nodes in enumerate(conn):
                ring = nodes[OUTLINE[etype]]
                polys.append(x[ring] + scale * u[ring])
                values.append(stress[e, COMPONENTS[a.component]] if stress is not None else 0)
        title = r.attr("title", "")
        time = g.attrs.get("time", 0.0)
        curve = load_curve(r)
    if curve:
        fig, (ax, axc) = plt.subplots(1, 2, figsize=(12, 5),
                                      gridspec_kw={"width_ratios": [1.4, 1]})
        (name, force, length), load, u = curve
        axc.plot(u, load, "o-", ms=3)
        axc.set_xlabel(f"displacement of the loaded node along the load [{length}]")
        axc.set_ylabel(f"resultant of load {name.split()[0]} [{force}]")
        axc.set_title(f"load-displacement of {name}", fontsize=10)
        axc.grid(alpha=0.3)
    else:
        fig, ax = plt.subplots(figsize=(7, 5))
    pc = PolyCollection(polys, array=np.asarray(values), cmap="viridis", edgecolors="k",
                        linewidths=0.4)
    ax.add_collection(pc)
    ax.autoscale()
    ax.set_aspect("equal")
    fig.colorbar(pc, ax=ax, label=f"sigma_{a.component} (element mean, tension +)")
    ax.set_title(f"{title}\nincrement {int(key)}, time {time:g}, displacements x{scale:.3g}",
                 fontsize=10)
    fig.tight_layout()
    save_figure(fig, out, dpi=120)
    print(f"plot_results: {out}")


if __name__ == "__main__":
    main()
