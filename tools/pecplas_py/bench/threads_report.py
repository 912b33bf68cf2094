#!/usr/bin/env python3
"""Thread scaling on a many-core node: the log of tools/bench_threads.sh -> doc/bench/threads.csv
and doc/bench/threads.png (the page doc/bench/threads.md reads them).

    python3 -m pecplas_py.bench.threads_report [LOG [DIR]]
        (default doc/bench/threads_node16.log; DIR, default doc/bench, receives the CSV and PNG)

Log lines read (written by tools/bench_threads.sh):
  RUN TAG threads=N load=L <pecplas-bench line: element n equations setup assembly
      factorisation solve residual output total peak_mb user sys>
  S TAG <pecplas-bench-threads line (threads = the most of regions and BLAS): regions blas work factor solve user sys calls
      threaded_calls threaded_flops dev>, with '# analysis ... BLAS OpenBLAS (build)' first
  OLD|NEW bare CASE N[ passive|again]: <pecplas-bench-bare line: analyse factorise solve sum
      nnz_L user sys>
  FOOT TAG threads=N time=REAL USER SYS | summary ... | wall time [s]: ... |
  MPI TAG case=Q4|Q8|FOOT ranks=R threads=T time=REAL USER SYS | (as FOOT) |  (MUMPS, R x T)
  SKIP ... / FAIL ...: a case left out for time, or failed (counted, not tabulated)
TAG: `new` or `rule` is the program as it is; others are candidates (`amd`: PECPLAS_ORDERING=AMD,
`blas8`: PECPLAS_THREAD_PARTS=1,8,0, `mumps`: the MPI build) and label the case. A case run
several times (tools/bench_threads.sh device: 3 runs at 1 and 16 threads) is tabulated by its
median with the spread [min - max]; the table is printed as Markdown.
"""
import csv
import math
import re
import statistics
import sys
from pathlib import Path

from pecplas_py import ROOT
BENCH = ROOT / "doc" / "bench"
HEADER = ["section", "case", "threads", "regions", "blas_threads", "blas_flops_per_thread",
          "blas_build", "program", "factorisation_s", "solve_s", "assembly_s", "residual_s",
          "total_s", "user_s", "sys_s", "tag", "ranks"]
PHASES = ("read_setup", "assembly", "factorisation", "solve", "residual", "output")


BASE_TAGS = ("new", "rule")


def size_label(equations):
    """1e6 for 999 698 equations, 3e5 for 299 568."""
    e = int(math.floor(math.log10(equations) + 1e-9))
    m = round(equations / 10**e)
    if m == 10:
        m, e = 1, e + 1
    return f"{m}e{e}"


def labelled(case, tag):
    return case if tag in BASE_TAGS else f"{case}, {tag}"


def footing_case(line):
    """The footing's size from the solver line (n=...), else the 3e5 of the first node run."""
    m = re.search(r"linear solver: \S+ n=(\d+)", line)
    return "footing " + (size_label(int(m.group(1))) if m else "3e5")


