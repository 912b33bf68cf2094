#!/usr/bin/env python3
"""Picture of a PECPLAS results file: the deformed mesh (magnified) coloured by a stress
component at the last written increment (element average of the Gauss-point values).

    python3 tools/plot_results.py output/default.h5 [-o out.png] [--component yy]
                                  [--increment N] [--scale S]
Components: xx, yy, zz, xy (tension positive)."""

import argparse
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

COMPONENTS = {"xx": 0, "yy": 1, "zz": 2, "xy": 3}
# corner nodes in boundary order; quadratic elements walk corner, mid, corner, ...
OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output")
    ap.add_argument("--component", default="yy", choices=COMPONENTS)
    ap.add_argument("--increment", type=int)
    ap.add_argument("--scale", type=float, help="displacement magnification (auto)")
    a = ap.parse_args()
    out = Path(a.output) if a.output else Path(a.h5).with_suffix(".png")
    with h5py.File(a.h5) as f:
        x = f["mesh/coordinates"][:]
        incs = sorted(f["increments"].keys()) if "increments" in f else []
        if not incs:
            sys.exit(f"{a.h5}: no increment with fields")
        key = f"{a.increment:06d}" if a.increment else incs[-1]
        g = f["increments"][key]
        u = g["displacement"][:]
        size = np.ptp(x, axis=0).max()
        scale = a.scale or (0.1 * size / max(np.abs(u).max(), 1e-300))
        polys, values = [], []
        for name, s in f["mesh/sets"].items():
            etype = s.attrs["etype"]
            etype = etype.decode() if isinstance(etype, bytes) else etype
            conn = s["connectivity"][:]
            stress = g["sets"][name]["stress_mean"][:] if name in g.get("sets", {}) else None
            for e, nodes in enumerate(conn):
                ring = nodes[OUTLINE[etype]]
                polys.append(x[ring] + scale * u[ring])
                values.append(stress[e, COMPONENTS[a.component]] if stress is not None else 0)
        title = f["/"].attrs.get("title", "")
        time = g.attrs.get("time", 0.0)
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
    fig.savefig(out, dpi=120)
    print(f"plot_results: {out}")



if __name__ == "__main__":
    main()
