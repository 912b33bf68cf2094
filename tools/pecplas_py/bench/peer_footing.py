#!/usr/bin/env python3
"""Newton's iteration count beside CalculiX's: the von Mises strip footing pushed by an
imposed settlement (pecplas_py.decks.make_footing_peer_decks: 20 increments to collapse, c_u = 100
kPa, closed form (2 + pi) c_u = 514.2 kPa) on the same meshes, ours with Q4 / Q8 / Q8R under
the default method (full Newton, its fallback quasi-Newton), TOLERANCE=1e-4, CalculiX 2.20
(`ccx`) with CPE4 / CPE8 / CPE8R and its default controls. Per run: increments, iterations (linear solves), cuts, wall time, plateau (the
footing's reaction at the last increment per unit width). Ours also with the footing pushed
through stiff springs, and on Mohr-Coulomb and Drucker-Prager soil (phi = psi = 30 deg, no
CalculiX twin), and the von Mises runs again with the thesis's method and its chain
(METHOD=MODIFIED_NEWTON: modified -> quasi- -> full Newton), code "ours, MODIFIED_NEWTON chain".

Iteration counts are deterministic: one run per case, on one thread (OMP_NUM_THREADS=1, ccx
also CCX_NPROC_EQUATION_SOLVER=1); the wall times are indicative.
Writes doc/bench/peer_footing.csv and doc/bench/peer_footing.md.

    python3 -m pecplas_py.bench.peer_footing [--quick] [--huge] [--no-ccx] [--keep DIR]
    python3 -m pecplas_py.bench.peer_footing --render   (the fragment again from the CSV)
    python3 -m pecplas_py.bench.peer_footing --chain [--quick] [--huge]   (only the
        MODIFIED_NEWTON chain's rows, merged into the CSV: the other rows, CalculiX's included,
        are kept)
--no-ccx: our rows only, CalculiX's rows of the CSV kept (each with its own provenance).
--quick: the 2 000-equation meshes only; default adds the 20 000-equation ones; --huge adds
100 000 equations (CalculiX: 14 to 53 minutes per element there on the 2-core machine, at low priority beside other work).
"""
import argparse
import csv
import os
import re
import shutil
import sys
import tempfile
from pathlib import Path

import h5py

from pecplas_py.bench import common as bc
from pecplas_py.decks import make_footing_peer_decks as fd

THREADS = 1
INCREMENTS = 20
#: refinement of each element at each size (pecplas_py.decks.make_footing_peer_decks)
LEVELS = {"2k": {"Q4": 1, "Q8": 1, "Q8R": 1}, "20k": {"Q4": 3, "Q8": 3, "Q8R": 3},
          "100k": {"Q4": 6, "Q8": 7, "Q8R": 7}}
HEADER = ["mesh", "code", "element", "material", "drive", "equations", "increments",
          "iterations", "cuts", "wall_s", "plateau_kpa", "rc", "load1", "threads"]
CLOSED_FORM = (2.0 + 3.141592653589793) * fd.C
#: code column of the thesis chain's rows (METHOD=MODIFIED_NEWTON)
CHAIN = "ours, MODIFIED_NEWTON chain"