def parse(text):
    rows, build, machine = [], {}, ""
    for line in text.splitlines():
        if line.startswith("=== machine:"):
            machine = re.sub(r"model name\s*:\s*", "", line[len("=== machine:"):].strip())
        m = re.match(r"RUN (\w+) threads=(\d+) load=\S+\s+(Q\d)\s+\d+\s+(\d+)\s+(.*)", line)
        if m:
            v = [float(x) for x in m.group(5).split()]
            ph = dict(zip(PHASES, v[:6]))
            case = labelled(f"{m.group(3)} {size_label(int(m.group(4)))}", m.group(1))
            rows.append(dict(section="run", case=case, threads=int(m.group(2)), tag=m.group(1),
                             program="pecplas-bench", factorisation_s=ph["factorisation"],
                             solve_s=ph["solve"], assembly_s=ph["assembly"],
                             residual_s=ph["residual"], total_s=v[6], user_s=v[8],
                             sys_s=v[9], **{f"phase_{k}": x for k, x in ph.items()}))
            continue
        m = re.match(r"S (\w+) # analysis .*BLAS \S+ \((\w+)\), OMP_NUM_THREADS (\d+)", line)
        if m:
            build[m.group(1)] = (m.group(2), int(m.group(3)))
            continue
        m = re.match(r"S (\w+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)", line)
        if m:
            tag = m.group(1)
            blas_build = build[tag][0]
            rows.append(dict(section="factorisation", case=("Q8" if "q8" in tag else "Q4") + " 1e6",
                             threads=max(int(m.group(2)), int(m.group(3))),
                             regions=int(m.group(2)), blas_threads=int(m.group(3)),
                             blas_flops_per_thread=float(m.group(4)), blas_build=blas_build,
                             program="pecplas-bench-threads",
                             factorisation_s=float(m.group(5)), solve_s=float(m.group(6)),
                             user_s=float(m.group(7)), sys_s=float(m.group(8))))
            continue
        m = re.match(r"(OLD|NEW) bare (Q\d) (\d+)( \w+)?: \s*(.*)", line)
        if m:
            v = [float(x) for x in m.group(5).split()]
            rows.append(dict(section="bare", case=f"{m.group(2)} 1e6", threads=int(m.group(3)),
                             program=("previous" if m.group(1) == "OLD" else "this") +
                             (m.group(4) or ""), factorisation_s=v[1], solve_s=v[2],
                             total_s=v[3], user_s=v[5], sys_s=v[6]))
            continue
        m = re.match(r"FOOT (\w+) threads=(\d+) time=(\S+) (\S+) (\S+) \|.*wall time \[s\]:(.*?)\|", line)
        if m:
            t = dict(re.findall(r"([a-z+]+) ([0-9.]+)", m.group(6)))
            rows.append(dict(section="run", case=labelled(footing_case(line), m.group(1)),
                             threads=int(m.group(2)), tag=m.group(1), program="pecplas", factorisation_s=float(t["factorisation"]),
                             solve_s=float(t["solve"]), assembly_s=float(t["assembly"]),
                             residual_s=float(t["residual"]), total_s=float(t["total"]),
                             user_s=float(m.group(4)), sys_s=float(m.group(5))))
            continue
        m = re.match(r"MPI (\w+) case=(\w+) ranks=(\d+) threads=(\d+) time=(\S+) (\S+) (\S+) \|"
                     r".*wall time \[s\]:(.*?)\|", line)
        if m:
            t = dict(re.findall(r"([a-z+]+) ([0-9.]+)", m.group(8)))
            r, n = int(m.group(3)), int(m.group(4))
            size = re.search(r"linear solver: \S+ n=(\d+)", line)
            case = (footing_case(line) if m.group(2) == "FOOT" else
                    f"{m.group(2)} {size_label(int(size.group(1))) if size else '1e6'}")
            rows.append(dict(section="run", case=f"{case}, {m.group(1)} {r}x{n}",
                             threads=r * n, ranks=r, tag=m.group(1), program="pecplas (MPI)",
                             factorisation_s=float(t["factorisation"]),
                             solve_s=float(t["solve"]), assembly_s=float(t["assembly"]),
                             residual_s=float(t["residual"]), total_s=float(t["total"]),
                             user_s=float(m.group(6)), sys_s=float(m.group(7))))
    return rows, machine


def summary(rows):
    """Markdown table of the whole-program runs: per case and thread count the median run
    total with its spread [min - max] over the runs, the median factorisation phase, the
    speed-up of the median total against the case's own median on 1 thread and against the
    program as it is (no candidate) on 1 thread on the same mesh."""
    groups = {}
    for r in rows:
        if r["section"] == "run":
            groups.setdefault((r["case"], r["threads"]), []).append(r)
    med = {k: statistics.median(x["total_s"] for x in v) for k, v in groups.items()}
    lines = ["| case | threads | runs | total [s], median [min - max] | factorisation [s] | "
             "speed-up | against the program on 1 thread | user / system [s] |",
             "|---|---|---|---|---|---|---|---|"]
    for (case, n), v in sorted(groups.items(), key=lambda kv: (kv[0][0], kv[0][1])):
        t = [x["total_s"] for x in v]
        own, base = med.get((case, 1)), med.get((case.split(",")[0], 1))
        speed = f"{own / med[(case, n)]:.2f}" if own else "-"
        against = f"{base / med[(case, n)]:.2f}" if base else "-"
        spread = f" [{min(t):.2f} - {max(t):.2f}]" if len(t) > 1 else ""
        lines.append(
            f"| {case} | {n} | {len(t)} | {med[(case, n)]:.2f}{spread} | "
            f"{statistics.median(x['factorisation_s'] for x in v):.2f} | {speed} | {against} | "
            f"{statistics.median(x['user_s'] for x in v):.1f} / "
            f"{statistics.median(x['sys_s'] for x in v):.1f} |")
    return "\n".join(lines)


