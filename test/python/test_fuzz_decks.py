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

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
from mutate_decks import mutate_once  # noqa: E402  (one mutator: tools/mutate_decks.py)

ROOT = Path(__file__).resolve().parents[2]
CHECKER = ROOT / "tools" / "check_results.py"
SOURCES = ["input/examples/strip_footing.inp", "input/s1/s1_friction_psi3_kn5e6.inp",
           "test/data/cli/oedometer.inp", "test/data/initial/geostatic_column.inp"]


@pytest.fixture(scope="module")
def exe():
    return pecplas_cmd()


@pytest.mark.parametrize("case", range(int(os.environ.get("PECPLAS_FUZZ_CASES", "80"))))
def test_mutated_deck_never_crashes(exe, tmp_path, case):
    rng = random.Random(1000 + case)
    src = ROOT / SOURCES[case % len(SOURCES)]
    deck = tmp_path / src.name
    deck.write_text("\n".join(mutate_once(src.read_text().splitlines(), rng)) + "\n")
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
