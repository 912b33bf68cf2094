#!/usr/bin/env python3
"""The numbers of doc/validation.md, "Staged construction": runs the examples of
input/examples/ (excavation_cantilever and its plate variant excavation_cantilever_plate,
pile_wished_in_place with S2 beside it, embankment_stages) into DIR and writes the generated
blocks (or, with --check, says whether the committed ones differ from these runs, beyond the
last digit; the times of the cantilever's phases are measured, not checked).

    python3 -m pecplas_py.scenes.phases_report [DIR] [--bin DIR] [--check] [--no-run]
                                               [--figures]

--figures also draws doc/img/excavation_phases.png (pecplas_py.plots.plot_phases) and
doc/img/excavation_moments.png (the wall's moment profiles)."""

import argparse
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

from pecplas_py import ROOT
from pecplas_py.doc_blocks import begin_marker, check_close, end_marker, update
from pecplas_py.exe import exe_cmd
from pecplas_py.plots import plot_phases
from pecplas_py.results import Results
from pecplas_py.scenes import excavation_report

SCRIPT = "scenes/phases_report.py"
DOC = ROOT / "doc" / "validation.md"
EXAMPLES = ROOT / "input" / "examples"


def run(deck, out, bin_dir):
    p = subprocess.run([*exe_cmd("pecplas", bin_dir), str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT)
    if p.returncode != 0:
        raise SystemExit(f"pecplas {deck}: exit {p.returncode}\n{p.stdout}{p.stderr}")
    return out


def gauss_tight(text):
    """A pile deck with its joints integrated at Gauss points and the solver tolerance at
    1e-10: the variant where the installation is exact (see doc/validation.md)."""
    solver = "*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=50, MAX_CUTS=6"
    if solver not in text:
        raise SystemExit("the pile deck's *SOLVER line is not the expected one")
    return (text.replace("INTEGRATION=LOBATTO", "INTEGRATION=GAUSS")
            .replace(solver, solver + ", TOLERANCE=1e-10"))


def run_gauss_tight(out, bin_dir=None):
    """Runs the Gauss / tight variants of S2 and of the wished-in-place pile into `out`;
    returns their results files (S2, wished)."""
    paths = []
    for name, deck in (("s2_goodman_gauss", ROOT / "input" / "s2" / "s2_goodman.inp"),
                       ("pile_wished_in_place_gauss", EXAMPLES / "pile_wished_in_place.inp")):
        variant = Path(out) / f"{name}.inp"
        variant.write_text(gauss_tight(deck.read_text()))
        paths.append(run(variant, Path(out) / f"{name}.h5", bin_dir))
    return tuple(paths)


def pile_numbers(s2, wished):
    """Max |u| during installation, the S2 head settlement at the peak load and the largest
    difference of the two head curves (node 1: the head on the axis)."""
    def curve(path, first_step):
        with Results(path) as r:
            h = r.history()
            rows = np.nonzero(h["step"] >= first_step)[0]
            node = r.node_index(1)
            u = np.array([r.field(f"{g:06d}", "displacement")[node, 1]
                          for g in h["global_increment"][rows]])
            f = r.pattern_factors()[rows, r.patterns.index("head")]
            install = [k for k in r.keys if r.phase_of(k) < first_step]
            u_inst = max((np.abs(r.field(k, "displacement")).max() for k in install),
                         default=0.0)
        return f, -u, u_inst
    f0, w0, _ = curve(s2, 1)
    f1, w1, u_inst = curve(wished, 2)
    peak = int(np.argmax(f0))
    return {"u_install": u_inst, "settlement_peak": w0[peak], "residual": w0[-1],
            "curve_diff": float(np.abs(w1 - w0).max()), "same_factors": bool(np.array_equal(f0, f1)),
            "rows": len(f0)}


def embankment_numbers(path):
    """Per lift: settlement of the ground surface on the axis, heave at the toe region's
    highest point beyond the toe, largest horizontal displacement in the clay."""
    out = []
    with Results(path) as r:
        x = r.coordinates
        axis = int(np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0][0])
        clay = np.unique(r.element_set("clay")["connectivity"][()])
        surface = clay[np.abs(x[clay, 1]) < 1e-9]
        beyond = surface[x[surface, 0] > 11.0 + 1e-9]
        ends = r.phase_ends()
        for p in r.phases():
            if p["index"] not in ends:
                continue
            u = r.field(ends[p["index"]], "displacement")
            out.append({"phase": p["index"], "name": p["name"],
                        "settlement_mm": -1e3 * u[axis, 1],
                        "toe_heave_mm": 1e3 * u[beyond, 1].max(),
                        "max_ux_mm": 1e3 * np.abs(u[clay, 0]).max(),
                        "sets": ", ".join(p["active_element_sets"])})
    return out


