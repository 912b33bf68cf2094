"""`pecplas DECK --target-error E [--goal node:N:x|y]` (`doc/adapt.md`) through the real
executable, on the L-shaped plate of test/data/adapt: one line per level with growing DOFs, the
target met (exit 0) and the last level written as a checked results file; bad option values are
input errors (exit 2, a message naming what was expected, no results file).

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm."""

import re
import subprocess
import sys
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
DECK = ROOT / "test/data/adapt/lshape.inp"
LEVEL = re.compile(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$")


@pytest.fixture(scope="session")
def pecplas():
    return pecplas_cmd()


def run(pecplas, *args):
    return subprocess.run([*pecplas, *map(str, args)], cwd=ROOT, capture_output=True, text=True)


def test_energy_target_met_last_level_written(pecplas, tmp_path):
    out = tmp_path / "l.h5"
    r = run(pecplas, DECK, "--target-error", "15%", "-o", out)
    assert r.returncode == 0, r.stderr
    levels = [m.groups() for m in map(LEVEL.match, r.stdout.splitlines()) if m]
    dofs = [int(g[1]) for g in levels]
    # the energy estimate is the goal error: the last level is the first one below 15 %
    est = [float(g[5]) for g in levels]
    assert len(levels) >= 2 and dofs == sorted(set(dofs))
    assert est[-1] <= 15.0 and all(e > 15.0 for e in est[:-1])
    assert "target met at level %d" % len(levels) in r.stdout
    check = subprocess.run([sys.executable, str(ROOT / "tools/check_results.py"), str(out)],
                           capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr


@pytest.mark.parametrize("args, expected", [
    (["--target-error", "1x"], "expected a relative error such as 1% or 0.01"),
    (["--target-error", "150%"], "expected a relative error such as 1% or 0.01"),
    (["--target-error", "1%", "--goal", "node:0:y"], "expected node:N:x, node:N:y"),
    (["--target-error", "1%", "--goal", "node:9999:y"], "the deck has no node 9999"),
    (["--goal", "node:21:y"], "--goal and --max-dofs need --target-error"),
])
def test_bad_options_exit_2_nothing_written(pecplas, tmp_path, args, expected):
    out = tmp_path / "l.h5"
    r = run(pecplas, DECK, *args, "-o", out)
    assert r.returncode == 2
    assert expected in r.stderr
    assert not out.exists()
