#!/usr/bin/env python3
"""Runs every deck of input/ with two builds of the programs and compares their results files:
a change that must not change results (a refactoring, a new layout of the tree) is checked
with it against the build before the change.

The decks, each run as its scene's make target runs it (from the project root):
  pecplas        input/default.inp, input/examples/, input/s1, s2, s3, s5, s6  -> NAME.h5
  pecplas-path   input/paths/, input/s4                                        -> NAME.csv, .h5
  S4 tables      pecplas-identify on the CNL curves of input/s4 (III.1 initial, III.2 and
                 III.5 improved), pecplas-sensitivity (table III.4)            -> CSV
  sweeps         input/sweeps/*/: the decks written by pecplas-sweep make (template x table),
                 each run with pecplas                                         -> CASE.h5
Compared: every dataset and every numeric attribute of the HDF5 files, and every cell of the
CSV files; a number differs when |a - b| > TOL * max(|a|, |b|) over the dataset (or CSV
column), i.e. relative to the dataset's largest entry, absolute where it is all zero; integers
and strings must be equal (the deck text without its `**` comment lines). Not compared: the
time stamps and timings (created, completed, finished, cpu_time), the version, the `checksum`
and `deck_text_checksum` attributes (hashes of the data and deck text compared here) and
pecplas-sweep's bookkeeping. Exit codes of the programs are compared too.

    python3 -m pecplas_py.checks.compare_results --old OLD_BIN --new NEW_BIN   # run both, compare
    python3 -m pecplas_py.checks.compare_results --old OLD_BIN --store DIR     # run OLD once, keep
    python3 -m pecplas_py.checks.compare_results --baseline DIR --new NEW_BIN  # NEW against DIR
    python3 -m pecplas_py.checks.compare_results --baseline DIR --no-run       # again, no run

OLD_BIN, NEW_BIN: a folder holding pecplas, pecplas-path, pecplas-identify and
pecplas-sensitivity (`fpm install --prefix P` -> P/bin, a CMake build folder, fpm's
build/gfortran_*/app). --only SUBSTRING runs the decks whose name contains it (repeatable).
Every run takes 16 s or less; all of them about 3 minutes per build on 2 cores. Prints the
largest difference of each deck and overall; exits 1 when any exceeds TOL (default 1e-12) or a file,
dataset or exit code differs, 2 on bad arguments.
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

from pecplas_py import ROOT, script_cmd

#: names (last path component) of datasets and attributes that are no results
IGNORED = {"created", "completed", "finished", "cpu_time", "version", "checksum",
           "deck_text_checksum"}
MANIFEST = "manifest.json"
#: the results folder of the sweeps' decks, relative to the root: the same in every run, so
#: the decks' paths written into the results (deck_text) are the same
SWEEP_DECKS = Path("build/compare_results/sweeps")


class Failure(Exception):
    pass


# ------------------------------------------------------------------ the decks
def sweep_tool():
    """pecplas-sweep: the command that runs programs/pecplas_sweep.py of this tree."""
    return script_cmd("programs.pecplas_sweep")


def jobs():
    """[(name, kind, args)] of every run, in order; kind says how it is run."""
    out = []

    def decks(folder):
        return sorted((ROOT / folder).glob("*.inp"))
    for deck in [ROOT / "input/default.inp"] + [d for f in ("input/examples", "input/s1",
                                                           "input/s2", "input/s3", "input/s5",
                                                           "input/s6") for d in decks(f)]:
        rel = deck.relative_to(ROOT)
        out.append((str(rel.with_suffix("")).removeprefix("input/"), "pecplas", str(rel)))
    for folder in ("input/paths", "input/s4"):
        for deck in decks(folder):
            rel = deck.relative_to(ROOT)
            out.append((str(rel.with_suffix("")).removeprefix("input/"), "path", str(rel)))
    for table, version in (("iii1", "initial"), ("iii2", "improved"), ("iii5", "improved")):
        curves = [f"s4/s4_{table}_cnl_{s}.csv" for s in (31, 56, 122)]
        out.append((f"s4/identification_{table}", "identify", (version, curves)))
    out.append(("s4/sensitivity", "sensitivity", None))
    for sweep in sorted(p for p in (ROOT / "input/sweeps").iterdir() if p.is_dir()):
        out.append((f"sweeps/{sweep.name}", "sweep", str(sweep.relative_to(ROOT))))
    return out


def run(cmd, log, cwd=ROOT):
    t0 = time.monotonic()
    with open(log, "w") as f:
        r = subprocess.run([str(c) for c in cmd], cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    return r.returncode, time.monotonic() - t0


def run_job(name, kind, args, bins, out):
    """Runs one job with the programs of `bins` into `out`; {file: exit code} and seconds."""
    base = out / name
    base.parent.mkdir(parents=True, exist_ok=True)
    log = base.parent / f"{base.name}.log"
    if kind == "pecplas":
        code, sec = run([bins / "pecplas", args, "-o", base.with_suffix(".h5"), "--quiet"], log)
        return {f"{name}.h5": code}, sec
    if kind == "path":
        code, sec = run([bins / "pecplas-path", args, "-o", base, "--quiet"], log)
        return {f"{name}.csv": code, f"{name}.h5": code}, sec
    if kind == "identify":
        # run in `out` with relative names: the table names its curve files
        version, curves = args
        code, sec = run([bins / "pecplas-identify", "--version", version, *curves, "-o",
                         f"{name}.csv"], log, cwd=out)
        return {f"{name}.csv": code}, sec
    if kind == "sensitivity":
        code, sec = run([bins / "pecplas-sensitivity", "-o", base.with_suffix(".csv")], log)
        return {f"{name}.csv": code}, sec
    # a sweep: its decks written once into SWEEP_DECKS (the same path in every run)
    decks = ROOT / SWEEP_DECKS / Path(args).name
    shutil.rmtree(decks, ignore_errors=True)
    r = subprocess.run([*sweep_tool(), "make", f"{args}/template.inp",
                        f"{args}/table.csv", "-o", decks], cwd=ROOT, capture_output=True,
                       text=True)
    if r.returncode != 0:
        raise Failure(f"pecplas-sweep make {args}: exit {r.returncode}\n{r.stderr}")
    codes, total = {}, 0.0
    base.mkdir(parents=True, exist_ok=True)
    for deck in sorted(decks.glob("*.inp")):
        code, sec = run([bins / "pecplas", deck.relative_to(ROOT), "-o",
                         base / f"{deck.stem}.h5", "--quiet"], base / f"{deck.stem}.log")
        codes[f"{name}/{deck.stem}.h5"] = code
        total += sec
    return codes, total


def run_all(bins, out, selected):
    """Runs the selected jobs with `bins` into `out` (emptied first), writes its manifest."""
    bins = Path(bins).resolve()
    for prog in ("pecplas", "pecplas-path", "pecplas-identify", "pecplas-sensitivity"):
        if not os.access(bins / prog, os.X_OK):
            raise Failure(f"{bins / prog}: not an executable")
    out = Path(out).resolve()
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    manifest = {"bin": str(bins), "files": {}, "seconds": {}}
    for name, kind, args in selected:
        codes, sec = run_job(name, kind, args, bins, out)
        manifest["files"].update(codes)
        manifest["seconds"][name] = round(sec, 2)
        print(f"  ran {name}: {sec:.1f} s, exit {sorted(set(codes.values()))}", flush=True)
    (out / MANIFEST).write_text(json.dumps(manifest, indent=1))
    return manifest


# ------------------------------------------------------------------ the comparison
class Worst:
    """The largest relative difference seen, and where."""

    def __init__(self):
        self.value, self.where, self.problems = 0.0, "", []

    def number(self, a, b, where):
        import numpy as np
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if a.shape != b.shape:
            self.problems.append(f"{where}: shape {a.shape} against {b.shape}")
            return
        if a.size == 0:
            return
        same_nan = np.isnan(a) & np.isnan(b)
        if np.any(np.isnan(a) != np.isnan(b)):
            self.problems.append(f"{where}: NaN in one file only")
            return
        a, b = np.where(same_nan, 0.0, a), np.where(same_nan, 0.0, b)
        if np.any(np.isinf(a) | np.isinf(b)):
            if not np.array_equal(a, b):
                self.problems.append(f"{where}: infinite values differ")
            a, b = np.where(np.isinf(a), 0.0, a), np.where(np.isinf(b), 0.0, b)
        diff = float(np.max(np.abs(a - b)))
        scale = float(max(np.max(np.abs(a)), np.max(np.abs(b))))
        rel = diff / scale if scale > 0 else diff
        if rel > self.value:
            self.value, self.where = rel, where

    def exact(self, a, b, where):
        if a != b:
            if isinstance(a, str) and isinstance(b, str):  # from the first differing character
                at = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
                a, b, where = a[at:], b[at:], f"{where} (from character {at})"
            show = (lambda x: (x[:60] + "...") if isinstance(x, str) and len(x) > 60 else x)
            self.problems.append(f"{where}: {show(a)!r} against {show(b)!r}")


def is_number(x):
    import numpy as np
    return np.asarray(x).dtype.kind in "fc"


def as_text(x):
    import numpy as np
    x = np.asarray(x)
    if x.dtype.kind in "SO":
        return [v.decode() if isinstance(v, bytes) else str(v) for v in x.ravel()]
    return x.tolist()


def deck(text):
    """A deck's text without its comment lines (`**`): what the program reads."""
    text = text.decode() if isinstance(text, bytes) else str(text)
    return "\n".join(line for line in text.splitlines() if not line.startswith("**"))


