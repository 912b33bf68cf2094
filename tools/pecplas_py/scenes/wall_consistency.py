#!/usr/bin/env python3
"""The wall in soil as a continuum strip and as a plate (pecplas_py.decks.wall_pair): head
displacement and largest bending moment at the end of each excavation phase, side by side,
for the variants of the study of doc/validation.md (Structures: why a coarse strip and the
plate differ).

    python3 -m pecplas_py.scenes.wall_consistency [DIR] [--bin DIR] [--only NAME ...]

Measures (`measure`):
- head displacement: u_x of the wall's axis at the top (the plate's top node; for the strip
  u_x along its top edge interpolated linearly to x = t/2);
- moment: the plate's smoothed nodal moments (plates/wall/node_forces); the strip's
  M(y) = integral over the thickness of sigma_yy (x - t/2) dx at each level of Gauss points,
  by the elements' Gauss rule across their width (2 points for Q4, 3 for Q8: exact for the
  stress across an element, a polynomial of degree 1 (Q4) or 2 (Q8) in x, times x). The
  geostatic stress, uniform across the strip, adds nothing. The largest |M| of each, and the
  plate's moment interpolated to the strip's levels to compare the profiles.
"""
import argparse
import math
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

from pecplas_py import ROOT
from pecplas_py.decks.wall_pair import WallPair, deck
from pecplas_py.exe import exe_cmd
from pecplas_py.results import Results

GAUSS = {2: {1.0 / math.sqrt(3.0): 1.0},
         3: {0.0: 8.0 / 9.0, math.sqrt(0.6): 5.0 / 9.0}}


def strip_moments(r, key, t):
    """(levels y descending, M(y)) of the strip at increment `key`."""
    s = r.element_set("wall")
    gxy = s["gauss_coordinates"][()]             # (nel, ngauss, 2)
    conn = s["connectivity"][()]
    x = r.coordinates
    stress = r.field(key, "sets/wall/stress")    # (nel, ngauss, 4)
    npts = round(math.sqrt(gxy.shape[1]))
    rule = GAUSS[npts]
    levels = {}
    for e in range(gxy.shape[0]):
        xe = x[conn[e, :4], 0]
        xc, h = 0.5 * (xe.min() + xe.max()), xe.max() - xe.min()
        for q in range(gxy.shape[1]):
            px, py = gxy[e, q]
            xi = (px - xc) / (h / 2)
            w = [wt for a, wt in rule.items() if abs(abs(xi) - a) < 1e-6]
            if len(w) != 1:
                raise ValueError(f"wall element {e}: Gauss point at xi = {xi}")
            k = round(py, 6)
            levels[k] = levels.get(k, 0.0) + w[0] * h / 2 * stress[e, q, 1] * (px - t / 2)
    ys = np.array(sorted(levels, reverse=True))
    return ys, np.array([levels[y] for y in ys])


def strip_head(r, key, t):
    """u_x of the strip's axis at its top (linear along the top edge)."""
    conn = r.element_set("wall")["connectivity"][()]
    nodes = np.unique(conn[conn >= 0])
    x = r.coordinates
    top = nodes[np.abs(x[nodes, 1]) < 1e-9]
    order = np.argsort(x[top, 0])
    u = r.field(key, "displacement")
    return float(np.interp(t / 2, x[top[order], 0], u[top[order], 0]))


def plate_profile(r, key):
    """(y of the plate nodes, M, u_x) at increment `key`, top first."""
    nodes = r.file["mesh/plates/wall/nodes"][()]
    y = r.coordinates[nodes, 1]
    m = r.field(key, "plates/wall/node_forces")[:, 2]
    ux = r.field(key, "displacement")[nodes, 0]
    o = np.argsort(-y)
    return y[o], m[o], ux[o]


def measure(plate_h5, strip_h5, t):
    """Per phase: {'head_plate', 'head_strip', 'm_plate', 'm_strip' (largest |M|),
    'depth_plate', 'depth_strip', 'profile_diff' (largest |M_plate - M_strip| over the
    strip's levels, the plate's moment interpolated linearly between its nodes)}."""
    out = []
    with Results(plate_h5) as rp, Results(strip_h5) as rs:
        ep, es = rp.phase_ends(), rs.phase_ends()
        for ph in sorted(ep):
            yp, mp, uxp = plate_profile(rp, ep[ph])
            ys, ms = strip_moments(rs, es[ph], t)
            # same sign convention? (M from sigma_yy (x - t/2) vs the plate's): align by the
            # sign that makes the profiles agree
            mpi = np.interp(-ys, -yp, mp)
            sign = 1.0 if np.dot(mpi, ms) >= 0 else -1.0
            ip, js = int(np.argmax(np.abs(mp))), int(np.argmax(np.abs(ms)))
            out.append({"phase": ph, "head_plate": float(uxp[0]),
                        "head_strip": strip_head(rs, es[ph], t),
                        "m_plate": float(abs(mp[ip])), "depth_plate": float(-yp[ip]),
                        "m_strip": float(abs(ms[js])), "depth_strip": float(-ys[js]),
                        "profile_diff": float(np.max(np.abs(sign * mpi - ms))),
                        "sign": sign})
    return out


