#!/usr/bin/env python3
"""Distributed solve: CHOLMOD on 1 and 2 threads against MUMPS on 1 and 2 MPI ranks.

Two problems from decks/make_default_deck.py (Q8, plane strain, half strip footing 10 m x 5 m):
`elastic` (the deck as written, linear: 6 increments) and `dp_footing` (the Drucker-Prager
footing of bench/scaling.py: geostatic stress, then 300 kPa in 2 increments, full
Newton; associated, so the tangent is symmetric: CHOLMOD, and MUMPS as LDL^T). Sizes: 1e5,
1e6 and 3e6 equations (--quick: 1e4 and 3e4; --sizes picks others), run one at a time,
smallest first. Each run uses the MPI build (make build-mpi); a run over --timeout is
reported as 'timeout'.

Per run: time per increment = (total - read+setup) / increments from the run summary; peak
resident memory of every rank (VmHWM of each pecplas process, polled); MUMPS's own analysis
estimates (factor entries INFOG(3), flops RINFOG(1), MB on the largest rank and on all
INFOG(16)/(17)) and the MB it used (INFOG(21)); CHOLMOD's factor entries and flops and the
ordering that ran (from the program's 'linear solver:' line); the load during the run (mean
number of runnable tasks, the sampling process excluded) and the 1-minute load average at its
end. A timing taken at load > 2 is marked not final. Before each run the memory it needs is
predicted from the smaller sizes already run (bench/mumps_report.py); a run that would
not fit in the memory available now is skipped and says so.

Rows are merged into doc/bench/mumps.csv (a rerun replaces the row of the same problem, size,
solver, threads and ranks; each row keeps the commit and date it was measured at), which is
written after every run, with the fragment doc/bench/mumps.md, so an interrupted series
keeps what it measured.

    python3 -m pecplas_py.bench.mumps [--quick] [--sizes 1e5 1e6] [--problems elastic]
                                 [--configs MUMPS:1:2] [--timeout 1800]
                                 [--pecplas build/cmake/mpi/pecplas]
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from pecplas_py import script_cmd
from pecplas_py.bench.common import BENCH_DIR, ROOT, provenance, write_fragment
from pecplas_py.bench.mumps_report import (CONFIGS, GB20_MB, fit, fragment,  # noqa: F401
                                           predicted_total_mb)
from pecplas_py.bench.scaling import equations, make_deck as make_dp_deck, size_for

HEADER = ["problem", "equations", "solver", "ordering", "threads", "ranks", "status",
          "increments", "iterations", "factorisations", "time_per_increment_s",
          "t_factorisation_s", "peak_mb_per_rank", "peak_mb_ranks", "peak_mb_total",
          "nnz_factor", "flops", "est_factor_entries", "est_flops", "est_mb_rank",
          "est_mb_total", "mumps_mb_rank", "cpu_s", "total_s", "load_run", "load1_end", "final", "note"]
PROV = ["commit", "machine", "date"]
TEXT = ("ordering", "peak_mb_ranks", "note", "commit", "machine", "date")
KEY = ("problem", "equations", "solver", "threads", "ranks")
CSV_PATH = BENCH_DIR / "mumps.csv"
MAX_LOAD = 2.0  # a timing taken at a higher load is not final (2 cores)
NAN = float("nan")
MEMORY_MARGIN = 1.15  # a run is started only when 1.15 x its predicted memory is available


def make_elastic_deck(nx, ny, path):
    subprocess.run([*script_cmd("decks.make_default_deck"), "--nx",
                    str(nx), "--ny", str(ny), "--width", "10", "--depth", "5", "--footing", "1",
                    "-o", str(path)], check=True)


MAKERS = {"elastic": make_elastic_deck, "dp_footing": make_dp_deck}


def with_solver(path, solver):
    text = path.read_text()
    text = re.sub(r"(\*SOLVER)(, LINEAR=[A-Z]+)?", rf"\1, LINEAR={solver}", text, count=1)
    path.write_text(text)


def descendants(pid):
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        try:
            for task in os.listdir(f"/proc/{p}/task"):
                with open(f"/proc/{p}/task/{task}/children") as f:
                    kids = [int(k) for k in f.read().split()]
                out += kids
                todo += kids
        except OSError:
            pass
    return out


def runnable_tasks(text):
    """Runnable tasks from /proc/loadavg's text ('0.5 0.4 0.3 3/170 999'), less the reader."""
    return max(0, int(text.split()[3].split("/")[0]) - 1)


