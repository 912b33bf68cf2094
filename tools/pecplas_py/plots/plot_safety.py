#!/usr/bin/env python3
"""Picture of a safety step (strength reduction, doc/results.md "Safety factor").

    python3 -m pecplas_py.plots.plot_safety RESULTS.h5 [-o OUT.png] [--circle XC YC R]...

(run from tools/, or with tools/ on PYTHONPATH) writes one PNG: the mesh coloured by the
magnitude of the mechanism (/safety/mechanism: the incremental displacements of the last
increments of the safety step, normalised to their largest value), with arrows of it, and
beside it the curve Msf against the chosen displacement (/safety/msf, /safety/displacement),
the factor, its resolution and how it was found in the title. `--circle XC YC R` (repeatable)
draws a slip circle over the mechanism (a limit-equilibrium critical circle, for comparison).
The displacements of a safety step are not physical: only the shape of the mechanism is.
Exit codes: 0 written, 2 bad input.
"""
import argparse
import sys
from pathlib import Path

import h5py
import numpy as np

OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7], "Q8R": [0, 4, 1, 5, 2, 6, 3, 7]}


def text(v):
    return v.decode() if isinstance(v, (bytes, np.bytes_)) else str(v)


def read(path):
    """Mesh polygons, mechanism (nnode, 2), curve and the /safety attributes."""
    with h5py.File(path, "r") as f:
        if "safety" not in f:
            raise ValueError(f"{path}: no /safety group (not the results of a safety step)")
        s = f["safety"]
        info = {k: (text(v) if isinstance(v, (bytes, str, np.bytes_)) else v)
                for k, v in s.attrs.items()}
        x = f["mesh/coordinates"][()]
        polys = []
        for name in f["mesh/sets"]:
            g = f["mesh/sets"][name]
            ring = OUTLINE.get(text(g.attrs["etype"]))
            conn = g["connectivity"][()]
            polys += [x[c[ring] if ring else c] for c in conn]
        mech = s["mechanism"][()] if "mechanism" in s else None
        return x, polys, mech, s["msf"][()], s["displacement"][()], info


def draw(path, out, circles=()):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    x, polys, mech, msf, disp, info = read(path)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(13, 5), gridspec_kw={"width_ratios": [1.6, 1]})
    if mech is not None and len(mech):
        mag = np.hypot(mech[:, 0], mech[:, 1])
        top = mag.max() if mag.max() > 0 else 1.0
        node_of = {tuple(np.round(p, 12)): i for i, p in enumerate(x)}
        vals = [np.mean([mag[node_of[tuple(np.round(p, 12))]] for p in poly]) / top
                for poly in polys]
        pc = PolyCollection(polys, array=np.asarray(vals), cmap="viridis", edgecolor="0.6",
                            linewidth=0.3)
        pc.set_clim(0, 1)
        ax.add_collection(pc)
        fig.colorbar(pc, ax=ax, label="mechanism |du| / max (last increments)")
        size = np.ptp(x, axis=0).max()
        keep = mag > 0.05 * top
        ax.quiver(x[keep, 0], x[keep, 1], mech[keep, 0] / top, mech[keep, 1] / top,
                  angles="xy", scale_units="xy", scale=1.0 / (0.05 * size), width=0.002,
                  color="w")
    else:
        ax.add_collection(PolyCollection(polys, facecolor="none", edgecolor="0.6",
                                         linewidth=0.3))
    for xc, yc, r in circles:
        t = np.linspace(0, 2 * np.pi, 400)
        ax.plot(xc + r * np.cos(t), yc + r * np.sin(t), "r-", lw=1.5, label="slip circle")
    ax.set_xlim(x[:, 0].min(), x[:, 0].max())
    ax.set_ylim(x[:, 1].min(), x[:, 1].max())
    ax.set_aspect("equal")
    ax.set_title("failure mechanism (shape only: safety-step displacements are not physical)",
                 fontsize=9)
    kind = info.get("kind", "")
    if kind == "factor":
        head = f"Msf = {info['factor']:.4g} (resolution {info['resolution']:.2g})"
    elif kind == "lower bound":
        head = f"Msf >= {info['factor']:.4g} (lower bound: increment budget used)"
    else:
        head = kind
    bx.plot(disp, msf, "o-", ms=3)
    bx.set_xlabel(info.get("displacement_of", "displacement"))
    bx.set_ylabel("Msf")
    bx.grid(alpha=0.3)
    bx.set_title(head)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("results")
    p.add_argument("-o", "--output")
    p.add_argument("--circle", nargs=3, type=float, action="append", default=[],
                   metavar=("XC", "YC", "R"))
    a = p.parse_args(argv)
    out = a.output or str(Path(a.results).with_suffix("")) + "_safety.png"
    try:
        draw(a.results, out, a.circle)
    except (OSError, ValueError, KeyError) as e:
        print(f"plot_safety: {e}", file=sys.stderr)
        return 2
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
