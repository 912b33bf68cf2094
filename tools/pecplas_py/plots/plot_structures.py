#!/usr/bin/env python3
"""N, Q, M and deflection along each plate, per phase, and the anchor forces per phase.

    python3 -m pecplas_py.plots.plot_structures RESULTS.h5 [-o OUT.png] [--data OUT.json]
        [--no-envelope]

One row of four panels per plate set: N, Q, M and the deflection (the displacement normal
to the plate's chord, first end to last) along the plate, one curve per phase at the
phase's last written increment where the plate is active, with the phase's envelope (min
and max node by node over its written increments, pecplas_py.structures) as a band of the
same colour. A plate steeper than 45° is drawn standing (elevation up), as a wall is drawn;
otherwise lying along its arc length. A last row: the force of each anchor bar at the end
of each phase (bars) with the phase's envelope (error bars), also printed as a table.
`--data FILE` writes the numbers drawn (JSON). Exit codes: 0 written, 2 bad input (a file
that is not a results file, or one without plates or anchors)."""

import argparse
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pecplas_py import structures  # noqa: E402
from pecplas_py.structures import NQM  # noqa: E402
from pecplas_py.figures import save_figure  # noqa: E402
from pecplas_py.results import Results  # noqa: E402

PANELS = ("N", "Q", "M", "deflection")


def phase_label(r, index):
    try:
        name = r.phase(index)["name"]
    except KeyError:
        name = ""
    return f"phase {index}" + (f" {name}" if name else "")


def units_of(r):
    u = structures.units(r)
    plate = u["plate_forces"]     # 'N, Q: kN/m; M: kN*m/m'
    nq, m = "", ""
    if plate and ";" in plate:
        nq = plate.split(";")[0].split(":")[-1].strip()
        m = plate.split(";")[1].split(":")[-1].strip()
    length = str(r.attr("length_unit", ""))
    length = "" if length in ("", "(not stated)") else length
    return {"N": nq, "Q": nq, "M": m, "deflection": length,
            "anchor": u["anchor_force"] if u["anchor_force"] != "(not stated)" else ""}


def table(env, labels):
    """Rows (phase, anchor, bar, end force, min, max) of the anchors."""
    rows = []
    for phase, e in env.items():
        for name, a in e["anchors"].items():
            for b in range(len(a["end"])):
                rows.append((labels[phase], name, b + 1, float(a["end"][b]),
                             float(a["min"][b]), float(a["max"][b])))
    return rows


