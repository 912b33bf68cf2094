"""Restart (doc/results.md, "Restart"): a run stopped in the middle of a step
(--stop-after-increments N, the test hook standing for a wall-time kill) and continued with
--restart equals the uninterrupted run; a results file of another deck is refused."""
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]


def run(args, cwd):
    return subprocess.run(pecplas_cmd() + [str(a) for a in args] + ["--quiet"], cwd=cwd,
                          capture_output=True, text=True)


def last_fields(path):
    with h5py.File(path) as f:
        k = sorted(f["increments"])[-1]
        g = f["increments"][k]
        joints = {n: g["joints"][n]["stress"][:] for n in g.get("joints", {})}
        rows = list(zip(f["history/step"][:], f["history/increment"][:],
                        f["history/global_increment"][:]))
        return g["displacement"][:], joints, rows, f.attrs["status"]


def interrupted_and_restarted(tmp_path, deck, n):
    """(full run, restarted run) results of `deck` stopped after n increments."""
    d = ROOT / deck
    full, part, rest = tmp_path / "full.h5", tmp_path / "part.h5", tmp_path / "rest.h5"
    r = run([d, "-o", full], d.parent)
    assert r.returncode in (0, 3), r.stderr
    r = run([d, "-o", part, "--stop-after-increments", n], d.parent)
    assert r.returncode == 4, r.stderr  # interrupted
    with h5py.File(part) as f:
        assert f.attrs["status"] == "interrupted" and len(f["history/step"]) == n
    r = run([d, "-o", rest, "--restart", part], d.parent)
    assert r.returncode in (0, 3), r.stderr
    return last_fields(full), last_fields(part), last_fields(rest)


@pytest.mark.parametrize("deck,n", [
    # MODJOIN cyclic penalty joint, full Newton: stopped 10 increments into the first reversal
    ("test/data/modjoin/fe_cyclic.inp", 30),
    # Katona contact (S1 box opening and closing): stopped in the middle of the opening step
    ("test/data/katona/s1_open_close.inp", 18),
    # Katona, friction limit: stopped after increment cuts (the halved size is resumed)
    ("test/data/katona/pad_slip.inp", 6)])
def test_restart_equals_uninterrupted(tmp_path, deck, n):
    """Final displacements and joint stresses equal the uninterrupted run's to 1e-12
    (relative to their largest value: the same arithmetic from the same state, roundoff
    only); the restarted history continues the interrupted one row for row."""
    (ua, ja, rows_a, st_a), (_, _, rows_b, _), (uc, jc, rows_c, st_c) = \
        interrupted_and_restarted(tmp_path, deck, n)
    assert st_a == st_c
    assert np.abs(uc - ua).max() <= 1e-12 * np.abs(ua).max()
    assert ja.keys() == jc.keys()
    for name in ja:
        assert np.abs(jc[name] - ja[name]).max() <= 1e-12 * np.abs(ja[name]).max(), name
    assert rows_b + rows_c == rows_a


def test_restart_from_another_deck_is_refused(tmp_path):
    """A results file of another deck: exit 2, a message saying so, no results file."""
    a = ROOT / "test/data/katona/s1_open_close.inp"
    b = ROOT / "test/data/katona/pad_slip.inp"
    r = run([a, "-o", tmp_path / "a.h5", "--stop-after-increments", 3], a.parent)
    assert r.returncode == 4
    r = run([b, "-o", tmp_path / "b.h5", "--restart", tmp_path / "a.h5"], b.parent)
    assert r.returncode == 2
    assert "written by another deck" in r.stderr and "a.h5" in r.stderr
    assert not (tmp_path / "b.h5").exists()
    r = run([a, "-o", tmp_path / "a.h5", "--restart", tmp_path / "a.h5"], a.parent)
    assert r.returncode == 2 and "another file" in r.stderr


def test_sigterm_then_restart_equals_uninterrupted(tmp_path):
    """A real SIGTERM (what Slurm sends before its kill) in the middle of the MODJOIN cyclic
    run: exit 4, status 'interrupted'; the run restarted from that file ends where the
    uninterrupted run ends (displacements and joint stresses to 1e-12). The signal's moment
    is the machine's: the assertion holds wherever it lands."""
    import signal
    import time
    d = ROOT / "test/data/modjoin/fe_cyclic.inp"
    full, part, rest = tmp_path / "full.h5", tmp_path / "part.h5", tmp_path / "rest.h5"
    if pecplas_cmd()[0] == "fpm":
        pytest.skip("the signal must reach pecplas itself, not `fpm run` (set PECPLAS_BIN)")
    t0 = time.monotonic()
    assert run([d, "-o", full], d.parent).returncode == 0
    duration = time.monotonic() - t0
    with h5py.File(full) as f:
        total = len(f["history/step"])
    proc = subprocess.Popen(pecplas_cmd() + [str(d), "-o", str(part), "--quiet"], cwd=d.parent,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(0.4 * duration)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    if proc.returncode == 0:
        pytest.skip("the run finished before the signal arrived (machine too fast for it)")
    assert proc.returncode == 4, err
    with h5py.File(part) as f:
        assert f.attrs["status"] == "interrupted"
        done = len(f["history/step"])
    assert 0 < done < total
    r = run([d, "-o", rest, "--restart", part], d.parent)
    assert r.returncode == 0, r.stderr
    ua, ja, _, _ = last_fields(full)
    uc, jc, _, _ = last_fields(rest)
    print(f"SIGTERM after {done} of {total} increments; restarted to the end")
    assert np.abs(uc - ua).max() <= 1e-12 * np.abs(ua).max()
    for name in ja:
        assert np.abs(jc[name] - ja[name]).max() <= 1e-12 * np.abs(ja[name]).max(), name
