#!/usr/bin/env python3
"""Fill-reducing orderings for CHOLMOD on the elastic block (make bench).

pecplas-bench-ordering builds the elastic plane-strain square of Q4 or Q8 elements (the
squares of bench/solver.py), runs it through the program for its stiffness matrix and,
for each ordering, analyses and factorises that matrix REPEATS times in the same process:

- AMD: CHOLMOD's approximate minimum degree alone;
- DEFAULT: CHOLMOD's default strategy (AMD, then also METIS when AMD's ordering has 500 or
  more flops per entry of L and a fill ratio of 5 or more; the smaller nnz(L) is kept);
- METIS, NESDIS: CHOLMOD's METIS_NodeND call and its own nested dissection, alone;
- M-NODES: METIS_NodeND on the graph of nodes (equations with the same column pattern merged);
- RULE: what the program uses (doc/bench/ordering.md states the rule), one factorisation;
- RULE2: the same, factorising the pattern a second time (as a Newton run does): the time
  of the second factorisation, which includes the METIS ordering the rule defers to it.

nnz(L) and the flop count of the analysis do not depend on the machine's load; the times
(median [min - max] of the repeats, one thread: OMP_NUM_THREADS=1) do, and the 1-minute load
average is recorded with each case.

Writes doc/bench/ordering.csv and the fragment doc/bench/ordering.md.

    python3 -m pecplas_py.bench.ordering [--quick] [--repeat 3] [--render]
"""
import argparse
import csv
import os
import tempfile

from pecplas_py.bench.common import (BENCH_DIR, executable, load1, run_timed, write_csv,
                                     write_fragment)

COLUMNS = ["element", "n", "equations", "ordering", "used", "nnz_L", "flops",
           "analyse_s", "analyse_min_s", "analyse_max_s", "factorise_s", "factorise_min_s",
           "factorise_max_s", "solution_rel_diff", "repeats", "load1"]
SMALL = [("Q4", 70), ("Q8", 41), ("Q4", 223), ("Q8", 129)]
LARGE = [("Q4", 707), ("Q8", 408)]
# at 1e6 each ordering costs minutes of repeats: AMD, CHOLMOD's default (AMD then METIS on
# the equation graph) and the rule (AMD then METIS on the graph of nodes) only
LARGE_ORDERINGS = "AMD,DEFAULT,RULE,RULE2"


def measure(exe, cases, orderings, repeats, tmp):
    rows = []
    for el, n in cases:
        load = load1()
        cmd = [exe, el, n, tmp, repeats] + ([orderings] if orderings else [])
        r = run_timed(cmd)
        if r["rc"] != 0:
            raise RuntimeError(f"pecplas-bench-ordering {el} {n} failed:\n{r['stdout']}"
                               f"{r['stderr']}")
        load = max(load, load1())
        for line in r["stdout"].splitlines():
            f = line.split()
            if len(f) < 14 or f[0] not in ("Q4", "Q8"):
                continue
            rows.append([f[0], int(f[1]), int(f[2]), f[3], f[4]] +
                        [float(x) for x in f[5:14]] + [repeats, load])
            print(" ".join(str(x) for x in rows[-1]), flush=True)
    return rows


