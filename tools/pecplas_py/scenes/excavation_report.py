#!/usr/bin/env python3
"""The cantilever wall example (input/examples/excavation_cantilever.inp) stage by stage:
after each excavation stage, the wall head displacement towards the excavation and the
largest bending moment of the wall strip, beside a limit-equilibrium hand estimate (Blum's
simplified method for a cantilever in dry sand, Rankine coefficients), and the time each
phase took.

    python3 -m pecplas_py.scenes.excavation_report [RESULTS.h5] [--run] [--bin DIR]
                                                   [--plot PNG]

With --run (or no results file) the deck is run first into output/excavation_cantilever.h5,
and each phase is timed by the arrival of its output lines (wall-clock seconds from the line
that lists its changes to the progress line of its last increment: the phase's own work,
without reading the deck and setting up). The CPU seconds of each phase come from
/history/cpu_time (cumulative CPU time of the run, so the first phase also counts the set-up)
in every case.

Bending moment of the strip: at each level of Gauss points of the wall (Q8, 3x3 Gauss), the
moment of the vertical stress about the strip's mid-line,
    M(y) = integral over the thickness of sigma_yy (x - x_mid) dx,
by the Gauss rule of the elements (exact for the element's stress field across its width,
a polynomial of degree 4 at most in x, times x). M > 0: tension on the excavation side.
The geostatic initial stress is uniform across the strip and adds no moment.

Blum's simplified method (free earth support of a cantilever, rotation point at depth d0
below the excavation level, net Rankine pressures, dry sand, no surcharge):
    moment about the rotation point:  Ka (H + d0)^3 = Kp' d0^3
    required embedment:               D = 1.2 d0
    zero shear at z below the excavation: Ka (H + z)^2 = Kp' z^2
    M_max = gamma / 6 [Ka (H + z)^3 - Kp' z^3]
with Ka = (1 - sin phi)/(1 + sin phi), Kp = 1/Ka, and Kp' = Kp (limit equilibrium) or
Kp / 1.5 (the passive resistance divided by a factor of safety of 1.5, as in design).
"""

import argparse
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from pecplas_py import ROOT
from pecplas_py.decks.make_phase_examples import SAND, STAGES, WALL_L, WALL_T
from pecplas_py.exe import exe_cmd
from pecplas_py.results import Results

DECK = ROOT / "input" / "examples" / "excavation_cantilever.inp"
OUT = ROOT / "output" / "excavation_cantilever.h5"
GAUSS3 = {0.0: 8.0 / 9.0, math.sqrt(0.6): 5.0 / 9.0}


def blum(H, phi=SAND["PHI"], gamma=SAND["GAMMA"], fs=1.0):
    """Blum's simplified cantilever: (d0, required embedment 1.2 d0, z of zero shear below
    the excavation level, M_max) for a retained height H."""
    s = math.sin(math.radians(phi))
    ka = (1 - s) / (1 + s)
    kp = (1 + s) / (1 - s) / fs
    d0 = H / ((kp / ka) ** (1.0 / 3.0) - 1.0)
    z = H / (math.sqrt(kp / ka) - 1.0)
    m = gamma / 6.0 * (ka * (H + z) ** 3 - kp * z ** 3)
    return d0, 1.2 * d0, z, m


