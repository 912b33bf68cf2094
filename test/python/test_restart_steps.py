"""Restart over every kind of step (doc/results.md, "`/restart` and restarting a run"): a run
stopped after n increments (--stop-after-increments, the test hook standing for a signal) and
continued with --restart writes, increment for increment, the datasets of the uninterrupted run
to the last bit: every dataset of every increment group after n (fields, reactions, joints,
plates, anchors, pore pressures), the history rows (all but the CPU time), /limit, /safety (all
but its wall time) and the root attributes (the status and its message, the initial procedure
of a staged run; not the times, threads and the deck's path). The same arithmetic from the same state on
the same machine and thread setting: no tolerance is needed, and any difference is a state the
restart data lost.

Step kinds here that test_restart.py does not cover: the safety step (strength reduction, its
sub-step stage included), arc-length control without a NODE= target, staged construction with
lifts, excavation with a water change and undrained soil."""
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_exe import pecplas_cmd
from pecplas_py.results import flat_items

ROOT = Path(__file__).resolve().parents[2]
BLOCK = ROOT / "test/data/safety/block.inp"

# timings and the build/threads of the machine: not results
SKIP_ATTRS = {"created", "finished", "wall_time", "checksum", "threads", "blas", "blas_core",
              "blas_core_source", "blas_flops_per_thread", "blas_threading", "threads_blas",
              "threads_cholmod_regions", "threads_element_loops", "completed", "complete"}


def run(deck, out, *extra):
    return subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet",
                                           *map(str, extra)],
                          cwd=Path(deck).parent, capture_output=True, text=True, timeout=300)


def items(group):
    """Every dataset value and attribute under `group` (path -> value)."""
    return flat_items(group, SKIP_ATTRS)


def equal(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=a.dtype.kind == "f")


def differences(full, part, rest, n):
    """What the restarted run (part + rest, stopped after n increments) wrote otherwise than
    the uninterrupted one."""
    bad = []
    with h5py.File(full) as F, h5py.File(part) as P, h5py.File(rest) as R:
        if P.attrs["status"] != "interrupted" or len(P["history/step"]) != n:
            bad.append(f"not stopped after {n}: {P.attrs['status']}, "
                       f"{len(P['history/step'])} increments")
        # the root attributes: the status and its message, how the initial state came about
        # (a staged run), the units, ... (not the deck's path: a restart may name it otherwise)
        for a in sorted(set(F.attrs) - SKIP_ATTRS - {"deck_file"}):
            if a not in R.attrs or not equal(F.attrs[a], R.attrs[a]):
                bad.append(f"root attribute {a}: {F.attrs[a]!r:.80} restarted "
                           f"{R.attrs.get(a)!r:.80}")
        for k in F["history"]:
            if k != "cpu_time" and not equal(F["history"][k][()], np.concatenate(
                    [P["history"][k][()], R["history"][k][()]])):
                bad.append(f"history/{k}")
        fi = {int(g.attrs["global_increment"]): g for g in F["increments"].values()}
        ri = {int(g.attrs["global_increment"]): g for g in R["increments"].values()}
        if sorted(ri) != sorted(g for g in fi if g > n):
            bad.append(f"increment groups {sorted(ri)}")
        for g in sorted(set(fi) & set(ri)):
            a, b = items(fi[g]), items(ri[g])
            bad += [f"increment {g}: {k}" for k in sorted(set(a) | set(b))
                    if k not in a or k not in b or not equal(a[k], b[k])]
        for name in ("limit", "safety"):
            a = items(F[name]) if name in F else {}
            b = items(R[name]) if name in R else {}
            bad += [f"/{name}: {k}" for k in sorted(set(a) | set(b))
                    if k not in a or k not in b or not equal(a[k], b[k])]
    return bad


def restarts_equal(tmp_path, deck, points):
    full = tmp_path / "full.h5"
    r = run(deck, full)
    assert r.returncode in (0, 3), r.stderr
    bad = {}
    for n in points:
        part, rest = tmp_path / f"p{n}.h5", tmp_path / f"r{n}.h5"
        r = run(deck, part, "--stop-after-increments", n)
        assert r.returncode == 4, (n, r.returncode, r.stdout[-300:], r.stderr)
        r = run(deck, rest, "--restart", part)
        assert r.returncode in (0, 3), (n, r.stderr)
        d = differences(full, part, rest, n)
        if d:
            bad[n] = d[:5]
    assert not bad, f"restarted runs that differ from the uninterrupted one: {bad}"
    return full


