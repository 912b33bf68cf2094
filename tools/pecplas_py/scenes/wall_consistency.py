#!/usr/bin/env python3
"""The wall in soil as a continuum strip and as a plate (pecplas_py.decks.wall_pair): head
displacement and largest bending moment at the end of each excavation phase, side by side,
for the variants of the study of doc/validation.md (Structures: why a coarse strip and the
plate differ).

    python3 -m pecplas_py.scenes.wall_consistency [DIR] [--bin DIR] [--only NAME ...]
                                                  [--write | --check]

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
# (name, description, pair); the test's pair is TEST (test/python/test_wall_consistency.py)
TEST = WallPair(clamp_toe=True, kt=1.0, t=0.1, e_w=2.1e8, row=0.125)
VARIANTS = [
    ("free_rough", "toe free, rough faces (K_t = 3e4), t = 0.4 m, Q8 2 across, 0.25 m rows",
     WallPair()),
    ("free_rough_fine", "the same, 0.125 m rows", WallPair(row=0.125)),
    ("free_rough_q8_1", "the same, one Q8 across, 0.5 m rows", WallPair(ncross=1, row=0.5)),
    ("free_rough_q4", "the same, four Q4 across, 0.5 m rows",
     WallPair(element="Q4", ncross=4, row=0.5)),
    ("free_smooth", "toe free, smooth faces (K_t = 1)", WallPair(kt=1.0)),
    ("free_smooth_k0_1", "toe free, smooth faces, K0 = 1", WallPair(kt=1.0, k0=1.0)),
    ("held_rough", "toe held, rough faces", WallPair(clamp_toe=True)),
    ("held_rough_q4", "toe held, rough faces, four Q4 across, 0.5 m rows",
     WallPair(clamp_toe=True, element="Q4", ncross=4, row=0.5)),
    ("held_smooth", "toe held, smooth faces", WallPair(clamp_toe=True, kt=1.0)),
    ("held_smooth_t0.8", "toe held, smooth faces, t = 0.8 m (EI kept)",
     WallPair(clamp_toe=True, kt=1.0, t=0.8, e_w=3.0e7 / 8)),
    ("held_smooth_t0.2", "toe held, smooth faces, t = 0.2 m (EI kept)",
     WallPair(clamp_toe=True, kt=1.0, t=0.2, e_w=3.0e7 * 8)),
    ("held_smooth_t0.1", "toe held, smooth faces, t = 0.1 m (EI kept)",
     WallPair(clamp_toe=True, kt=1.0, t=0.1, e_w=3.0e7 * 64)),
    ("test", "the test: toe held, smooth faces, steel t = 0.1 m (E = 2.1e8 kPa), "
     "0.125 m rows", TEST),
    ("free_mc", "toe free, Mohr-Coulomb soil (phi = 30 deg, c = 1 kPa) and joints "
     "(delta = 20 deg)", WallPair(soil=MC, soil_type="MOHR_COULOMB", law="MOHR_COULOMB",
                                  increments=5)),
]
SCRIPT = "scenes/wall_consistency.py"


def markdown(results):
    """The table of doc/validation.md from {name: measure() rows}."""
    lines = ["| variant | max \\|M\\|, plate / strip [kN m/m] | difference | profile "
             "difference / max \\|M\\| | head u_x, plate / strip [mm] | difference |",
             "|---|---|---|---|---|---|"]
    for name, text, _ in VARIANTS:
        if name not in results:
            continue
        r = results[name][-1]
        lines.append(f"| {text} | {r['m_plate']:.2f} / {r['m_strip']:.2f} "
                     f"| {100 * (r['m_plate'] / r['m_strip'] - 1):+.1f} % "
                     f"| {100 * r['profile_diff'] / r['m_strip']:.1f} % "
                     f"| {1e3 * r['head_plate']:.3f} / {1e3 * r['head_strip']:.3f} "
                     f"| {100 * (r['head_plate'] / r['head_strip'] - 1):+.1f} % |")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", nargs="?", default=str(ROOT / "output" / "wall_consistency"))
    ap.add_argument("--bin", help="directory of the pecplas executable")
    ap.add_argument("--only", nargs="*", help="variants to run (default: all)")
    ap.add_argument("--write", action="store_true",
                    help="write the table into doc/validation.md (all variants)")
    ap.add_argument("--check", action="store_true",
                    help="compare the table with doc/validation.md (all variants)")
    a = ap.parse_args(argv)
    results = {}
    for name, _, p in VARIANTS:
        if a.only and name not in a.only:
            continue
        results[name] = run_pair(p, name, a.dir, a.bin)
    text = markdown(results)
    print(text)
    if a.write or a.check:
        from pecplas_py.doc_blocks import check_close, update
        doc = ROOT / "doc" / "validation.md"
        if a.check:
            bad = check_close(doc, SCRIPT, {"wall-consistency": text})
            print(bad or "wall_consistency: doc/validation.md is up to date")
            return 1 if bad else 0
        update(doc, SCRIPT, {"wall-consistency": text}, False)
    return 0


if __name__ == "__main__":
    sys.exit(main())
