#!/usr/bin/env python3
"""A peer side by side: our code and CalculiX (ccx) on the same meshes.

1. The S2 frictional pile (decks/make_s2_decks.py, axisymmetric): ours with the Mohr-Coulomb
   penalty joints and with Katona contact, CalculiX with face-to-face penalty contact and
   Coulomb friction on the deck exported by peers/export_abaqus.py (same K_n, K_t as ours).
2. The CGS-4 inclined-plane block (plane strain, test/data/joints/inclined_plane.inp): slip
   limit F/G against (tan a + mu)/(1 - mu tan a) = 0.412371.

Every code runs one thread (OMP_NUM_THREADS=1), timed by bench_common.run_timed in this run:
each case (one code on one mesh) is run REPEATS = 3 times back to back and reported as the median
wall time with its spread [min - max], with the 1-minute load average when the case started
(--quick: one run per case).
Writes doc/bench/peer.csv, doc/bench/peer_pile.png, doc/bench/peer_block.png, doc/bench/peer.md.

    python3 -m pecplas_py.bench.peer [--quick] [--keep DIR]
"""
import argparse
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from pecplas_py import script_cmd
from pecplas_py.bench import common as bc
from pecplas_py.peers import export_abaqus as ex
from pecplas_py.results import Results

ROOT = bc.ROOT
HEAD_LOAD = 2000.0
A, L, GAMMA, K0, PHI = 0.5, 10.0, 18.0, 0.5, 30.0
Q_SHAFT = K0 * GAMMA * L**2 / 2 * math.tan(math.radians(PHI)) * math.pi * 2 * A  # 816.2 kN
CGS_DECK = ROOT / "test" / "data" / "joints" / "inclined_plane.inp"
CGS_KATONA = ROOT / "test" / "data" / "katona" / "inclined_plane.inp"
TAN_A, MU = 0.1, 0.3
FG_EXACT = (TAN_A + MU) / (1 - MU * TAN_A)


def find_node(m, x, y):
    return min(m["nodes"], key=lambda k: (m["nodes"][k][0] - x)**2 + (m["nodes"][k][1] - y)**2)


# ---------------------------------------------------------------- our code
def ours_curve(h5, node, comp, pattern):
    """(pattern factor, displacement component of `node`) for every written increment, with
    the starting point (0, 0)."""
    with Results(h5) as r:
        rows = r.field_rows()
        fac = r.pattern_factors(rows)[:, pattern]
        u = r.fields("displacement")[:, node - 1, comp]
        steps = r.history("step")[rows]
    return np.r_[0.0, fac], np.r_[0.0, u], np.r_[1, steps]


REPEATS = 3       # runs per case in full mode: median wall time and spread [min - max]
RUNS = [REPEATS]  # runs per case of this run (1 in --quick)
THREADS = 1       # OMP_NUM_THREADS of every code (main)
HEADER = ["scene", "code", "elements", "dofs_2d", "wall_s", "peak_mb", "rc",
          "settlement_100kN_mm", "settlement_2000kN_mm", "final_or_limit",
          "shaft_resultant_kN", "wall_min_s", "wall_max_s", "repeats", "load1", "threads"]


def spread(walls):
    """(median, min, max) of the wall times of a case's runs."""
    return statistics.median(walls), min(walls), max(walls)


def ratio_spread(ccx, ours):
    """CalculiX / ours from two (median, min, max) wall times: the ratio of the medians and
    the range the runs allow (CalculiX fastest / ours slowest, CalculiX slowest / ours
    fastest)."""
    return ccx[0] / ours[0], ccx[1] / ours[2], ccx[2] / ours[1]


def timed(cmd, cwd=None):
    """Run `cmd` RUNS times, back to back: the last run's outcome (its files are the ones
    read) with the median wall time, its spread (wall_min, wall_max), the number of runs and
    the 1-minute load average when the case started (load1)."""
    load = bc.load1()
    runs = [bc.run_timed(cmd, cwd=cwd, timeout=600) for _ in range(RUNS[0])]
    med, lo, hi = spread([r["wall"] for r in runs])
    return dict(runs[-1], wall=med, wall_min=lo, wall_max=hi, repeats=len(runs), load1=load)


def timing_columns(r):
    """The CSV columns wall_min_s .. threads of a timed() outcome."""
    return [f"{r['wall_min']:.3f}", f"{r['wall_max']:.3f}", r["repeats"], f"{r['load1']:.2f}",
            THREADS]