def test_restart_inside_the_safety_step(tmp_path):
    """The block on a Mohr-Coulomb joint (R/T = 7/3, doc/validation.md): 3 increments of load,
    then 15 of strength reduction. Stopped after the load steps (3), the first reduction
    increment (4), the middle (10), the last at the full RESOLUTION (16) and inside the
    stage that seeks a failed trial again in RESOLUTION/4 (17: the restart must go on in
    steps of RESOLUTION/4): the same trials, the same factor to the last bit, the same
    curve and mechanism. (The safety step ignored --stop-after-increments and signals, and a
    restart from a state inside it began the reduction again from Msf = 1 on that state.)"""
    full = restarts_equal(tmp_path, BLOCK, [3, 4, 10, 16, 17])
    with h5py.File(full) as f:
        s = f["safety"]
        assert s.attrs["kind"] == "factor" and s.attrs["increments"] == 15
        # the factor ends in the sub-step stage: its resolution is RESOLUTION/4 = 0.0005
        assert s.attrs["resolution"] <= 0.002 / 4 * (1 + 1e-12)


def test_restart_from_the_end_of_a_safety_run(tmp_path):
    """A completed safety run's restart data are those of its last reduction increment:
    restarted from them, the run makes the failing trials again and claims the same factor
    (restarted before from the reduced state as if it were the step's start, it claimed
    Msf = 2.33331 after 10 increments for the 2.33289 after 15)."""
    full, rest = tmp_path / "full.h5", tmp_path / "rest.h5"
    assert run(BLOCK, full).returncode == 0
    r = run(BLOCK, rest, "--restart", full)
    assert r.returncode == 0, r.stderr
    with h5py.File(full) as F, h5py.File(rest) as R:
        assert len(R["history/step"]) == 0
        a, b = items(F["safety"]), items(R["safety"])
        assert a.keys() == b.keys() and all(equal(a[k], b[k]) for k in a)


def test_restart_data_without_the_safety_walk_are_refused(tmp_path):
    """Restart data of an earlier version, which kept no state of the safety step, at the end
    of the step before it may be of an increment inside it (a run killed there): refused
    (exit 2, no results file) instead of reducing from a state that is not the step's start.
    Stopped in an earlier step, they are read as before."""
    for n, code in ((3, 2), (1, 0)):
        part, rest = tmp_path / f"p{n}.h5", tmp_path / f"r{n}.h5"
        assert run(BLOCK, part, "--stop-after-increments", n).returncode == 4
        with h5py.File(part, "a") as f:
            del f["restart/safety"]  # as an earlier version wrote them
        r = run(BLOCK, rest, "--restart", part)
        assert r.returncode == code, (n, r.stderr)
        if code == 2:
            assert "earlier version" in r.stderr and "safety" in r.stderr
            assert not rest.exists()


@pytest.mark.parametrize("deck,points", [
    # arc-length with a NODE= target (step 1, increments 1-4), then an arc-length step
    # without one (5-8): inside each, at the landing on the target and after it
    ("test/data/progress/arc.inp", [1, 4, 5, 7]),
    # staged embankment, lifts activated with their weight (5 + 5 + 5 + 1 increments): at the
    # end of lift 1 (the next phase's changes made by the restarted run), after the first
    # increment of lift 2 (replayed) and of lift 3; a restarted staged run wrote no
    # initial_procedure attribute (it came with phase 1's record)
    ("input/examples/embankment_stages.inp", [5, 6, 11]),
    # undrained footing (40 increments): the excess pore pressures carried
    ("test/data/water/footing_undrained_a.inp", [20]),
])
def test_restart_equals_uninterrupted_everywhere(tmp_path, deck, points):
    """Other step kinds, stopped inside a step, at its end and after a phase change."""
    restarts_equal(tmp_path, ROOT / deck, points)


def test_restart_under_gravity_loading_with_water(tmp_path):
    """The slope of input/examples/slope_safety.inp under its weight (gravity loading, a
    phreatic level: the forces of the steady pore pressures are held and the water comes in
    with the gravity pattern), in 3 increments, stopped after the first and the second. Those
    forces were computed again by the restart from the restored displacements instead of the
    phase start's: the restarted run was 1e-14 (displacements) and 6e-9 (residuals) off.
    The file says `initial_procedure` = 'gravity loading'."""
    text = (ROOT / "input/examples/slope_safety.inp").read_text()
    text = text[:text.index("*STEP, NAME=safety")].replace(
        "*STEP, NAME=gravity, INCREMENTS=2", "*STEP, NAME=gravity, INCREMENTS=3")
    assert "INCREMENTS=3" in text
    deck = tmp_path / "slope_gravity.inp"
    deck.write_text(text)
    full = restarts_equal(tmp_path, deck, [1, 2])
    # (doc/results.md; the name was cut to 'gravity loadin')
    with h5py.File(full) as f:
        assert f.attrs["initial_procedure"] == "gravity loading"

