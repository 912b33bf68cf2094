#!/usr/bin/env python3
"""Figures and numbers of the structure examples (doc/validation.md, Structures): for the
strutted excavation (input/examples/excavation_strutted.inp, the wall as a plate, and
excavation_strutted_strip.inp, the same wall as a continuum strip) the strut force and the
largest wall moment at the end of each stage, the head displacement, the wall deflection
profiles (PNG) and the run times; for the anchored wall the anchor force per phase.

    python3 -m pecplas_py.scenes.structures_report PLATE.h5 STRIP.h5 [ANCHORED.h5] [--png FILE]

The strip's moment at a level is the first moment of sigma_yy about the wall's axis over the
elements across it, integrated by their Gauss points (2 x 2 per Q4: exact for a linear
stress across each element).
"""
import argparse

import h5py
import numpy as np

WALL_X = 10.0


def stage_ends(f):
    """Global increment of the last increment of each step, and the step numbers."""
    h = f["history"]
    steps, glob = h["step"][()], h["global_increment"][()]
    ends = {}
    for s, g in zip(steps, glob):
        ends[int(s)] = int(g)
    return ends


def inc(f, g):
    return f["increments"][f"{g:06d}"]


def plate_stage(f, g):
    grp = inc(f, g)
    nodes = f["mesh/plates/wall/nodes"][()]
    xy = f["mesh/coordinates"][()]
    y = xy[nodes, 1]
    m = grp["plates/wall/node_forces"][()][:, 2]
    ux = grp["displacement"][()][nodes, 0]
    strut = grp["anchors/strut/force"][()][0] if "anchors/strut" in grp else 0.0
    return dict(y=y, ux=ux, mmax=np.max(np.abs(m)), head=ux[np.argmax(y)], strut=strut)


def strip_stage(f, g):
    grp = inc(f, g)
    xy = f["mesh/coordinates"][()]
    centre = np.where(np.isclose(xy[:, 0], WALL_X + 0.4) & (xy[:, 1] >= -12.0 - 1e-9))[0]
    order = np.argsort(xy[centre, 1])
    centre = centre[order]
    ux = grp["displacement"][()][centre, 0]
    gx = f["mesh/sets/wall/gauss_coordinates"][()]
    s = grp["sets/wall/stress"][()][:, :, 1]
    # per level (element row): the integral of sigma_yy (x - xc) across the wall, by each
    # element's 2 x 2 Gauss points (weight w/2 across, averaged over its two Gauss rows; its
    # width w = sqrt(3) times the spread of its Gauss points across)
    levels = {}
    for e in range(gx.shape[0]):
        yc = round(float(np.mean(gx[e, :, 1])), 6)
        w = np.sqrt(3.0) * (np.max(gx[e, :, 0]) - np.min(gx[e, :, 0]))
        mom = np.sum(s[e] * (gx[e, :, 0] - (WALL_X + 0.4))) * w / 4.0
        levels[yc] = levels.get(yc, 0.0) + mom
    mmax = max(abs(v) for v in levels.values())
    strut = grp["anchors/strut/force"][()][0] if "anchors/strut" in grp else 0.0
    return dict(y=xy[centre, 1], ux=ux, mmax=mmax, head=ux[-1], strut=strut)


def run_time(f):
    h = f["history"]
    return float(h["cpu_time"][()][-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("plate")
    ap.add_argument("strip")
    ap.add_argument("anchored", nargs="?")
    ap.add_argument("--png", default="doc/img/excavation_strutted.png")
    a = ap.parse_args()
    fp, fs = h5py.File(a.plate), h5py.File(a.strip)
    ep, es = stage_ends(fp), stage_ends(fs)
    names = {1: "excavate_1 (2 m)", 2: "strut", 3: "excavate_2 (4 m)", 4: "excavate_3 (6 m)"}
    print("| stage | strut force, plate [kN] | strip | max wall moment, plate [kN m/m] | strip "
          "| head displacement, plate [mm] | strip |")
    print("|---|---|---|---|---|---|---|")
    prof = []
    for k in sorted(ep):
        p, s = plate_stage(fp, ep[k]), strip_stage(fs, es[k])
        prof.append((names.get(k, str(k)), p, s))
        print(f"| {names.get(k, k)} | {p['strut']:.1f} | {s['strut']:.1f} | {p['mmax']:.1f} | "
              f"{s['mmax']:.1f} | {1e3*p['head']:.2f} | {1e3*s['head']:.2f} |")
    print(f"CPU time: plate {run_time(fp):.2f} s, strip {run_time(fs):.2f} s")
    if a.anchored:
        fa = h5py.File(a.anchored)
        for k, g in sorted(stage_ends(fa).items()):
            grp = inc(fa, g)
            t = grp["anchors/tie/force"][()][0] if "anchors/tie" in grp else float("nan")
            print(f"anchored wall, step {k}: tie force {t:.2f} kN")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(5, 6))
    for i, (name, p, s) in enumerate(prof):
        c = f"C{i}"
        ax.plot(1e3*p["ux"], p["y"], "-", color=c, label=f"{name}: plate")
        ax.plot(1e3*s["ux"], s["y"], "--", color=c, label=f"{name}: strip")
    ax.set_xlabel("horizontal displacement of the wall [mm]")
    ax.set_ylabel("y [m]")
    ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=120)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