def run(text, path, bin_dir=None):
    path = Path(path)
    path.write_text(text)
    out = path.with_suffix(".h5")
    p = subprocess.run([*exe_cmd("pecplas", bin_dir), str(path), "-o", str(out), "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"pecplas {path}: exit {p.returncode}\n{p.stdout[-2000:]}"
                         f"{p.stderr[-2000:]}")
    return out


def run_pair(p, name, out_dir, bin_dir=None):
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    hp = run(deck(p, plate=True), out_dir / f"{name}_plate.inp", bin_dir)
    hs = run(deck(p, plate=False), out_dir / f"{name}_strip.inp", bin_dir)
    return measure(hp, hs, p.t)


MC = dict(E=3.0e4, NU=0.3, GAMMA=18.0, C=1.0, PHI=30.0, PSI=0.0)
VARIANTS = {
    "test": WallPair(),
    "q4_2_050": WallPair(element="Q4", ncross=2, row=0.5),
    "q4_4_050": WallPair(element="Q4", ncross=4, row=0.5),
    "q4_4_025": WallPair(element="Q4", ncross=4, row=0.25),
    "q8_1_050": WallPair(ncross=1, row=0.5),
    "q8_2_050": WallPair(ncross=2, row=0.5),
    "q8_2_0125": WallPair(ncross=2, row=0.125),
    "q8_2_smooth": WallPair(kt=1.0),
    "q8_2_thick": WallPair(t=0.8),
    "q8_2_thick_smooth": WallPair(t=0.8, kt=1.0),
    "q8_2_thin_smooth": WallPair(t=0.2, kt=1.0),
    "q8_2_thin": WallPair(t=0.2),
    "q8_2_smooth_k1": WallPair(kt=1.0, k0=1.0),
    "q8_2_smooth_k1_tip": WallPair(kt=1.0, k0=1.0, tip_k=1.0),
    "q8_2_k1_tip": WallPair(k0=1.0, tip_k=1.0),
    "q8_2_thin_k1_tip": WallPair(t=0.2, k0=1.0, tip_k=1.0),
    "clamped": WallPair(clamp_toe=True),
    "clamped_k1": WallPair(clamp_toe=True, k0=1.0),
    "clamped_smooth": WallPair(clamp_toe=True, kt=1.0),
    "clamped_q4_4_050": WallPair(clamp_toe=True, element="Q4", ncross=4, row=0.5),
    "clamped_smooth_thin": WallPair(clamp_toe=True, kt=1.0, t=0.2),
    "clamped_smooth_q8_1": WallPair(clamp_toe=True, kt=1.0, ncross=1, row=0.5),
    "q8_2_mc": WallPair(soil=MC, soil_type="MOHR_COULOMB", law="MOHR_COULOMB", increments=5),
}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", nargs="?", default=str(ROOT / "output" / "wall_consistency"))
    ap.add_argument("--bin", help="directory of the pecplas executable")
    ap.add_argument("--only", nargs="*", help="variants to run (default: all)")
    a = ap.parse_args(argv)
    print("| variant | phase | head u_x plate [mm] | strip | diff | max M plate [kN m/m] "
          "(depth) | strip (depth) | diff | profile diff / max M |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, p in VARIANTS.items():
        if a.only and name not in a.only:
            continue
        for r in run_pair(p, name, a.dir, a.bin):
            dh = r["head_plate"] / r["head_strip"] - 1
            dm = r["m_plate"] / r["m_strip"] - 1
            print(f"| {name} | {r['phase']} | {1e3 * r['head_plate']:.3f} | "
                  f"{1e3 * r['head_strip']:.3f} | {100 * dh:+.2f} % | {r['m_plate']:.2f} "
                  f"({r['depth_plate']:.2f}) | {r['m_strip']:.2f} ({r['depth_strip']:.2f}) | "
                  f"{100 * dm:+.2f} % | {100 * r['profile_diff'] / r['m_strip']:.2f} % |",
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