def wall_moments(r, key, x_mid=WALL_T / 2):
    """(levels y, M(y), N(y)) of the wall strip at increment `key` (see the module doc)."""
    s = r.element_set("wall")
    gxy = s["gauss_coordinates"][()]             # (nel, ngauss, 2)
    conn = s["connectivity"][()]
    x = r.coordinates
    stress = r.field(key, "sets/wall/stress")    # (nel, ngauss, 4)
    levels = {}
    for e in range(gxy.shape[0]):
        xe = x[conn[e, :4], 0]
        xc, h = 0.5 * (xe.min() + xe.max()), xe.max() - xe.min()
        for p in range(gxy.shape[1]):
            px, py = gxy[e, p]
            xi = (px - xc) / (h / 2)
            w = [wt for a, wt in GAUSS3.items() if abs(abs(xi) - a) < 1e-6]
            if len(w) != 1:
                raise SystemExit(f"wall element {e}: Gauss point at xi = {xi}, not a 3-point rule")
            key_y = round(py, 6)
            m, n = levels.get(key_y, (0.0, 0.0))
            sy = stress[e, p, 1]
            levels[key_y] = (m + w[0] * h / 2 * sy * (px - x_mid), n + w[0] * h / 2 * sy)
    ys = np.array(sorted(levels, reverse=True))
    return ys, np.array([levels[y][0] for y in ys]), np.array([levels[y][1] for y in ys])


def head_node(r):
    """0-based node of the wall's top corner on the excavation side."""
    conn = r.element_set("wall")["connectivity"][()]
    nodes = np.unique(conn)
    x = r.coordinates[nodes]
    hit = nodes[(np.abs(x[:, 0] - WALL_T) < 1e-9) & (np.abs(x[:, 1]) < 1e-9)]
    return int(hit[0])


def run_timed(deck, out, bin_dir=None):
    """Runs the deck; returns {phase (step): wall seconds} from the arrival of its output
    lines: a phase starts with its line ` phase k (name):` (the changes it makes), or else
    when the step before ends (the first one when the run's banner has been printed), and
    ends with the progress line of its last increment."""
    env = dict(os.environ, GFORTRAN_UNBUFFERED_PRECONNECTED="y")
    cmd = [*exe_cmd("pecplas", bin_dir), str(deck), "-o", str(out)]
    out.parent.mkdir(parents=True, exist_ok=True)
    starts, ends, banner = {}, {}, None
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True, env=env) as proc:
        for line in proc.stdout:
            now = time.monotonic()
            words = line.split()
            if len(words) > 1 and words[0] == "step" and words[1].isdigit():
                ends[int(words[1])] = now
            elif len(words) > 1 and words[0] == "phase" and words[1].isdigit():
                starts[int(words[1])] = now
            elif words[:1] == ["nodes"] and banner is None:
                banner = now
        if proc.wait() != 0:
            raise SystemExit(f"pecplas {deck} failed (exit {proc.returncode})")
    walls, before = {}, banner
    for step in sorted(ends):
        start = starts.get(step, before)
        walls[step] = ends[step] - start if start is not None else float("nan")
        before = ends[step]
    return walls


def table(h5, walls=None):
    """The rows of the report, one per excavation stage."""
    rows = []
    with Results(h5) as r:
        ends = r.phase_ends()
        node = head_node(r)
        hist = r.history()
        cpu = {}
        prev = 0.0
        for step in sorted(set(hist["step"].tolist())):
            last = np.nonzero(hist["step"] == step)[0][-1]
            cpu[step] = float(hist["cpu_time"][last]) - prev
            prev = float(hist["cpu_time"][last])
        for k, H in enumerate(STAGES):
            phase = k + 1
            key = ends[phase]
            u = r.field(key, "displacement")[node]
            ys, m, _ = wall_moments(r, key)
            i = int(np.argmax(np.abs(m)))
            _, need, z, m_blum = blum(H)
            _, need15, z15, m_blum15 = blum(H, fs=1.5)
            rows.append({"stage": phase, "H": H, "head_ux_mm": 1e3 * u[0],
                         "head_uy_mm": 1e3 * u[1], "M_max": float(m[i]), "depth_M": -float(ys[i]),
                         "blum_M": m_blum, "blum_depth_M": H + z, "blum_embed": need,
                         "blum15_M": m_blum15, "blum15_depth_M": H + z15, "blum15_embed": need15,
                         "cpu_s": cpu.get(phase, float("nan")),
                         "wall_s": (walls or {}).get(phase, float("nan")),
                         "increments": int(np.sum(hist["step"] == phase))})
    return rows


