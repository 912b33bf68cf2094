"""Runs the files written by the Fortran suite `io_results` through pecplas_py.checks.check_results,
and checks that the checker itself catches broken files.

Run from the project root:
    python3 -m pytest test/python/test_results_file.py
This first runs `fpm test -- io_results` (which writes output/test/io_results_*.h5); set
PECPLAS_NO_FPM=1 to use the files already there. Under `make test` the Fortran stage has just
written them: $PECPLAS_TEST_START names a file touched when that run began, and a file older
than it (left by an earlier run) fails the test.
"""

import os
import shutil
import subprocess
from pathlib import Path

import xml.etree.ElementTree as ET

import h5py
import numpy as np
import pytest

from pecplas_py import script_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "output" / "test"
CHECKER = script_cmd("checks.check_results")

# file written by the Fortran test -> status it must carry
EXPECTED = {
    "io_results_completed.h5": "completed",
    "io_results_running.h5": "running",
    "crash/io_results_running.h5": "running",
    "io_results_limit.h5": "limit load",
    "io_results_failed.h5": "failed",
    "io_results_final.h5": "running",
    "io_results_nopattern.h5": "completed",
    "io_results_phases.h5": "completed",
}


@pytest.fixture(scope="session", autouse=True)
def fortran_output():
    """Writes the files with the Fortran test suite (unless PECPLAS_NO_FPM is set, or under
    `make test`, whose first stage wrote them)."""
    start = os.environ.get("PECPLAS_TEST_START")
    if start:
        t0 = os.stat(start).st_mtime
        stale = [n for n in EXPECTED if not (OUT / n).exists() or (OUT / n).stat().st_mtime < t0]
        assert not stale, ("not written by the Fortran stage of this `make test` (did "
                           "`fpm test` fail?): " + ", ".join(stale))
        return
    if not os.environ.get("PECPLAS_NO_FPM") and shutil.which("fpm"):
        for suite in ("io_results", "io_results_phases"):
            run = subprocess.run(["fpm", "test", "--", suite], cwd=ROOT,
                                 capture_output=True, text=True)
            assert run.returncode == 0, f"fpm test -- {suite} failed:\n" + run.stdout + run.stderr
    missing = [name for name in EXPECTED if not (OUT / name).exists()]
    if missing:
        pytest.skip("run `fpm test -- io_results` first; missing " + ", ".join(missing))


def run_checker(*args):
    return subprocess.run([*CHECKER, *map(str, args)],
                          capture_output=True, text=True)


@pytest.mark.parametrize("name,status", sorted(EXPECTED.items()))
def test_fortran_files_pass_checker(name, status):
    # a file never finished keeps its temporary sidecar (checked in test_results_safety)
    extra = ["--no-xdmf"] if status == "running" else []
    run = run_checker(OUT / name, "--expect-status", status, *extra)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.startswith("OK")


def test_completed_file_contents():
    """Independent reading with h5py: shapes as documented, strings as str."""
    with h5py.File(OUT / "io_results_completed.h5", "r") as f:
        assert f.attrs["status"] == "completed" and int(f.attrs["complete"]) == 1
        assert isinstance(f.attrs["deck_text"], str) and "résultats" in f.attrs["deck_text"]
        assert f["mesh/coordinates"].shape == (7, 2)
        assert f["mesh/sets/SOIL/connectivity"][...].tolist() == [[0, 1, 4, 3], [1, 2, 5, 4]]
        assert list(f["history"].attrs["patterns"]) == ["WEIGHT", "HEAD_LOAD"]
        assert f["history/time"][...].tolist() == [0.5, 1.0, 1.5]
        u3 = f["increments/000002/displacement3"][...]
        assert np.array_equal(u3[:, :2], f["increments/000002/displacement"][...])
        assert not u3[:, 2].any()
        stress = f["increments/000003/sets/SOIL/stress"][...]  # (nel, ngauss, 4)
        mean = f["increments/000003/sets/SOIL/stress_mean"][...]
        # mean over 4 Gauss points: a few roundings
        assert np.allclose(mean, stress.mean(axis=1), rtol=4 * np.finfo(float).eps, atol=0)


@pytest.fixture
def broken(tmp_path):
    """A copy of the completed file and its .xmf, to be damaged by a test."""
    for ext in (".h5", ".xmf"):
        shutil.copy(OUT / ("io_results_completed" + ext), tmp_path / ("io_results_completed" + ext))
    return tmp_path / "io_results_completed.h5"


