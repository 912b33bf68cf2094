#!/usr/bin/env python3
"""Katona contact against the Mohr–Coulomb penalty joint, by speed (part of `make bench`):
the S1 opening–closing shear box and the S2-type pile of decks/make_katona_pile.py (h = 0.2 and
0.05 m), each with Katona (Lagrange multipliers, rigid contact), and with the penalty joint
under full Newton and under modified Newton alone (`FALLBACK=NO`, the thesis's method). The
decks differ only by the law TYPE and the *SOLVER line. A run longer than --limit seconds is
stopped there and reported as stopped, with the increments it had converged. Then the
saddle-factor comparison of `pecplas-bench-katona` on the pile and finer Hertz meshes.

Every wall time is measured here (median of --repeats runs when a run takes less than 5 s),
beside the 1-minute load average when the case started: on a machine shared with other work
(load above the core count) the times are longer than on an idle one, the ratios less so.
Writes doc/bench/katona.csv and the fragment doc/bench/katona.md (bench/summary.py puts
it into doc/bench/README.md).

    python3 -m pecplas_py.bench.katona [--limit 120] [--repeats 3] [--quick] [--out DIR]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import tempfile
from pathlib import Path

from pecplas_py import script_cmd
from pecplas_py.bench.common import (BENCH_DIR, ROOT, executable, run_timed,
                                     write_csv, write_fragment, load1)

HEADER = ["case", "law", "method", "equations", "status", "increments", "requested",
          "iterations", "factorisations", "state_iterations", "state_max", "wall_s",
          "repeats", "load1"]
S1_PENALTY = {"1e8": ROOT / "input/s1/s1_open_close_kn1e8.inp",
              "1e5": ROOT / "input/s1/s1_open_close_kn1e5.inp"}
S1_KATONA = ROOT / "test/data/katona/s1_open_close.inp"
SOLVER = {"katona": None, "newton": "METHOD=NEWTON",
          "modified": "METHOD=MODIFIED_NEWTON, FALLBACK=NO"}
#: the values of pecplas-bench-katona (seconds; n equations, m doublet rows)
SADDLE = ["n", "m", "fact", "solve", "g", "column", "an", "fa", "load1", "error"]
LABEL = {"katona": "Katona", "newton": "Mohr–Coulomb penalty, full Newton",
         "modified": "Mohr–Coulomb penalty, modified Newton alone"}


def set_solver(text, method):
    """The deck with its *SOLVER line's method replaced (other options kept)."""
    if SOLVER[method] is None:
        return text

    def repl(m):
        opts = [o for o in m.group(1).split(",") if o.strip() and
                not re.match(r"\s*(METHOD|FALLBACK)\s*=", o, re.I)]
        return "*SOLVER, " + SOLVER[method] + "".join("," + o for o in opts)
    return re.sub(r"^\*SOLVER(.*)$", repl, text, count=1, flags=re.M)


def pile_deck(tmp, h, law, method):
    path = tmp / f"pile_{h:g}_{law.lower()}_{method}.inp"
    subprocess.run([*script_cmd("decks.make_katona_pile"), "--h", str(h),
                    "--law", law, "--method",
                    "NEWTON" if method == "newton" else "MODIFIED_NEWTON", "--out", str(path)],
                   check=True, capture_output=True)
    text = path.read_text()
    if method == "modified":
        text = text.replace("METHOD=MODIFIED_NEWTON", "METHOD=MODIFIED_NEWTON, FALLBACK=NO")
    path.write_text(text)
    return path


def s1_deck(tmp, kn, method):
    src = S1_KATONA if method == "katona" else S1_PENALTY[kn]
    path = tmp / f"s1_{method}_{kn}.inp"
    path.write_text(set_solver(src.read_text(), method))
    return path


def parse(stdout):
    """Counts of the program's summary; for a run stopped early, the converged increments
    and their iterations from its progress lines."""
    def grab(pattern, default=None):
        m = re.search(pattern, stdout)
        return int(m.group(1)) if m else default
    steps = re.findall(r"^ step\s+\d+.*?\biter\s+(\d+)", stdout, re.M)
    m = re.search(r"summary: (\d+) increments, (\d+) iterations, \d+ cuts, (\d+) factorisations",
                  stdout)
    st = re.search(r"(\d+) state iterations \(max (\d+)", stdout)
    status = re.search(r"status: (\w+)", stdout)
    return {"equations": grab(r"equations (\d+)"),
            "status": status.group(1) if status else "stopped",
            "increments": int(m.group(1)) if m else len(steps),
            "iterations": int(m.group(2)) if m else sum(int(s) for s in steps),
            "factorisations": int(m.group(3)) if m else None,
            "state_iterations": int(st.group(1)) if st else None,
            "state_max": int(st.group(2)) if st else None}


def requested(deck):
    return sum(int(n) for n in re.findall(r"\*STEP[^\n]*INCREMENTS=(\d+)", deck.read_text()))


