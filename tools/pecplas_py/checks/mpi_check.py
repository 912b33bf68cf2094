#!/usr/bin/env python3
"""The MPI build's acceptance check (`make test-mpi`, doc/mpi.md).

For each deck: one serial run with the deck's own solver (CHOLMOD or UMFPACK, as AUTO
chooses), then `mpirun -np N pecplas` with *SOLVER, LINEAR=MUMPS for each N; the MUMPS
results must have the same status, the same increments and iteration counts, and every
displacement and reaction dataset equal to the serial one within 1e-8 of that dataset's
largest absolute value (both solvers are backward stable; the converged Newton states differ
by the residual tolerance times roundoff, far below 1e-8). Only rank 0 may write: the run's
directory must hold only the results file and its .xmf afterwards. Decks given with
--singular hold a mechanism: with MUMPS they must end as input errors (exit 2) that name the
free node, as CHOLMOD and UMFPACK do, and write no results file. On more than one rank the
run's summary must say that each rank assembled the stiffness of its own elements (the
partitioned assembly, doc/mpi.md). --restart DECK N stops DECK (with MUMPS) after N
increments on each rank count and restarts it on each rank count: a run restarted on the
rank count that wrote the data (the last factorised matrix carried, on several ranks each
rank's part of it) must end on the uninterrupted run's displacements on that rank count, to
1e-12 of their largest on one rank, and on several write every dataset as it does within
EXACT_TOL (MUMPS on several ranks is not repeatable to the bit; see restart_differences);
every other pair (each rank's part is on a pattern of its own, which
no other rank count has, doc/mpi.md) must complete within RESTART_TOL of the uninterrupted
run on the restarting rank count (a different first iteration, the same equilibrium to the
deck's Newton tolerance). --restart-exact DECK N (repeatable) stops DECK (with MUMPS) after
N increments on the largest rank count and restarts it there: every dataset it writes
(history rows, increment groups, /limit, /safety, root attributes) must equal the
uninterrupted run's within EXACT_TOL, the iteration counts exactly. --signal DECK runs DECK (with MUMPS) on 2 ranks
and sends SIGTERM to one rank other than 0 half-way: every rank must stop after the same
increment (exit 4 from mpirun, status 'interrupted' in rank 0's results file, which names the
signal's rank; no rank left waiting in a collective). --write-failure DECK runs DECK (with
MUMPS) on 2 ranks with rank 0's 10th results-file write failing on purpose
(PECPLAS_TEST_FAIL_WRITE): the run must end at once with exit 3 and the message that names
the file holding the increments written before (not hang while rank 1 waits). --unit runs Fortran test suites of the MPI build's test
program (e.g. linalg_mumps) under `mpirun -np N` for each N: every rank must pass them all.

Usage: python3 -m pecplas_py.checks.mpi_check PECPLAS_BIN DECK... [--singular DECK...]
                                            [--np 1 2] [--work DIR]
                                            [--restart DECK N] [--restart-exact DECK N]...
                                            [--signal DECK] [--write-failure DECK]
                                            [--unit TESTS_BIN SUITE...]
Exit status 0 when every comparison holds, 1 otherwise (each failure printed).
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

from pecplas_py.results import flat_items

TOL = 1.0e-8
RESTART_TOL = 1.0e-5
# A run restarted on the rank count that wrote its data repeats the uninterrupted run's
# iterations (the parts of the last factorised matrix carried); MUMPS on several ranks is not
# repeatable to the bit, so "equal" is: the same status and iteration counts, and every
# dataset within EXACT_TOL of the largest value of its units in the increment. Measured on 2 ranks: two uninterrupted runs
# of input/default.inp differ by 4e-15 (displacements), 1.3e-12 (reactions), 2.4e-13 (joint
# stresses) of their largest, the cantilever excavation by 1.1e-14; restarted from the set-up
# stiffness instead (the data held no matrix), default.inp ended 5.1e-6 and the excavation
# 6.3e-5 away, with other iteration counts. EXACT_TOL lies between: 770 times the largest
# scatter, 5000 times below the smallest such difference.
EXACT_TOL = 1.0e-9
# not results: times, the machine's threads and BLAS, the deck's path
SKIP_ATTRS = {"created", "finished", "completed", "complete", "wall_time", "checksum",
              "threads", "blas", "blas_core", "blas_core_source", "blas_flops_per_thread",
              "blas_threading", "threads_blas", "threads_cholmod_regions",
              "threads_element_loops", "deck_file", "deck_text_checksum"}
COMPARED = ("displacement", "reaction")


def mumps_deck(text):
    """The deck with LINEAR=MUMPS on its *SOLVER line (a *SOLVER line added if it has none)."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if re.match(r"\s*\*SOLVER\b", line, re.I):
            line = re.sub(r",\s*LINEAR\s*=\s*[A-Za-z]+", "", line, flags=re.I)
            lines[i] = re.sub(r"(\*SOLVER)", r"\1, LINEAR=MUMPS", line, count=1, flags=re.I)
            return "\n".join(lines) + "\n"
    for i, line in enumerate(lines):
        if re.match(r"\s*\*STEP\b", line, re.I):
            return "\n".join(lines[:i] + ["*SOLVER, LINEAR=MUMPS"] + lines[i:]) + "\n"
    raise ValueError("deck has neither *SOLVER nor *STEP")