def compare_attrs(a, b, where, worst):
    # each attribute read once: reading them is most of the time of a comparison
    da = {k: a.attrs[k] for k in a.attrs if k not in IGNORED}
    db = {k: b.attrs[k] for k in b.attrs if k not in IGNORED}
    for k in sorted(set(da) | set(db)):
        if k not in da or k not in db:
            worst.problems.append(f"{where}@{k}: only in {'new' if k in db else 'old'}")
        elif is_number(da[k]) and is_number(db[k]):
            worst.number(da[k], db[k], f"{where}@{k}")
        else:
            worst.exact(deck(da[k]) if k == "deck_text" else as_text(da[k]),
                        deck(db[k]) if k == "deck_text" else as_text(db[k]), f"{where}@{k}")


def compare_h5(old, new, worst):
    import h5py
    with h5py.File(old, "r") as fa, h5py.File(new, "r") as fb:
        items = {}

        def collect(which):
            def visit(name, obj):
                items.setdefault(name, [None, None])[which] = obj
            return visit
        fa.visititems(collect(0))
        fb.visititems(collect(1))
        compare_attrs(fa, fb, "/", worst)
        for name in sorted(items):
            a, b = items[name]
            if name.rsplit("/", 1)[-1] in IGNORED:
                continue
            if a is None or b is None:
                worst.problems.append(f"{name}: only in {'new' if a is None else 'old'}")
                continue
            compare_attrs(a, b, name, worst)
            if isinstance(a, h5py.Dataset):
                if a.dtype.kind in "fc" and b.dtype.kind in "fc":
                    worst.number(a[()], b[()], name)
                else:
                    worst.exact(as_text(a[()]), as_text(b[()]), name)


