#!/usr/bin/env python3
"""Benchmark of the program's own overhead and of the interface-law speed (make bench).

1. pecplas-bench-laws: MODJOIN updates per second (one law call incl. tangent) and the wall
   time of an 8000-step CNL path, single core.
2. pecplas-bench: elastic plane-strain squares (Q4, Q8) at about 1e4, 1e5 (and 1e6 in full
   mode) equations, one process per case: phase times of the whole program; then
   pecplas-bench-bare, in a process of its own, a bare CHOLMOD analyse + factorise + solve
   of the SAME matrix (written by the run to an HDF5 file, read untimed); the ratio
   total / bare is the price of everything that is not the sparse factorisation. Both run
   under the same thread setting (OMP_NUM_THREADS, each part's threads as the program's rule
   gives them, see doc/deck.md *SOLVER THREADS=), 1 and 2 threads; each case is run REPEATS times and reported
   as median and spread (min-max), with the 1-minute load average at the start of each case:
   a rerun on a quiet machine should land within the spread.

Writes doc/bench/solver.csv, doc/bench/laws.csv and the fragments solver.md, laws.md.

    python3 -m pecplas_py.bench.solver [--quick]
"""
import argparse
import os
import re
import statistics
import tempfile

from pecplas_py.bench.common import (BENCH_DIR, executable, fresh_memory_gbs, load1, run_timed,
                                     write_csv, write_fragment)

COLUMNS = ["element", "n", "equations", "read_setup_s", "assembly_s", "factorisation_s",
           "solve_s", "residual_s", "output_s", "total_s", "bare_cholmod_s", "ratio",
           "peak_mb", "nnz_L", "run_user_s", "run_sys_s", "bare_user_s", "bare_sys_s"]
# per row: thread setting, repeats, load average and the spread of the timed columns
EXTRA = ["threads", "repeats", "load1", "total_min_s", "total_max_s", "bare_min_s",
         "bare_max_s", "ratio_min", "ratio_max", "run_user_min_s", "run_user_max_s",
         "run_sys_min_s", "run_sys_max_s", "bare_sys_min_s", "bare_sys_max_s", "fresh_gbs"]
SPREAD = ("total_s", "bare_cholmod_s", "ratio", "run_user_s", "run_sys_s", "bare_sys_s")
REPEATS = 3
THREADS = (1, 2)


def median_row(runs, threads, load, fresh):
    """Median of each timed column over the repeated runs, with the spread of total, bare
    and ratio; load and fresh (fresh_memory_gbs) describe the machine when the case started."""
    row = list(runs[0][:3])
    for k in range(3, len(COLUMNS)):
        row.append(statistics.median(r[k] for r in runs))
    col = {c: [r[i] for r in runs] for i, c in enumerate(COLUMNS)}
    return (row + [threads, len(runs), load] + [f(col[c]) for c in SPREAD for f in (min, max)]
            + [fresh])


def laws():
    """MODJOIN law speed: pecplas-bench-laws run REPEATS times; per version the median of
    each column with the spread (min-max) and the load average before the runs."""
    load = load1()
    runs = {}
    for _ in range(REPEATS):
        r = run_timed([executable("pecplas-bench-laws")])
        for line in r["stdout"].splitlines():
            m = re.match(r"\s*(MODJOIN\w*)\s+([-+.\dEe]+)\s+([-+.\dEe]+)\s+([-+.\dEe]+)\s",
                         line)
            if m:
                runs.setdefault(m.group(1), []).append([float(m.group(k)) for k in (2, 3, 4)])
    rows = []
    for v, rs in runs.items():
        cols = list(zip(*rs))
        rows.append([v] + [statistics.median(c) for c in cols]
                    + [min(cols[0]), max(cols[0]), len(rs), load])
    write_csv(BENCH_DIR / "laws.csv", ["version", "updates_per_s_0.001mm",
                                       "updates_per_s_0.1mm", "cnl_8000_steps_s",
                                       "updates_per_s_0.001mm_min",
                                       "updates_per_s_0.001mm_max", "repeats", "load1"], rows)
    md = ["## Interface-law speed (MODJOIN, single core)", "",
          "One update = one law call including the consistent tangent, on a CNL path "
          "(substeps of at most 0.001 mm, so a 0.1 mm increment costs ~100 substeps). "
          f"Median of {REPEATS} runs of `pecplas-bench-laws`, spread [min - max]; one thread; "
          f"load average {load:.2f} before the runs (on {os.cpu_count()} cores; above the "
          "core count the rates are not final).", "",
          "| version | updates/s (0.001 mm) | updates/s (0.1 mm) | 8000-step CNL path [s] |",
          "|---|---|---|---|"]
    md += [f"| {v} | {a:.3g} [{lo:.3g} - {hi:.3g}] | {b:.3g} | {c:.4f} |"
           for v, a, b, c, lo, hi, _, _ in rows]
    write_fragment("laws", "\n".join(md))
    return rows


