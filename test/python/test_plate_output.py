"""The plate in the tools (pecplas_py.structures, pecplas_py.plots.plot_structures): N, Q, M
and the deflection along a plate at the end of each phase in which the plate is active.

The file is the one the Fortran suite plates writes in its restart test (a cantilever plate
deactivated in phase 1, installed in phase 2, loaded at its tip by P = 100 in phase 3); under
`make test` its Fortran stage has just written it, otherwise this runs `fpm test -- plates`
first (PECPLAS_NO_FPM=1: use the file already there)."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from pecplas_py import script_cmd
from pecplas_py import structures
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
H5 = ROOT / "build" / "test_out" / "plates" / "restart_whole.h5"


@pytest.fixture(scope="module")
def cantilever():
    if not os.environ.get("PECPLAS_TEST_START") and not os.environ.get("PECPLAS_NO_FPM") \
            and shutil.which("fpm"):
        run = subprocess.run(["fpm", "test", "--", "plates", "restart_plate_activation"],
                             cwd=ROOT, capture_output=True, text=True)
        assert run.returncode == 0, run.stdout + run.stderr
    if not H5.exists():
        pytest.skip("run `fpm test -- plates` first")
    return H5


def test_curves_of_the_phases_with_the_plate(cantilever):
    with Results(cantilever) as r:
        env = structures.envelopes(r)
        line = structures.plate_line(r, "beam")
        # the clamp's reaction moment (F_int - F_ext at the held rotation): -P L
        reaction = r.field(r.last_key(), "plates/beam/moment_reaction")
    # phase 1 has the plate deactivated: no curve
    assert [p for p in sorted(env) if "beam" in env[p]["plates"]] == [2, 3]
    end = env[3]["plates"]["beam"]["end"]
    s, q, m, w = line["s"], end["Q"], end["M"], end["deflection"]
    # cantilever L = 10, tip load 100: M(0) = P L, Q = P, tip deflection
    # P L^3 / 3EI + P L / GAs (exact element: to roundoff, 1e-10 relative)
    assert s[-1] == pytest.approx(10.0, rel=1e-12)
    assert abs(m[0]) == pytest.approx(1000.0, rel=1e-10)
    assert abs(q) == pytest.approx([100.0] * len(q), rel=1e-10)
    assert abs(w[-1]) == pytest.approx(100 * 10**3 / 3e5 + 100 * 10 / (5e7 / 12), rel=1e-10)
    assert reaction[0] == pytest.approx(-1000.0, rel=1e-10)
    assert list(reaction[1:]) == [0.0] * (len(reaction) - 1)


def test_cli_writes_the_png(cantilever, tmp_path):
    out = tmp_path / "structures.png"
    run = subprocess.run([*script_cmd("plots.plot_structures"), str(cantilever), "-o", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_xdmf_shows_the_plate_where_it_is_active(cantilever):
    """The sidecar: a plates_beam grid (polylines, cell N, Q, M) in the 3 increments of the
    phases with the plate (2 and 3: installed, then 2 load increments), none in phase 1."""
    import xml.etree.ElementTree as ET
    root = ET.parse(cantilever.with_suffix(".xmf")).getroot()
    steps = [g for g in root.iter("Grid") if g.get("CollectionType") == "Spatial"]
    names = [[c.get("Name") for c in step.findall("Grid")] for step in steps]
    assert [("plates_beam" in n) for n in names] == [False, True, True, True]
    grid = next(c for c in steps[-1].findall("Grid") if c.get("Name") == "plates_beam")
    assert {a.get("Name") for a in grid.findall("Attribute")} == {"displacement", "N", "Q", "M"}
