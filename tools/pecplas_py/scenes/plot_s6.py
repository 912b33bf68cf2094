#!/usr/bin/env python3
"""Figures of scene S6 (pile pull-out, thesis figs IV.5-IV.10) from the results of `make s6`:
head load-uplift of MODJOIN, its table IV.1 variants and Mohr-Coulomb (IV.5, IV.6, IV.10);
axial force along the pile at the thesis's loads 2.83, 4.40, 6.28 kN or up to the limit load
(IV.7, from the shaft stresses: N(z) = Q - int_0^z tau 2 pi a dz); tau, sigma_n, tau/sigma_n
along the shaft at four loads (IV.8); tau, sigma_n, tau/sigma_n against the relative slip at
depths 0.525, 1.016, 1.581 m (IV.9).

    python3 -m pecplas_py.scenes.plot_s6 [DIR]  # DIR holds s6_*.h5 (default output/s6)
"""
import math

from pecplas_py.scenes.scene_cli import scene_dir

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.results import Results
from pecplas_py.scenes.s6_results import head_curve, keys_and_loads, shaft

DEPTHS = (0.525, 1.016, 1.581)   # points of interest of the thesis [m]
QS = (2.83, 4.40, 6.28)          # measured cycle peaks [kN]
A = 0.0275


def at_load(keys, loads, q):
    """The first increment whose pull reaches q past the early peak, else the last one."""
    i = int(np.argmax(loads))
    late = [j for j in range(len(keys)) if loads[j] >= q and loads[j:].min() >= 0.9 * q]
    return keys[late[0]] if late else keys[i]


def axial_force(h5, key, q):
    z, s, _ = shaft(h5, key)
    zz, tau = z.reshape(-1, 2), s[:, 1].reshape(-1, 2)
    dz = np.abs(zz[:, 0] - zz[:, 1])
    n = q - np.r_[0.0, np.cumsum(tau.mean(axis=1) * dz * 2 * math.pi * A)]
    return np.r_[-zz[:, 0], -zz[-1, 1]], n


def slips(h5, keys):
    with Results(h5) as r:
        return np.array([r.field(k, "joints/shaft/relative_displacement").reshape(-1, 2)[:, 1]
                         for k in keys])


def main():
    d = scene_dir(__doc__, "output/s6")
    runs = {p.stem: p for p in sorted(d.glob("s6_*.h5"))}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, xmax in zip(axes, (40, 5)):
        for name, p in runs.items():
            load, u = head_curve(p)
            ax.plot(u * 1e3, load, "-" if name.endswith(("modjoin", "coulomb")) else "--",
                    label=name[3:])
        for q in QS:
            ax.axhline(q, color="grey", lw=0.5)
        ax.set_xlim(0, xmax)
        ax.set_xlabel("head uplift [mm]")
        ax.set_ylabel("pull Q [kN]")
    axes[0].legend(fontsize=8)
    fig.suptitle("S6 head load-uplift (figs IV.5, IV.6, IV.10 style; grey: measured peaks)")
    fig.tight_layout()
    save_figure(fig, d / "s6_head.png", dpi=120)
    for name in ("s6_modjoin", "s6_mohr_coulomb"):
        if name not in runs:
            continue
        h5 = runs[name]
        keys, loads = keys_and_loads(h5)
        qmax = loads.max()
        fig, axes = plt.subplots(1, 4, figsize=(15, 5), sharey=True)
        for q in QS:
            k = at_load(keys, loads, q)
            qq = loads[keys.index(k)]
            zn, n = axial_force(h5, k, qq)
            axes[0].plot(n, zn, "o-", ms=3, label=f"Q = {qq:.2f} kN")
        four = [0.25, 0.5, 0.75, 1.0]
        for f in four:
            k = at_load(keys, loads, f * qmax)
            z, s, _ = shaft(h5, k)
            o = np.argsort(-z)
            lab = f"Q = {loads[keys.index(k)]:.2f} kN"
            axes[1].plot(s[o, 1], -z[o], label=lab)
            axes[2].plot(s[o, 0], -z[o])
            ratio = np.where(s[o, 0] > 0, s[o, 1] / np.maximum(s[o, 0], 1e-12), np.nan)
            axes[3].plot(ratio, -z[o])
        axes[3].axvline(math.tan(math.radians(41.0)), color="grey", lw=0.5)
        for a, t in zip(axes, ("axial force N [kN]", "tau [kPa]", "sigma_n [kPa]",
                               "tau / sigma_n (grey: tan 41)")):
            a.set_xlabel(t)
            for zz in DEPTHS:
                a.axhline(zz, color="grey", lw=0.4)
        axes[0].invert_yaxis()
        axes[0].set_ylabel("depth [m]")
        axes[0].legend(fontsize=7)
        axes[1].legend(fontsize=7)
        fig.suptitle(f"S6 {name[3:]}: axial force (fig. IV.7) and shaft stresses (fig. IV.8)")
        fig.tight_layout()
        save_figure(fig, d / f"{name}_shaft.png", dpi=120)
        # fig. IV.9: stress paths at the three depths
        z, _, _ = shaft(h5, keys[0])
        st = np.array([shaft(h5, k)[1] for k in keys])
        sl = slips(h5, keys)
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
        for depth in DEPTHS:
            i = int(np.argmin(np.abs(-z - depth)))
            lab = f"{depth} m (point at {-z[i]:.3f} m)"
            axes[0].plot(np.abs(sl[:, i]) * 1e3, np.abs(st[:, i, 1]), label=lab)
            axes[1].plot(np.abs(sl[:, i]) * 1e3, st[:, i, 0])
            axes[2].plot(np.abs(sl[:, i]) * 1e3, np.abs(st[:, i, 1])
                         / np.maximum(st[:, i, 0], 1e-12))
        for a, t in zip(axes, ("|tau| [kPa]", "sigma_n [kPa]", "|tau| / sigma_n")):
            a.set_xlabel("relative slip [mm]")
            a.set_ylabel(t)
        axes[0].legend(fontsize=7)
        fig.suptitle(f"S6 {name[3:]}: stresses at three shaft points (fig. IV.9 style)")
        fig.tight_layout()
        save_figure(fig, d / f"{name}_paths.png", dpi=120)
    print(f"plot_s6: figures in {d}")


if __name__ == "__main__":
    main()