def plate_table(h5, strip_rows):
    """The plate variant (input/examples/excavation_cantilever_plate.inp) stage by stage
    beside the strip's rows (`table`): the plate's top node's u_x and its largest |M| (the
    smoothed nodal moments, plates/wall/node_forces) with its depth."""
    rows = []
    with Results(h5) as r:
        ends = r.phase_ends()
        nodes = r.file["mesh/plates/wall/nodes"][()]
        y = r.coordinates[nodes, 1]
        top = nodes[int(np.argmax(y))]
        for s in strip_rows:
            key = ends[s["stage"]]
            m = r.field(key, "plates/wall/node_forces")[:, 2]
            i = int(np.argmax(np.abs(m)))
            rows.append({"stage": s["stage"], "H": s["H"],
                         "head_ux_mm": 1e3 * float(r.field(key, "displacement")[top, 0]),
                         "M_max": float(abs(m[i])), "depth_M": -float(y[i]),
                         "strip_head_ux_mm": s["head_ux_mm"], "strip_M_max": abs(s["M_max"]),
                         "strip_depth_M": s["depth_M"]})
    return rows


def plate_markdown(rows):
    lines = ["| stage | excavation H [m] | head u_x, plate [mm] | strip [mm] "
             "| max \\|M\\|, plate [kN m/m] (depth [m]) | strip (depth [m]) |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['stage']} | {r['H']:g} | {r['head_ux_mm']:.2f} "
                     f"| {r['strip_head_ux_mm']:.2f} | {r['M_max']:.2f} ({r['depth_M']:.2f}) "
                     f"| {r['strip_M_max']:.2f} ({r['strip_depth_M']:.2f}) |")
    return "\n".join(lines)


def markdown(rows):
    lines = ["| stage | excavation H [m] | wall head u_x [mm] | FE M_max [kN m/m] (depth [m]) "
             "| Blum M_max, Kp [kN m/m] (depth) | Blum M_max, Kp/1.5 (depth) "
             "| Blum embedment 1.2 d0, Kp / Kp/1.5 [m] | CPU [s] | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['stage']} | {r['H']:g} | {r['head_ux_mm']:.2f} "
                     f"| {r['M_max']:.2f} ({r['depth_M']:.2f}) "
                     f"| {r['blum_M']:.2f} ({r['blum_depth_M']:.2f}) "
                     f"| {r['blum15_M']:.2f} ({r['blum15_depth_M']:.2f}) "
                     f"| {r['blum_embed']:.2f} / {r['blum15_embed']:.2f} "
                     f"| {r['cpu_s']:.2f} | {r['wall_s']:.2f} |")
    return "\n".join(lines)


def plot(h5, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from pecplas_py.figures import save_figure
    fig, ax = plt.subplots(figsize=(5, 6))
    with Results(h5) as r:
        ends = r.phase_ends()
        for k, H in enumerate(STAGES):
            ys, m, _ = wall_moments(r, ends[k + 1])
            ax.plot(m, ys, "o-", ms=2, label=f"stage {k + 1}, H = {H:g} m")
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel("bending moment M [kN m/m] (+: tension on the excavation side)")
    ax.set_ylabel("y [m]")
    ax.set_ylim(-WALL_L, 0)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save_figure(fig, png, dpi=110)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5", nargs="?", help="results of the deck (default: run it)")
    ap.add_argument("--run", action="store_true", help="run the deck first (timed)")
    ap.add_argument("--bin", help="directory of the pecplas executable")
    ap.add_argument("--plot", help="PNG of the moment profiles after each stage")
    a = ap.parse_args(argv)
    walls = None
    h5 = Path(a.h5) if a.h5 else OUT
    if a.run or not a.h5:
        walls = run_timed(DECK, h5, a.bin)
    rows = table(h5, walls)
    print(markdown(rows))
    if a.plot:
        plot(h5, a.plot)
    return rows


if __name__ == "__main__":
    sys.exit(0 if main() else 1)
