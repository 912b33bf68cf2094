#!/usr/bin/env python3
"""Benchmark of deck reading: the same elastic Q4 square read from a keyword deck (*NODES,
*ELEMENTS, *NSET, *EDGES) and from a Gmsh file through *MESH (make bench).

pecplas-bench-deck N writes both decks (17-digit coordinates, the same node ids and sets),
reads each one in the same process, checks that both give the same mesh, and prints the two
read times. At the largest size the keyword deck is also run through the whole program
(elastic, one increment) to give the share of its reading in the run. Each case is run
REPEATS times (median, with the 1-minute load average when the case started: timings on a
loaded machine are not headline figures); the whole run once.

Writes doc/bench/deck.csv and the fragment doc/bench/deck.md.

    python3 -m pecplas_py.bench.deck [--quick]
"""
import argparse
import statistics
import tempfile

from pecplas_py.bench.common import (BENCH_DIR, executable, load1, run_timed, write_csv,
                                     write_fragment)

REPEATS = 3
COLUMNS = ["n", "equations", "keyword_read_s", "mesh_read_s", "ratio", "elastic_run_s",
           "keyword_share_pct", "repeats", "load1"]


def run_case(exe, args):
    r = run_timed([exe, *args])
    f = r["stdout"].split()
    if r["rc"] != 0 or len(f) < 4:
        raise RuntimeError(f"pecplas-bench-deck {args} failed:\n{r['stdout']}{r['stderr']}")
    return [float(x) for x in f]


def case(exe, n, tmp, run):
    """Medians over REPEATS reads of (equations, keyword read, *MESH read, ratio); with
    `run`, one whole elastic run of the keyword deck and the share of the median read in
    it."""
    load = load1()
    runs = [run_case(exe, [n, tmp]) for _ in range(REPEATS)]
    med = [statistics.median(r[k] for r in runs) for k in range(4)]
    total = share = float("nan")
    if run:
        total = run_case(exe, [n, tmp, "--run"])[4]
        share = 100.0 * med[1] / total
    return [n, int(med[0]), med[1], med[2], med[3], total, share, len(runs), load]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="skip the 1e6-equation case")
    a = ap.parse_args()
    exe = executable("pecplas-bench-deck")
    sizes = [100, 300] if a.quick else [100, 223, 300, 707]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            rows.append(case(exe, n, tmp, run=n == sizes[-1]))
            print(" ".join(str(x) for x in rows[-1]), flush=True)
    write_csv(BENCH_DIR / "deck.csv", COLUMNS, rows)
    md = ["## Deck reading: keyword mesh against *MESH", "",
          "The same elastic Q4 square (17-digit coordinates) read from a keyword deck "
          "(`*NODES`, `*ELEMENTS`, `*NSET`, `*EDGES`) and from a Gmsh file through `*MESH`, "
          "in one process (`pecplas-bench-deck`), median of " + str(REPEATS) + " runs; "
          "wall seconds; load = 1-minute load average when the case started. The share is "
          "the keyword read in one whole elastic run of the keyword deck (largest size). "
          "Both reads build the same mesh, node and element id lookups and the deck line of "
          "every node; the keyword read does a little more: it checks every element for a "
          "repeated node and a zero area at its deck line (the *MESH route leaves this to "
          "the element check before the run) and keeps the line of every element.", "",
          "| equations | load | keyword read | *MESH read | ratio | elastic run | share |",
          "|---|---|---|---|---|---|---|"]
    for r in rows:
        d = dict(zip(COLUMNS, r))
        run = "" if d["elastic_run_s"] != d["elastic_run_s"] else f"{d['elastic_run_s']:.2f}"
        share = ("" if d["keyword_share_pct"] != d["keyword_share_pct"]
                 else f"{d['keyword_share_pct']:.1f} %")
        md.append(f"| {d['equations']} | {d['load1']:.1f} | {d['keyword_read_s']:.3f} | "
                  f"{d['mesh_read_s']:.3f} | {d['ratio']:.2f} | {run} | {share} |")
    write_fragment("deck", "\n".join(md))


if __name__ == "__main__":
    main()
