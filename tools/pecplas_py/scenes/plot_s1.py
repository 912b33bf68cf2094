#!/usr/bin/env python3
"""Figures of scene S1 (shear box) in the style of the thesis's figs II.3-II.4: mean joint
shear stress and mean shear stress of the lower block against the load, for the results of
the decks of input/s1/ (run by `make s1`), and the normal stress of the opening-closing cases.

    python3 -m pecplas_py.scenes.plot_s1 [DIR]  # default output/s1; writes PNGs there
"""

from pecplas_py.scenes.scene_cli import scene_dir

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.results import Results


def series(path):
    """load measure (factor of the first pattern), mean joint (sigma_n, tau), lower-block
    mean shear sigma_xy, for each increment with fields."""
    with Results(path) as r:
        factors = r.pattern_factors()
        load, sn, tau, sxy = [0.0], [1.3], [0.0], [0.0]
        for row, k in zip(r.field_rows(), r.keys):
            s = r.field(k, "joints/joint/stress").reshape(-1, 2)
            load.append(float(np.ravel(factors[row])[0]))
            sn.append(s[:, 0].mean())
            tau.append(s[:, 1].mean())
            sxy.append(r.field(k, "sets/lower/stress").reshape(-1, 4)[:, 3].mean())
        status = r.status
    return np.array(load), np.array(sn), np.array(tau), np.array(sxy), status


def main():
    d = scene_dir(__doc__, "output/s1")
    # fig II.3-like: cohesive and frictional joints under force control / displacement control
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, label in [("s1_cohesive_disp", "cohesive c = 1"),
                        ("s1_friction_psi0_kn5e6", "phi = 30, psi = 0")]:
        p = d / f"{name}.h5"
        if p.exists():
            load, _, tau, sxy, _ = series(p)
            axes[0].plot(load, tau, "o-", ms=3, label=f"joint tau, {label}")
            axes[0].plot(load, sxy, "--", label=f"lower block sigma_xy (mean), {label}")
    axes[0].set_xlabel("imposed horizontal displacement of the upper block [mm]")
    axes[0].set_ylabel("shear stress [kPa]")
    axes[0].set_title("S1: plateaus (c, sigma_n tan phi)", fontsize=10)
    axes[0].legend(fontsize=7)
    for name in sorted(d.glob("s1_friction_psi*_kn*.h5")):
        load, sn, tau, _, _ = series(name)
        axes[1].plot(load, tau, label=name.stem.replace("s1_friction_", ""))
    axes[1].set_xlabel("imposed horizontal displacement [mm]")
    axes[1].set_ylabel("mean joint shear stress [kPa]")
    axes[1].set_title("S1: dilatancy with stiff (5e6) and soft (5e3) K_n", fontsize=10)
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, d / "s1_shear.png", dpi=120)
    print(d / "s1_shear.png")
    # opening-closing: normal stress against the imposed vertical displacement
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for p in sorted(d.glob("s1_open_close_*.h5")):
        load, sn, _, _, status = series(p)
        ax.plot(load, sn, "o-", ms=3, label=f"{p.stem} ({status})")
    ax.set_xlabel("imposed vertical displacement of the upper block [mm] (+ = lift)")
    ax.set_ylabel("mean joint sigma_n [kPa] (compression +)")
    ax.set_title("S1: compression - opening - closing", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, d / "s1_open_close.png", dpi=120)
    print(d / "s1_open_close.png")


if __name__ == "__main__":
    main()
