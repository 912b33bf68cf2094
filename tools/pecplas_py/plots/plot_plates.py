#!/usr/bin/env python3
"""N, Q, M and the deflection along each plate of a results file, one curve per phase.

    python3 -m pecplas_py.plots.plot_plates output/wall.h5 [-o out.png] [--plate NAME]

One row of four panels per plate set (axial force N, shear force Q, moment M, deflection:
the displacement along the normal of the plate's first element), plotted against the length
along the plate (from its first node), at the last written increment of each phase (of each
step in a run without phases); a phase in which the plate is not active draws nothing. The
forces are the `node_forces` of the results (per unit width, or per unit length of
circumference in axisymmetry; doc/results.md)."""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.results import Results, text


def plate_curves(r, name):
    """[(phase label, s, N, Q, M, deflection)] of plate `name` at each phase end."""
    mesh = r.file[f"mesh/plates/{name}"]
    nodes = mesh["nodes"][()]
    x = r.coordinates[nodes]
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(x, axis=0), axis=1))])
    conn = mesh["connectivity"][()]
    t = r.coordinates[conn[0, 1]] - r.coordinates[conn[0, 0]]
    n = np.array([-t[1], t[0]]) / np.linalg.norm(t)
    units = r.attr("units", "")
    out = []
    ends = r.phase_ends()
    for phase in r.phases():
        key = ends.get(phase["index"])
        if key is None or f"increments/{key}/plates/{name}" not in r.file:
            continue
        f = r.field(key, f"plates/{name}/node_forces")
        u = r.field(key, f"plates/{name}/displacement")
        label = f"{phase['index']} {phase['name']}".strip()
        out.append((label, s, f[:, 0], f[:, 1], f[:, 2], u @ n))
    return out, units


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("results", type=Path)
    ap.add_argument("-o", "--output", type=Path, help="PNG (default: RESULTS_plates.png)")
    ap.add_argument("--plate", help="only this plate set")
    args = ap.parse_args(argv)
    with Results(args.results) as r:
        if "mesh/plates" not in r.file:
            sys.exit(f"{args.results}: no plate sets")
        names = [args.plate] if args.plate else sorted(r.file["mesh/plates"].keys())
        rows = []
        for name in names:
            if f"mesh/plates/{name}" not in r.file:
                sys.exit(f"{args.results}: no plate set {name!r}")
            rows.append((name,) + plate_curves(r, name))
        title = text(r.attr("title", ""))
    fig, axes = plt.subplots(len(rows), 4, figsize=(16, 3.6 * len(rows)), squeeze=False)
    for i, (name, curves, units) in enumerate(rows):
        for label, s, nn, qq, mm, w in curves:
            for ax, v in zip(axes[i], (nn, qq, mm, w)):
                ax.plot(s, v, marker=".", label=label)
        for ax, what in zip(axes[i], ("N", "Q", "M", "deflection (along n)")):
            ax.set_title(f"{name}: {what}")
            ax.set_xlabel("length along the plate")
            ax.axhline(0.0, color="0.7", lw=0.8)
            ax.grid(True, lw=0.3)
        axes[i][0].legend(fontsize=7)
    fig.suptitle(f"{title} {('[' + str(units) + ']') if units else ''}".strip())
    fig.tight_layout()
    out = args.output or args.results.with_name(args.results.stem + "_plates.png")
    save_figure(fig, out)
    print(out)


if __name__ == "__main__":
    main()
