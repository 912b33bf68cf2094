"""Installation: `cmake --install` of the CMake build into a temporary prefix puts the four
programs, pecplas-sweep, pecplas-plot and pecplas-slope into PREFIX/bin; the installed pecplas runs the default deck and
reports its version and libraries (README, doc/build.md). `make test` builds with CMake first
and sets PECPLAS_BIN to that build's pecplas; without it the test is skipped."""
import os
import subprocess
from pathlib import Path

import pytest

from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
PROGRAMS = ["pecplas", "pecplas-path", "pecplas-identify", "pecplas-sensitivity", "pecplas-sweep",
            "pecplas-plot", "pecplas-slope"]


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    exe = os.environ.get("PECPLAS_BIN")
    if not exe or not (Path(exe).parent / "cmake_install.cmake").is_file():
        pytest.skip("needs PECPLAS_BIN in a CMake build tree (make test sets it)")
    p = tmp_path_factory.mktemp("prefix")
    r = subprocess.run(["cmake", "--install", str(Path(exe).parent), "--prefix", str(p)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    return p


def test_installed_programs(prefix):
    """Exactly the seven programs, executable (no benchmark or test program)."""
    assert sorted(q.name for q in (prefix / "bin").iterdir()) == sorted(PROGRAMS)
    assert all(os.access(prefix / "bin" / q, os.X_OK) for q in PROGRAMS)


def test_installed_pecplas_runs_default_deck(prefix, tmp_path):
    """The README's usage line with the installed binary, run outside the source tree:
    completes (exit 0) with the thesis pile's settlement of 78 mm at 2000 kN (README, to the
    millimetre it states)."""
    out = tmp_path / "default.h5"
    r = subprocess.run([str(prefix / "bin/pecplas"), str(ROOT / "input/default.inp"), "-o",
                        str(out), "--quiet"], cwd=tmp_path, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with Results(out) as r:
        assert r.status == "completed"
        x = r.coordinates
        centre = int(((x[:, 0] ** 2 + x[:, 1] ** 2)).argmin())
        fac = r.pattern_factors()[:, 0]
        key = f"{int(r.history('global_increment')[fac.argmax()]):06d}"
        s = -r.field(key, "displacement")[centre, 1]
    assert abs(s - 0.078) < 0.0005


def test_installed_slope_help(prefix):
    """pecplas-slope is installed as a script that runs with the system Python."""
    r = subprocess.run([str(prefix / "bin/pecplas-slope"), "--help"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and "--phreatic" in r.stdout


def test_installed_version(prefix):
    """--version names the version of fpm.toml, a commit, the compiler and the libraries."""
    r = subprocess.run([str(prefix / "bin/pecplas"), "--version"], capture_output=True,
                       text=True)
    assert r.returncode == 0
    lines = r.stdout.splitlines()
    version = next(ln.split('"')[1] for ln in (ROOT / "fpm.toml").read_text().splitlines()
                   if ln.startswith("version"))
    assert lines[0] == f"PECPLAS {version}"
    keys = [ln.split(":")[0] for ln in lines[1:]]
    assert keys == ["commit", "compiler", "SuiteSparse", "HDF5", "MUMPS"]
    assert len(lines[1]) > len("commit: ") and lines[2].startswith("compiler: ")
    assert "CHOLMOD" in lines[3] and lines[5] == "MUMPS: not built"


def test_installed_sweep_help(prefix):
    """pecplas-sweep is installed as a script that runs with the system Python."""
    r = subprocess.run([str(prefix / "bin/pecplas-sweep"), "--help"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and "collect" in r.stdout


def test_installed_plot_help(prefix):
    """pecplas-plot is installed as a script that runs with the system Python."""
    r = subprocess.run([str(prefix / "bin/pecplas-plot"), "--help"], capture_output=True,
                       text=True)
    assert r.returncode == 0 and "--range-set" in r.stdout
