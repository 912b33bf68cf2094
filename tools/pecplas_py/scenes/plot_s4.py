#!/usr/bin/env python3
"""Figures of scene S4 (homogeneous paths of MODJOIN) in the style of the thesis's figures:
III.9 / III.11 / III.24 (CNL and CND at sigma_n0 = 31, 56, 122 kPa with tables III.1, III.2,
III.5: shear curve tau-eps_t, normal behaviour eps_n-eps_t or sigma_n-eps_t, stress path
tau-sigma_n), III.12 (initial vs improved version at 56 kPa), III.29-III.30 (cyclic CNL, one
and ten cycles, both III.6 sets, at +/-2 mm and +/-1 mm, with the end-of-cycle envelope as
fig. III.26), III.31 (cyclic CND at 193 kPa), and table III.4 as bars
(when output/s4/sensitivity.csv exists), from the CSVs written by `make s4`.

    python3 -m pecplas_py.scenes.plot_s4 [DIR]  # default output/s4; writes PNGs there
"""
import csv

from pecplas_py.scenes.scene_cli import scene_dir

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py.figures import save_figure

SIGMAS = (31, 56, 122)
TABLES = {"iii1": ("fig. III.9", "table III.1, initial version"),
          "iii2": ("figs III.11, III.23", "table III.2, improved version"),
          "iii5": ("fig. III.24", "table III.5, improved version, medium density")}
STYLES = {31: "-", 56: "--", 122: "-."}
PHI_PSI = {"iii1": (41.0, 27.0), "iii2": (41.0, 27.0), "iii5": (37.0, 30.0)}


def read(path):
    """Numeric columns of a pecplas-path CSV as arrays (None when the file is missing)."""
    if not path.exists():
        return None
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows])
            for k in ("eps_t", "eps_n", "sigma_n", "tau", "plastic_slip")}


def label_axes(ax, x, y, title):
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3)


def monotonic(d, key):
    """Three CNL and three CND tests of one table: 2 x 3 panels."""
    fig_ref, what = TABLES[key]
    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    for s in SIGMAS:
        cnl = read(d / f"s4_{key}_cnl_{s}.csv")
        cnd = read(d / f"s4_{key}_cnd_{s}.csv")
        lab = f"sigma_n0 = {s} kPa"
        if cnl is not None:
            ax[0, 0].plot(cnl["eps_t"], cnl["tau"], STYLES[s], label=lab)
            ax[0, 1].plot(cnl["eps_t"], cnl["eps_n"], STYLES[s], label=lab)
            ax[0, 2].plot(cnl["eps_t"], cnl["tau"] / cnl["sigma_n"], STYLES[s], label=lab)
        if cnd is not None:
            ax[1, 0].plot(cnd["eps_t"], cnd["tau"], STYLES[s], label=lab)
            ax[1, 1].plot(cnd["eps_t"], cnd["sigma_n"], STYLES[s], label=lab)
            ax[1, 2].plot(cnd["sigma_n"], cnd["tau"], STYLES[s], label=lab)
    label_axes(ax[0, 0], "eps_t [mm]", "tau [kPa]", "(a) CNL: shear curve")
    label_axes(ax[0, 1], "eps_t [mm]", "eps_n [mm] (closure +, dilation -)",
               "(b) CNL: normal displacement")
    phi, psi = PHI_PSI[key]
    for angle, name in ((phi, "tan(phi)"), (psi, "tan(psi)")):
        ax[0, 2].axhline(np.tan(np.radians(angle)), color="k", ls=":", lw=0.8)
        ax[0, 2].text(0.1, np.tan(np.radians(angle)), name, fontsize=7, va="bottom")
    label_axes(ax[0, 2], "eps_t [mm]", "tau / sigma_n", "CNL: mobilised ratio (eps_n turns "
               "at tan(psi))")
    label_axes(ax[1, 0], "eps_t [mm]", "tau [kPa]", "(c) CND: shear curve")
    label_axes(ax[1, 1], "eps_t [mm]", "sigma_n [kPa]", "(d) CND: normal stress")
    label_axes(ax[1, 2], "sigma_n [kPa]", "tau [kPa]", "CND: stress path")
    for a in ax.flat:
        a.legend(fontsize=7)
    fig.suptitle(f"S4, MODJOIN {what} (thesis {fig_ref})", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / f"s4_{key}.png", dpi=110)
    plt.close(fig)