def write_mumps_deck(deck, suffix="mumps"):
    """The MUMPS variant of `deck` written next to it (so that its relative paths still hold)
    as a hidden file; its path. The caller removes it."""
    stem = os.path.splitext(os.path.basename(deck))[0]
    mdeck = os.path.join(os.path.dirname(os.path.abspath(deck)), f".{stem}_{suffix}.inp")
    with open(deck) as f:
        text = mumps_deck(f.read())
    with open(mdeck, "w") as f:
        f.write(text)
    return mdeck


def run(cmd, env):
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True)
    return proc, time.perf_counter() - t0


def compare(ref_path, got_path):
    """Problems found between two results files (empty list: equal within TOL)."""
    problems = []
    with h5py.File(ref_path, "r") as ref, h5py.File(got_path, "r") as got:
        for attr in ("status", "complete"):
            if ref.attrs[attr] != got.attrs[attr]:
                problems.append(f"{attr}: {ref.attrs[attr]!r} vs {got.attrs[attr]!r}")
        for name in ("iterations", "global_increment"):
            a, b = ref["history"][name][()], got["history"][name][()]
            if a.shape != b.shape or np.any(a != b):
                problems.append(f"history/{name} differs")
        if sorted(ref["increments"]) != sorted(got["increments"]):
            problems.append("different increments written")
            return problems
        worst = 0.0
        for inc in ref["increments"]:
            for ds in COMPARED:
                a = ref["increments"][inc][ds][()]
                b = got["increments"][inc][ds][()]
                scale = max(np.max(np.abs(a)), np.finfo(float).tiny)
                err = np.max(np.abs(a - b)) / scale
                worst = max(worst, err)
                if not err <= TOL:
                    problems.append(f"increments/{inc}/{ds}: relative difference {err:.2e}")
        problems.append(worst)  # last item: the largest difference, for the report
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binary")
    parser.add_argument("decks", nargs="*")
    parser.add_argument("--np", nargs="+", type=int, default=[1, 2])
    parser.add_argument("--work", default=None)
    parser.add_argument("--singular", nargs="*", default=[])
    parser.add_argument("--unit", nargs="+", default=[], metavar="TESTS_BIN SUITE")
    parser.add_argument("--restart", nargs=2, default=None, metavar=("DECK", "N"))
    parser.add_argument("--restart-exact", nargs=2, action="append", default=[],
                        metavar=("DECK", "N"))
    parser.add_argument("--signal", default=None, metavar="DECK")
    parser.add_argument("--write-failure", default=None, metavar="DECK")
    args = parser.parse_args()
    if len(args.unit) == 1:
        parser.error("--unit needs the test program and at least one suite")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    # Debian's OpenMPI refuses root unless told (CI runs as root); 2 ranks on 1 core is allowed.
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    # Waiting ranks yield the core and float: on a shared machine a rank that spins in MPI
    # waits starves the rank it waits for (measured: footing np=2 95 s spinning, 17 s yielding).
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    env.setdefault("OMPI_MCA_hwloc_base_binding_policy", "none")
    work = args.work or tempfile.mkdtemp(prefix="pecplas-mpi-")
    failures = 0
    for deck in args.decks:
        stem = os.path.splitext(os.path.basename(deck))[0]
        ref = os.path.join(work, f"{stem}_serial.h5")
        proc, t_ref = run([args.binary, deck, "-o", ref, "--quiet"], env)
        if proc.returncode != 0:
            print(f"FAIL {deck}: serial run exit {proc.returncode}\n{proc.stderr}")
            failures += 1
            continue
        mdeck = write_mumps_deck(deck)
        try:
            for n in args.np:
                rundir = os.path.join(work, f"{stem}_np{n}")
                os.makedirs(rundir, exist_ok=True)
                out = os.path.join(rundir, "results.h5")
                proc, t = run(["mpirun", "-np", str(n), args.binary, mdeck, "-o", out], env)
                if proc.returncode != 0:
                    print(f"FAIL {deck} np={n}: exit {proc.returncode}\n{proc.stdout}{proc.stderr}")
                    failures += 1
                    continue
                problems = compare(ref, out)
                worst = problems.pop()
                extra = sorted(set(os.listdir(rundir)) - {"results.h5", "results.xmf"})
                if extra:
                    problems.append(f"files written besides rank 0's results: {extra}")
                split = assembly_split(proc.stdout)
                if n > 1 and not (split and split[0] == n):
                    problems.append("summary does not report a partitioned assembly")
                if problems:
                    failures += 1
                    print(f"FAIL {deck} np={n}:\n  " + "\n  ".join(problems))
                else:
                    where = (f"; assembly CPU per rank {split[1]}-{split[2]} s"
                             if split else "")
                    print(f"ok   {deck} np={n}: MUMPS = serial within {worst:.1e} "
                          f"(tolerance {TOL:.0e}); {t:.2f} s vs serial {t_ref:.2f} s{where}")
        finally:
            os.remove(mdeck)
    for deck in args.singular:
        failures += check_singular(args.binary, deck, args.np, work, env)
    if args.restart:
        failures += check_restart(args.binary, args.restart[0], int(args.restart[1]), args.np,
                                  work, env)
    for deck, n_stop in args.restart_exact:
        failures += check_restart_exact(args.binary, deck, int(n_stop), max(args.np), work,
                                        env)
    if args.signal:
        failures += check_signal(args.binary, args.signal, work, env)
    if args.write_failure:
        failures += check_write_failure(args.binary, args.write_failure, work, env)
    if args.unit:
        failures += check_unit(args.unit[0], args.unit[1:], args.np, env)
    return 1 if failures else 0


