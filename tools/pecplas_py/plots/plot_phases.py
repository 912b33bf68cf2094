#!/usr/bin/env python3
"""Phase by phase picture of a staged run: one panel per phase, the deformed mesh at the
phase's last written increment, with only the element sets and joint sets active in that
phase (an excavation shows its pit growing, an embankment its lifts), coloured by a stress
component (element mean of the Gauss values); joints are drawn as lines. Every panel uses the
same displacement magnification and colour scale, so that the panels compare.

    python3 -m pecplas_py.plots.plot_phases output/excavation_cantilever.h5 [-o out.png]
        [--component yy] [--scale S] [--columns N] [--displacements-from-phase K]
        [--window X0 X1 Y0 Y1]

Components: xx, yy, zz, xy (tension positive). A run without /phases (one step or several,
no model change) gives one panel per step. `--displacements-from-phase K` draws the
displacements measured from the end of phase K (e.g. the phase that set up the initial
state) rather than the total ones; a phase that reset displacements already starts from
zero."""

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.results import Results, text

COMPONENTS = {"xx": 0, "yy": 1, "zz": 2, "xy": 3}
# corner nodes in boundary order; quadratic elements walk corner, mid, corner, ...
OUTLINE = {"T3": [0, 1, 2], "Q4": [0, 1, 2, 3], "T6": [0, 3, 1, 4, 2, 5],
           "Q8": [0, 4, 1, 5, 2, 6, 3, 7], "Q8R": [0, 4, 1, 5, 2, 6, 3, 7]}


def panels(r, component="yy", from_phase=None):
    """One dict per phase with a written increment: phase (dict of Results.phases), key,
    polys (deformed outlines before scaling: (x, u) pairs), values, joint segments."""
    ends = r.phase_ends()
    x = r.coordinates
    comp = COMPONENTS[component]
    u0 = None
    if from_phase is not None:
        if from_phase not in ends:
            raise SystemExit(f"{r.path}: phase {from_phase} has no written increment")
        u0 = r.field(ends[from_phase], "displacement")
    out = []
    for phase in r.phases():
        key = ends.get(phase["index"])
        if key is None:
            continue
        u = r.field(key, "displacement")
        if u0 is not None:
            u = u - u0
        g = r.increment(key)
        esets, jsets = r.active_sets(key)
        if "sets" not in g:       # no stresses written: the phase's masks say what is there
            esets = phase["active_element_sets"]
        rings, values = [], []
        for name in esets:
            s = r.element_set(name)
            etype = text(s.attrs["etype"])
            conn = s["connectivity"][:]
            stress = g[f"sets/{name}/stress_mean"][:] if f"sets/{name}/stress_mean" in g \
                else None
            for e, nodes in enumerate(conn):
                ring = nodes[OUTLINE[etype]]
                rings.append(ring)
                values.append(stress[e, comp] if stress is not None else np.nan)
        joints = []
        if "joints" not in g:
            jsets = phase["active_joint_sets"]
        for name in jsets:
            conn = r.joint_set(name)["connectivity"][:]
            for nodes in conn:
                # a Goodman element: nodes of one face then the other; its first face
                half = max(1, len(nodes) // 2)
                face = nodes[:half]
                joints.append([face[0], face[-1]] if half > 1 else [nodes[0], nodes[-1]])
        out.append({"phase": phase, "key": key, "u": u, "rings": rings,
                    "values": np.asarray(values, dtype=float), "joints": joints, "x": x})
    return out


def draw(r, out, component="yy", scale=None, columns=None, from_phase=None, window=None):
    """Writes the figure; returns the number of panels. `window` (x0, x1, y0, y1): the part
    of the model drawn (default: all of it)."""
    data = panels(r, component, from_phase)
    if not data:
        raise SystemExit(f"{r.path}: no phase with a written increment")
    x = r.coordinates
    size = np.ptp(x, axis=0).max()
    umax = max(np.abs(d["u"]).max() for d in data)
    scale = scale or (0.05 * size / max(umax, 1e-300))
    finite = np.concatenate([d["values"][np.isfinite(d["values"])] for d in data])
    vmin, vmax = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
    n = len(data)
    ncol = columns or min(n, 3)
    nrow = -(-n // ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol, 4.2 * nrow), squeeze=False)
    pc = None
    for ax, d in zip(axes.ravel(), data):
        xy = d["x"] + scale * d["u"]
        pc = PolyCollection([xy[ring] for ring in d["rings"]], array=d["values"],
                            cmap="viridis", edgecolors="k", linewidths=0.25)
        pc.set_clim(vmin, vmax)
        ax.add_collection(pc)
        if d["joints"]:
            ax.add_collection(LineCollection([xy[j] for j in d["joints"]], colors="tab:red",
                                             linewidths=1.2))
        if window:
            ax.set_xlim(window[0], window[1])
            ax.set_ylim(window[2], window[3])
        else:
            ax.set_xlim(x[:, 0].min() - 0.02 * size, x[:, 0].max() + 0.02 * size)
            ax.set_ylim(x[:, 1].min() - 0.02 * size, x[:, 1].max() + 0.02 * size)
        ax.set_aspect("equal")
        p = d["phase"]
        head = f"phase {p['index']}" + (f" {p['name']}" if p["name"] else "")
        changes = p["changes"][:2] + (["..."] if len(p["changes"]) > 2 else [])
        ax.set_title("\n".join([head + f" (increment {int(d['key'])})", *changes]),
                     fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in axes.ravel()[n:]:
        ax.set_visible(False)
    unit = str(r.attr("stress_unit", ""))
    unit = "" if unit in ("", "(not stated)") else f" [{unit}]"
    fig.colorbar(pc, ax=axes.ravel().tolist(), shrink=0.8,
                 label=f"sigma_{component} (element mean, tension +){unit}")
    what = "displacements" if from_phase is None else f"displacements since phase {from_phase}"
    fig.suptitle(f"{r.attr('title', '')}: {what} x{scale:.3g}, red: joints", fontsize=10)
    save_figure(fig, out, dpi=110)
    plt.close(fig)
    return n


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG (default: the results file with _phases.png)")
    ap.add_argument("--component", default="yy", choices=COMPONENTS)
    ap.add_argument("--scale", type=float, help="displacement magnification (auto)")
    ap.add_argument("--columns", type=int, help="panels per row (default: up to 3)")
    ap.add_argument("--displacements-from-phase", type=int, dest="from_phase",
                    help="draw the displacements since the end of this phase")
    ap.add_argument("--window", type=float, nargs=4, metavar=("X0", "X1", "Y0", "Y1"),
                    help="draw only this part of the model")
    a = ap.parse_args(argv)
    out = Path(a.output) if a.output else Path(a.h5).with_name(Path(a.h5).stem + "_phases.png")
    with Results(a.h5) as r:
        if not r.keys:
            sys.exit(f"{a.h5}: no increment with fields")
        n = draw(r, out, a.component, a.scale, a.columns, a.from_phase, a.window)
    print(f"plot_phases: {out} ({n} phases)")


if __name__ == "__main__":
    main()
