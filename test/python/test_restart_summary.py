"""The console summary of a restarted run (doc/results.md, "`/restart` and restarting a
run"): its counts are the whole run's, equal to those the uninterrupted run prints; its times
and the linear solver's own statistics are this process's and say so."""
import re
import subprocess
from pathlib import Path

import h5py
import pytest

from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]


def run(deck, out, *extra):
    return subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), *map(str, extra)],
                          cwd=deck.parent, capture_output=True, text=True, timeout=300)


def counted(stdout):
    """The summary's lines with counts (summary, methods, katona, status), the times and
    what says whose they are taken out."""
    lines = stdout[stdout.index(" summary:"):].splitlines()
    keep = []
    for line in lines:
        if line.startswith((" summary:", " methods:", " katona:")):
            line = re.sub(r", [0-9.]+ s CPU.*$", "", line)
            keep.append(re.sub(r", time.*$", "", line))
        elif line.startswith(" status:"):
            keep.append(line.split("results:")[0])
    return keep


@pytest.mark.parametrize("deck,n", [
    # Katona friction limit: increment cuts, the arc-length probe, limit load; the
    # flexibility of the contact belongs to the last factorisation at the stop
    ("test/data/katona/pad_slip.inp", 6),
    # arc-length control with a NODE= target, then without one: stopped inside the first
    ("test/data/progress/arc.inp", 3),
    # a staged embankment: stopped after the first increment of lift 2
    ("input/examples/embankment_stages.inp", 6)])
def test_restarted_summary_counts_the_whole_run(tmp_path, deck, n):
    d = ROOT / deck
    full = run(d, tmp_path / "full.h5")
    assert full.returncode in (0, 3), full.stderr
    part = run(d, tmp_path / "part.h5", "--stop-after-increments", n)
    assert part.returncode == 4, part.stderr
    rest = run(d, tmp_path / "rest.h5", "--restart", tmp_path / "part.h5")
    assert rest.returncode == full.returncode, rest.stderr
    assert counted(rest.stdout) == counted(full.stdout)
    # the times and the solver's statistics are this process's, and say so
    said = f"of this process (restarted after increment {n})"
    assert f"s CPU {said}" in rest.stdout
    assert f" wall time [s] {said}:" in rest.stdout
    assert " linear solver (this process): " in rest.stdout
    assert "this process" not in full.stdout


def test_restart_data_without_counts(tmp_path):
    """Restart data of an earlier version hold no counts but the increments, iterations
    and cuts: the summary says which of its numbers are this process's."""
    d = ROOT / "test/data/katona/pad_slip.inp"
    assert run(d, tmp_path / "part.h5", "--stop-after-increments", 6).returncode == 4
    with h5py.File(tmp_path / "part.h5", "a") as f:
        del f["restart/counters"]
    rest = run(d, tmp_path / "rest.h5", "--restart", tmp_path / "part.h5")
    assert rest.returncode == 3, rest.stderr
    line = next(x for x in rest.stdout.splitlines() if x.startswith(" summary:"))
    with h5py.File(tmp_path / "part.h5") as p, h5py.File(tmp_path / "rest.h5") as r:
        rows = len(p["history/step"]) + len(r["history/step"])
    assert line.startswith(f" summary: {rows} increments, "), line
    assert "solves (factorisations and solves: this process)" in line
    for key in (" methods:", " katona:"):
        line = next(x for x in rest.stdout.splitlines() if x.startswith(key))
        assert "(this process)" in line, line