def blocks(rows, pile, emb, host, gauss=None, plate=None):
    b = {}
    if plate is not None:
        b["phases-cantilever-plate"] = excavation_report.plate_markdown(plate)
    b["phases-cantilever"] = (excavation_report.markdown(rows) + "\n\nTimes: one run of the "
                              f"release build on {host}, one thread; CPU from the history "
                              "(the first phase also counts reading the deck and setting up), "
                              "wall from the phase's first output line to its last increment "
                              "(writing the results included).")
    # values at round-off or solver-tolerance level vary between builds: quoted as bounds
    # or orders of magnitude, which do not
    def order(x):
        return f"1e{round(math.log10(x)):+03d}" if x > 0 else "0"

    text = (f"During the installation phase the largest displacement of any node is "
            f"{pile['u_install']:.2e} m; the S2 head settles {1e3 * pile['settlement_peak']:.2f} "
            f"mm at 2000 kN and keeps {1e3 * pile['residual']:.2f} mm after unloading, and the "
            f"wished-in-place pile's head curve ({pile['rows']} increments, the same load "
            f"factors: {'yes' if pile['same_factors'] else 'no'}) differs from it by about "
            f"{order(pile['curve_diff'])} m.")
    if gauss is not None:
        u_bound = "less than 1e-15 m" if gauss["u_install"] < 1e-15 else \
            f"at most {gauss['u_install']:.1e} m"
        ratio = gauss["curve_diff"] / gauss["settlement_peak"]
        c_bound = "less than 1e-7 of the settlement" if ratio < 1e-7 else \
            f"{ratio:.1e} of the settlement"
        text += (f" With Gauss points on every joint and the solver tolerance at 1e-10 (both "
                 f"decks), the installation moves every node by {u_bound}, and the two head curves "
                 f"differ by {c_bound}.")
    b["phases-pile"] = text
    lines = ["| phase | active element sets | axis settlement [mm] | largest heave beyond the "
             "toe [mm] | largest horizontal displacement in the clay [mm] |",
             "|---|---|---|---|---|"]
    for e in emb:
        lines.append(f"| {e['phase']} {e['name']} | {e['sets']} | {e['settlement_mm']:.1f} "
                     f"| {e['toe_heave_mm']:.1f} | {e['max_ux_mm']:.1f} |")
    b["phases-embankment"] = "\n".join(lines)
    return b


def with_committed_times(rows, doc=DOC):
    """`rows` with the CPU and wall times of the committed cantilever table (measured, not
    reproduced), and the committed host line: what a check compares is then the mechanics."""
    text = Path(doc).read_text()
    start = text.index(begin_marker(SCRIPT, "phases-cantilever"))
    block = text[start:text.index(end_marker("phases-cantilever"), start)]
    times = {}
    for line in block.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and cells[0].isdigit():
            times[int(cells[0])] = (float(cells[-2]), float(cells[-1]))
    host = re.search(r"release build on (.+?), one thread", block)
    out = []
    for r in rows:
        r = dict(r)
        r["cpu_s"], r["wall_s"] = times.get(r["stage"], (float("nan"), float("nan")))
        out.append(r)
    return out, (host.group(1) if host else "this machine")


def check_runs(exc, s2, wished, embankment, s2_gauss, wished_gauss, plate=None):
    """The differences between the committed blocks and runs given (results files; `plate`
    the cantilever's plate variant, its block left out when None), beyond the last printed
    digit; '' when they match."""
    rows, host = with_committed_times(excavation_report.table(exc))
    b = blocks(rows, pile_numbers(s2, wished), embankment_numbers(embankment), host,
               pile_numbers(s2_gauss, wished_gauss),
               None if plate is None else excavation_report.plate_table(plate, rows))
    return check_close(DOC, SCRIPT, b)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", nargs="?", default=str(ROOT / "output" / "phases"))
    ap.add_argument("--bin", help="directory of the pecplas executable")
    ap.add_argument("--check", action="store_true", help="compare with the committed blocks")
    ap.add_argument("--no-run", action="store_true", help="use the results already in DIR")
    ap.add_argument("--figures", action="store_true", help="draw the figures of doc/img")
    a = ap.parse_args(argv)
    out = Path(a.dir)
    out.mkdir(parents=True, exist_ok=True)
    exc = out / "excavation_cantilever.h5"
    walls = None
    if not a.no_run:
        walls = excavation_report.run_timed(EXAMPLES / "excavation_cantilever.inp", exc, a.bin)
        run(EXAMPLES / "excavation_cantilever_plate.inp", out / "excavation_cantilever_plate.h5",
            a.bin)
        run(ROOT / "input" / "s2" / "s2_goodman.inp", out / "s2_goodman.h5", a.bin)
        run(EXAMPLES / "pile_wished_in_place.inp", out / "pile_wished_in_place.h5", a.bin)
        run(EXAMPLES / "embankment_stages.inp", out / "embankment_stages.h5", a.bin)
        run_gauss_tight(out, a.bin)
    rows = excavation_report.table(exc, walls)
    pile = pile_numbers(out / "s2_goodman.h5", out / "pile_wished_in_place.h5")
    emb = embankment_numbers(out / "embankment_stages.h5")
    host = "this machine"
    try:
        cpu = Path("/proc/cpuinfo").read_text()
        m = re.search(r"model name\s*:\s*(.+)", cpu)
        host = m.group(1).strip() if m else host
    except OSError:
        pass
    gauss = pile_numbers(out / "s2_goodman_gauss.h5", out / "pile_wished_in_place_gauss.h5")
    plate = excavation_report.plate_table(out / "excavation_cantilever_plate.h5", rows)
    b = blocks(rows, pile, emb, host, gauss, plate)
    if walls is None:
        # no run timed here: the committed table (with its times) stays
        b.pop("phases-cantilever")
    if a.check:
        # the times (last two columns) and the host are measured, not compared
        bad = check_runs(exc, out / "s2_goodman.h5", out / "pile_wished_in_place.h5",
                         out / "embankment_stages.h5", out / "s2_goodman_gauss.h5",
                         out / "pile_wished_in_place_gauss.h5",
                         out / "excavation_cantilever_plate.h5")
        if bad:
            print(bad)
            return 1
        print("phases_report: doc/validation.md is up to date")
        return 0
    update(DOC, SCRIPT, b, False)
    print("\n\n".join(b.values()))
    if a.figures:
        with Results(exc) as r:
            plot_phases.draw(r, ROOT / "doc" / "img" / "excavation_phases.png", component="xx",
                             window=(-6.0, 7.0, -11.0, 1.0))
        excavation_report.plot(exc, ROOT / "doc" / "img" / "excavation_moments.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