def fragment(rows, repeats):
    md = ["## CHOLMOD fill-reducing ordering (`tools/pecplas_py/bench/ordering.py`)", "",
          "The elastic plane-strain squares of the overhead benchmark; for each ordering, "
          "nnz(L) and the flop count of CHOLMOD's analysis (independent of the machine's "
          "load) and the analysis (ordering + symbolic) and numeric factorisation times, "
          f"median [min - max] of {repeats} runs, one thread; load = 1-minute load average "
          "(larger of start and end of the case). Flops relative to AMD on the same matrix. "
          "`rel. diff` = largest difference of the solution of K x = 1 from AMD's, over "
          "max|x| (round-off). `used` is the ordering CHOLMOD reports (DEFAULT and RULE "
          "pick one of the others).", "",
          "| element | equations | ordering | used | nnz(L) | flops | flops / AMD "
          "| analysis [s] | factorisation [s] | analysis + factorisation [s] | rel. diff "
          "| load |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    amd = {(r[0], r[2]): r[6] for r in rows if r[3] == "AMD"}
    for r in rows:
        d = dict(zip(COLUMNS, r))
        ref = amd.get((d["element"], d["equations"]))
        rel = f"{d['flops'] / ref:.3f}" if ref else ""
        md.append(f"| {d['element']} | {d['equations']} | {d['ordering']} | {d['used']} | "
                  f"{d['nnz_L']:.3e} | {d['flops']:.3e} | {rel} | "
                  f"{d['analyse_s']:.3f} [{d['analyse_min_s']:.3f} - {d['analyse_max_s']:.3f}]"
                  f" | {d['factorise_s']:.3f} [{d['factorise_min_s']:.3f} - "
                  f"{d['factorise_max_s']:.3f}] | {d['analyse_s'] + d['factorise_s']:.3f} | "
                  f"{d['solution_rel_diff']:.1e} | {d['load1']:.1f} |")
    md += ["", "Rule (doc/theory.md §5): AMD; when AMD leaves 1000 or more flops per entry of L, "
           "METIS on the graph of nodes as well, at once, the smaller flop count kept; from 500 "
           "to 1000 the same at the second factorisation of the pattern (RULE2: its "
           "factorisation time is that of the second factorisation, METIS included), so a "
           "run that factorises once does not pay for METIS. DEFAULT is what CHOLMOD does by "
           "itself."]
    by = {(r[0], r[2], r[3]): dict(zip(COLUMNS, r)) for r in rows}
    for (el, neq, o), rule in by.items():
        amd, default = by.get((el, neq, "AMD")), by.get((el, neq, "DEFAULT"))
        if o != "RULE" or not amd or not default:
            continue
        rule2 = by.get((el, neq, "RULE2"))
        t = {k: v["analyse_s"] + v["factorise_s"] for k, v in
             (("rule", rule), ("amd", amd), ("default", default))}
        md.append(f"- {el}, {neq} equations: the rule uses {rule['used']}, "
                  f"{rule['flops'] / amd['flops']:.2f} x AMD's flops "
                  f"(DEFAULT: {default['used']}, {default['flops'] / amd['flops']:.2f} x); "
                  f"analysis + one factorisation {t['rule']:.2f} s against {t['default']:.2f} s "
                  f"for DEFAULT and {t['amd']:.2f} s for AMD alone"
                  + (f"; at a second factorisation the rule uses {rule2['used']}, "
                     f"{rule2['flops'] / amd['flops']:.2f} x AMD's flops." if rule2 else "."))
    if max(r[-1] for r in rows) > 2:
        md += ["", f"**Times not final: load average up to {max(r[-1] for r in rows):.1f} on "
               f"{os.cpu_count()} cores** (other programs were running); nnz(L) and flops "
               "are."]
    return "\n".join(md)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="1e4 and 1e5 equations only")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--render", action="store_true",
                    help="only write the fragment again from doc/bench/ordering.csv")
    a = ap.parse_args()
    if a.render:
        with open(BENCH_DIR / "ordering.csv") as f:
            recs = list(csv.reader(f))[1:]
        rows = [[r[0], int(r[1]), int(r[2]), r[3], r[4]] + [float(x) for x in r[5:14]] +
                [int(r[14]), float(r[15])] for r in recs]
        write_fragment("ordering", fragment(rows, rows[0][14]))
        return
    os.environ["OMP_NUM_THREADS"] = "1"
    exe = executable("pecplas-bench-ordering")
    with tempfile.TemporaryDirectory() as tmp:
        rows = measure(exe, SMALL, None, a.repeat, tmp)
        if not a.quick:
            rows += measure(exe, LARGE, LARGE_ORDERINGS, a.repeat, tmp)
    write_csv(BENCH_DIR / "ordering.csv", COLUMNS, rows)
    write_fragment("ordering", fragment(rows, a.repeat))


if __name__ == "__main__":
    main()
