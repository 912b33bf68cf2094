"""Reading S5 shear-box results (used by scenes/plot_s5.py and test/python/test_s5.py):
interface distributions, the mid-interface history, and the point driver (pecplas-path) on the
mid-interface slip path."""
import subprocess
from pathlib import Path

import numpy as np

from pecplas_py import ROOT
from pecplas_py.exe import exe_cmd
from pecplas_py.results import Results

L = 0.31
SIGMA_N0 = 100.0
LAW = """*INTERFACE_LAW, NAME=iii6_dr80, TYPE=MODJOIN_CYCLIC, LENGTH_UNIT=MM, MODEL_UNIT=M
K0 = 90, G0 = 45, PHI = 37, C = 0, R0 = 0.3, BETA = 1.2
ALPHA = 0.75, A = 0.25, B = 0.73, PSI = 27, A_G = 0.4, B_CYC = 0.9
"""


def interface(path, key):
    """x, sigma_n, tau, eps_t, eps_n of the joint points (Lobatto: on the doublets), sorted by x."""
    with Results(path) as r:
        x = r.joint_set("interface")["point_coordinates"][:, :, 0].ravel()
        s = r.field(key, "joints/interface/stress").reshape(-1, 2)
        e = r.field(key, "joints/interface/relative_displacement").reshape(-1, 2)
    o = np.argsort(x, kind="stable")
    return x[o], s[o, 0], s[o, 1], e[o, 1], e[o, 0]


def keys_and_steps(path):
    with Results(path) as r:
        keys = r.keys
        steps = [r.step_of(k) for k in keys]
    return keys, steps


def step_ends(path):
    keys, steps = keys_and_steps(path)
    return [k for k, s, n in zip(keys, steps, steps[1:] + [None]) if s != n]


def mid_history(path):
    """(eps_t, eps_n, sigma_n, tau) at the joint point nearest mid-interface, from the initial
    state (row 0) through every increment."""
    keys, _ = keys_and_steps(path)
    rows = [(0.0, 0.0, SIGMA_N0, 0.0)]
    for k in keys:
        x, sn, tau, et, en = interface(path, k)
        i = int(np.argmin(np.abs(x - L / 2)))
        rows.append((et[i], en[i], sn[i], tau[i]))
    return np.array(rows).T


def point_driver(targets, workdir, steps=200):
    """pecplas-path, same law, CNL at SIGMA_N0, through the given eps_t targets [m]; returns the
    CSV columns eps_t, eps_n, sigma_n, tau."""
    workdir = Path(workdir)
    deck = workdir / "s5_point.inp"
    deck.write_text(LAW + f"*PATH, TYPE=CNL, SIGMA_N0={SIGMA_N0}, STEPS={steps}\n"
                    + ", ".join(f"{t:.12g}" for t in targets) + "\n")
    r = subprocess.run([*exe_cmd("pecplas-path"), str(deck), "-o", str(workdir / "s5_point"),
                        "--quiet"], cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("pecplas-path: " + r.stderr)
    d = np.genfromtxt(workdir / "s5_point.csv", delimiter=",", names=True, dtype=None,
                      encoding=None)
    return d["eps_t"], d["eps_n"], d["sigma_n"], d["tau"]


def compare(fe, pd, nseg):
    """Point-driver tau and eps_n interpolated at the FE mid-interface slips, segment by
    segment (both paths run through the same reversal points); returns (tau_pd, en_pd)."""
    et, en, sn, tau = fe
    pet, pen, _, ptau = pd
    # segment index of each FE row: a new segment starts after each reversal of eps_t
    d = np.diff(et)
    seg = np.concatenate([[0], np.cumsum(np.r_[0, (np.sign(d[1:]) != np.sign(d[:-1]))
                                                & (np.abs(d[1:]) > 0)])])
    n_pd = (len(pet) - 1) // nseg
    tau_pd, en_pd = np.empty_like(et), np.empty_like(et)
    for s in range(nseg):
        sl = slice(s * n_pd, (s + 1) * n_pd + 1)
        xs, o = pet[sl], None
        o = np.argsort(xs)
        m = seg == s
        tau_pd[m] = np.interp(et[m], xs[o], ptau[sl][o])
        en_pd[m] = np.interp(et[m], xs[o], pen[sl][o])
    return tau_pd, en_pd