def mem_available_mb():
    for line in Path("/proc/meminfo").read_text().splitlines():
        if line.startswith("MemAvailable:"):
            return int(line.split()[1]) / 1024.0
    return float("nan")


def run_polled(cmd, env, timeout):
    """(rc or None on timeout, stdout, {pid: VmHWM MB} of the pecplas processes, mean runnable
    tasks during the run)."""
    with tempfile.TemporaryFile("w+") as fo:
        p = subprocess.Popen(cmd, stdout=fo, stderr=subprocess.STDOUT, env=env, text=True)
        hwm, loads, t0 = {}, [], time.perf_counter()
        while p.poll() is None:
            for q in [p.pid] + descendants(p.pid):
                try:
                    with open(f"/proc/{q}/status") as st:
                        txt = st.read()
                    if "pecplas" in txt.split("\n", 1)[0]:
                        m = re.search(r"VmHWM:\s+(\d+)", txt)
                        if m:
                            hwm[q] = max(hwm.get(q, 0.0), int(m.group(1)) / 1024.0)
                except OSError:
                    pass
            loads.append(runnable_tasks(Path("/proc/loadavg").read_text()))
            if time.perf_counter() - t0 > timeout:
                p.kill()
                p.wait()
                return None, "", hwm, sum(loads) / len(loads)
            time.sleep(0.05)
        fo.seek(0)
        return p.returncode, fo.read(), hwm, (sum(loads) / len(loads) if loads else 0.0)


def number(pattern, text, default=float("nan")):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else default


def parse_run(text):
    """The numbers of one run from the program's output (summary and 'linear solver:' line)."""
    incs = number(r"summary: (\d+) increments", text, 0)
    total = number(r"total ([0-9.]+)", text)
    setup = number(r"read\+setup ([0-9.]+)", text)
    ordering = re.search(r" ordering=(.+?)(?= \w+=|\s*$)", text, re.M)
    return {"ordering": ordering.group(1).strip() if ordering else "",
            "status": (re.search(r"status: (\S+)", text) or [0, "failed"])[1],
            "increments": int(incs),
            "iterations": int(number(r"increments, (\d+) iterations", text, 0)),
            "factorisations": int(number(r"(\d+) factorisations,", text, 0)),
            "time_per_increment_s": (total - setup) / incs if incs else float("nan"),
            "t_factorisation_s": number(r"factorisation ([0-9.]+)", text),
            "cpu_s": number(r"([0-9.]+) s CPU", text), "total_s": total,
            "nnz_factor": number(r"nnz\(factor\)=(\d+)", text),
            "flops": number(r" flops=\s*([0-9.E+-]+)", text),
            "est_factor_entries": number(r"est_factor_entries=(-?\d+)", text),
            "est_flops": number(r"est_flops=\s*([0-9.E+-]+)", text),
            "est_mb_rank": number(r"est_mb_rank=(\d+)", text),
            "est_mb_total": number(r"est_mb_total=(\d+)", text),
            "mumps_mb_rank": number(r" mb_rank=(\d+)", text)}


def one_run(binary, deck, solver, threads, ranks, timeout):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OPENBLAS_NUM_THREADS=str(threads),
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_mpi_yield_when_idle="1",
               OMPI_MCA_hwloc_base_binding_policy="none")
    d = Path(deck)
    sdeck = d.with_name(f"{d.stem}_{solver}.inp")
    sdeck.write_text(d.read_text())
    with_solver(sdeck, solver)
    out = d.with_name(f"{d.stem}_{solver}_{threads}_{ranks}.h5")
    cmd = [binary, str(sdeck), "-o", str(out)]
    if solver == "MUMPS":
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    rc, text, hwm, load = run_polled(cmd, env, timeout)
    out.unlink(missing_ok=True)
    r = parse_run(text)
    if rc is None:
        r["status"] = "timeout"
        r["note"] = f"over {timeout:.0f} s"
    peaks = sorted(hwm.values(), reverse=True)
    r.update(peak_mb_per_rank=round(peaks[0], 1) if peaks else float("nan"),
             peak_mb_ranks=";".join(f"{v:.0f}" for v in peaks),
             peak_mb_total=round(sum(peaks), 1) if peaks else float("nan"),
             load_run=round(load, 2), load1_end=os.getloadavg()[0])
    r["final"] = "yes" if r["load_run"] <= MAX_LOAD and r["status"] == "completed" else "no"
    return r