def versions(d):
    """Initial (III.1) vs improved (III.2) at 56 kPa (fig. III.12)."""
    fig, ax = plt.subplots(1, 4, figsize=(16, 4))
    for key, style, lab in (("iii1", "--", "initial (III.1)"), ("iii2", "-", "improved (III.2)")):
        cnl = read(d / f"s4_{key}_cnl_56.csv")
        cnd = read(d / f"s4_{key}_cnd_56.csv")
        if cnl is None or cnd is None:
            continue
        ax[0].plot(cnl["eps_t"], cnl["tau"], style, label=lab)
        ax[1].plot(cnl["eps_t"], cnl["eps_n"], style, label=lab)
        ax[2].plot(cnd["eps_t"], cnd["tau"], style, label=lab)
        ax[3].plot(cnd["eps_t"], cnd["sigma_n"], style, label=lab)
    label_axes(ax[0], "eps_t [mm]", "tau [kPa]", "(a) CNL 56 kPa: shear")
    label_axes(ax[1], "eps_t [mm]", "eps_n [mm]", "(b) CNL 56 kPa: normal displacement")
    label_axes(ax[2], "eps_t [mm]", "tau [kPa]", "(c) CND 56 kPa: shear")
    label_axes(ax[3], "eps_t [mm]", "sigma_n [kPa]", "(d) CND 56 kPa: normal stress")
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle("S4: initial and improved versions of MODJOIN (thesis fig. III.12)", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / "s4_versions_56.png", dpi=110)
    plt.close(fig)


STEPS_CYC = 200  # increments per segment of the cyclic decks (decks/make_s4_decks.py)


def cycle_ends(r):
    """tau and eps_n at +amplitude at the end of each cycle (0 = end of the primary loading)."""
    idx = np.arange(STEPS_CYC, len(r["tau"]), 2 * STEPS_CYC)
    return r["tau"][idx], r["eps_n"][idx]


def cyclic(d, key, fig_ref, what, suffix, amp):
    """Cyclic CNL at 100 kPa: one cycle, ten cycles, the tenth cycle (figs III.29-III.30),
    and the end-of-cycle envelope against the cycle number (as fig. III.26)."""
    one = read(d / f"s4_{key}_cyclic_cnl_1{suffix}.csv")
    ten = read(d / f"s4_{key}_cyclic_cnl_10{suffix}.csv")
    if one is None or ten is None:
        return
    fig, ax = plt.subplots(2, 4, figsize=(18, 8))
    ax[0, 0].plot(one["eps_t"], one["tau"])
    ax[1, 0].plot(one["eps_t"], one["eps_n"])
    ax[0, 1].plot(ten["eps_t"], ten["tau"], lw=0.8)
    ax[1, 1].plot(ten["eps_t"], ten["eps_n"], lw=0.8)
    # the tenth cycle: the last two segments (+a -> -a -> +a)
    last = slice(len(ten["eps_t"]) - 2 * STEPS_CYC - 1, None)
    ax[0, 2].plot(ten["eps_t"][last], ten["tau"][last])
    ax[1, 2].plot(ten["eps_t"][last], ten["eps_n"][last])
    titles = ("one cycle after the primary loading", "ten cycles", "the tenth cycle")
    for j, t in enumerate(titles):
        label_axes(ax[0, j], "eps_t [mm]", "tau [kPa]", f"({'ace'[j]}) {t}: shear")
        label_axes(ax[1, j], "eps_t [mm]", "eps_n [mm] (closure +)",
                   f"({'bdf'[j]}) {t}: normal displacement")
    tc, ec = cycle_ends(ten)
    n = np.arange(len(tc))
    ax[0, 3].plot(n, tc, "o-")
    ax[1, 3].plot(n, ec, "o-")
    label_axes(ax[0, 3], "cycle number", f"tau at +{amp:g} mm [kPa]",
               "(g) end-of-cycle shear (as fig. III.26)")
    label_axes(ax[1, 3], "cycle number", f"eps_n at +{amp:g} mm [mm]",
               "(h) accumulated contraction")
    fig.suptitle(f"S4, cyclic CNL at 100 kPa, +/-{amp:g} mm, MODJOIN cyclic, {what} "
                 f"(thesis {fig_ref})", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / f"s4_{key}_cyclic_cnl{suffix}.png", dpi=110)
    plt.close(fig)