def run_ours(exe, work, element, m, material, drive, chain=False):
    """One run of our deck: (row fields) equations, increments, iterations, cuts, wall,
    plateau, rc. `chain`: METHOD=MODIFIED_NEWTON (the thesis's method and its chain, modified
    -> quasi- -> full Newton, doc/theory.md §4); else the default method (full Newton)."""
    text = fd.ours(element, m, material, drive, INCREMENTS, fd.SETTLE[material])
    name = f"ours_{material}_{element}_m{m}_{drive}"
    if chain:
        text = text.replace("*SOLVER, TOLERANCE=0.0001",
                            "*SOLVER, TOLERANCE=0.0001, METHOD=MODIFIED_NEWTON")
        name += "_chain"
    deck, h5 = work / f"{name}.inp", work / f"{name}.h5"
    deck.write_text(text)
    load = bc.load1()
    r = bc.run_timed([exe, str(deck), "-o", str(h5)], timeout=7200)
    out = r["stdout"] or ""
    s = re.search(r"summary: (\d+) increments, (\d+) iterations, (\d+) cuts", out)
    neq = re.search(r"equations (\d+)", out)
    inc, its, cuts = (int(g) for g in s.groups()) if s else (0, 0, 0)
    plateau = float("nan")
    if h5.exists():
        nodes, _, ids, nx, ny = fd.mesh(element, m)
        sets = fd.node_sets(nodes, ids, nx, ny)
        pushed = sets["footing"]
        if drive == "springs":
            n0 = len(nodes)
            pushed = list(range(n0 + 1, n0 + 1 + len(sets["footing"])))
        with h5py.File(h5, "r") as f:
            keys = sorted(f["increments"])
            if keys:
                reac = f["increments"][keys[-1]]["reaction"][()]
                plateau = -sum(reac[i - 1, 1] for i in pushed) / fd.B
    return dict(equations=int(neq.group(1)) if neq else 0, increments=inc, iterations=its,
                cuts=cuts, wall=r["wall"], plateau=plateau, rc=r["rc"], load1=load)


def run_ccx(work, element, m, equations):
    """One CalculiX run of the twin deck: increments, iterations, cuts (attempts beyond the
    first), wall, plateau (|RF_y| of the footing set at the last converged time), rc; the
    mesh's `equations` are ours (the same mesh and supports)."""
    name = f"ccx_{element}_m{m}"
    (work / f"{name}.inp").write_text(fd.ccx(element, m, INCREMENTS, fd.SETTLE["vm"]))
    load = bc.load1()
    r = bc.run_timed(["ccx", "-i", name], cwd=work, timeout=7200)
    sta, dat = work / f"{name}.sta", work / f"{name}.dat"
    inc, its, cuts = ccx_counts(sta.read_text()) if sta.exists() else (0, 0, 0)
    plateau = ccx_plateau(dat.read_text()) if dat.exists() else float("nan")
    return dict(equations=equations, increments=inc, iterations=its, cuts=cuts,
                wall=r["wall"], plateau=plateau, rc=r["rc"], load1=load)


def ccx_counts(sta):
    """(converged increments, iterations, cuts) from a CalculiX .sta file: one line per
    attempt (step, increment, attempt, iterations, ...), a cut attempt's number ending in U."""
    inc = its = cuts = 0
    for line in sta.splitlines()[2:]:
        f = line.split()
        if len(f) >= 4 and f[0].isdigit():
            its += int(f[3])
            if f[2].endswith("U"):
                cuts += 1
            else:
                inc += 1
    return inc, its, cuts


def ccx_plateau(dat):
    """-RF_y / B of the last 'total force' block of a CalculiX .dat file (*NODE PRINT,
    TOTALS=ONLY on the footing set)."""
    lines = dat.splitlines()
    plateau = float("nan")
    for k, line in enumerate(lines):
        if line.strip().startswith("total force") and k + 2 < len(lines):
            plateau = -float(lines[k + 2].split()[1]) / fd.B
    return plateau


def row(mesh, code, element, material, drive, d):
    return [mesh, code, element, material, drive, d["equations"], d["increments"],
            d["iterations"], d["cuts"], f"{d['wall']:.2f}", f"{d['plateau']:.1f}", d["rc"],
            f"{d['load1']:.2f}", THREADS]


