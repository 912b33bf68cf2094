"""Robustness: mutated copies of real decks (lines deleted, duplicated, swapped, numbers
replaced by garbage or extreme values, truncated files) must never crash the program: exit
code 0, 2 (input error) or 3 (stopped), a message on stderr for 2, and any results file left
behind passes the checker (no NaN, consistent history). Fixed seed, so failures reproduce."""
import os
import random
import subprocess
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py.checks import check_results
from pecplas_py.checks.mutate_decks import mutate_once  # one mutator: checks/mutate_decks.py

ROOT = Path(__file__).resolve().parents[2]
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
        # the checker's own function, as `python3 -m pecplas_py.checks.check_results r.h5`
        # runs it (its .xmf beside it checked too), in this process: a new interpreter for
        # each file cost 1 s of CPU in imports alone (the CLI itself: test_results_file.py)
        problems, summary = check_results.check(str(out))
        assert not problems, f"{out}: {summary}\n" + "\n".join(problems)


BIG = 12_000_000  # characters: more than the 8 MB stack of a default Linux process
HUGE_TOKENS = {
    # a number of 12 million digits: converted through a stack buffer of its length
    # (segfault before)
    "long_number": ("2, 1, 0\n", "2, 1." + "5" * BIG + ", 0\n", 0, ""),
    # an unknown keyword of 12 MB: its name was grown a character at a time (quadratic:
    # more than a minute before)
    "long_keyword": ("*MATERIAL", "*" + "A" * BIG + "\n*MATERIAL", 2, "unknown keyword"),
    # names quoted by the messages are cut ('...(n characters)'), not printed whole
    "long_material_name": ("NAME=soil", "NAME=" + "A" * BIG, 2, "undefined material 'soil'"),
    "long_set_name": ("*SECTION, SET=block", "*SECTION, SET=" + "A" * BIG, 2,
                      "undefined element set"),
    "long_include": ("*NODES", "*INCLUDE, FILE=" + "A" * BIG + "\n*NODES", 2,
                     "cannot read include file"),
    "long_comment": ("*MATERIAL", "** " + "A" * BIG + "\n*MATERIAL", 0, ""),
    # parameters are checked for duplicates pairwise: their number is capped
    "many_parameters": ("*STEP, NAME=load, INCREMENTS=4",
                        "*STEP, NAME=load, INCREMENTS=4" +
                        "".join(f", K{i}=1" for i in range(100000)), 2,
                        "more than 64 parameters on one keyword line"),
}


@pytest.mark.parametrize("case", sorted(HUGE_TOKENS))
def test_deck_with_a_huge_token(exe, tmp_path, case):
    """Lines of megabytes in a deck: a clear error or a normal run within seconds, never a
    crash or a hang, and an error message of readable length."""
    old, new, code, text = HUGE_TOKENS[case]
    src = (ROOT / "test/data/cli/oedometer.inp").read_text()
    assert old in src
    deck = tmp_path / "big.inp"
    deck.write_text(src.replace(old, new, 1))
    out = tmp_path / "r.h5"
    r = subprocess.run([*exe, str(deck), "-o", str(out), "--quiet"], cwd=ROOT,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == code, (r.returncode, r.stderr[-2000:])
    assert len(r.stderr) < 2000, r.stderr[:500]
    if code == 2:
        assert "pecplas: error: " + str(deck) + ":" in r.stderr and text in r.stderr, r.stderr
        assert "characters)" in r.stderr or case == "many_parameters"
        assert not out.exists()
    else:
        assert out.exists()