def assembly_split(stdout):
    """(ranks, smallest CPU s, largest CPU s) from the summary's 'ranks:' line, or None."""
    m = re.search(r"ranks: (\d+), each assembles the stiffness of its own elements: "
                  r"wall [\d.]+ to [\d.]+ s, CPU ([\d.]+) to ([\d.]+) s", stdout)
    return (int(m.group(1)), float(m.group(2)), float(m.group(3))) if m else None


def unit_passed(returncode, stdout, nranks):
    """True when the test program exited 0 and each of the ranks passed tests, none failed."""
    tallies = re.findall(r"^(\d+) passed, (\d+) failed$", stdout, re.M)
    return (returncode == 0 and len(tallies) == nranks
            and all(int(p) > 0 and int(f) == 0 for p, f in tallies))


def check_unit(tests_bin, suites, nps, env):
    """Number of failed suite runs under mpirun (0: every rank passed every test)."""
    failures = 0
    for suite in suites:
        for n in nps:
            proc, t = run(["mpirun", "-np", str(n), tests_bin, suite], env)
            tallies = re.findall(r"^(\d+) passed, (\d+) failed$", proc.stdout, re.M)
            if unit_passed(proc.returncode, proc.stdout, n):
                print(f"ok   suite {suite} np={n}: {tallies[0][0]} tests passed on each of "
                      f"{n} rank(s) ({t:.1f} s)")
            else:
                failures += 1
                print(f"FAIL suite {suite} np={n}: exit {proc.returncode}, tallies {tallies}\n"
                      f"{proc.stdout}{proc.stderr}")
    return failures