def envelopes(d):
    """End-of-cycle shear (absolute and relative to cycle 0) and contraction against the cycle
    number, both III.6 sets at +/-1 and +/-2 mm (fig. III.26 style)."""
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    drawn = False
    for key, lab in (("iii6_dr80", "Dr 80 %"), ("iii6_dr15", "Dr 15 %")):
        for suffix, amp, style in (("_a1", 1, "o-"), ("", 2, "s--")):
            r = read(d / f"s4_{key}_cyclic_cnl_10{suffix}.csv")
            if r is None:
                continue
            drawn = True
            tc, ec = cycle_ends(r)
            n = np.arange(len(tc))
            name = f"{lab}, +/-{amp} mm"
            ax[0].plot(n, tc, style, label=name)
            ax[1].plot(n, tc / tc[0], style, label=name)
            ax[2].plot(n, ec - ec[0], style, label=name)
    if not drawn:
        plt.close(fig)
        return
    label_axes(ax[0], "cycle number", "tau at +a [kPa]", "(a) end-of-cycle shear")
    label_axes(ax[1], "cycle number", "tau_c / tau_c(0)", "(b) relative cyclic hardening")
    label_axes(ax[2], "cycle number", "eps_n - eps_n(0) [mm]", "(c) accumulated contraction")
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle("S4, cyclic CNL at 100 kPa, table III.6: end of each cycle (thesis fig. III.26 "
                 "style)", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / "s4_iii6_cyclic_envelopes.png", dpi=110)
    plt.close(fig)


def cyclic_cnd(d):
    """Cyclic CND at 193 kPa (fig. III.31)."""
    r = read(d / "s4_iii6_dr80_cyclic_cnd_193.csv")
    if r is None:
        return
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    ax[0].plot(r["eps_t"], r["tau"])
    ax[1].plot(r["eps_t"], r["sigma_n"])
    ax[2].plot(r["sigma_n"], r["tau"])
    phi = np.radians(37.0)
    s = np.linspace(0.0, max(r["sigma_n"].max(), 193.0) * 1.05, 10)
    ax[2].plot(s, s * np.tan(phi), "k:", lw=0.8, label="tau = sigma_n tan(37)")
    ax[2].plot(s, -s * np.tan(phi), "k:", lw=0.8)
    ax[2].legend(fontsize=7)
    label_axes(ax[0], "eps_t [mm]", "tau [kPa]", "(a) shear curve")
    label_axes(ax[1], "eps_t [mm]", "sigma_n [kPa]", "(b) normal stress")
    label_axes(ax[2], "sigma_n [kPa]", "tau [kPa]", "(c) stress path")
    fig.suptitle("S4, cyclic CND at 193 kPa, +/-2 mm, MODJOIN cyclic, table III.6 Dr = 80 % "
                 "(thesis fig. III.31)", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / "s4_iii6_dr80_cyclic_cnd_193.png", dpi=110)
    plt.close(fig)


def sensitivity(d):
    """Table III.4 as bars: ours beside the thesis's, per curve."""
    path = d / "sensitivity.csv"
    if not path.exists():
        return
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    names = [r["parameter"] for r in rows]
    curves = [c[len("percent_"):] for c in rows[0] if c.startswith("percent_")]
    fig, ax = plt.subplots(1, len(curves), figsize=(4.2 * len(curves), 4), sharey=True)
    x = np.arange(len(names))
    for a, c in zip(np.atleast_1d(ax), curves):
        ours = [float(r[f"percent_{c}"] or 0) for r in rows]
        theirs = [float(r[f"thesis_{c}"] or 0) for r in rows]
        a.bar(x - 0.2, ours, 0.4, label="ours")
        a.bar(x + 0.2, theirs, 0.4, label="thesis (table III.4)")
        a.set_xticks(x, names, rotation=60, fontsize=8)
        a.set_title(c.replace("_", " "), fontsize=9)
        a.grid(alpha=0.3, axis="y")
    np.atleast_1d(ax)[0].set_ylabel("Q_p / max Q_p [%]")
    np.atleast_1d(ax)[0].legend(fontsize=7)
    fig.suptitle("S4: sensitivity of MODJOIN (table III.2, 56 kPa, 0-6 mm), III.21", fontsize=11)
    fig.tight_layout()
    save_figure(fig, d / "s4_sensitivity.png", dpi=110)
    plt.close(fig)


def main():
    d = scene_dir(__doc__, "output/s4")
    for key in TABLES:
        monotonic(d, key)
    versions(d)
    for suffix, amp in (("", 2), ("_a1", 1)):
        cyclic(d, "iii6_dr80", "fig. III.30", "table III.6 Dr = 80 %", suffix, amp)
        cyclic(d, "iii6_dr15", "fig. III.29", "table III.6 Dr = 15 %", suffix, amp)
    envelopes(d)
    cyclic_cnd(d)
    sensitivity(d)
    print(f"plot_s4: figures in {d}")


if __name__ == "__main__":
    main()
