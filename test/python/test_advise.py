"""`pecplas --advise DECK` (`doc/adapt.md`, `doc/build.md`) through the real executable: the mesh
axis is the adaptive sequence, and the configuration advised for 1 % and 5 % really is within its
claimed error of an independent reference computed here (uniform meshes of the same elastic strip
footing, pecplas_py.decks.make_default_deck, 16 x 8 and 32 x 16 Q8); no results file is written; bad
goals are input errors.

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm."""

import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py import script_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
# a 2 x 1 Q8 strip footing (2 m x 1 m block, footing half-width 1 m, elastic, gravity then
# 100 kPa): small enough that the whole advice takes a few seconds
GEOMETRY = ["--width", "2", "--depth", "1"]
ROW = re.compile(r"^\s+(\d+)\s+(\d+)\s+(MODIFIED_NEWTON|NEWTON)\s+(\S+)\s+(\d+)\s+(\S+)\s+(\S+)"
                 r"\s+(\S+)\s+(\S+)\s+(.*)$")


@pytest.fixture(scope="session")
def pecplas():
    return pecplas_cmd()


def run(pecplas, *args, cwd=ROOT):
    return subprocess.run([*pecplas, *map(str, args)], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def footing(path, nx, ny):
    subprocess.run([*script_cmd("decks.make_default_deck"), "--nx", str(nx),
                    "--ny", str(ny), *GEOMETRY, "-o", str(path)], check=True,
                   capture_output=True)
    return path


@pytest.fixture(scope="module")
def uniform(pecplas, tmp_path_factory):
    """Displacements (x, y) -> u of the 16 x 8 and 32 x 16 uniform meshes."""
    tmp = tmp_path_factory.mktemp("uniform")
    out = []
    for nx in (16, 32):
        deck = footing(tmp / f"u{nx}.inp", nx, nx // 2)
        r = run(pecplas, deck, "-o", tmp / f"u{nx}.h5", "--quiet")
        assert r.returncode == 0, r.stderr
        with Results(tmp / f"u{nx}.h5") as r:
            x = r.coordinates
            u = r.field(r.last_key(), "displacement")
        out.append((x, u))
    return out


def independent(uniform, point, comp):
    """Reference value at `point` (component comp) from the 32 x 16 mesh, and its relative
    uncertainty: the change from 16 x 8 to 32 x 16 (Q8 converges at least linearly here,
    so the remaining error is no larger than that change)."""
    vals = []
    for x, u in uniform:
        i = int(np.argmin(np.hypot(x[:, 0] - point[0], x[:, 1] - point[1])))
        assert np.hypot(*(x[i] - point)) < 1e-12
        vals.append(u[i, comp])
    return vals[1], abs(vals[1] - vals[0]) / abs(vals[1])


def parse(stdout):
    rows = [m.groups() for m in map(ROW.match, stdout.splitlines()) if m]
    advice = {}
    for lab in ("1 %", "5 %"):
        line = [ln for ln in stdout.splitlines() if ln.startswith(f"advice (error < {lab})")]
        assert len(line) == 1, stdout
        advice[lab] = line[0]
    return rows, advice


def advised_row(rows, line):
    """The table row of an advice line (method, increments, level)."""
    m = re.search(r"METHOD=(\S+), INCREMENTS=(\d+) .*mesh: (the deck's|adaptive level (\d+)) "
                  r"\((\d+) DOFs\), estimated error (\S+),", line)
    assert m, line
    level = int(m.group(4) or 1)
    hit = [r for r in rows if r[2] == m.group(1) and int(r[4]) == int(m.group(2))
           and int(r[0]) == level]
    assert len(hit) >= 1, line
    assert int(hit[0][1]) == int(m.group(5))
    assert float(hit[0][8]) == pytest.approx(float(m.group(6)), rel=1e-3)
    return hit[0]


@pytest.mark.parametrize("goal, point, comp", [
    # default goal: the node of largest free displacement (footing centre, vertical); the
    # deck's own mesh is within 1 % here
    (None, (0.0, 0.0), 1),
    # horizontal displacement at the surface beyond the footing edge: the deck's mesh is 16 %
    # off, so the advice must come from a refined level of the adaptive sequence
    ("node:12:x", (1.5, 0.0), 0)])
def test_advised_configuration_meets_its_claim(pecplas, tmp_path, uniform, goal, point, comp):
    deck = footing(tmp_path / "footing.inp", 2, 1)
    before = set(tmp_path.iterdir())
    r = run(pecplas, "--advise", deck, *(["--goal", goal] if goal else []))
    assert r.returncode == 0, r.stdout + r.stderr
    assert set(tmp_path.iterdir()) == before, "advice mode wrote files"
    rows, advice = parse(r.stdout)
    ref, unc = independent(uniform, np.array(point), comp)
    print(f"\nindependent reference {ref:.6e} (uncertainty {unc:.1e})")
    levels = sorted({int(x[0]) for x in rows})
    assert levels == list(range(1, levels[-1] + 1)) and levels[-1] >= 3, r.stdout
    m = re.search(r"reference: level (\d+), goal (\S+), its own estimated error (\S+) %",
                  r.stdout)
    assert m and int(m.group(1)) == levels[-1], r.stdout
    # the finest level is within its own estimate of the independent reference (allowance:
    # the independent reference's uncertainty)
    ref_err = float(m.group(3)) / 100
    assert abs(float(m.group(2)) - ref) / abs(ref) <= ref_err + unc + 1e-5, r.stdout
    for lab, tol in (("1 %", 0.01), ("5 %", 0.05)):
        row = advised_row(rows, advice[lab])
        claimed, value = float(row[8]), float(row[7])
        true = abs(value - ref) / abs(ref)
        print(f"{lab}: level {row[0]}, {row[1]} DOFs, claimed {claimed:.3e}, "
              f"against the independent reference {true:.3e}")
        # the claim: below the tolerance, and a bound of the true error (up to what the
        # independent reference resolves)
        assert claimed < tol, advice[lab]
        assert true <= claimed + unc, advice[lab]
        assert true < tol, advice[lab]
        # the cheapest (by cost) of the rows whose error is below the tolerance
        ok = [x for x in rows if x[9].startswith("completed") and float(x[8]) < tol]
        assert float(row[6]) <= min(float(x[6]) for x in ok), advice[lab]
    if goal:
        assert int(advised_row(rows, advice["1 %"])[0]) > 1, r.stdout


def test_advise_bad_goal_is_input_error(pecplas, tmp_path):
    deck = footing(tmp_path / "footing.inp", 2, 1)
    for args, text in ((["--goal", "node:999999:y"], "no node 999999"),
                       (["--goal", "energy"], "takes node goals"),
                       (["--goal", "node:1:q"], "expected node:N:x"),
                       (["--advise-node", "999999"], "no node 999999")):
        r = run(pecplas, "--advise", deck, *args)
        assert r.returncode == 2, r.stdout + r.stderr
        assert text in r.stderr, r.stderr
        assert "advise" in r.stderr


def test_advise_node_needs_a_number(pecplas):
    r = run(pecplas, "--advise", "input/examples/strip_footing.inp", "--advise-node", "x")
    assert r.returncode == 2
    assert "--advise-node" in r.stderr
