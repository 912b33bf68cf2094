#!/usr/bin/env python3
"""Figures of scene S6 (pile pull-out, thesis figs IV.4-IV.10) from the results of `make s6`:
head load-uplift for MODJOIN (and the table IV.1 variants) and Mohr-Coulomb; tau and sigma_n
along the shaft at a few load levels for both laws.

    python3 tools/plot_s6.py [DIR]     # DIR holds s6_*.h5 (default output/s6)
"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from s6_results import head_curve, keys_and_loads, shaft  # noqa: E402

DEPTHS = (0.525, 1.016, 1.581)   # points of interest of the thesis [m]


def main():
    d = Path(sys.argv[1] if len(sys.argv) > 1 else "output/s6")
    runs = {p.stem: p for p in sorted(d.glob("s6_*.h5"))}
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, p in runs.items():
        load, u = head_curve(p)
        ax.plot(u * 1e3, load, "-" if name.endswith(("modjoin", "coulomb")) else "--",
                label=name[3:])
    ax.axhline(6.28, color="grey", lw=0.5)
    ax.set_xlabel("head uplift [mm]")
    ax.set_ylabel("pull Q [kN]")
    ax.set_xlim(0, 20)
    ax.legend(fontsize=8)
    ax.set_title("S6 pile pull-out: head load-uplift")
    fig.tight_layout()
    fig.savefig(d / "s6_head.png", dpi=120)
    for name in ("s6_modjoin", "s6_mohr_coulomb"):
        if name not in runs:
            continue
        keys, loads = keys_and_loads(runs[name])
        pick = sorted({int(i) for i in np.linspace(0, len(keys) - 1, 4)})
        fig, (a1, a2) = plt.subplots(1, 2, figsize=(8, 5), sharey=True)
        for i in pick:
            z, s, _ = shaft(runs[name], keys[i])
            o = np.argsort(-z)
            a1.plot(s[o, 0], -z[o], label=f"Q = {loads[i]:.2f} kN")
            a2.plot(s[o, 1], -z[o])
        for a in (a1, a2):
            for zz in DEPTHS:
                a.axhline(zz, color="grey", lw=0.4)
        a1.invert_yaxis()
        a1.set_xlabel("sigma_n [kPa]")
        a2.set_xlabel("tau [kPa]")
        a1.set_ylabel("depth [m]")
        a1.legend(fontsize=8)
        fig.suptitle(f"S6 shaft stresses, {name[3:]}")
        fig.tight_layout()
        fig.savefig(d / f"{name}_shaft.png", dpi=120)
    print(f"plot_s6: figures in {d}")


if __name__ == "__main__":
    main()