def checked_fields(r, what, count):
    """The fields of the one output line of a benchmark program; an error if it failed."""
    f = r["stdout"].split()
    if r["rc"] != 0 or len(f) < count:
        raise RuntimeError(f"{what} failed:\n{r['stdout']}{r['stderr']}")
    return f


def one_case(exe, bare, el, n, tmp):
    """One run of pecplas-bench and then, in a process of its own, the bare CHOLMOD solve
    of the matrix it assembled (after its results file is written back to the disk, so
    that the kernel's write-back does not slow the bare down): a row in COLUMNS order."""
    f = checked_fields(run_timed([exe, el, n, tmp]), f"pecplas-bench {el} {n}", 13)
    os.sync()
    g = checked_fields(run_timed([bare, os.path.join(tmp, f"square_{el}_{n}.matrix.h5")]),
                       f"pecplas-bench-bare {el} {n}", 7)
    run = dict(zip(["read_setup_s", "assembly_s", "factorisation_s", "solve_s", "residual_s",
                    "output_s", "total_s", "peak_mb", "run_user_s", "run_sys_s"],
                   map(float, f[3:13])))
    run.update(bare_cholmod_s=float(g[3]), nnz_L=float(g[4]), bare_user_s=float(g[5]),
               bare_sys_s=float(g[6]))
    run["ratio"] = run["total_s"] / run["bare_cholmod_s"]
    return [f[0], int(f[1]), int(f[2])] + [run[c] for c in COLUMNS[3:]]


def solver(quick, threads_list=THREADS):
    exe = executable("pecplas-bench")
    bare = executable("pecplas-bench-bare")
    cases = [("Q4", 70), ("Q8", 41), ("Q4", 223), ("Q8", 129)]
    if not quick:
        cases += [("Q4", 707), ("Q8", 408)]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for threads in threads_list:
            os.environ["OMP_NUM_THREADS"] = str(threads)
            for el, n in cases:
                load, fresh = load1(), fresh_memory_gbs()
                runs = []
                for _ in range(REPEATS):
                    runs.append(one_case(exe, bare, el, n, tmp))
                rows.append(median_row(runs, threads, load, fresh))
                print(" ".join(str(x) for x in rows[-1]), flush=True)
    write_csv(BENCH_DIR / "solver.csv", COLUMNS + EXTRA, rows)
    write_fragment("solver", solver_fragment(rows))
    return rows


def overhead_lines(rows):
    """Where total - bare goes for the 1e6 rows (median run's phases): the program's own
    phases, and the difference of its factorisation + solve from the bare ones."""
    md = []
    for r in rows:
        d = dict(zip(COLUMNS + EXTRA, r))
        if d["equations"] <= 5e5:
            continue
        own = {"read+setup": d["read_setup_s"], "assembly": d["assembly_s"],
               "residual": d["residual_s"], "output": d["output_s"]}
        solver = d["factorisation_s"] + d["solve_s"] - d["bare_cholmod_s"]
        rest = d["total_s"] - sum(own.values()) - d["factorisation_s"] - d["solve_s"]
        parts = ", ".join(f"{k} {v:.2f}" for k, v in own.items())
        md.append(f"- {d['element']} at 1e6, {int(d['threads'])} thread(s): total - bare = "
                  f"{d['total_s'] - d['bare_cholmod_s']:.2f} s = {parts}, the rest (results-file "
                  f"creation and finish, checks) {rest:.2f}, the run's analysis + factorisation + solve "
                  f"against the bare's {solver:+.2f} (medians of each column, so the parts "
                  "need not add up exactly).")
    if md:
        md.insert(0, "")
        md.insert(1, "Where the difference goes (s):")
    return md