def test_checker_catches_nan(broken):
    with h5py.File(broken, "r+") as f:
        f["increments/000002/sets/SOIL/strain"][0, 0, 0] = np.nan
    run = run_checker(broken)
    assert run.returncode == 1 and "non-finite" in run.stdout


def test_checker_catches_unequal_history(broken):
    with h5py.File(broken, "r+") as f:
        f["history/residual"].resize((2,))
    run = run_checker(broken)
    assert run.returncode == 1 and "differ in length" in run.stdout


def test_checker_catches_half_row_of_a_running_file(broken):
    """A running file is read only when flushed after a whole increment (doc/results.md,
    "Safety"): a row in some history columns only, or fields without their row, are
    problems in a 'running' file too."""
    with h5py.File(broken, "r+") as f:
        f.attrs["status"], f.attrs["complete"] = "running", 0
        f["history/residual"].resize((2,))
    run = run_checker(broken)
    assert run.returncode == 1 and "differ in length" in run.stdout
    with h5py.File(broken, "r+") as f:
        f["history/residual"].resize((3,))
        f.copy("increments/000003", "increments/000004")
    run = run_checker(broken)
    assert run.returncode == 1 and "/increments/000004 has no history row" in run.stdout


def test_checker_catches_bad_xdmf_reference(broken):
    xmf = broken.with_suffix(".xmf")
    text = xmf.read_text()
    xmf.write_text(text.replace("/increments/000003/reaction3", "/increments/000003/nothing", 1)
                   .replace('Dimensions="2 4"', 'Dimensions="4 2"', 1))
    run = run_checker(broken)
    assert run.returncode == 1
    assert "no dataset /increments/000003/nothing" in run.stdout
    assert "Dimensions (4, 2)" in run.stdout


def test_checker_catches_false_completion(broken):
    with h5py.File(broken, "r+") as f:
        f.attrs["status"] = "diverged"
    run = run_checker(broken)
    assert run.returncode == 1 and "contradicts" in run.stdout


def xdmf_grids(xmf):
    """{increment grid name: set of the names of its grids} of a sidecar, in time order."""
    root = ET.parse(xmf).getroot()
    out = {}
    for grid in root.iter("Grid"):
        if grid.get("CollectionType") == "Spatial":
            out[grid.get("Name")] = {g.get("Name") for g in grid.findall("Grid")}
    return out


def test_phases_listed_and_played_by_the_xdmf():
    """A staged run (io_results_phases: LINING removed in phase 2, installed again in phase
    3): the reader lists the phases and their changes, the removed set has no fields and no
    grid in the increments of phase 2, and the sidecar shows it again afterwards."""
    with Results(OUT / "io_results_phases.h5") as r:
        phases = r.phases()
        assert [p["name"] for p in phases] == ["geostatic", "excavate", "install"]
        assert phases[1]["changes"] == ["DEACTIVATE LINING (1 element)"]
        assert phases[2]["changes"] == ["ACTIVATE LINING, STRESS=ZERO",
                                        "CHANGE_MATERIAL SOIL, clay2"]
        assert [p["first_global_increment"] for p in phases] == [1, 3, 4]
        assert phases[0]["changes"] == ["initial procedure: K0 procedure"]
        assert r.attr("initial_procedure") == "K0 procedure"
        assert phases[1]["active_element_sets"] == ["SOIL"]
        assert r.active_sets("000003") == (["SOIL"], [])
        assert r.active_sets("000004") == (["LINING", "SOIL"], [])
    grids = xdmf_grids(OUT / "io_results_phases.xmf")
    assert grids == {"000001": {"SOIL", "LINING"}, "000002": {"SOIL", "LINING"},
                     "000003": {"SOIL"}, "000004": {"SOIL", "LINING"}}


def test_checker_catches_fields_of_a_removed_set(tmp_path):
    for ext in (".h5", ".xmf"):
        shutil.copy(OUT / ("io_results_phases" + ext), tmp_path / ("io_results_phases" + ext))
    broken = tmp_path / "io_results_phases.h5"
    with h5py.File(broken, "r+") as f:
        f.copy("increments/000002/sets/LINING", "increments/000003/sets/LINING")
    run = run_checker(broken, "--no-xdmf")
    assert run.returncode == 1 and "fields of a set not active" in run.stdout