def check_singular(binary, deck, nps, work, env):
    """Number of failed runs of a deck with a mechanism under MUMPS (0: all as expected)."""
    stem = os.path.splitext(os.path.basename(deck))[0]
    mdeck = write_mumps_deck(deck)
    failures = 0
    try:
        for n in nps:
            out = os.path.join(work, f"{stem}_np{n}.h5")
            proc, _ = run(["mpirun", "-np", str(n), binary, mdeck, "-o", out, "--quiet"], env)
            said = "can move without resistance" in proc.stderr and "MUMPS" in proc.stderr
            if proc.returncode == 2 and said and not os.path.exists(out):
                print(f"ok   {deck} np={n}: mechanism reported by MUMPS, exit 2, no results file")
            else:
                failures += 1
                print(f"FAIL {deck} np={n}: exit {proc.returncode}, results file "
                      f"{os.path.exists(out)}\n{proc.stderr}")
    finally:
        os.remove(mdeck)
    return failures


def last_displacement(path):
    with h5py.File(path, "r") as f:
        return f["increments"][sorted(f["increments"])[-1]]["displacement"][...], \
            f.attrs["status"]


def check_restart(binary, deck, n_stop, nps, work, env):
    """Number of failed restarts across rank counts (0: all as expected)."""
    stem = os.path.splitext(os.path.basename(deck))[0]
    mdeck = write_mumps_deck(deck, "mumps_restart")
    failures = 0

    def mpirun(n, *args):
        return run(["mpirun", "-np", str(n), binary, mdeck, "--quiet"] + list(args), env)[0]

    try:
        full, part = {}, {}
        for n in nps:
            full[n] = os.path.join(work, f"{stem}_full_np{n}.h5")
            part[n] = os.path.join(work, f"{stem}_part_np{n}.h5")
            proc = mpirun(n, "-o", full[n])
            stop = mpirun(n, "-o", part[n], "--stop-after-increments", str(n_stop))
            if proc.returncode != 0 or stop.returncode != 4:
                print(f"FAIL restart {deck} np={n}: uninterrupted exit {proc.returncode}, "
                      f"stopped exit {stop.returncode} (4 expected)\n{proc.stderr}{stop.stderr}")
                return failures + 1
        for wrote in nps:
            for n in nps:
                out = os.path.join(work, f"{stem}_rest_{wrote}to{n}.h5")
                proc = mpirun(n, "-o", out, "--restart", part[wrote])
                if proc.returncode != 0:
                    failures += 1
                    print(f"FAIL restart {deck} {wrote}->{n} ranks: exit {proc.returncode}\n"
                          f"{proc.stderr}")
                    continue
                uc, status = last_displacement(out)
                ref, _ = last_displacement(full[n])
                # on the rank count that wrote the data: the uninterrupted run's iterations
                # (one rank: to the last bits; several: MUMPS's own scatter, EXACT_TOL)
                tol = (1e-12 if n == 1 else EXACT_TOL) if wrote == n else RESTART_TOL
                err = np.abs(uc - ref).max() / np.abs(ref).max()
                # on several ranks, every dataset written after the restart too
                bad = (restart_differences(full[n], part[n], out, n_stop)
                       if wrote == n > 1 else [])
                if bad:
                    failures += 1
                    print(f"FAIL restart {deck} {wrote}->{n} ranks: {len(bad)} differences "
                          f"from the uninterrupted run beyond {EXACT_TOL:.0e}: "
                          + ", ".join(bad[:8]))
                elif status == "completed" and err <= tol:
                    print(f"ok   restart {deck} after {n_stop}: written on {wrote}, restarted "
                          f"on {n} rank(s): {err:.1e} of the uninterrupted run (limit {tol:.0e})")
                else:
                    failures += 1
                    print(f"FAIL restart {deck} {wrote}->{n} ranks: status {status}, "
                          f"{err:.1e} of the uninterrupted run (limit {tol:.0e})")
    finally:
        os.remove(mdeck)
    return failures


def _items(group):
    """Every dataset value and attribute under `group` (path -> value), results only."""
    return flat_items(group, SKIP_ATTRS)