def medians(runs):
    """One row per thread count: the median total and factorisation of its runs."""
    out = []
    for n in sorted({x["threads"] for x in runs}):
        v = [x for x in runs if x["threads"] == n]
        out.append(dict(threads=n, total_s=statistics.median(x["total_s"] for x in v),
                        factorisation_s=statistics.median(x["factorisation_s"] for x in v)))
    return out


def plot(rows, machine, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.4))
    cases = sorted({x["case"] for x in rows if x["section"] == "run"},
                   key=lambda c: ("," in c, c))
    for case, marker in zip(cases, ("o-", "s-", "^-", "v-", "D-", "x-", "+-", "*-") * 4):
        r = medians([x for x in rows if x["section"] == "run" and x["case"] == case])
        if not r:
            continue
        own = next((x["total_s"] for x in r if x["threads"] == 1), None)
        base = medians([x for x in rows if x["section"] == "run"
                        and x["case"] == case.split(",")[0]])
        t1 = own or next((x["total_s"] for x in base if x["threads"] == 1), None)
        if not t1:
            continue
        ax1.plot([x["threads"] for x in r], [t1 / x["total_s"] for x in r], marker,
                 label=f"{case}: whole run" + (f" ({t1:.1f} s on 1 thread)" if own else
                                               " (against the program on 1 thread)"))
        if "," not in case and own:
            f1 = next(x["factorisation_s"] for x in r if x["threads"] == 1)
            ax1.plot([x["threads"] for x in r], [f1 / x["factorisation_s"] for x in r],
                     marker.replace("-", ":"), alpha=0.6, label=f"{case}: factorisation phase")
    ax1.plot([1, 16], [1, 16], "k--", lw=0.8, label="ideal")
    ax1.axhline(1.0, color="r", lw=0.8)
    ax1.set_xscale("log", base=2)
    ax1.set_yscale("log", base=2)
    ax1.set_xticks([1, 2, 4, 8, 16])
    ax1.set_xticklabels(["1", "2", "4", "8", "16"])
    ax1.set_yticks([0.5, 1, 2, 4, 8, 16])
    ax1.set_yticklabels(["0.5", "1", "2", "4", "8", "16"])
    ax1.set_xlabel("threads")
    ax1.set_ylabel("speed-up against 1 thread")
    ax1.legend(fontsize=7)
    ax1.grid(True, which="both", alpha=0.3)
    ax1.set_title("the program: CHOLMOD regions 1, BLAS up to n (one per 1e6 flops of a call)",
                  fontsize=9)
    bars = []
    for x in rows:
        if x["section"] == "factorisation":
            w = x["blas_flops_per_thread"]
            lab = (f"{x['case'][:2]} R{x['regions']} B{x['blas_threads']} "
                   f"{'every call' if w == 0 else f'{w:.0e}/thr'}"
                   f"{' omp' if x['blas_build'] == 'OpenMP' else ''}")
            bars.append((lab, x["factorisation_s"]))
        elif x["section"] == "bare" and x["program"] == "previous" and x["threads"] == 16:
            bars.append((f"{x['case'][:2]} previous program", x["factorisation_s"]))
    if not bars:
        bars = [("no factorisation sweep in this log", 1.0)]
    ax2.barh(range(len(bars)), [b[1] for b in bars], color="tab:blue")
    ax2.set_yticks(range(len(bars)))
    ax2.set_yticklabels([b[0] for b in bars], fontsize=6)
    ax2.invert_yaxis()
    ax2.set_xscale("log")
    ax2.set_xlabel("one factorisation [s] (R: threads of CHOLMOD's regions, B: BLAS threads)")
    ax2.grid(True, axis="x", which="both", alpha=0.3)
    fig.suptitle(f"Threads on {machine}", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    log = Path(sys.argv[1]) if len(sys.argv) > 1 else BENCH / "threads_node16.log"
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else BENCH
    rows, machine = parse(log.read_text())
    with open(out / "threads.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(HEADER)
        for r in rows:
            w.writerow([r.get(k, "") for k in HEADER])
    plot(rows, machine, out / "threads.png")
    print(f"{len(rows)} rows -> {out / 'threads.csv'}, {out / 'threads.png'}")
    print(summary(rows))


if __name__ == "__main__":
    main()
