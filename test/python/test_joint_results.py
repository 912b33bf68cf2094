"""Joint sets in the results file of the real `pecplas` executable: the joint patch test
read back through pecplas_py.results (uniform contact pressure 100 at every joint point, all
in stick), and pecplas_py.checks.check_results accepting the file and catching damaged joint data.

Uses $PECPLAS_BIN (set by `make test` and CTest), else runs through fpm."""

import shutil
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_py.results import Results
from pecplas_exe import pecplas_cmd

from pecplas_py import script_cmd

ROOT = Path(__file__).resolve().parents[2]
CHECKER = script_cmd("checks.check_results")
DECK = "test/data/joints/patch_goodman6_axi_gen.inp"


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    cmd = pecplas_cmd()
    out = tmp_path_factory.mktemp("joints") / "patch.h5"
    r = subprocess.run([*cmd, DECK, "-o", str(out)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "slip 0 open 0" in r.stdout          # progress line counts joint modes
    return out


def checker(path):
    return subprocess.run([*CHECKER, path], capture_output=True, text=True)


def test_checker_accepts_joint_file(results):
    r = checker(results)
    assert r.returncode == 0, r.stdout
    assert "1 joint sets" in r.stdout


def test_joint_fields_read_back(results):
    with Results(results) as res:
        js = res.joint_set("joint")
        assert js.attrs["etype"] == "GOODMAN6" and js.attrs["law"] == "contact"
        conn = js["connectivity"][...]                       # (nel, 6), 0-based
        x = res.coordinates
        # doublets are coincident: face-1 node 1 with face-2 node 4, 2 with 3, 5 with 6
        for a, b in [(0, 3), (1, 2), (4, 5)]:
            assert np.array_equal(x[conn[:, a]], x[conn[:, b]])
        stress = res.field("000002", "joints/joint/stress")  # (nel, npoint, 2)
        assert stress.shape == (2, 3, 2)
        assert np.allclose(stress[..., 0], 100.0, rtol=1e-10)   # sigma_n = P
        assert np.allclose(stress[..., 1], 0.0, atol=1e-8)      # tau = 0
        assert np.all(res.field("000002", "joints/joint/mode") == 1)    # stick
        # the law sees closure: eps_n = sigma_n / KN > 0
        assert np.allclose(res.field("000002", "joints/joint/relative_displacement")[..., 0],
                           100.0 / 1e5, rtol=1e-10)


@pytest.fixture
def broken(results, tmp_path):
    for ext in (".h5", ".xmf"):
        shutil.copy(results.with_suffix(ext), tmp_path / ("patch" + ext))
    return tmp_path / "patch.h5"


def test_checker_catches_bad_mode(broken):
    with h5py.File(broken, "r+") as f:
        f["increments/000001/joints/joint/mode"][0, 0] = 9
    r = checker(broken)
    assert r.returncode == 1 and "mode holds values" in r.stdout


def test_checker_catches_missing_joint_fields(broken):
    with h5py.File(broken, "r+") as f:
        del f["increments/000002/joints/joint/stress"]
    r = checker(broken)
    assert r.returncode == 1 and "missing /increments/000002/joints/joint/stress" in r.stdout
