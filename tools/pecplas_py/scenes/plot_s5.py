#!/usr/bin/env python3
"""Figures of scene S5 (thesis figs IV.1-IV.3): sigma_n, tau and tau/sigma_n along the
interface of the FE shear box at a few instants of the cycle, and the mid-interface response
(tau and eps_n against the relative slip, sigma_n) with the point driver's (pecplas-path, same
law, CNL 100 kPa) on the same slip path. Reads output/s5/s5_shear_box.h5 (`make s5`), runs
pecplas-path in output/s5 and writes PNGs there.

    python3 -m pecplas_py.scenes.plot_s5 [OUTPUT_DIR]
"""

from pecplas_py.scenes.scene_cli import scene_dir

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.scenes.s5_results import (L, compare, interface, keys_and_steps, mid_history,
                                          point_driver, step_ends)


def main():
    out = scene_dir(__doc__, "output/s5")
    h5 = out / "s5_shear_box.h5"
    keys, _ = keys_and_steps(h5)
    ends = step_ends(h5)
    # the reversal points, and the mid-slip instants of the unloading and reloading
    picks = [(k, f"end of step {i + 1}") for i, k in enumerate(ends)]
    picks += [(keys[keys.index(ends[0]) + 20], "half of step 2 (plate at 0)"),
              (keys[keys.index(ends[1]) + 20], "half of step 3 (plate at 0)")]
    fig, axes = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
    for k, label in picks:
        x, sn, tau, _, _ = interface(h5, k)
        for ax, v in zip(axes, (sn, tau, tau / sn)):
            ax.plot(x, v, ".-", ms=3, label=label)
    for ax, name in zip(axes, ("sigma_n [kPa]", "tau [kPa]", "tau / sigma_n")):
        ax.set_ylabel(name)
        ax.axvspan(0.0, 0.02, color="0.92", zorder=0)
        ax.axvspan(L - 0.02, L, color="0.92", zorder=0)
    axes[-1].set_xlabel("x along the interface [m] (shaded: within 0.02 m of a wall)")
    axes[0].set_title("S5: stresses along the interface (fig. IV.2 style)", fontsize=10)
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    save_figure(fig, out / "s5_distributions.png", dpi=120)
    print(out / "s5_distributions.png")

    fe = mid_history(h5)
    et, en, sn, tau = fe
    targets = et[[keys.index(k) + 1 for k in ends]]
    pd = point_driver(targets, out)
    tau_pd, _ = compare(fe, pd, len(targets))
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    axes[0].plot(pd[0] * 1e3, pd[3], "k-", lw=1, label="point driver (CNL 100 kPa)")
    axes[0].plot(et * 1e3, tau, "o", ms=3, mfc="none", label="FE mid-interface")
    axes[0].set_xlabel("relative slip eps_t [mm]")
    axes[0].set_ylabel("tau [kPa]")
    axes[1].plot(pd[0] * 1e3, pd[1] * 1e3, "k-", lw=1)
    axes[1].plot(et * 1e3, en * 1e3, "o", ms=3, mfc="none")
    axes[1].set_xlabel("relative slip eps_t [mm]")
    axes[1].set_ylabel("eps_n [mm] (closure +)")
    axes[2].plot(np.arange(len(sn)), sn, "o-", ms=2, label="FE sigma_n")
    axes[2].axhline(100.0, color="k", lw=1, label="CNL 100 kPa")
    axes[2].set_xlabel("increment")
    axes[2].set_ylabel("sigma_n [kPa]")
    axes[0].legend(fontsize=8)
    axes[2].legend(fontsize=8)
    dev = np.abs(tau - tau_pd).max() / np.abs(pd[3]).max()
    fig.suptitle(f"S5: mid-interface FE vs point driver (fig. IV.3 style), "
                 f"max |dtau| = {100 * dev:.2f} % of peak", fontsize=10)
    fig.tight_layout()
    save_figure(fig, out / "s5_mid_interface.png", dpi=120)
    print(out / "s5_mid_interface.png")


if __name__ == "__main__":
    main()
