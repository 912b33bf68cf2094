"""`pecplas DECK --target-error E [--goal node:N:x|y]` (`doc/adapt.md`) through the real
executable, on the L-shaped plate of test/data/adapt: one line per level with growing DOFs, the
target met (exit 0) and the last level written as a checked results file; bad option values are
input errors (exit 2, a message naming what was expected, no results file).

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm."""

import re
import subprocess
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py import script_cmd

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
    check = subprocess.run([*script_cmd("checks.check_results"), str(out)],
                           capture_output=True, text=True)
    assert check.returncode == 0, check.stdout + check.stderr


@pytest.mark.parametrize("args, expected", [
    (["--target-error", "1x"], "expected a relative error such as 1% or 0.01"),
    (["--target-error", "150%"], "expected a relative error such as 1% or 0.01"),
    (["--target-error", "1%", "--goal", "node:0:y"], "expected energy, node:N:x, node:N:y, reaction:SET"),
    (["--target-error", "1%", "--goal", "node:9999:y"], "the deck has no node 9999"),
    (["--goal", "node:21:y"], "--goal and --max-dofs need --target-error"),
    (["--target-error", "1%", "--goal", "reaction:"], "reaction:SET:y (r, z, 1, 2 for x, y) "
                                                    "or limit, got 'reaction:'"),
    (["--target-error", "1%", "--goal", "reaction:base:w"], "got 'reaction:base:w'"),
    (["--target-error", "1%", "--goal", "reaction:nosuch"], "no set 'nosuch'"),
    (["--target-error", "1%", "--goal", "limits"], "expected energy, node:N:x"),
])
def test_bad_options_exit_2_nothing_written(pecplas, tmp_path, args, expected):
    out = tmp_path / "l.h5"
    r = run(pecplas, DECK, *args, "-o", out)
    assert r.returncode == 2
    assert expected in r.stderr
    assert not out.exists()


def test_adapt_keyword_runs_the_loop(pecplas, tmp_path):
    """*ADAPT, TARGET=15% in the deck: `pecplas DECK` runs the same levels as
    --target-error 15% (same DOFs and estimates) and meets the target."""
    deck = tmp_path / "l_adapt.inp"
    deck.write_text(DECK.read_text() + "*ADAPT, TARGET=15%\n")
    r = run(pecplas, deck, "-o", tmp_path / "deck.h5")
    c = run(pecplas, DECK, "--target-error", "15%", "-o", tmp_path / "cli.h5")
    assert r.returncode == 0 and c.returncode == 0, r.stderr + c.stderr

    def levels(out):
        return [m.groups()[1:6] for m in map(LEVEL.match, out.splitlines()) if m]
    assert levels(r.stdout) == levels(c.stdout) and len(levels(r.stdout)) >= 2


def test_adapt_keyword_reaction_goal(pecplas, tmp_path):
    """*ADAPT, GOAL=reaction:base runs the same levels as --goal reaction:base."""
    deck = tmp_path / "l_reaction.inp"
    deck.write_text(DECK.read_text() + "*ADAPT, TARGET=1%, GOAL=reaction:base, MAX_DOFS=400\n")
    r = run(pecplas, deck, "-o", tmp_path / "deck.h5")
    c = run(pecplas, DECK, "--target-error", "1%", "--goal", "reaction:base", "--max-dofs",
            400, "-o", tmp_path / "cli.h5")
    assert "reaction on node set 'base'" in r.stdout, r.stdout + r.stderr
    lv = [m.groups()[1:6] for m in map(LEVEL.match, r.stdout.splitlines()) if m]
    assert lv == [m.groups()[1:6] for m in map(LEVEL.match, c.stdout.splitlines()) if m]
    assert len(lv) >= 1 and r.returncode == c.returncode


@pytest.mark.parametrize("line, expected", [
    ("*ADAPT, TARGET=150%", "TARGET: expected a relative error such as 1% or 0.01"),
    ("*ADAPT, GOAL=node:21:y", "expected TARGET=<relative error>"),
    ("*ADAPT, TARGET=1%, GOAL=node:21:w", "GOAL: expected energy, node:N:x, node:N:y, reaction:SET"),
    ("*ADAPT, TARGET=1%, MAX_DOFS=0", "MAX_DOFS"),
    ("*ADAPT, TARGET=1%, GOAL=reaction:nosuch", "GOAL: expected reaction:SET with SET a node "
                                                "set of the deck (*NSET), no set 'nosuch'"),
    ("*ADAPT, TARGET=1%, GOAL=node:9999:y", "GOAL: the deck has no node 9999"),
    ("*ADAPT, TARGET=1%, GOAL=limit:2", "GOAL: expected energy"),
])
def test_adapt_keyword_errors_name_the_line(pecplas, tmp_path, line, expected):
    text = DECK.read_text()
    deck = tmp_path / "bad.inp"
    deck.write_text(text + line + "\n")
    out = tmp_path / "bad.h5"
    r = run(pecplas, deck, "-o", out)
    nline = len(text.splitlines()) + 1
    assert r.returncode == 2 and expected in r.stderr, r.stderr
    assert f"bad.inp:{nline}:" in r.stderr and "*ADAPT" in r.stderr
    assert not out.exists()


@pytest.mark.parametrize("how", ["keyword", "option"])
def test_adaptive_run_prints_warnings_and_strict_refuses(pecplas, tmp_path, how):
    """An adaptive run (*ADAPT or --target-error) reports the deck's warnings as one run does
    (an unused node set here), and under --strict refuses the deck: exit 2, the warning as the
    error at its line, no results file."""
    deck = tmp_path / "l_spare.inp"
    text = DECK.read_text() + "*NSET, NAME=spare_set\n1\n"
    args = ["--target-error", "15%"]
    if how == "keyword":
        text += "*ADAPT, TARGET=15%\n"
        args = []
    deck.write_text(text)
    out = tmp_path / "s.h5"
    r = run(pecplas, deck, *args, "--strict", "-o", out)
    assert r.returncode == 2, r.stdout + r.stderr
    assert "spare_set" in r.stderr and not out.exists()
    r = run(pecplas, deck, *args, "-o", out)
    assert r.returncode == 0, r.stderr
    assert "warning:" in r.stderr and "spare_set" in r.stderr and out.exists()


@pytest.mark.parametrize("source, extra, expected", [
    ("test/data/plates/cantilever_tip.inp", "", "not available for a deck with plates (*PLATE)"),
    ("test/data/cli/oedometer.inp",
     "*ANCHOR, NAME=prop, TYPE=FIXED_END, EA=2e6, LENGTH=5, ANGLE=90, SPACING=2\n3\n",
     "not available for a deck with anchors (*ANCHOR)"),
])
def test_adapt_keyword_with_structures_names_the_line(pecplas, tmp_path, source, extra,
                                                       expected):
    # a plate or an anchor cannot follow the refinement: *ADAPT is refused at its own line
    text = (ROOT / source).read_text()
    text = text.replace("*BOUNDARY", extra + "*BOUNDARY", 1) + "*ADAPT, TARGET=5%\n"
    deck = tmp_path / "bad.inp"
    deck.write_text(text)
    out = tmp_path / "bad.h5"
    r = run(pecplas, deck, "-o", out)
    nline = len(text.splitlines())
    assert r.returncode == 2 and expected in r.stderr, r.stderr
    assert f"bad.inp:{nline}: [*ADAPT]" in r.stderr, r.stderr
    assert not out.exists()
