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
of the wall leaves the soil-side node at the wall's top a corner of a single triangle. The
open/closed states of the top joint element's points then cycle (a point re-closing with
230-390 kPa of normal stress where the converged state has 0-8 kPa), the residual jumps by
two orders of magnitude between iterations whose tangents agree with central differences
of the internal forces to 1e-5-1e-3, the cut increments reach points at the apex whose zero
tangent makes the stiffness singular (228 singular tangents), and the run takes 367
iterations with 6 cuts (the default chain, with its quasi-Newton fallback: 338 iterations,
2 cuts). The tangents are consistent in both meshes; the deck keeps the well-split one so
that a tangent of T6, Mohr-Coulomb or GOODMAN6 that stopped being consistent shows as more
iterations here.
"""
import re
import subprocess
from pathlib import Path

from pecplas_exe import pecplas_cmd

DECK = Path(__file__).resolve().parents[1] / "data" / "joints" / "anchored_wall_t6.inp"
INCREMENTS = 5 + 2 + 5


def test_t6_goodman6_full_newton(tmp_path):
    p = subprocess.run(pecplas_cmd() + [str(DECK), "-o", str(tmp_path / "aw_t6.h5")],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0 and "status: completed" in p.stdout, p.stdout + p.stderr
    m = re.search(r"summary: (\d+) increments, (\d+) iterations, (\d+) cuts", p.stdout)
    assert m, p.stdout
    n, total, cuts = (int(g) for g in m.groups())
    s = re.search(r"singular tangents (\d+)", p.stdout)
    assert s, p.stdout
    print(f"{n} increments, {total} iterations, {cuts} cuts, {s.group(1)} singular tangents")
    assert (n, cuts) == (INCREMENTS, 0)
    assert total <= 5 * INCREMENTS
    assert int(s.group(1)) == 0
