#!/usr/bin/env python3
"""Stability of the S1 compression-opening-closing test (input/s1/s1_open_close_kn1e5.inp)
against the joint's normal stiffness: K_n / E1 = 1, 10, ..., 1e8 (E1 = 1e5 kPa), modified and
full Newton, tolerance 1e-3 and 1e-4. For each run: status, iterations per increment (mean,
max), total iterations, factorisations, and the largest interpenetration (closure of the
zero-thickness joint, eps_n > 0, in mm). Prints a Markdown table (doc/validation.md).

    python3 tools/s1_stability.py [--pecplas PATH] [--max-iterations 10000]
"""
import argparse
import re
import subprocess
import tempfile
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
TEMPLATE = ROOT / "input" / "s1" / "s1_open_close_kn1e5.inp"
E1 = 1e5


def run(exe, ratio, method, tol, maxit, tmp):
    text = TEMPLATE.read_text()
    text = re.sub(r"KN = [^,]+,", f"KN = {ratio * E1:g},", text)
    text = re.sub(r"^\*SOLVER.*$", f"*SOLVER, METHOD={method}, TOLERANCE={tol:g}, "
                  f"MAX_ITERATIONS={maxit}, MAX_CUTS=3", text, flags=re.M)
    deck = tmp / f"oc_{ratio:g}_{method}_{tol:g}.inp"
    deck.write_text(text)
    out = deck.with_suffix(".h5")
    r = subprocess.run([exe, str(deck), "-o", str(out), "--quiet"], capture_output=True,
                       text=True)
    with h5py.File(out) as f:
        it = f["history/iterations"][:]
        pen = 0.0
        for k in f["increments"]:
            eps = f["increments"][k]["joints/joint/relative_displacement"][:].reshape(-1, 2)
            pen = max(pen, eps[:, 0].max())
        status = f.attrs["status"]
    m = re.search(r"(\d+) factorisations", r.stdout + r.stderr)
    return status, it, pen * 1e3


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pecplas", default=None)
    ap.add_argument("--max-iterations", type=int, default=10000)
    a = ap.parse_args()
    exe = a.pecplas or subprocess.run(
        ["fpm", "run", "--profile", "release", "--target", "pecplas", "--runner", "echo"],
        cwd=ROOT, capture_output=True, text=True).stdout.split()[-1]
    print("| K_n/E1 | method | tol | status | increments | iterations/increment mean (max) "
          "| total iterations | max interpenetration [mm] |")
    print("|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        for e in range(0, 9):
            ratio = 10.0**e
            for method in ("MODIFIED_NEWTON", "NEWTON"):
                for tol in (1e-3, 1e-4):
                    status, it, pen = run(exe, ratio, method, tol, a.max_iterations, tmp)
                    print(f"| 1e{e} | {method.lower()} | {tol:g} | {status} | {len(it)} | "
                          f"{it.mean():.1f} ({it.max()}) | {it.sum()} | {pen:.2e} |",
                          flush=True)


if __name__ == "__main__":
    main()
