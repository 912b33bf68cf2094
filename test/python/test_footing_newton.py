"""Full Newton on an imposed settlement: the smooth rigid strip footing on von Mises soil of
pecplas_py.decks.make_footing_peer_decks (c_u = 100 kPa, E = 1e5 kPa, weightless, 0.05 m in 20
increments, TOLERANCE=1e-4; 2 675 equations with Q4, 2 003 with Q8 and Q8R).

Each element completes the 20 increments with no cut and at most 5 iterations per increment
on average (measured 73, 74 and 76 iterations: 3.7-3.8 per increment; CalculiX 2.20 needs
59, 61 and 60 on the same meshes with CPE4, CPE8, CPE8R), and its plateau - the footing's
reaction at the last increment - is within 0.5 % of CalculiX's on the same mesh (measured
563.9, 535.6, 525.8 kPa against CalculiX's 563.9, 535.5, 525.8; the closed form is
(2 + pi) c_u = 514.2 kPa, which the meshes overestimate by 2-10 %). Before the imposed
increment entered the first iteration through the tangent (doc/theory.md §4) these runs took
140, 187 and 881 iterations, Q8R with 4 cuts.
"""
import pytest

from pecplas_py.decks import make_footing_peer_decks as decks
from pecplas_py.results import Results
from deck_runs import run

#: CalculiX 2.20's plateau on the same meshes (kPa; pecplas_py.bench.peer_footing)
CCX_PLATEAU = {"Q4": 563.9, "Q8": 535.5, "Q8R": 525.8}


@pytest.mark.parametrize("element", ["Q4", "Q8", "Q8R"])
def test_vonmises_footing_newton(tmp_path, element):
    text = decks.ours(element, 1, "vm", "settle", 20, decks.SETTLE["vm"])
    p, status, hist, _, _ = run(text, tmp_path, f"footing_{element}")
    assert status == "completed", p.stderr
    n = len(hist["iterations"])
    total = int(hist["iterations"].sum())
    with Results(tmp_path / f"footing_{element}.h5") as res:
        reaction = res.field(res.last_key(), "reaction")
    nodes, _, ids, nx, ny = decks.mesh(element, 1)
    footing = decks.node_sets(nodes, ids, nx, ny)["footing"]
    plateau = -sum(reaction[i - 1, 1] for i in footing) / decks.B
    print(f"{element}: {n} increments, {total} iterations ({total / n:.2f} per increment), "
          f"plateau {plateau:.1f} kPa (CalculiX {CCX_PLATEAU[element]})")
    assert n == 20, "an increment was cut"
    assert total <= 5 * 20
    assert abs(plateau / CCX_PLATEAU[element] - 1.0) <= 0.005
