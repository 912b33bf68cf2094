"""Robustness: mutated copies of real decks (lines deleted, duplicated, swapped, numbers
replaced by garbage or extreme values, truncated files) must never crash the program: exit
code 0, 2 (input error) or 3 (stopped), a message on stderr for 2, and any results file left
behind passes the checker (no NaN, consistent history). Fixed seed, so failures reproduce."""
import os
import random
import subprocess
import sys
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
CHECKER = ROOT / "tools" / "check_results.py"
SOURCES = ["input/examples/strip_footing.inp", "input/s1/s1_friction_psi3_kn5e6.inp",
           "test/data/cli/oedometer.inp", "test/data/initial/geostatic_column.inp"]
GARBAGE = ["abc", "1e999", "-1e999", "nan", "0", "-0", "1e-320", "*", ",", "", "9" * 40,
           "-7", "3.5.1", "*NODES", "1, 2", "ALL"]


def mutate(text, rng):
    lines = text.splitlines()
    kind = rng.randrange(5)
    i = rng.randrange(len(lines))
    if kind == 0:
        del lines[i]
    elif kind == 1:
        lines.insert(i, lines[rng.randrange(len(lines))])
    elif kind == 2:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind == 3:
        fields = lines[i].split(",")
        fields[rng.randrange(len(fields))] = rng.choice(GARBAGE)
        lines[i] = ",".join(fields)
    else:
        lines = lines[: rng.randrange(1, len(lines))]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def exe():
    return pecplas_cmd()


@pytest.mark.parametrize("case", range(int(os.environ.get("PECPLAS_FUZZ_CASES", "80"))))
def test_mutated_deck_never_crashes(exe, tmp_path, case):
    rng = random.Random(1000 + case)
    src = ROOT / SOURCES[case % len(SOURCES)]
    deck = tmp_path / src.name
    deck.write_text(mutate(src.read_text(), rng))
    # relative includes/meshes of the source deck stay reachable
    out = tmp_path / "r.h5"
    r = subprocess.run([*exe, str(deck), "-o", str(out), "--quiet"], cwd=ROOT,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode in (0, 2, 3), (r.returncode, r.stderr[-2000:])
    if r.returncode == 2:
        assert "pecplas: error:" in r.stderr
    if out.exists():
        chk = subprocess.run([sys.executable, str(CHECKER), str(out)], capture_output=True,
                             text=True)
        assert chk.returncode == 0, chk.stdout + chk.stderr