def compare_csv(old, new, worst):
    def rows(path):
        with open(path, newline="") as f:
            return [[c.strip() for c in row] for row in csv.reader(f)]
    ra, rb = rows(old), rows(new)
    if len(ra) != len(rb) or any(len(x) != len(y) for x, y in zip(ra, rb)):
        worst.problems.append(f"{Path(old).name}: {len(ra)} rows against {len(rb)}, or a "
                              "row of another length")
        return
    for col in range(len(ra[0]) if ra else 0):
        a, b, texts = [], [], []
        for i, (x, y) in enumerate(zip(ra, rb)):
            try:
                a.append(float(x[col]))
                b.append(float(y[col]))
            except ValueError:
                texts.append((x[col], y[col], i))
        head = ra[0][col] if ra else str(col)
        for x, y, i in texts:
            worst.exact(x, y, f"column {head}, row {i}")
        if a:
            worst.number(a, b, f"column {head}")


def compare_job(old, new, name, mo, mn):
    """The Worst of one job's files (its exit codes and results)."""
    files = sorted(f for f in set(mo["files"]) | set(mn["files"])
                   if f == name or f.startswith(name + ".") or f.startswith(name + "/"))
    worst = Worst()
    if not files:
        worst.problems.append("not run in one of the two")
    for f in files:
        ca, cb = mo["files"].get(f), mn["files"].get(f)
        if ca is None or cb is None:
            worst.problems.append(f"{f}: only in {'new' if ca is None else 'old'}")
            continue
        worst.exact(ca, cb, f"{f}: exit code")
        pa, pb = Path(old) / f, Path(new) / f
        if pa.exists() != pb.exists():
            worst.problems.append(f"{f}: written by {'new' if pb.exists() else 'old'} only")
            continue
        if not pa.exists():
            continue
        sub = Worst()
        (compare_h5 if f.endswith(".h5") else compare_csv)(pa, pb, sub)
        worst.problems += [f"{f} {p}" for p in sub.problems]
        if sub.value > worst.value:
            worst.value, worst.where = sub.value, f"{f}: {sub.where}"
    return worst


