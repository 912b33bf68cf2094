"""S1 opening-closing through the results file: compressed, then open with zero stress at
the end of the lift, then closed and compressed again; never a NaN. Runs the deck itself into
a fresh temporary directory every time (never a file left by an earlier run)."""

import subprocess
from pathlib import Path

import numpy as np
import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    path = tmp_path_factory.mktemp("s1") / "oc.h5"
    run = subprocess.run([*pecplas_cmd(), "input/s1/s1_open_close_kn1e5.inp", "-o", str(path),
                          "--quiet"], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert path.exists(), "pecplas exited 0 but wrote no " + str(path)
    with Results(path) as r:
        steps = r.history("step")
        rows = {}
        for key in r.keys:
            j = "joints/joint/"
            rows[int(key)] = (r.step_of(key), r.field(key, j + "stress").reshape(-1, 2),
                              r.field(key, j + "mode").ravel(),
                              r.field(key, j + "relative_displacement").reshape(-1, 2))
        yield steps, rows


def last_of_step(rows, step):
    return rows[max(k for k, r in rows.items() if r[0] == step)]


def test_compressed_open_closed(results):
    steps, rows = results
    # each row: (step, stress (sigma_n, tau), mode, relative displacement (eps_n, eps_t))
    comp, lift, close = (last_of_step(rows, s) for s in (1, 2, 3))
    assert np.all(comp[2] == 1) and np.all(comp[1][:, 0] > 1.3)     # stick, compressed
    assert np.all(lift[2] == 3)                                        # open
    assert np.all(lift[1] == 0.0)                                      # zero stress exactly
    assert np.all(lift[3][:, 0] < 0.0)    # eps_n = -g_n < 0: a real gap, no interpenetration
    assert np.all(close[2] != 3) and np.all(close[1][:, 0] > 0.0)     # re-contact


def test_no_nan(results):
    _, rows = results
    for _, s, _, e in rows.values():
        assert np.isfinite(s).all() and np.isfinite(e).all()


def test_docs_match_fresh_runs(tmp_path):
    """The S1 dilatancy numbers of doc/validation.md (generated block written by
    scenes/s1_report.py) equal those of fresh runs of the six decks to the last printed digit."""
    from pecplas_py.scenes import s1_report
    runs = s1_report.run_decks(s1_report.DILATANCY, tmp_path, pecplas_cmd())
    diff = s1_report.check_doc(runs)
    assert not diff, diff + ("\nregenerate: make s1 (python3 -m pecplas_py.scenes.s1_report "
                             "output/s1)")
