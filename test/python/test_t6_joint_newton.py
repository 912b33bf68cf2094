"""Full Newton on T6 elements with Mohr-Coulomb sand and GOODMAN6 joints converges like on Q8.

test/data/joints/anchored_wall_t6.inp is input/examples/anchored_wall.inp (sheet pile, Mohr-
Coulomb sand c = 1 kPa, phi = 30, psi = 0; Mohr-Coulomb joints K_n = 1e6; a prestressed tie;
two excavation stages, 12 increments) with every Q4 split into two T6 and the joints made
GOODMAN6, solved by METHOD=NEWTON, FALLBACK=NO.

Bound: every increment converges without a cut, in at most 5 iterations per increment on
average (the bound of the footings in test_footing_newton.py: quadratic convergence from a
residual of order 0.1-0.5 of the load to the tolerance 1e-4 takes 3-4 iterations, plus one
for a change of the joints' or points' states). Measured 40 iterations (3.3 per increment),
the Q8 mesh of the same scene with GOODMAN6 joints 41, and no singular tangent.

The mesh matters: split along the same diagonal as its neighbours, the square behind the top
of the wall leaves the soil-side node at the wall's top a corner of a single triangle. Without
full Newton's re-closure limit the open/closed states of the top joint element's points then
cycled (a point re-closing with 230-390 kPa of normal stress where the converged state has
0-8 kPa), the residual jumped by two orders of magnitude between iterations whose tangents
agree with central differences of the internal forces to 1e-5-1e-3, the cut increments
reached points at the apex whose zero tangent makes the stiffness singular (228 singular
tangents), and the run took 367 iterations with 6 cuts (the default chain, with its
quasi-Newton fallback: 338 iterations, 2 cuts). The tangents are consistent in both meshes;
the deck keeps the well-split one so that a tangent of T6, Mohr-Coulomb or GOODMAN6 that
stopped being consistent shows as more iterations here.

test_lone_corner_reclosure_limit runs the same deck with that square split like its
neighbours (the soil-side node at the wall's top a corner of a single triangle: the audit's
mesh). Full Newton's re-closure limit (pecplas_solve_reclosure, doc/theory.md §4) shortens
the steps that re-close the top joint's open points deep into the penalty; with it the run
takes the same bound as the well-split mesh: 12 increments, no cut, no singular tangent,
at most 5 iterations per increment (measured 44 iterations, 3 steps limited). Without the
limit it took 17 increments, 367 iterations, 6 cuts and 228 singular tangents.
"""
import re
import subprocess
from pathlib import Path

from pecplas_exe import pecplas_cmd

DECK = Path(__file__).resolve().parents[1] / "data" / "joints" / "anchored_wall_t6.inp"
INCREMENTS = 5 + 2 + 5
# the square behind the wall's top as the test deck splits it, and as its neighbours are split
WELL_SPLIT = ("461, 476, 477, 507, 1773, 1836, 1835\n", "901, 477, 508, 507, 1833, 1834, 1836\n")
LONE_CORNER = ("461, 476, 477, 508, 1773, 1833, 1836\n", "901, 476, 508, 507, 1836, 1834, 1835\n")


def run_counts(deck, tmp_path):
    """Runs `deck`; returns (increments, iterations, cuts, singular tangents, re-closure
    limits) of its summary."""
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(tmp_path / "aw_t6.h5")],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0 and "status: completed" in p.stdout, p.stdout + p.stderr
    m = re.search(r"summary: (\d+) increments, (\d+) iterations, (\d+) cuts", p.stdout)
    assert m, p.stdout
    s = re.search(r"singular tangents (\d+).*re-closure limits (\d+)", p.stdout)
    assert s, p.stdout
    counts = tuple(int(g) for g in m.groups() + s.groups())
    print("%d increments, %d iterations, %d cuts, %d singular tangents, %d re-closure limits"
          % counts)
    return counts


def test_t6_goodman6_full_newton(tmp_path):
    n, total, cuts, singular, _ = run_counts(DECK, tmp_path)
    assert (n, cuts) == (INCREMENTS, 0)
    assert total <= 5 * INCREMENTS
    assert singular == 0


def test_lone_corner_reclosure_limit(tmp_path):
    text = DECK.read_text()
    for good, lone in zip(WELL_SPLIT, LONE_CORNER):
        assert text.count(good) == 1
        text = text.replace(good, lone)
    deck = tmp_path / "anchored_wall_t6_lone_corner.inp"
    deck.write_text(text)
    n, total, cuts, singular, limits = run_counts(deck, tmp_path)
    assert (n, cuts) == (INCREMENTS, 0)
    assert total <= 5 * INCREMENTS
    assert singular == 0
    # the limit is what converges it (the run above without it: 367 iterations, 6 cuts)
    assert limits >= 1
