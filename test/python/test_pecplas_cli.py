"""The real `pecplas` executable, as a user or a batch script runs it: exit codes, the
results file and its XDMF sidecar, and the physics of the strip-footing example's geostatic
step (input/examples/strip_footing.inp; `make run`'s own deck, the S2 pile, is checked by
test_s2_s3.py).

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm."""

import subprocess
from pathlib import Path

import numpy as np
import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py import script_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
CHECKER = script_cmd("checks.check_results")


@pytest.fixture(scope="session")
def pecplas():
    return pecplas_cmd()


def run(pecplas, *args):
    return subprocess.run([*pecplas, *map(str, args)], cwd=ROOT, capture_output=True,
                          text=True)


def test_strip_footing_runs_and_geostatic_settlement_is_exact(pecplas, tmp_path):
    out = tmp_path / "strip_footing.h5"
    r = run(pecplas, "input/examples/strip_footing.inp", "-o", out)
    assert r.returncode == 0, r.stdout + r.stderr
    # one progress line per increment: 1 geostatic + 5 loading
    assert sum(" inc " in line for line in r.stdout.splitlines()) == 6
    assert "status: completed" in r.stdout
    chk = subprocess.run([*CHECKER, out, "--expect-status", "completed"],
                         capture_output=True, text=True)
    assert chk.returncode == 0, chk.stdout + chk.stderr
    with Results(out) as res:
        x = res.coordinates                               # (nnode, 2)
        u = res.field("000001", "displacement")           # after gravity only
        # laterally confined column of depth H = 2 under its own weight: the surface
        # settles gamma H^2 / (2 M) with M = E (1 - nu) / ((1 + nu)(1 - 2 nu)); the
        # quadratic profile is inside the Q8 space, so the agreement is to round-off.
        E, nu, gamma, H = 2.0e4, 0.3, 18.0, 2.0
        M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
        top = np.isclose(x[:, 1], 0.0)
        assert np.allclose(u[top, 1], -gamma * H**2 / (2 * M), rtol=1e-10)
        # vertical reactions balance the weight gamma * H * width (width 4)
        reac = res.field("000001", "reaction")
        assert np.isclose(reac[:, 1].sum(), gamma * H * 4.0, rtol=1e-10)


def test_input_error_exit_2_names_file_line_and_writes_nothing(pecplas, tmp_path):
    out = tmp_path / "bad.h5"
    deck = "test/data/decks/bad_nu_half.inp"
    r = run(pecplas, deck, "-o", out, "--quiet")
    assert r.returncode == 2
    assert deck + ":" in r.stderr and "NU" in r.stderr
    assert not out.exists()


def test_singular_model_exit_2(pecplas, tmp_path):
    out = tmp_path / "floating.h5"
    r = run(pecplas, "test/data/cli/floating.inp", "-o", out, "--quiet")
    assert r.returncode == 2
    assert "singular" in r.stderr and "direction" in r.stderr
    assert not out.exists()


def test_stopped_run_exit_3_keeps_increments(pecplas, tmp_path):
    out = tmp_path / "diverge.h5"
    r = run(pecplas, "test/data/cli/diverge.inp", "-o", out, "--quiet")
    assert r.returncode == 3
    assert r.stdout == ""          # --quiet: nothing on stdout
    chk = subprocess.run([*CHECKER, out, "--expect-status", "diverged"],
                         capture_output=True, text=True)
    assert chk.returncode == 0, chk.stdout + chk.stderr
    with Results(out) as res:
        assert not res.complete
        assert len(res.history("step")) == 2


@pytest.mark.parametrize("args,code", [(["--help"], 0), (["--version"], 0), ([], 2),
                                       (["--bogus"], 2), (["a.inp", "b.inp"], 2),
                                       (["no_such_deck.inp"], 2)])
def test_command_line(pecplas, args, code):
    r = run(pecplas, *args)
    assert r.returncode == code, r.stdout + r.stderr