def fragment(rows, quick=False):
    """doc/bench/peer_footing.md from the rows (HEADER)."""
    t = ["## Newton beside CalculiX: the von Mises footing under imposed settlement", "",
         "`python3 -m pecplas_py.bench.peer_footing` (`--quick`: 2 000 equations only; `--huge` "
         "adds 100 000). Decks of `pecplas_py.decks.make_footing_peer_decks`: a smooth rigid strip "
         "footing pushed 0.05 m into weightless von Mises soil (c_u = 100 kPa, E = 1e5 kPa) "
         f"in {INCREMENTS} increments, closed form (2 + pi) c_u = {CLOSED_FORM:.1f} kPa. Ours: "
         "the default method (full Newton, doc/theory.md §4), TOLERANCE=1e-4; CalculiX: its "
         "default controls "
         "(residual below 0.5 % of the mean force, correction below 1 % of the increment: "
         "looser than ours). One run per case on one thread; iterations = linear solves "
         "(every attempt's). \"ours, MODIFIED_NEWTON chain\": the same decks with the thesis's "
         "method, METHOD=MODIFIED_NEWTON (modified Newton, then quasi-Newton, then full Newton, "
         "the chain starting each increment with the method that converged the last one).",
         "", "| mesh | element | equations | code | increments | iterations | per increment "
         "| ratio to CalculiX | cuts | wall [s] | plateau [kPa] | vs CalculiX |",
         "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    vm = [r for r in rows if r[3] == "vm" and r[4] == "settle"]
    for r in vm:
        ccx = next((x for x in vm if x[0] == r[0] and x[2] == r[2] and x[1] == "CalculiX"),
                   None)
        ratio = dq = ""
        if ccx is not None and r[1] != "CalculiX" and int(ccx[7]) > 0:
            ratio = f"{int(r[7]) / int(ccx[7]):.2f}"
            dq = f"{float(r[10]) / float(ccx[10]) - 1:+.2%}"
        per = f"{int(r[7]) / max(int(r[6]), 1):.1f}"
        t.append(f"| {r[0]} | {r[2]} | {r[5]} | {r[1]} | {r[6]} | {r[7]} | {per} | {ratio} | "
                 f"{r[8]} | {r[9]} | {r[10]} | {dq} |")
    other = [r for r in rows if not (r[3] == "vm" and r[4] == "settle")]
    if other:
        t += ["", "Ours only (no CalculiX twin): the footing pushed through stiff normal springs "
              "(the same von Mises soil), and Mohr-Coulomb and Drucker-Prager soils (c = 100 "
              "kPa, phi = psi = 30 deg, 0.2 m in 20 increments; Prandtl's N_c c = 3 014 kPa).",
              "", "| mesh | element | soil | drive | equations | increments | iterations | "
              "cuts | wall [s] | plateau [kPa] |", "|---|---|---|---|---|---|---|---|---|---|"]
        for r in other:
            t.append(f"| {r[0]} | {r[2]} | {r[3]} | {r[4]} | {r[5]} | {r[6]} | {r[7]} | "
                     f"{r[8]} | {r[9]} | {r[10]} |")
    if any(r[1] == "CalculiX" and r[9] == "nan" for r in rows):
        t += ["", "wall nan: that CalculiX run was made at the lowest priority (nice 19) beside "
              "other work on the 2-core machine, so its wall time says nothing about its "
              "speed; its iterations and plateau do not depend on it."]
    if not any(r[0] == "100k" and r[1] == "CalculiX" for r in rows):
        t += ["", "CalculiX is not run at 100 000 equations: "
              "its 20 000-equation runs took 4 to 8 minutes each on the 2-core machine of "
              "these tables, shared with other work, and its sparse direct solver's time grows "
              "faster than the equations, so the three 100 000-equation runs would hold the "
              "machine for hours (estimated over an hour each); the 20 000-equation rows "
              "compare the same elements."]
    loads = [float(r[12]) for r in rows]
    t += ["", f"Load (1-minute load average when each case started): "
          f"{bc.load_range(loads)}, on {os.cpu_count()} cores."]
    if max(loads) > (os.cpu_count() or 1):
        t[-1] += (f" **Wall times not final: load average up to {max(loads):.1f} on "
                  f"{os.cpu_count()} cores** (other programs were running); the iteration "
                  "counts do not depend on it.")
    return "\n".join(t)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="2 000 equations only")
    ap.add_argument("--huge", action="store_true", help="also 100 000 equations")
    ap.add_argument("--no-ccx", action="store_true", help="our runs only")
    ap.add_argument("--keep", help="keep decks and results in this directory")
    ap.add_argument("--render", action="store_true",
                    help="only write the fragment again from doc/bench/peer_footing.csv")
    ap.add_argument("--chain", action="store_true",
                    help="only the default chain's rows, merged into the CSV")
    a = ap.parse_args()
    if a.render or a.chain or a.no_ccx:
        # the rows as stored, each with its own commit, machine and date
        with open(bc.BENCH_DIR / "peer_footing.csv") as f:
            stored = list(csv.reader(f))[1:]
        rows = [r[:len(HEADER)] for r in stored]
        if a.render:
            bc.write_fragment("peer_footing", fragment(rows))
            return
    if not a.no_ccx and shutil.which("ccx") is None:
        sys.exit("bench_peer_footing: ccx is not on the PATH (apt-get install calculix-ccx)")
    for v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "CCX_NPROC_EQUATION_SOLVER"):
        os.environ[v] = str(THREADS)
    exe = bc.executable("pecplas")
    work = Path(a.keep) if a.keep else Path(tempfile.mkdtemp(prefix="bench_footing_"))
    work.mkdir(parents=True, exist_ok=True)
    sizes = ["2k"] + ([] if a.quick else ["20k"]) + (["100k"] if a.huge else [])
    if a.chain:
        new = [row(size, CHAIN, element, "vm", "settle",
                   run_ours(exe, work, element, m, "vm", "settle", chain=True))
               for size in sizes for element, m in LEVELS[size].items()]
        prov = bc.provenance()
        new = [[str(v) for v in r] + [prov["commit"], prov["machine"], prov["date"]]
               for r in new]
        # each new row after the full-Newton row of its mesh and element (stored order kept)
        full, placed = [], set()
        for r in stored:
            if any(r[:5] == x[:5] for x in new):
                continue
            full.append(r)
            for k, x in enumerate(new):
                if r[1] == "ours" and [r[0], r[2], r[3], r[4]] == [x[0], x[2], x[3], x[4]]:
                    full.append(x)
                    placed.add(k)
        full += [x for k, x in enumerate(new) if k not in placed]
        with open(bc.BENCH_DIR / "peer_footing.csv", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(HEADER + ["commit", "machine", "date"])
            w.writerows(full)
        bc.write_fragment("peer_footing", fragment([r[:len(HEADER)] for r in full]))
        for r in new:
            print(" | ".join(map(str, r)))
        return
    rows = []
    for size in sizes:
        for element, m in LEVELS[size].items():
            ours = run_ours(exe, work, element, m, "vm", "settle")
            rows.append(row(size, "ours", element, "vm", "settle", ours))
            print(" | ".join(map(str, rows[-1])), flush=True)
            rows.append(row(size, CHAIN, element, "vm", "settle",
                            run_ours(exe, work, element, m, "vm", "settle", chain=True)))
            print(" | ".join(map(str, rows[-1])), flush=True)
            if not a.no_ccx:
                rows.append(row(size, "CalculiX", element, "vm", "settle",
                                run_ccx(work, element, m, ours["equations"])))
            else:
                # the stored CalculiX row of the same mesh and element, its provenance kept
                rows += [r for r in stored if r[1] == "CalculiX" and r[0] == size and
                         r[2] == element and r[3] == "vm" and r[4] == "settle"]
            print(" | ".join(map(str, rows[-1])), flush=True)
    # the other drive and soils at 2 000 and 20 000 equations (not at 100 000: hours)
    for size in [s for s in sizes if s != "100k"]:
        for element, m in LEVELS[size].items():
            for material, drive in (("vm", "springs"), ("mc", "settle"), ("dp", "settle")):
                rows.append(row(size, "ours", element, material, drive,
                                run_ours(exe, work, element, m, material, drive)))
                print(" | ".join(map(str, rows[-1])), flush=True)
    prov = bc.provenance()
    full = [[str(v) for v in r] if len(r) > len(HEADER) else
            [str(v) for v in r] + [prov["commit"], prov["machine"], prov["date"]] for r in rows]
    with open(bc.BENCH_DIR / "peer_footing.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(HEADER + ["commit", "machine", "date"])
        w.writerows(full)
    rows = [r[:len(HEADER)] for r in full]
    bc.write_fragment("peer_footing", fragment(rows, a.quick))
    for r in rows:
        print(" | ".join(map(str, r)))
    if not a.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