def run_case(exe, case, law, method, deck, limit, repeats):
    """One row: the run (repeated while it takes under 5 s), its counts, the median wall."""
    load = load1()
    walls, r = [], None
    for _ in range(repeats):
        r = run_timed([exe, deck, "-o", deck.with_suffix(".h5")], timeout=limit)
        walls.append(r["wall"])
        if r["rc"] is None or r["wall"] > 5.0:
            break
    c = parse(r["stdout"])
    if r["rc"] is None:
        c["status"] = f"stopped at the {limit:g} s limit"
    row = [case, law, method, c["equations"], c["status"], c["increments"], requested(deck),
           c["iterations"], c["factorisations"], c["state_iterations"], c["state_max"],
           f"{statistics.median(walls):.3f}", len(walls), f"{load:.1f}"]
    print("bench_katona:", " | ".join(str(x) for x in row), flush=True)
    return row


def saddle(exe_bench, deck):
    """Timings of pecplas-bench-katona on a deck (dict of floats; empty on failure)."""
    r = run_timed([exe_bench, deck], timeout=600)
    out = r["stdout"]
    keys = {"fact": r"CHOLMOD factorise R\s+([\d.]+)", "solve": r"CHOLMOD.*?  solve\s+([\d.]+)",
            "g": r"flexibility G \(2nd solves\)\s+([\d.]+)", "column": r"per column\s+([\d.]+)",
            "an": r"UMFPACK saddle: analyse\s+([\d.]+)", "fa": r"saddle:.*?factorise\s+([\d.]+)",
            "m": r"doublet rows 2nd (\d+)", "n": r"equations (\d+)"}
    v = {}
    for k, p in keys.items():
        m = re.search(p, out)
        if m:
            v[k] = float(m.group(1))
    v["load1"] = load1()
    note = re.search(r"^ UMFPACK: (.*)$", out, re.M)
    if note:
        v["error"] = note.group(1)[:300]
    elif "fa" not in v:
        v["error"] = (out + r["stderr"]).strip().splitlines()[0][:300] if (out + r["stderr"]).strip() \
            else f"exit {r['rc']}"
    return v


def fmt_time(row):
    wall = float(row[11])
    return f"{wall:.3g}" if wall < 100 else f"{wall:.0f}"


