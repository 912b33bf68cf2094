"""The phase-by-phase figure (pecplas_py.plots.plot_phases) of a staged results file: one
panel per phase, only the sets active in it.

The file is the one the Fortran suite io_results_phases writes (LINING removed in phase 2
and installed again in phase 3); under `make test` its Fortran stage has just written it,
otherwise this runs `fpm test -- io_results_phases` first (PECPLAS_NO_FPM=1: use the file
already there)."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from pecplas_py import script_cmd
from pecplas_py.plots import plot_phases
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
H5 = ROOT / "output" / "test" / "io_results_phases.h5"


@pytest.fixture(scope="module")
def phased():
    if not os.environ.get("PECPLAS_TEST_START") and not os.environ.get("PECPLAS_NO_FPM") \
            and shutil.which("fpm"):
        run = subprocess.run(["fpm", "test", "--", "io_results_phases"], cwd=ROOT,
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stdout + run.stderr
    if not H5.exists():
        pytest.skip("run `fpm test -- io_results_phases` first")
    return H5


def test_one_panel_per_phase_with_the_active_sets_only(phased):
    with Results(phased) as r:
        data = plot_phases.panels(r)
    assert [d["phase"]["index"] for d in data] == [1, 2, 3]
    # SOIL: 2 quadrilaterals; LINING: 1 triangle, removed in phase 2
    assert [len(d["rings"]) for d in data] == [3, 2, 3]


def test_cli_writes_the_png(phased, tmp_path):
    out = tmp_path / "phases.png"
    run = subprocess.run([*script_cmd("plots.plot_phases"), str(phased), "-o", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "(3 phases)" in run.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