def timing_of(row):
    """(median, min, max, runs, load1) of a CSV row; a row written before the spread was
    recorded (11 columns) counts as one run at an unknown load."""
    d = dict(zip(HEADER, row))
    med = float(d["wall_s"])

    def num(key, default):
        try:
            return float(d[key]) if d.get(key, "") != "" else default
        except ValueError:
            return default
    return (med, num("wall_min_s", med), num("wall_max_s", med), int(num("repeats", 1)),
            num("load1", float("nan")))


def run_ours(exe, deck, h5):
    return timed([exe, deck, "-o", h5, "--quiet"])


# ---------------------------------------------------------------- CalculiX
def run_ccx(deck, work, name, print_nodes, contact_print=False):
    """Export `deck` to work/name.inp and run ccx there; returns (run_timed dict, model)."""
    m = ex.parse_deck(deck)
    m["nsets"]["PRINT_NODES"] = print_nodes
    warnings = []
    ex.export(m, work / f"{name}.inp", warn=warnings.append)
    if contact_print:
        _add_contact_print(work / f"{name}.inp")
    r = timed(["ccx", "-i", name], cwd=work)
    r["warnings"] = warnings
    r["increments"] = len(re.findall(r"increment\s+\d+ attempt", r["stdout"]))
    r["iterations"] = len(re.findall(r"iteration\s+\d+", r["stdout"]))
    return r, m


def _add_contact_print(inp):
    """Print the contact stresses (CSTR) in every increment of every step."""
    text = inp.read_text().replace("*NODE FILE\nU\n*END STEP",
                                   "*NODE FILE\nU\n*CONTACT PRINT\nCSTR\n*END STEP")
    inp.write_text(text)


def ccx_nodes(dat, node, comp):
    """(total time, displacement component) of `node` for every printed increment."""
    out, t = [], None
    for line in Path(dat).read_text().splitlines():
        if line.strip().startswith("displacements (vx,vy,vz)"):
            t = float(line.split()[-1])
        elif t is not None and line.split()[:1] == [str(node)] and len(line.split()) == 4:
            out.append((t, float(line.split()[1 + comp])))
            t = None
    return np.array(out)


def ccx_shaft(dat, m, time, faces):
    """Shaft shear resultant [kN] from CalculiX's contact stresses at `time`: for every slave
    face of the shaft, the mean |tau| over its integration points times the face's full ring
    area 2 pi r h (the face-to-face rule's weights are not printed: equal weights assumed)."""
    per, on = {}, False
    for line in Path(dat).read_text().splitlines():
        if "contact stress" in line:
            on = abs(float(line.split()[-1]) - time) < 1e-9
            continue
        s = line.split()
        if on and len(s) == 5:
            per.setdefault(int(s[0]), []).append(math.hypot(float(s[3]), float(s[4])))
        elif on and s:
            on = False
    total = 0.0
    for eid, taus in per.items():
        if eid in faces:
            ys = [m["nodes"][n][1] for n in next(e[3] for e in m["elements"] if e[0] == eid)]
            total += np.mean(taus) * 2 * math.pi * A * (max(ys) - min(ys))
    return total


