#!/usr/bin/env python3
"""Plot a pecplas-path result: tau-eps_t, eps_n-eps_t and the stress path tau-sigma_n.

usage: python3 -m pecplas_py.plots.plot_path RESULT.csv [RESULT2.csv ...] [-o FIGURE.png]

Each CSV (columns step, eps_t, eps_n, sigma_n, tau, mode, plastic_slip, as written by
pecplas-path) becomes one curve; the figure goes next to the first CSV (same name, .png)
unless -o is given. Several files on one figure compare paths (CNL, CND, CNS).
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from pecplas_py.figures import save_figure


def read_path_csv(path):
    """Columns of a pecplas-path CSV as lists (numbers as float, mode as str)."""
    cols = {k: [] for k in ("step", "eps_t", "eps_n", "sigma_n", "tau", "mode", "plastic_slip")}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            for k in cols:
                v = row[k].strip()
                cols[k].append(v if k == "mode" else float(v))
    return cols


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="+", help="pecplas-path CSV result(s)")
    parser.add_argument("-o", "--output", help="figure file (default: first CSV with .png)")
    args = parser.parse_args(argv)

    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(15, 4.5))
    for path in args.csv:
        d = read_path_csv(path)
        label = os.path.splitext(os.path.basename(path))[0]
        ax1.plot(d["eps_t"], d["tau"], label=label)
        ax2.plot(d["eps_t"], d["eps_n"], label=label)
        ax3.plot(d["sigma_n"], d["tau"], label=label)
    ax1.set_xlabel("eps_t (tangential relative displacement)")
    ax1.set_ylabel("tau")
    ax1.set_title("shear stress")
    ax2.set_xlabel("eps_t")
    ax2.set_ylabel("eps_n (closure positive, < 0 = dilation)")
    ax2.set_title("normal displacement")
    ax3.set_xlabel("sigma_n (compression positive)")
    ax3.set_ylabel("tau")
    ax3.set_title("stress path")
    for ax in (ax1, ax2, ax3):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    fig.tight_layout()
    out = args.output or os.path.splitext(args.csv[0])[0] + ".png"
    save_figure(fig, out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