def split_text(d):
    """For a 1-thread row: total - bare split into the program's own computing (user time),
    the kernel's work (system time) and the time on no CPU, each as the run's minus the
    bare's (medians), and the user-time ratio; empty with more threads, where CPU time is
    not a part of the wall time."""
    if d["threads"] != 1:
        return ""
    user = d["run_user_s"] - d["bare_user_s"]
    system = d["run_sys_s"] - d["bare_sys_s"]
    idle = (d["total_s"] - d["run_user_s"] - d["run_sys_s"]) - \
        (d["bare_cholmod_s"] - d["bare_user_s"] - d["bare_sys_s"])
    return (f"; total - bare {d['total_s'] - d['bare_cholmod_s']:.2f} s = user {user:+.2f}, "
            f"system {system:+.2f}, on no CPU {idle:+.2f}; user time run / bare "
            f"{d['run_user_s'] / d['bare_user_s']:.2f}")


def cpu_lines(rows):
    """User and system CPU times of the 1e6 rows (median [min-max]): the system time is the
    kernel's work for the process (page faults on fresh memory, file writes), and for the
    1-thread rows where total - bare goes (split_text). Rows of CSVs written before these
    columns (nan) are left out."""
    md = []
    steady = True
    for r in rows:
        d = dict(zip(COLUMNS + EXTRA, r))
        if d["equations"] <= 5e5 or not d["run_sys_s"] == d["run_sys_s"]:
            continue
        md.append(f"- {d['element']} at 1e6, {int(d['threads'])} thread(s): the run "
                  f"user {d['run_user_s']:.2f} [{d['run_user_min_s']:.2f}-"
                  f"{d['run_user_max_s']:.2f}], system {d['run_sys_s']:.2f} "
                  f"[{d['run_sys_min_s']:.2f}-{d['run_sys_max_s']:.2f}]; the bare user "
                  f"{d['bare_user_s']:.2f}, system {d['bare_sys_s']:.2f} "
                  f"[{d['bare_sys_min_s']:.2f}-{d['bare_sys_max_s']:.2f}]"
                  + split_text(d) + ".")
        steady = steady and (d["run_user_max_s"] - d["run_user_min_s"]
                             < d["run_sys_max_s"] - d["run_sys_min_s"])
    if md:
        md[:0] = ["", "CPU time of the run and of the bare solve (s, median [min-max]; system "
                  "time = the kernel's work for the process: page faults on fresh memory, "
                  "file writes):"]
        if steady:
            md.append("In every 1e6 row the run's user time varies less than its system "
                      "time: the run-to-run spread comes from the kernel's handling of "
                      "memory and files on this machine more than from the program's own "
                      "work.")
    return md