# ---------------------------------------------------------------- scenes
def pile(exe, work, refine, rows):
    d = work / f"s2_r{refine}"
    subprocess.run([*script_cmd("decks.make_s2_decks"), "--refine",
                    str(refine), "--out", str(d)], check=True, capture_output=True)
    tag = "" if refine == 1 else f"_r{refine}"
    mc, ka = d / "s2" / f"s2_mohr_coulomb{tag}.inp", d / "s2" / f"s2_katona{tag}.inp"
    m = ex.parse_deck(mc)
    head = find_node(m, 0.0, 0.0)
    shaft_joint = next(j for j in m["joints"] if j["set"] == "shaft")
    faces = {ex.edge_face(m, a, b)[0] for side in ex.joint_sides(shaft_joint)[:2]
             for a, b in side}
    tied = d / "s2" / f"s2_mc_tied_tip{tag}.inp"
    tied.write_text(tied_tip(mc.read_text()))
    curves, runs = {}, {}
    for label, deck in (("ours, Mohr-Coulomb penalty", mc), (TIED, tied), ("ours, Katona", ka)):
        h5 = d / (deck.stem + ".h5")
        r = run_ours(exe, deck, h5)
        runs[label] = r
        if r["rc"] == 0:
            fac, u, _ = ours_curve(h5, head, 1, 0)
            curves[label] = (fac * HEAD_LOAD, -u * 1e3)
            q = _ours_shaft(h5)
            r["shaft"] = abs(q)
    r, _ = run_ccx(mc, d, "s2_ccx", [head], contact_print=True)
    runs["CalculiX"] = r
    tu = ccx_nodes(d / "s2_ccx.dat", head, 1)
    t = tu[:, 0]
    load = np.where(t <= 1.0, 0.0, np.where(t <= 2.0, (t - 1.0), 3.0 - t)) * HEAD_LOAD
    curves["CalculiX"] = (np.r_[0.0, load], np.r_[0.0, -tu[:, 1] * 1e3])
    r["shaft"] = ccx_shaft(d / "s2_ccx.dat", m, 2.0, faces)
    neq = 2 * len(m["nodes"])
    for label, r in runs.items():
        lo, s = curves.get(label, (np.array([0.0]), np.array([np.nan])))
        rows.append([f"S2 pile r{refine}", label, len(m["elements"]), neq, f"{r['wall']:.3f}",
                     f"{r['peak_mb']:.1f}", r["rc"], _at(lo, s, 100.0, first=True),
                     _at(lo, s, HEAD_LOAD), f"{s[-1]:.2f}", f"{r.get('shaft', float('nan')):.0f}",
                     *timing_columns(r)])
    return curves, runs, m


TIED = "ours, Mohr-Coulomb penalty, tip tied"


def tied_tip(text):
    """Our Mohr-Coulomb S2 deck with the tip joint made bonded and stiff (K_t = K_n, huge
    cohesion), as CalculiX has it: its contact cannot use the tip faces, which touch the axis."""
    law = ("*INTERFACE_LAW, NAME=tied, TYPE=MOHR_COULOMB\n"
           "KN = 2e7, KT = 2e7, PHI = 30, C = 1e9, PSI = 0\n")
    old = "*JOINTS, TYPE=GOODMAN4, SET=tip, LAW=iface"
    assert old in text
    return text.replace(old, law + old.replace("LAW=iface", "LAW=tied"))


def _ours_shaft(h5):
    from pecplas_py.scenes.s2_results import last_key, shaft
    try:
        return shaft(h5, last_key(h5, 1))[3]
    except Exception:          # a joint kind without tributary data: leave it out
        return float("nan")


def _at(load, s, target, first=False):
    idx = [i for i, x in enumerate(load) if abs(x - target) < 1e-6]
    if not idx:
        return "nan"
    return f"{s[idx[0] if first else idx[-1]]:.3f}"


def block(exe, work, rows):
    d = work / "cgs4"
    d.mkdir(parents=True, exist_ok=True)
    m = ex.parse_deck(CGS_DECK)
    pad = 9                 # the pad's joint-face node where the push acts (CGS_DECK)
    curves, runs, limits = {}, {}, {}
    for label, deck in (("ours, Mohr-Coulomb penalty", CGS_DECK), ("ours, Katona", CGS_KATONA)):
        h5 = d / (deck.parent.name + ".h5")
        r = run_ours(exe, deck, h5)
        runs[label] = r
        fac, u, steps = ours_curve(h5, pad, 0, 1)
        sel = steps == 2
        curves[label] = (fac[sel], u[sel] * 1e6)
        limits[label] = float(fac[-1])
    r, _ = run_ccx(CGS_DECK, d, "cgs_ccx", [pad])
    runs["CalculiX"] = r
    tu = ccx_nodes(d / "cgs_ccx.dat", pad, 0)
    tu = tu[tu[:, 0] > 1.0]
    fac = 0.5 * (tu[:, 0] - 1.0)        # push pattern: 10 kN x factor, target 0.5
    curves["CalculiX"] = (fac, tu[:, 1] * 1e6)
    limits["CalculiX"] = float(fac[-1])
    for label, r in runs.items():
        rows.append(["CGS-4 block", label, len(m["elements"]), 2 * len(m["nodes"]),
                     f"{r['wall']:.3f}", f"{r['peak_mb']:.1f}", r["rc"], "", "",
                     f"{limits[label]:.10f}", "", *timing_columns(r)])
    return curves, runs, limits