def parse_config(text):
    """'MUMPS:1:2' -> ('MUMPS', 1, 2), one of CONFIGS."""
    solver, threads, ranks = text.split(":")
    c = (solver.upper(), int(threads), int(ranks))
    if c not in CONFIGS:
        raise SystemExit(f"bench_mumps: unknown configuration {text}; known: "
                         + " ".join(f"{s}:{t}:{r}" for s, t, r in CONFIGS))
    return c


def read_rows(path):
    """Rows of an existing CSV as dicts (numbers as floats where they parse)."""
    if not Path(path).exists():
        return []
    rows = []
    with open(path, newline="") as f:
        for d in csv.DictReader(f):
            row = {}
            for k, v in d.items():
                try:
                    row[k] = v if k in TEXT else float(v)
                except (TypeError, ValueError):
                    row[k] = v if v is not None else ""
            for k in ("equations", "threads", "ranks"):
                row[k] = int(row[k])
            for k in HEADER:  # a column an older version did not write
                row.setdefault(k, "" if k in TEXT else NAN)
            rows.append(row)
    return rows


def merge(old, new):
    """old rows with those of new's keys replaced by new's, ordered by problem then size."""
    keys = {tuple(r[k] for k in KEY) for r in new}
    kept = [r for r in old if tuple(r[k] for k in KEY) not in keys]
    order = {p: i for i, p in enumerate(MAKERS)}
    conf = {c: i for i, c in enumerate(CONFIGS)}
    return sorted(kept + new, key=lambda r: (order.get(r["problem"], 9), r["equations"],
                                              conf.get((r["solver"], r["threads"], r["ranks"]), 9)))


def write_rows(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(HEADER + PROV)
        for r in rows:
            w.writerow([r.get(k, "") for k in HEADER + PROV])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="1e4 and 3e4 equations")
    ap.add_argument("--sizes", type=float, nargs="+", default=None)
    ap.add_argument("--problems", nargs="+", choices=list(MAKERS), default=list(MAKERS))
    ap.add_argument("--configs", nargs="+", default=None, metavar="SOLVER:THREADS:RANKS",
                    help="a subset of " + " ".join(f"{s}:{t}:{r}" for s, t, r in CONFIGS))
    ap.add_argument("--timeout", type=float, default=1800.0)
    ap.add_argument("--pecplas", default=str(ROOT / "build" / "cmake" / "mpi" / "pecplas"))
    a = ap.parse_args()
    if not Path(a.pecplas).exists():
        sys.exit(f"bench_mumps: no MPI build at {a.pecplas} (make build-mpi)")
    configs = CONFIGS if not a.configs else [parse_config(c) for c in a.configs]
    sizes = sorted(a.sizes or ((1e4, 3e4) if a.quick else (1e5, 1e6, 3e6)))
    rows = read_rows(CSV_PATH)
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="pecplas-bench-mumps-") as tmp:
        for target in sizes:
            for prob in a.problems:
                nx, ny = size_for(target)
                deck = Path(tmp) / f"{prob}_{int(target)}.inp"
                MAKERS[prob](nx, ny, deck)
                neq = equations(nx, ny)
                for solver, threads, ranks in configs:
                    row = {k: "" if k in TEXT else NAN for k in HEADER}
                    row.update(problem=prob, equations=neq, solver=solver, threads=threads,
                               ranks=ranks)
                    need = predicted_total_mb(rows, row)
                    have = mem_available_mb()
                    if need == need and need * MEMORY_MARGIN > have:
                        row.update(status="skipped", final="no", note=(
                            f"needs about {need / 1024:.1f} GB, {have / 1024:.1f} GB available"))
                    else:
                        row.update(one_run(a.pecplas, deck, solver, threads, ranks,
                                           a.timeout))
                    row.update(provenance())
                    rows = merge(rows, [row])
                    print(" ".join(str(row.get(k, "")) for k in HEADER), flush=True)
                    write_rows(CSV_PATH, rows)
                    write_fragment("mumps", fragment(rows, time.perf_counter() - t0))
                deck.unlink(missing_ok=True)


if __name__ == "__main__":
    main()
