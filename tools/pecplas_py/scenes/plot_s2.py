#!/usr/bin/env python3
"""Figures of scenes S2 and S3 (thesis figs II.6-II.13): head load-settlement curves of the
interface models, sigma_n and tau along the shaft at the end of loading and of unloading, and
the S3 curves for psi = 0, 1, 5, 15, 30°. Reads output/s2/*.h5 and output/s3/*.h5
(`make s2`, `make s3`) and writes PNGs beside them.

    python3 -m pecplas_py.scenes.plot_s2 [OUTPUT_DIR]
"""

from pecplas_py.scenes.scene_cli import scene_dir

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure
from pecplas_py.scenes.s2_results import head_curve, last_key, shaft


def main():
    out = scene_dir(__doc__, "output")
    s2 = sorted((out / "s2").glob("s2_*.h5"))
    if s2:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for p in s2:
            load, s, _ = head_curve(p)
            ax.plot(np.r_[0, s] * 1e3, np.r_[0, load], label=p.stem[3:])
        ax.set_xlabel("head settlement [mm]")
        ax.set_ylabel("head load [kN]")
        ax.set_title("S2: pile under one load cycle (fig. II.7 style)", fontsize=10)
        ax.legend(fontsize=8)
        fig.tight_layout()
        save_figure(fig, out / "s2" / "s2_head_curve.png", dpi=120)
        print(out / "s2" / "s2_head_curve.png")
        fig, axes = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
        for p in s2:
            for step, style in ((1, "-"), (2, "--")):
                z, s, _, _ = shaft(p, last_key(p, step))
                order = np.argsort(z)
                tag = f"{p.stem[3:]}, {'end of loading' if step == 1 else 'unloaded'}"
                axes[0].plot(s[order, 0], z[order], style, label=tag)
                axes[1].plot(s[order, 1], z[order], style, label=tag)
        axes[0].set_xlabel("sigma_n along the shaft [kPa] (compression +)")
        axes[1].set_xlabel("tau along the shaft [kPa]")
        axes[0].set_ylabel("z [m]")
        axes[1].legend(fontsize=6)
        fig.suptitle("S2: shaft stresses at the end of loading and unloading (figs II.8-II.11)",
                     fontsize=10)
        fig.tight_layout()
        save_figure(fig, out / "s2" / "s2_shaft.png", dpi=120)
        print(out / "s2" / "s2_shaft.png")
    s3 = sorted((out / "s3").glob("s3_psi*.h5"), key=lambda p: int(p.stem[6:].split("_")[0]))
    if s3:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for p in s3:
            load, s, steps = head_curve(p)
            m = steps == 1
            ax.plot(np.r_[0, s[m]] * 1e3, np.r_[0, load[m]], label=f"psi = {p.stem[6:]}°")
        ax.set_xlabel("head settlement [mm]")
        ax.set_ylabel("head load [kN]")
        ax.set_title("S3: effect of dilatancy (fig. II.13 style)", fontsize=10)
        ax.legend(fontsize=8)
        fig.tight_layout()
        save_figure(fig, out / "s3" / "s3_dilatancy.png", dpi=120)
        print(out / "s3" / "s3_dilatancy.png")


if __name__ == "__main__":
    main()