def fragment(rows, sad, prov, limit):
    loads = [float(r[13]) for r in rows]
    cores = os.cpu_count() or 1
    busy = max(loads) > cores
    md = ["## Katona contact: speed against the penalty joint", "",
          f"`tools/pecplas_py/bench/katona.py` (commit `{prov['commit']}`, {prov['date']}): S1 "
          "opening–closing (decks of `input/s1/`, Katona: `test/data/katona/s1_open_close.inp`) "
          "and the pile of `tools/pecplas_py/decks/make_katona_pile.py` (load 2000 kN in 20 "
          "increments, unload in "
          "20), the law TYPE and the *SOLVER method being the only differences. Wall seconds of "
          "the whole run (median of the repeats), release build; load = 1-minute load average "
          f"when the case started, on {cores} cores"
          + (f" — **the machine was shared with other work (load up to {max(loads):.1f}): the "
             "times are longer than on an idle machine, the ratios between rows less "
             "affected**" if busy else "") + ". "
          f"Runs longer than {limit:g} s are stopped there. Increments: converged (an "
          "increment cut in two counts as two), of those requested; iterations of a stopped "
          "run: those of its converged increments, a lower bound.", "",
          "| case | law, method | equations | status | increments (requested) | iterations | "
          "factorisations | state iterations (max / increment) | wall [s] | load |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        states = f"{r[9]} ({r[10]})" if r[9] is not None else "—"
        fac = r[8] if r[8] is not None else "—"
        iters = r[7] if r[4] == "completed" or "limit" not in r[4] else f"> {r[7]}"
        md.append(f"| {r[0]} | {LABEL[r[2]]} | {r[3]} | {r[4]} | {r[5]} ({r[6]}) | {iters} | "
                  f"{fac} | {states} | {fmt_time(r)} | {r[13]} |")
    by = {(r[0], r[2]): r for r in rows}
    ratios = []
    for case in sorted({r[0] for r in rows}):
        k, n = by.get((case, "katona")), by.get((case, "newton"))
        if k and n and k[4] == "completed" and n[4] == "completed":
            ratios.append(f"{case}: {float(k[11]) / float(n[11]):.3f}")
    md += ["", "Katona / penalty with full Newton (wall time, completed runs; target: at most "
           "1.5): " + "; ".join(ratios) + "." if ratios else ""]
    if sad:
        md += ["", "Saddle-factor comparison (`pecplas-bench-katona DECK`, seconds): CHOLMOD "
               "factorisation of R and one solve, the flexibility G = D R⁻¹ Dᵀ (one column per "
               "doublet row), against the UMFPACK analysis and factorisation of the full saddle "
               "matrix, which a sparse saddle solver would redo at every state iteration:", "",
               "| mesh | equations | doublet rows | factorise R | solve | G (per column) | "
               "saddle analyse + factorise | load |", "|---|---|---|---|---|---|---|---|"]
        for name, v in sad.items():
            if "fa" not in v:
                md.append(f"| {name} | — | — | — | — | — | failed: "
                          f"{v.get('error', '').replace('|', '/')} | {v['load1']:.1f} |")
                continue
            md.append(f"| {name} | {v['n']:.0f} | {v['m']:.0f} | {v['fact']:.3f} | "
                      f"{v['solve']:.4f} | {v['g']:.2f} ({1e3 * v['column']:.2f} ms) | "
                      f"{v['an']:.3f} + {v['fa']:.3f}"
                      + (f" ({v['error'].replace('|', '/')})" if v.get("error") else "")
                      + f" | {v['load1']:.1f} |")
        even = [f"{name}: 2 n_d up to {v['fa'] / v['column']:.0f} n_s" for name, v in sad.items()
                if v.get("column")]
        if even:
            md += ["", "The bordered path is the cheaper while 2 n_d · t_column < n_s · t_saddle "
                   "(n_d doublets, n_s state iterations per factorisation of R, t_saddle the "
                   "saddle factorisation): " + "; ".join(even) + "."]
    return "\n".join(md) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--limit", type=float, default=120.0, help="time limit of one run [s]")
    ap.add_argument("--repeats", type=int, default=3, help="repeats of runs under 5 s")
    ap.add_argument("--quick", action="store_true", help="S1 and the h = 0.2 pile only, "
                    "full Newton and Katona, limit 60 s")
    ap.add_argument("--out", default=str(BENCH_DIR), help="directory of katona.csv / .md")
    ap.add_argument("--render", action="store_true",
                    help="only rewrite the fragment from the CSV files of --out")
    a = ap.parse_args(argv)
    if a.render:
        render(Path(a.out), a.limit)
        return
    if a.quick:
        a.limit = min(a.limit, 60.0)
    # progress lines reach the captured output as they are printed (a stopped run's count)
    os.environ["GFORTRAN_UNBUFFERED_PRECONNECTED"] = "y"
    rows, sad = [], {}
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        # private copies: a build during the runs (fpm relinks) must not replace them
        exe = shutil.copy2(executable("pecplas"), tmp / "pecplas")
        s1 = [("S1 opening–closing", "katona", "katona", "1e8"),
              ("S1 opening–closing, K_n = 1e8", "MOHR_COULOMB", "newton", "1e8")]
        if not a.quick:
            s1 += [("S1 opening–closing, K_n = 1e8", "MOHR_COULOMB", "modified", "1e8"),
                   ("S1 opening–closing, K_n = 1e5", "MOHR_COULOMB", "modified", "1e5")]
        for case, law, method, kn in s1:
            rows.append(run_case(exe, case, law, method, s1_deck(tmp, kn, method), a.limit,
                                 a.repeats))
        for h in ((0.2,) if a.quick else (0.2, 0.05)):
            for method in (("katona", "newton") if a.quick else ("katona", "newton",
                                                                 "modified")):
                law = "KATONA" if method == "katona" else "MOHR_COULOMB"
                rows.append(run_case(exe, f"pile h = {h:g} m", law, method,
                                     pile_deck(tmp, h, law, method), a.limit, a.repeats))
        if not a.quick:
            bench = shutil.copy2(executable("pecplas-bench-katona"), tmp / "bench-katona")
            sad["pile h = 0.05 m"] = saddle(bench, pile_deck(tmp, 0.05, "KATONA", "katona"))
            hertz = tmp / "hertz_h005.inp"
            subprocess.run([*script_cmd("decks.make_hertz_deck"), "--h", "0.05",
                            "--out", str(hertz)], check=True, capture_output=True)
            sad["Hertz h = 0.05 mm"] = saddle(bench, hertz)
    out = Path(a.out)
    write_csv(out / "katona.csv", HEADER, rows)
    write_csv(out / "katona_saddle.csv", ["mesh"] + SADDLE,
              [[name] + [v.get(k, "") for k in SADDLE] for name, v in sad.items()])
    render(out, a.limit)


def render(out, limit):
    """The fragment from katona.csv and katona_saddle.csv of `out` (no run)."""
    import csv
    with open(out / "katona.csv") as f:
        recs = list(csv.reader(f))[1:]
    rows = [[None if x == "" else x for x in r[:len(HEADER)]] for r in recs]
    for r in rows:
        for i in (5, 6, 7, 8, 9, 10, 12):
            r[i] = int(r[i]) if r[i] is not None else None
    prov = {"commit": recs[0][len(HEADER)], "date": recs[0][len(HEADER) + 2]}
    sad = {}
    if (out / "katona_saddle.csv").exists():
        with open(out / "katona_saddle.csv") as f:
            for r in list(csv.reader(f))[1:]:
                sad[r[0]] = {k: (x if k == "error" else float(x))
                             for k, x in zip(SADDLE, r[1:]) if x != ""}
    text = fragment(rows, sad, prov, limit)
    if out == BENCH_DIR:
        write_fragment("katona", text)
    else:
        (out / "katona.md").write_text(text)
    print(f"bench_katona: {out / 'katona.md'}")


if __name__ == "__main__":
    main()