# ---------------------------------------------------------------- output
def plot(panels, path, xlabel, ylabel, title):
    """One panel per mesh, every code's curve in each."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 * len(panels), 5), squeeze=False)
    styles = {"ours, Mohr-Coulomb penalty": ("C0", "-", None), TIED: ("C1", "-", None),
              "ours, Katona": ("C2", "-", None), "CalculiX": ("C3", "--", "o")}
    for ax, (name, curves) in zip(axes[0], panels.items()):
        for label, (y, x) in curves.items():
            c, ls, mk = styles[label]
            ax.plot(x, y, color=c, ls=ls, marker=mk, ms=3, label=label)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(f"{title}{name}", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="reference pile mesh only, one run per case")
    ap.add_argument("--keep", help="keep the decks, results and ccx files in this directory")
    a = ap.parse_args()
    if shutil.which("ccx") is None:
        sys.exit("bench_peer: ccx is not on the PATH (apt-get install calculix-ccx)")
    os.environ["OMP_NUM_THREADS"] = str(THREADS)
    os.environ["OPENBLAS_NUM_THREADS"] = str(THREADS)
    os.environ["CCX_NPROC_EQUATION_SOLVER"] = str(THREADS)
    RUNS[0] = 1 if a.quick else REPEATS
    exe = bc.executable("pecplas")
    work = Path(a.keep) if a.keep else Path(tempfile.mkdtemp(prefix="bench_peer_"))
    work.mkdir(parents=True, exist_ok=True)
    rows, pile_curves = [], {}
    for refine in ((1,) if a.quick else (1, 4, 8)):
        c, _, m = pile(exe, work, refine, rows)
        pile_curves[f", refine {refine} ({len(m['elements'])} Q4)"] = c
    bcurves, _, _ = block(exe, work, rows)
    bc.write_csv(bc.BENCH_DIR / "peer.csv", HEADER, rows)
    finest = list(pile_curves)[-1]
    panels = {k: pile_curves[k] for k in dict.fromkeys([list(pile_curves)[0], finest])}
    plot(panels, bc.BENCH_DIR / "peer_pile.png", "head settlement [mm]", "head load [kN]",
         "S2 pile, ours vs CalculiX")
    plot({"": bcurves}, bc.BENCH_DIR / "peer_block.png", "pad displacement along x [µm]",
         "push F/G", f"CGS-4 block (exact slip limit {FG_EXACT:.6f})")
    bc.write_fragment("peer", fragment(rows, _ccx_version(), a.quick))
    for r in rows:
        print(" | ".join(map(str, r)))
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)


def fragment(rows, version, quick=False):
    """doc/bench/peer.md from the rows of peer.csv (HEADER) and the ccx version; the prose
    states what the numbers show."""
    pile = [r for r in rows if r[0].startswith("S2")]
    t = ["## A peer side by side: CalculiX", "",
         "`python3 -m pecplas_py.bench.peer` (`--quick`: reference mesh only, one run per case). "
         "The same meshes, exported by `tools/pecplas_py/peers/export_abaqus.py`; ours and `ccx` "
         "(CalculiX "
         f"{version}) run on one thread each (OMP_NUM_THREADS=1, ccx also "
         "CCX_NPROC_EQUATION_SOLVER=1), wall times of whole runs (input to results). "
         + timing_text(rows, quick), "",
         "| scene | code | Q4 | wall [s] | ratio | u(100 kN) [mm] | u(2000 kN) [mm] | "
         "permanent [mm] | shaft at 2000 kN [kN] |", "|---|---|---|---|---|---|---|---|---|"]
    for r in pile:
        ccx = next(x for x in pile if x[0] == r[0] and x[1] == "CalculiX")
        t.append(f"| {r[0]} | {r[1]} | {r[2]} | {wall_text(r)} | {ratio_text(ccx, r)} | "
                 f"{r[7]} | {r[8]} | {r[9]} | {r[10]} |")
    t += ["", "![pile](peer_pile.png)", "",
          "| CGS-4 block (plane strain, 4 Q4) | wall [s] | ratio | slip limit F/G | error |",
          "|---|---|---|---|---|"]
    blk = [r for r in rows if r[0].startswith("CGS")]
    ccx = next(x for x in blk if x[1] == "CalculiX")
    for r in blk:
        lim = float(r[9])
        t.append(f"| {r[1]} | {wall_text(r)} | {ratio_text(ccx, r)} | {lim:.6f} | "
                 f"{(lim - FG_EXACT) / FG_EXACT:+.1e} |")
    t += ["", f"Exact: (tan a + mu)/(1 - mu tan a) = {FG_EXACT:.6f}. Both codes are under "
          "force control and stop at the limit (ours exit 3, ccx \"too many cutbacks\"): the "
          "limit is the last converged load, to the increment size (0.01 in F/G, cut near "
          "the limit). Past the limit CalculiX ends with \"too many cutbacks\" (exit 201) or, "
          "in some runs of the same input, inside the factorisation of the now singular "
          "system (exit 255) a few cuts earlier: its last converged F/G then moves by up to "
          "4e-4 (0.412363 and 0.412188 seen); ours are repeatable.", "",
          "![block](peer_block.png)", ""]
    fin = [r for r in pile if r[0] == pile[-1][0]]
    get = {r[1]: r for r in fin}
    tied, ccx = get[TIED], get["CalculiX"]
    d2000 = (float(ccx[8]) - float(tied[8])) / float(tied[8])
    dperm = (float(ccx[9]) - float(tied[9])) / float(tied[9])
    t += ["**Is the CalculiX pile trustworthy?** On the finest mesh here "
          f"({pile[-1][0]}), against our Mohr-Coulomb penalty joints with the tip tied as in "
          f"CalculiX: settlement at 100 kN (elastic, stick) {ccx[7]} vs {tied[7]} mm, at 2000 kN "
          f"{ccx[8]} vs {tied[8]} mm ({d2000:+.1%}; the gap is not monotone in the mesh, see the "
          "table, and not explained: by hand, CalculiX with convergence tolerances "
          "1e-5 / 1e-4 instead of 5e-3 / 1e-2 gives the same 96.22 mm on refine 8), "
          f"permanent {ccx[9]} vs {tied[9]} mm "
          f"({dperm:+.1%}), shaft shear resultant {ccx[10]} vs {tied[10]} kN (hand estimate "
          f"from the initial stresses {Q_SHAFT:.0f} kN; both exceed it because the soil's "
          "normal stress on the shaft rises as the pile is pushed). The geostatic "
          "state is reproduced (contact pressure per shaft face = K0 gamma z at the face's "
          "middle depth before loading, head displacement 1e-7 m after the gravity step). "
          "So the axisymmetric contact works here *for the shaft and the column*, whose faces "
          "are away from the axis; it does **not** for the pile base: CalculiX cannot use as "
          "a master surface a face with a node on the axis (it becomes a collapsed face in "
          "the 2° wedge), and both faces of the tip (pile base, column top) touch the axis. "
          "The exporter ties the tip doublets (*EQUATION), so the CalculiX pile is a "
          "pile with a rough, bonded base, and compares with our tip-tied deck, not with our "
          "reference S2 deck. The CGS-4 block is the fair frictional comparison: same mesh, "
          "same penalty stiffnesses, analytic answer.", "",
          "**What the comparison taught us about S2.** The tip's shear stiffness decides much "
          "of the curve after the shaft slips. Settlement at 2000 kN, reference penalty deck "
          "(tip K_t = E_soil = 2e4 kPa/m: the pile base shears easily over the column) / "
          "tip tied / Katona (rigid stick) / CalculiX (tied): " + "; ".join(
              f"{sc.split()[-1]}: " + " / ".join(next(r[8] for r in pile if r[0] == sc and
                                                       r[1] == c) for c in
                                                  ("ours, Mohr-Coulomb penalty", TIED,
                                                   "ours, Katona", "CalculiX")) + " mm"
              for sc in dict.fromkeys(r[0] for r in pile)) + ". On the reference mesh (one "
          "element across the pile) a rough tip settles a quarter more; by hand on that mesh, "
          "our penalty deck with K_t = 2e7 and PHI = 30 at the tip gives 98.9 mm (the Katona "
          "and CalculiX answer), with PHI ~ 0 (smooth) 77.8 mm. So the gap between our penalty "
          "and Katona S2 curves on the reference mesh (78.3 vs 98.7 mm, doc/validation.md "
          "S2) is the tip's roughness on a coarse mesh, not an error of the Katona solver "
          "(the same conclusion as the stiff-spring study there), and it closes with "
          "refinement. Katona stays stiffer at small loads "
          "(no stick compliance 1/K_t); CalculiX, with the same K_t, matches the penalty "
          "joints there. The mechanism (doc/validation.md S2, measured "
          "there): the rough base holds the column's top radially, so the column presses "
          "less on the surrounding soil (252 against 336 kPa) and slides more easily along "
          "the below-tip joint.", "",
          "**Differences of formulation.**", "",
          "- Contact: ours are node-to-node joints on coincident node doublets (small "
          "displacement, the joint frame fixed): Katona with Lagrange multipliers (exact "
          "stick, zero penetration) or Mohr-Coulomb penalty joints (K_n, K_t, Lobatto points "
          "on the shaft). CalculiX: face-to-face penalty contact, slope K_n and "
          "stick slope K_t per unit area as ours, integrated on the slave faces with its own "
          "rule, with a contact search on the faces. Face-to-face was chosen over node-to-face "
          "because its stiffnesses are per unit area (ours too) and it does not need a "
          "tributary area; node-to-face scales the spring by an area CalculiX computes.",
          "- Geometry: CalculiX expands every CAX4 into a C3D8 wedge of 2° (MPCs tie the "
          "nodes of the two planes to the defining plane): a 3D solve of a 2D problem, with "
          "3D contact search on the wedge faces; ours is a true axisymmetric 2D element.",
          "- Initial stresses: ours holds the nodal forces of the geostatic stresses as a "
          "constant load (equilibrated by definition); CalculiX gets the stresses at every "
          "integration point (*INITIAL CONDITIONS, TYPE=STRESS) and the self-weight that "
          "balances them (*DLOAD GRAV, density GAMMA/g) in a first step; the contact "
          "pressure then builds up from a penetration of p/K_n (about 5 µm).",
          "- The tip: frictional joint in ours, tied in CalculiX (above).",
          "- Increments: the same 20 + 20 (ccx may cut an increment; its step times are "
          "mapped back to the load). Convergence: ours on the Euclidean residual norm, "
          "1e-4 of the external forces or reactions (doc/theory.md); CalculiX's defaults "
          "(largest residual below 0.5 % of the average force, correction below 1 % of "
          "the increment), looser than ours, but tightening them 500 and 100 times did not "
          "move the refine-8 curve.",
          "- Speed: CalculiX pays for the 3D expansion (extra nodes tied by MPCs), the contact "
          "search and its fixed start-up (about 1 s even on the 4-element block, where it "
          "also cuts the increment many times near the slip limit). The runs of a case are "
          "made back to back and the cases one after the other, so a change of the "
          "machine's load between cases moves a ratio: the spread (full mode) and the load "
          "above say by how much."]
    return "\n".join(t)


def timing_text(rows, quick=False):
    """What the wall times of `rows` are: runs per case, thread setting, load range."""
    runs = max(timing_of(r)[3] for r in rows)
    loads = [timing_of(r)[4] for r in rows]
    if runs > 1:
        t = (f"Median of {runs} runs per case with the spread [min - max]; ratio = "
             "CalculiX median / our median, with the range the runs allow [CalculiX fastest "
             "/ ours slowest - CalculiX slowest / ours fastest].")
    else:
        t = ("One run per case" + (" (quick mode)" if quick else "") + ": no spread, the "
             "times are indicative. Ratio = CalculiX wall / our wall.")
    t += (" Load (1-minute load average when each case started): "
          f"{bc.load_range(loads)}, on {os.cpu_count()} cores.")
    known = [x for x in loads if math.isfinite(x)]
    if known and max(known) > (os.cpu_count() or 1):
        t += (f" **Not final: load average up to {max(known):.1f} on {os.cpu_count()} "
              "cores** (other programs were running).")
    return t


def wall_text(row):
    """'median [min - max]' of a row's wall time, the median alone for a single run."""
    med, lo, hi, runs, _ = timing_of(row)
    return f"{med:.3f}" + (f" [{lo:.3f} - {hi:.3f}]" if runs > 1 else "")


def ratio_text(ccx, row):
    """CalculiX / ours for `row` ('' for CalculiX itself), with its range over the runs."""
    if row[1] == "CalculiX":
        return ""
    c, o = timing_of(ccx), timing_of(row)
    med, lo, hi = ratio_spread(c[:3], o[:3])
    return f"{med:.1f}" + (f" [{lo:.1f} - {hi:.1f}]" if c[3] > 1 or o[3] > 1 else "")


def _ccx_version():
    r = subprocess.run(["ccx", "-v"], capture_output=True, text=True)
    m = re.search(r"Version\s+(\S+)", r.stdout + r.stderr)
    return m.group(1) if m else "?"


if __name__ == "__main__":
    main()