def solver_fragment(rows):
    md = ["## Program overhead against a bare CHOLMOD solve", "",
          "Elastic plane-strain squares, one process per case. `total` is the whole program "
          "(read + setup, assembly incl. the CSC pattern, factorisation incl. analysis, solve, "
          "residual, HDF5 output); `bare` is CHOLMOD analyse + factorise + solve of the same "
          "matrix (same ordering rule) in a process of its own, `pecplas-bench-bare`, which "
          "reads the matrix the run assembled from a file (not timed), after the run's "
          "results file is written back to the disk (sync), under the same thread setting "
          "(OMP_NUM_THREADS = "
          "threads). Times in seconds (wall), median of " + str(REPEATS) + " runs, spread "
          "min-max; load = 1-minute load average when the case started; fresh = how fast "
          "the kernel handed out fresh memory when the case started (GB/s, a 256 MB block "
          "filled for the first time, median of 3: every first touch of a page costs a page "
          "fault; a run pays about 1/fresh seconds per GB it touches first, the bare "
          "likewise).", "",
          "| element | equations | threads | load | fresh GB/s | read+setup | assembly "
          "| factorisation | solve | output | total [min-max] | bare CHOLMOD [min-max] "
          "| ratio [min-max] | peak MB |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        d = dict(zip(COLUMNS + EXTRA, r))
        fresh = f"{d['fresh_gbs']:.2f}" if d["fresh_gbs"] == d["fresh_gbs"] else "-"
        md.append(f"| {d['element']} | {d['equations']} | {d['threads']} | {d['load1']:.1f} | "
                  f"{fresh} | "
                  f"{d['read_setup_s']:.3f} | {d['assembly_s']:.3f} | "
                  f"{d['factorisation_s']:.3f} | {d['solve_s']:.3f} | {d['output_s']:.3f} | "
                  f"{d['total_s']:.3f} [{d['total_min_s']:.3f}-{d['total_max_s']:.3f}] | "
                  f"{d['bare_cholmod_s']:.3f} [{d['bare_min_s']:.3f}-{d['bare_max_s']:.3f}] | "
                  f"{d['ratio']:.2f} [{d['ratio_min']:.2f}-{d['ratio_max']:.2f}] | "
                  f"{d['peak_mb']:.0f} |")
    md += ["", "Both use the same CHOLMOD ordering rule (doc/theory.md §5; nnz(L) in "
           "`solver.csv`)."]
    for r in rows:
        d = dict(zip(COLUMNS + EXTRA, r))
        if d["equations"] > 5e5:
            md.append(f"- Target total / bare <= 1.2 at 1e6, {d['element']}, {d['threads']} "
                      f"thread(s): {d['ratio']:.2f} [{d['ratio_min']:.2f}-{d['ratio_max']:.2f}]"
                      f", {'met' if d['ratio'] <= 1.2 else 'not met'} on this run.")
    md += overhead_lines(rows)
    md += cpu_lines(rows)
    if any(dict(zip(COLUMNS + EXTRA, r))["threads"] > 1 for r in rows):
        md += ["", "With more than one thread the run and the bare solve give each part the "
               "threads of the program's rule (doc/deck.md, *SOLVER THREADS=: element loops n, "
               "CHOLMOD's regions as plain code, every BLAS call n threads; thread scaling on "
               "a 16-core node in threads.md)."]
    worst = max(d[EXTRA.index("load1") + len(COLUMNS)] for d in rows)
    if worst > 2:
        md += ["", f"**Not final: load average up to {worst:.1f} on {os.cpu_count()} cores** "
               "(other programs were running)."]
    return "\n".join(md)


def read_rows(path):
    """The rows of a solver.csv in COLUMNS + EXTRA order; columns that a CSV written by an
    earlier version lacks are nan."""
    import csv
    with open(path) as f:
        recs = list(csv.DictReader(f))
    rows = []
    for r in recs:
        row = [r["element"], int(r["n"]), int(r["equations"])]
        row += [float(r.get(c) or "nan") for c in (COLUMNS + EXTRA)[3:]]
        row[len(COLUMNS)] = int(row[len(COLUMNS)])  # threads
        rows.append(row)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="skip the 1e6-equation cases")
    ap.add_argument("--threads", type=int, nargs="+", default=list(THREADS),
                    help="thread settings to run (default: 1 2)")
    ap.add_argument("--no-laws", action="store_true", help="skip the interface-law part")
    ap.add_argument("--render", action="store_true",
                    help="only write the solver fragment again from doc/bench/solver.csv")
    a = ap.parse_args()
    if a.render:
        write_fragment("solver", solver_fragment(read_rows(BENCH_DIR / "solver.csv")))
        return
    if not a.no_laws:
        for v, up, up1, t, lo, hi, _, _ in laws():
            print(f"{v}: {up:.3g} [{lo:.3g} - {hi:.3g}] updates/s, 8000-step CNL {t:.4f} s",
                  flush=True)
    solver(a.quick, a.threads)


if __name__ == "__main__":
    main()