def draw(r, out, envelope=True):
    """Writes the PNG; returns the numbers drawn (dict)."""
    plates = structures.plate_names(r)
    anchors = structures.anchor_names(r)
    env = structures.envelopes(r)
    labels = {p: phase_label(r, p) for p in env}
    unit = units_of(r)
    nrow = len(plates) + (1 if anchors else 0)
    fig, axes = plt.subplots(nrow, 4, figsize=(15, 3.6 * nrow), squeeze=False)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    data = {"plates": {}, "anchors": table(env, labels), "phases": {}}
    for row, name in enumerate(plates):
        line = structures.plate_line(r, name)
        pos = line["x"][:, 1] if line["vertical"] else line["s"]
        data["plates"][name] = {"position": pos.tolist(), "vertical": bool(line["vertical"]),
                                "phases": {}}
        for i, (phase, e) in enumerate(env.items()):
            if name not in e["plates"]:
                continue
            p = e["plates"][name]
            c = colours[i % len(colours)]
            data["plates"][name]["phases"][str(phase)] = {
                k: {"end": p["end"][k].tolist(), "min": p[k][0].tolist(),
                    "max": p[k][1].tolist()} for k in PANELS}
            for ax, k in zip(axes[row], PANELS):
                if line["vertical"]:
                    ax.plot(p["end"][k], pos, color=c, lw=1.4, label=labels[phase])
                    if envelope:
                        ax.fill_betweenx(pos, p[k][0], p[k][1], color=c, alpha=0.18, lw=0)
                else:
                    ax.plot(pos, p["end"][k], color=c, lw=1.4, label=labels[phase])
                    if envelope:
                        ax.fill_between(pos, p[k][0], p[k][1], color=c, alpha=0.18, lw=0)
        # a force that is zero to round-off (N of a plate under transverse load only) is
        # drawn on the scale of the plate's largest force, not magnified to its noise
        big = {k: max((float(np.abs(p["end"][k]).max()) for e in env.values()
                       for p in [e["plates"].get(name)] if p), default=0.0) for k in NQM}
        for ax, k in zip(axes[row], PANELS):
            if k in NQM and big[k] <= 1e-9 * max(big.values()):
                lim = 0.05 * max(big.values()) or 1.0
                (ax.set_xlim if line["vertical"] else ax.set_ylim)(-lim, lim)
            u = f" [{unit[k]}]" if unit[k] else ""
            what = f"{k}{u}" if k != "deflection" else f"deflection (normal to chord){u}"
            if line["vertical"]:
                ax.set_xlabel(what, fontsize=8)
                ax.set_ylabel("elevation", fontsize=8)
                ax.axvline(0.0, color="0.6", lw=0.6)
            else:
                ax.set_ylabel(what, fontsize=8)
                ax.set_xlabel("position along the plate", fontsize=8)
                ax.axhline(0.0, color="0.6", lw=0.6)
            ax.set_title(f"plate {name}: {k}", fontsize=9)
            ax.tick_params(labelsize=7)
        axes[row][0].legend(fontsize=7)
    if anchors:
        ax = axes[-1][0]
        phases = list(env)
        width = 0.8 / max(1, len(phases))
        ticks, names = [], []
        for j, name in enumerate(anchors):
            nbar = len(r.file[f"mesh/anchors/{name}/length"][()])
            for b in range(nbar):
                ticks.append(len(names))
                names.append(f"{name}" + (f" #{b + 1}" if nbar > 1 else ""))
        for i, phase in enumerate(phases):
            xs, ys, lo, hi = [], [], [], []
            t = 0
            for name in anchors:
                nbar = len(r.file[f"mesh/anchors/{name}/length"][()])
                a = env[phase]["anchors"].get(name)
                for b in range(nbar):
                    if a is not None:
                        xs.append(t + (i - (len(phases) - 1) / 2) * width)
                        ys.append(a["end"][b])
                        lo.append(a["end"][b] - a["min"][b])
                        hi.append(a["max"][b] - a["end"][b])
                    t += 1
            if xs:
                ax.bar(xs, ys, width, color=colours[i % len(colours)], label=labels[phase],
                       yerr=[lo, hi] if envelope else None, capsize=3)
        ax.set_xticks(ticks, names, fontsize=7)
        u = f" [{unit['anchor']}]" if unit["anchor"] else ""
        ax.set_ylabel(f"anchor force, tension +{u}", fontsize=8)
        ax.set_title("anchors: end of phase (bars), envelope (whiskers)", fontsize=9)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.legend(fontsize=7)
        ax.tick_params(labelsize=7)
        tab = axes[-1][1]
        tab.axis("off")
        cells = [[ph, n, str(b), f"{e:.4g}", f"{lo:.4g}", f"{hi:.4g}"]
                 for ph, n, b, e, lo, hi in data["anchors"]][:20]
        if cells:
            tt = tab.table(cellText=cells, colLabels=["phase", "anchor", "bar", "end", "min",
                                                      "max"], loc="upper left")
            tt.auto_set_font_size(False)
            tt.set_fontsize(7)
            tt.auto_set_column_width(list(range(6)))
        for ax in axes[-1][2:]:
            ax.set_visible(False)
    data["phases"] = {str(p): labels[p] for p in env}
    fig.suptitle(f"{r.attr('title', '')}: structures per phase (end of phase; bands: envelope "
                 "of the phase)", fontsize=10)
    fig.tight_layout()
    save_figure(fig, out, dpi=110)
    plt.close(fig)
    return data


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("h5")
    ap.add_argument("-o", "--output", help="PNG (default: the results file with "
                    "_structures.png)")
    ap.add_argument("--data", help="write the numbers drawn (JSON)")
    ap.add_argument("--no-envelope", action="store_true", help="end of each phase only")
    a = ap.parse_args(argv)
    out = Path(a.output) if a.output else \
        Path(a.h5).with_name(Path(a.h5).stem + "_structures.png")
    try:
        r = Results(a.h5)
    except OSError as e:
        print(f"plot_structures: {a.h5}: not a readable results file ({e})", file=sys.stderr)
        return 2
    with r:
        if not structures.plate_names(r) and not structures.anchor_names(r):
            print(f"plot_structures: {a.h5}: no plates or anchors (/mesh/plates, "
                  "/mesh/anchors)", file=sys.stderr)
            return 2
        if not r.keys:
            print(f"plot_structures: {a.h5}: no increment with fields", file=sys.stderr)
            return 2
        data = draw(r, out, not a.no_envelope)
    for ph, n, b, e, lo, hi in data["anchors"]:
        print(f"  {ph:24s} {n:12s} bar {b:3d}  end {e:12.5g}  min {lo:12.5g}  max {hi:12.5g}")
    if a.data:
        Path(a.data).write_text(json.dumps(data, indent=1))
    print(f"plot_structures: {out} ({len(data['plates'])} plate sets, "
          f"{len({row[1] for row in data['anchors']})} anchor sets, {len(data['phases'])} "
          "phases)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
