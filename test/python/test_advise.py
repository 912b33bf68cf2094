"""`pecplas --advise DECK` (`doc/build.md`, `doc/bench/README.md`) through the real executable: exit code 0, one table row
per configuration (six on the deck's mesh, two on the refined one, Q4 and Q8 decks alike), two advice lines whose error is below their threshold, and
no results file written.

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm."""

import re
import subprocess
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def pecplas():
    return pecplas_cmd()


def run(pecplas, *args, cwd=ROOT):
    return subprocess.run([*pecplas, *map(str, args)], cwd=cwd, capture_output=True, text=True)


def test_advise_prints_table_and_advice_writes_nothing(pecplas, tmp_path):
    # a copy of the S3 deck whose *OUTPUT would land in tmp_path: nothing may appear there
    deck = tmp_path / "s3_psi5.inp"
    text = (ROOT / "input/s3/s3_psi5.inp").read_text()
    text = re.sub(r"(?im)^\*OUTPUT.*$", "*OUTPUT, FILE=" + str(tmp_path / "never.h5"), text)
    deck.write_text(text)
    before = set(tmp_path.iterdir())
    r = run(pecplas, "--advise", deck)
    assert r.returncode == 0, r.stdout + r.stderr
    rows = [ln.split() for ln in r.stdout.splitlines()
            if ln.strip().startswith(("MODIFIED_NEWTON", "NEWTON"))]
    # columns: method, mesh, factor, increments, wall, error, status
    assert len(rows) == 8, r.stdout
    assert [x[1] for x in rows] == ["deck"] * 6 + ["h/2"] * 2, r.stdout
    # the reference (NEWTON x2 on the refined mesh) has error 0
    ref = [x for x in rows if x[0] == "NEWTON" and x[1] == "h/2" and float(x[2]) == 2.0]
    assert len(ref) == 1 and float(ref[0][5]) == 0.0, r.stdout
    assert "reference NEWTON x2 increments, mesh h/2" in r.stdout
    for thr, lab in ((0.01, "1 %"), (0.05, "5 %")):
        line = [ln for ln in r.stdout.splitlines() if ln.startswith(f"advice (error < {lab})")]
        assert len(line) == 1, r.stdout
        m = re.search(r"error ([0-9.E+-]+)$", line[0])
        assert m and float(m.group(1)) < thr, line[0]
    assert set(tmp_path.iterdir()) == before, "advice mode wrote files"


def test_advise_q8_deck_refines_its_mesh(pecplas):
    r = run(pecplas, "--advise", "input/examples/strip_footing.inp")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "mesh level not varied" not in r.stdout
    rows = [ln.split() for ln in r.stdout.splitlines()
            if ln.strip().startswith(("MODIFIED_NEWTON", "NEWTON"))]
    assert len(rows) == 8 and sum(x[1] == "h/2" for x in rows) == 2, r.stdout


def test_advise_bad_node_is_input_error(pecplas):
    r = run(pecplas, "--advise", "input/examples/strip_footing.inp", "--advise-node", "999999")
    assert r.returncode == 2
    assert "no node 999999" in r.stderr


def test_advise_node_needs_a_number(pecplas):
    r = run(pecplas, "--advise", "input/examples/strip_footing.inp", "--advise-node", "x")
    assert r.returncode == 2
    assert "--advise-node" in r.stderr