def compare_dirs(old, new, tol, selected, jobs=1):
    """Prints the largest difference of each job; returns the number of failed jobs."""
    from concurrent.futures import ProcessPoolExecutor
    mo = json.loads((Path(old) / MANIFEST).read_text())
    mn = json.loads((Path(new) / MANIFEST).read_text())
    failed, overall = 0, Worst()
    width = max((len(n) for n, _, _ in selected), default=10)
    print(f"{'deck':<{width}}  {'largest rel. difference':>24}  where")
    names = [name for name, _, _ in selected]
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        results = pool.map(compare_job, *zip(*[(old, new, n, mo, mn) for n in names]))
    for name, worst in zip(names, results):
        bad = worst.value > tol or worst.problems
        failed += bool(bad)
        print(f"{name:<{width}}  {worst.value:>24.3e}  {worst.where}"
              + ("  FAIL" if bad else ""))
        for p in worst.problems[:10]:
            print(f"    {p}")
        if len(worst.problems) > 10:
            print(f"    ... and {len(worst.problems) - 10} more")
        if worst.value > overall.value:
            overall.value, overall.where = worst.value, f"{name}: {worst.where}"
    print(f"overall largest relative difference {overall.value:.3e} ({overall.where or '-'}); "
          f"{failed} of {len(selected)} decks differ beyond {tol:g} or in files, datasets, "
          "strings or exit codes")
    return failed


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="\n".join(__doc__.splitlines()[1:]))
    p.add_argument("--old", help="folder of the old build's programs")
    p.add_argument("--new", help="folder of the new build's programs")
    p.add_argument("--baseline", help="results of an earlier --store run, instead of --old")
    p.add_argument("--store", help="with --old alone: keep its results in this folder")
    p.add_argument("--work", default=str(ROOT / "build/compare_results"),
                   help="folder for the runs (default build/compare_results)")
    p.add_argument("--tol", type=float, default=1e-12, help="relative tolerance (1e-12)")
    p.add_argument("--only", action="append", help="decks whose name contains this (repeatable)")
    p.add_argument("--no-run", action="store_true",
                   help="compare the new results an earlier run left in WORK/new (no --new)")
    p.add_argument("-j", "--jobs", type=int, default=1,
                   help="files compared at a time (default 1; the runs are one at a time)")
    a = p.parse_args(argv)
    if bool(a.old) == bool(a.baseline) or (a.store and (a.new or not a.old)) or (
            not a.store and not a.new and not a.no_run):
        p.error("give --old OLD --new NEW, --old OLD --store DIR, or --baseline DIR --new NEW")
    selected = [j for j in jobs() if not a.only or any(s in j[0] for s in a.only)]
    work = Path(a.work)
    t0 = time.monotonic()
    try:
        if a.store:
            print(f"running {len(selected)} jobs with {a.old} into {a.store}")
            run_all(a.old, a.store, selected)
            print(f"stored in {a.store} ({time.monotonic() - t0:.0f} s)")
            return 0
        old = Path(a.baseline) if a.baseline else work / "old"
        if a.old:
            print(f"running {len(selected)} jobs with {a.old}")
            run_all(a.old, old, selected)
        elif not (old / MANIFEST).exists():
            raise Failure(f"{old}: no {MANIFEST} (write it with --old BIN --store {old})")
        if not a.no_run:
            print(f"running {len(selected)} jobs with {a.new}")
            run_all(a.new, work / "new", selected)
        failed = compare_dirs(old, work / "new", a.tol, selected, a.jobs)
    except Failure as e:
        print(f"compare_results: {e}", file=sys.stderr)
        return 2
    print(f"time {time.monotonic() - t0:.0f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
