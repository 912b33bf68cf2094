"""Shared pieces of the `make bench` scripts (tools/pecplas_py/bench/*.py).

Every benchmark CSV records where its numbers come from: `write_csv` appends the columns
`commit` and `machine` to every row. Every timing comes from a run made by the script that
writes the chart (`run_timed`), never from a stored number.

    from pecplas_py.bench.common import (ROOT, BENCH_DIR, executable, run_timed, write_csv,
                                         provenance)
"""
import csv
import math
import os
import platform
import subprocess
import time
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.exe import exe_path

BENCH_DIR = ROOT / "doc" / "bench"


def executable(target="pecplas"):
    """Path of a release executable (pecplas_py.exe: $PECPLAS_BIN's build, else fpm's release
    build, built if needed); raises ExeError (a RuntimeError) when there is none."""
    return exe_path(target)


def provenance():
    """{'commit': short hash (+'-dirty'), 'machine': host, CPU model, cores, 'date': UTC}."""
    def git(*args):
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True,
                              text=True).stdout.strip()
    commit = git("rev-parse", "--short", "HEAD") or "unknown"
    # the benchmark's own outputs (doc/bench) do not make the code dirty
    if git("status", "--porcelain", "--untracked-files=no", "--", ".", ":!doc/bench"):
        commit += "-dirty"
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    machine = f"{platform.node()} {cpu} x{os.cpu_count()} {platform.system()}"
    return {"commit": commit, "machine": machine,
            "date": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}


def run_timed(cmd, cwd=None, timeout=None):
    """Run one command; returns dict(wall [s], rc, stdout, stderr, peak_mb) where peak_mb is
    the peak resident memory of that program. A timeout kills the process and returns
    rc = None.

    peak_mb is the last VmHWM read from /proc/PID/status while the program runs (polled every
    5 ms; the high-water mark belongs to the exec'd program's address space, so the Python
    parent's size, which the forked child carries until exec, does not count). wait4's
    ru_maxrss would include that pre-exec size; it is only the fallback for runs too short
    to be sampled."""
    import tempfile
    with tempfile.TemporaryFile("w+") as fo, tempfile.TemporaryFile("w+") as fe:
        t0 = time.perf_counter()
        p = subprocess.Popen([str(c) for c in cmd], cwd=cwd, stdout=fo, stderr=fe, text=True)
        rc = None
        hwm = None
        status_file = f"/proc/{p.pid}/status"
        while True:
            try:
                with open(status_file) as st:
                    for line in st:
                        if line.startswith("VmHWM:"):
                            hwm = float(line.split()[1]) / 1024.0
                            break
            except OSError:
                pass
            pid, status, ru = os.wait4(p.pid, os.WNOHANG)
            if pid != 0:
                rc = os.waitstatus_to_exitcode(status)
                break
            if timeout is not None and time.perf_counter() - t0 > timeout:
                p.kill()
                pid, status, ru = os.wait4(p.pid, 0)
                break
            time.sleep(0.005)
        p.returncode = rc if rc is not None else -9
        wall = time.perf_counter() - t0
        fo.seek(0)
        fe.seek(0)
        return {"wall": wall, "rc": rc, "stdout": fo.read(), "stderr": fe.read(),
                "peak_mb": hwm if hwm is not None else ru.ru_maxrss / 1024.0}


def write_csv(path, header, rows):
    """Write rows (sequences matching header) with commit and machine columns appended."""
    prov = provenance()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(list(header) + ["commit", "machine", "date"])
        for r in rows:
            w.writerow(list(r) + [prov["commit"], prov["machine"], prov["date"]])
    return path


def write_fragment(name, text):
    """A markdown section of the benchmark summary: doc/bench/<name>.md (collected by
    bench/summary.py into doc/bench/README.md)."""
    BENCH_DIR.mkdir(parents=True, exist_ok=True)
    p = BENCH_DIR / f"{name}.md"
    p.write_text(text.rstrip() + "\n")
    return p


def load1():
    """1-minute load average (the machine's load at the time of a timing); nan if unknown."""
    try:
        with open("/proc/loadavg") as f:
            return float(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return float("nan")


def fresh_memory_gbs(mb=256, repeats=3):
    """How fast the kernel hands out fresh memory right now [GB/s]: the median over
    `repeats` of the time to fill `mb` MB never touched before (a new allocation of that
    size is mapped fresh: every page faults and is cleared by the kernel, then written once).
    A program pays about 1/rate seconds per GB of memory it touches for the first time
    (arrays, the page cache of the files it writes); on a virtual machine the rate varies
    with the host's state, which makes it the hidden variable of a run-to-run spread."""
    n = int(mb) << 20
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        block = b"\x01" * n  # one allocation, filled by memset: the first touch of each page
        times.append(time.perf_counter() - t0)
        del block
    times.sort()
    return n / times[len(times) // 2] / 1e9


def load_range(loads):
    """The 1-minute load averages of a run as text, 'min - max' to one decimal ('x' when they
    round alike); 'unknown' when none is known (nan, empty or missing values are left out)."""
    known = []
    for x in loads:
        try:
            x = float(x)
        except (TypeError, ValueError):
            continue
        if math.isfinite(x):
            known.append(x)
    if not known:
        return "unknown"
    lo, hi = f"{min(known):.1f}", f"{max(known):.1f}"
    return lo if lo == hi else f"{lo} - {hi}"


def one_thread():
    """Make every program this script starts run on one thread (OpenMP, CHOLMOD and the BLAS:
    OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = 1, doc/deck.md *SOLVER THREADS=); returns the
    setting as the fragments state it."""
    os.environ["OMP_NUM_THREADS"] = "1"
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    return "one thread (OMP_NUM_THREADS=1)"