def _differ(a, b, tol, scale=None):
    """True when a and b differ: shape, type, or (numbers) by more than tol times `scale`
    (default: the larger's largest absolute value)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        return True
    if a.dtype.kind != "f" or b.dtype.kind != "f":
        return not np.array_equal(a, b)
    if a.size == 0:
        return False
    if scale is None:
        scale = max(np.nanmax(np.abs(a)), np.nanmax(np.abs(b)), np.finfo(float).tiny)
    diff = np.abs(a - b)
    return bool(np.any(np.isnan(a) != np.isnan(b)) or np.nanmax(diff) > tol * scale)


def _unit_scales(group, a, b):
    """{dataset: the largest absolute value of the datasets of its units in the increment
    group} (either run's): roundoff in a quantity is relative to the largest quantity of its
    kind, not to its own values (a closed joint's relative displacements are 1e-19, noise
    around zero, on both runs)."""
    units = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" and "units" in obj.attrs:
            units[name] = obj.attrs["units"]
    group.visititems(visit)
    largest = {}
    for name, u in units.items():
        for x in (a.get(name), b.get(name)):
            if x is not None and np.size(x):
                largest[u] = max(largest.get(u, 0.0), float(np.nanmax(np.abs(x))))
    return {name: largest[u] for name, u in units.items() if largest.get(u, 0.0) > 0.0}


def restart_differences(full, part, rest, n_stop, tol=EXACT_TOL):
    """What the run stopped after n_stop increments (`part`) and restarted (`rest`) wrote
    otherwise than the uninterrupted run (`full`), dataset by dataset: the root attributes,
    the history rows (all but the CPU time; the iteration counts exactly; the residuals,
    relative to the loads already, within tol), every dataset and
    attribute of every increment group after n_stop, /limit and /safety (but its wall time),
    numbers within tol of the largest value of the datasets of their units in the increment
    (_unit_scales; others of their own)."""
    bad = []
    with h5py.File(full, "r") as F, h5py.File(part, "r") as P, h5py.File(rest, "r") as R:
        if P.attrs["status"] != "interrupted" or len(P["history/step"]) != n_stop:
            bad.append(f"not stopped after {n_stop}: {P.attrs['status']}, "
                       f"{len(P['history/step'])} increments")
        for a in sorted(set(F.attrs) - SKIP_ATTRS):
            if a not in R.attrs or _differ(F.attrs[a], R.attrs[a], tol):
                bad.append(f"root attribute {a}")
        for k in F["history"]:
            if k == "cpu_time":
                continue
            joined = np.concatenate([P["history"][k][()], R["history"][k][()]])
            # the residual is relative to the loads and reactions already: its scale is 1
            # (a converged residual of 7e-13 is roundoff, 2e-13 apart from run to run)
            if _differ(F["history"][k][()], joined, 0.0 if k == "iterations" else tol,
                       1.0 if k == "residual" else None):
                bad.append(f"history/{k}")
        fi = {int(g.attrs["global_increment"]): g for g in F["increments"].values()}
        ri = {int(g.attrs["global_increment"]): g for g in R["increments"].values()}
        if sorted(ri) != sorted(g for g in fi if g > n_stop):
            bad.append(f"increment groups {sorted(ri)}")
        for g in sorted(set(fi) & set(ri)):
            a, b = _items(fi[g]), _items(ri[g])
            scales = _unit_scales(fi[g], a, b)
            bad += [f"increment {g}: {k}" for k in sorted(set(a) | set(b))
                    if k not in a or k not in b or _differ(a[k], b[k], tol, scales.get(k))]
        for name in ("limit", "safety"):
            a = _items(F[name]) if name in F else {}
            b = _items(R[name]) if name in R else {}
            bad += [f"/{name}: {k}" for k in sorted(set(a) | set(b))
                    if k not in a or k not in b or _differ(a[k], b[k], tol)]
    return bad


def check_restart_exact(binary, deck, n_stop, n, work, env):
    """0 when DECK (with MUMPS) on n ranks, stopped after n_stop increments and restarted on
    n ranks, writes what the uninterrupted run on n ranks writes (restart_differences); 1
    otherwise."""
    stem = os.path.splitext(os.path.basename(deck))[0]
    mdeck = write_mumps_deck(deck, "mumps_exact")
    full, part, rest = (os.path.join(work, f"{stem}_exact_{k}.h5")
                        for k in ("full", "part", "rest"))
    t0 = time.perf_counter()
    try:
        def mpirun(*args):
            return run(["mpirun", "-np", str(n), binary, mdeck, "--quiet"] + list(args),
                       env)[0]
        a = mpirun("-o", full)
        b = mpirun("-o", part, "--stop-after-increments", str(n_stop))
        c = mpirun("-o", rest, "--restart", part) if b.returncode == 4 else b
        if a.returncode not in (0, 3) or b.returncode != 4 or c.returncode != a.returncode:
            print(f"FAIL restart {deck} on {n} ranks after {n_stop}: exits {a.returncode}, "
                  f"{b.returncode} (4 expected), {c.returncode}\n{a.stderr}{b.stderr}"
                  f"{c.stderr}")
            return 1
        bad = restart_differences(full, part, rest, n_stop)
    finally:
        os.remove(mdeck)
    if bad:
        print(f"FAIL restart {deck} on {n} ranks after {n_stop}: {len(bad)} differences "
              f"from the uninterrupted run beyond {EXACT_TOL:.0e}: " + ", ".join(bad[:8]))
        return 1
    print(f"ok   restart {deck} on {n} ranks after {n_stop}: every dataset as the "
          f"uninterrupted run's within {EXACT_TOL:.0e} ({time.perf_counter() - t0:.1f} s)")
    return 0


def check_signal(binary, deck, work, env):
    """Number of failures (0 or 1) of a SIGTERM sent to rank 1 alone of a 2-rank run."""
    import signal
    mdeck = write_mumps_deck(deck, "mumps_signal")
    out = os.path.join(work, "signal.h5")
    try:
        proc, t = run(["mpirun", "-np", "2", binary, mdeck, "-o", out, "--quiet"], env)
        if proc.returncode != 0:
            print(f"FAIL signal {deck}: the uninterrupted run exit {proc.returncode}")
            return 1
        os.remove(out)
        p = subprocess.Popen(["mpirun", "-np", "2", binary, mdeck, "-o", out, "--quiet"],
                             env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(0.5 * t)
        kids = subprocess.run(["pgrep", "-P", str(p.pid), "-f", "pecplas"],
                              capture_output=True, text=True).stdout.split()
        if len(kids) == 2:
            os.kill(int(sorted(kids, key=int)[-1]), signal.SIGTERM)
        try:
            _, err = p.communicate(timeout=120)
        except subprocess.TimeoutExpired:
            p.kill()
            print(f"FAIL signal {deck}: the ranks hung after SIGTERM to one of them")
            return 1
        if len(kids) != 2 or p.returncode == 0:
            print(f"ok   signal {deck}: (not tested: the run ended before the signal, or its "
                  f"ranks were not found: {kids})")
            return 0
        with h5py.File(out, "r") as f:
            status = f.attrs["status"]
            message = f.attrs["status_message"]
            rows = len(f["history/step"])
        if p.returncode == 4 and status == "interrupted" and "another MPI rank" in message:
            print(f"ok   signal {deck}: SIGTERM to rank 1 alone stopped both ranks after "
                  f"increment {rows}: {message}")
            return 0
        print(f"FAIL signal {deck}: exit {p.returncode}, status {status}: {message}\n{err}")
        return 1
    finally:
        os.remove(mdeck)


def check_write_failure(binary, deck, work, env):
    """Number of failures (0 or 1) of a 2-rank run whose rank 0 cannot write increment 10."""
    mdeck = write_mumps_deck(deck, "mumps_write")
    out = os.path.join(work, "write_failure.h5")
    try:
        fail_env = dict(env, PECPLAS_TEST_FAIL_WRITE="10")
        try:
            proc = subprocess.run(["mpirun", "-np", "2", binary, mdeck, "-o", out, "--quiet"],
                                  env=fail_env, capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            print(f"FAIL write failure {deck}: the ranks hung after rank 0's write failed")
            return 1
        said = "cannot write results" in proc.stderr and "failed on purpose" in proc.stderr
        if proc.returncode == 3 and said and not os.path.exists(out):
            print(f"ok   write failure {deck}: rank 0's 10th write failed on 2 ranks: exit 3 "
                  "at once, the increments before kept in the running file")
            return 0
        print(f"FAIL write failure {deck}: exit {proc.returncode}\n{proc.stderr}")
        return 1
    finally:
        os.remove(mdeck)


if __name__ == "__main__":
    sys.exit(main())
