"""The pure pieces of the work-precision benchmark (bench/wp_analysis.py, bench/wp_decks.py),
on synthetic data: no program runs.

- Richardson: f(h) = f0 + C h^p is exact for the three-level formula, so the limit and the
  order come back to round-off (tolerance 1e-9 relative on f0, 1e-6 on p), for ratio-2 and
  for uneven levels; an oscillating sequence falls back to the finest value with the last
  change as its uncertainty.
- The cheapest run within a tolerance, on a hand-made table where the answer is known.
- The deck edits: Q4 -> Q8 adds exactly one node per distinct element edge (Euler count on a
  2 x 1 block: 7 edges) and turns GOODMAN4 joints into GOODMAN6 with the face mid-nodes.
"""
import math
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.bench.wp_analysis import cheapest_within, relative_error, richardson
from pecplas_py.bench.wp_decks import (count_dofs, first_step_only, scale_steps, set_solver,
                                       to_q8)


@pytest.mark.parametrize("p", [1.0, 2.0, 3.5])
def test_richardson_ratio_two(p):
    f0, c = 0.0885, -0.04
    h = [1 / 3, 1 / 6, 1 / 12, 1 / 24, 1 / 48]
    r = richardson(h, [f0 + c * x**p for x in h])
    assert r["monotone"]
    assert r["p"] == pytest.approx(p, abs=1e-6)
    assert r["ref"] == pytest.approx(f0, rel=1e-9)
    # only the three finest levels are used
    assert r["levels"] == pytest.approx((1 / 12, 1 / 24, 1 / 48))


def test_richardson_uneven_levels():
    # levels n = 2, 3, 6 (the S6 MODJOIN series): ratios 1.5 and 2
    f0, c, p = 9.23e-4, 3e-5, 2.0
    h = [1 / 2, 1 / 3, 1 / 6]
    r = richardson(h, [f0 + c * x**p for x in h])
    assert r["p"] == pytest.approx(p, abs=1e-6)
    assert r["ref"] == pytest.approx(f0, rel=1e-9)


def test_richardson_non_monotone_falls_back_to_finest():
    h, f = [1 / 4, 1 / 8, 1 / 16], [1.00, 1.02, 1.01]
    r = richardson(h, f)
    assert not r["monotone"] and r["p"] is None
    assert r["ref"] == 1.01
    assert r["uncertainty"] == pytest.approx(0.01)


def test_richardson_diverging_falls_back():
    # differences growing under refinement: no positive order
    h, f = [1 / 4, 1 / 8, 1 / 16], [1.00, 1.01, 1.03]
    r = richardson(h, f)
    assert r["p"] is None and r["ref"] == 1.03


def test_cheapest_within_tolerance():
    rows = [dict(name="coarse", error=0.08, wall=0.1),
            dict(name="mid", error=0.03, wall=0.5),
            dict(name="fine", error=0.004, wall=4.0),
            dict(name="fast-but-failed", error=float("nan"), wall=0.01),
            dict(name="finest", error=0.0005, wall=30.0),
            dict(name="tie", error=0.002, wall=4.0)]
    assert cheapest_within(rows, 0.05)["name"] == "mid"
    assert cheapest_within(rows, 0.01)["name"] == "tie"      # same cost, smaller error
    assert cheapest_within(rows, 1e-4) is None
    assert math.isnan(relative_error(None, 1.0))
    assert relative_error(1.02, 1.0) == pytest.approx(0.02)


DECK = """*NODES
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
7, 0, 1
8, 1, 1
*ELEMENTS, TYPE=Q4, SET=soil
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*ELEMENTS, TYPE=Q4, SET=top
3, 7, 8, 8, 7
*JOINTS, TYPE=GOODMAN4, SET=j, LAW=l
100, 4, 5, 8, 7
*NSET, NAME=base
1, 2, 3
*EDGES, NAME=head
8, 7
*STEP, NAME=load, INCREMENTS=20
p, 1
*STEP, NAME=unload, INCREMENTS=20
p, 0
*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=50, MAX_CUTS=6
"""


def test_q8_conversion_counts_edges():
    # drop the degenerate third element: a 2 x 1 block of Q4 has 7 distinct edges
    deck = DECK.replace("*ELEMENTS, TYPE=Q4, SET=top\n3, 7, 8, 8, 7\n", "")
    deck = deck.replace("*EDGES, NAME=head\n8, 7\n", "*EDGES, NAME=head\n5, 4\n")
    deck = deck.replace("100, 4, 5, 8, 7", "100, 1, 2, 5, 4")
    q8 = to_q8(deck)
    assert count_dofs(q8) == 2 * (8 + 7)
    joint = next(line for line in q8.splitlines() if line.startswith("100,"))
    assert len(joint.split(",")) == 7 and "TYPE=GOODMAN6" in q8
    base = q8.split("*NSET, NAME=base\n")[1].split("*")[0].replace(",", " ").split()
    assert len(base) == 3 + 2          # the 3 corners + the mid-nodes of the 2 bottom edges
    coords = {int(line.split(",")[0]): float(line.split(",")[2])
              for line in q8.split("*NODES\n")[1].split("*")[0].splitlines()}
    assert all(coords[int(k)] == 0.0 for k in base)          # all on the base line y = 0
    assert "TYPE=Q8" in q8 and "TYPE=Q4" not in q8


def test_step_and_solver_edits():
    d = first_step_only(DECK, factor=0.45, increments=5)
    assert "unload" not in d and "*STEP, NAME=load, INCREMENTS=5" in d and "p, 0.45" in d
    d = set_solver(d, "MODIFIED_NEWTON", 5000)
    assert "METHOD=MODIFIED_NEWTON, MAX_ITERATIONS=5000" in d
    with pytest.raises(ValueError):
        set_solver("*NODES\n1, 0, 0\n", "NEWTON")


def test_scale_steps_imposed_uplift():
    """The S6 MODJOIN edit: every step's increments scaled, the last step's target and
    increments replaced; a deck without steps is refused."""
    deck = ("*LOAD, NAME=pull, TYPE=DISPLACEMENT\nhead, Y, 0.04\n"
            "*STEP, NAME=a, INCREMENTS=25\npull, 0.0125\n"
            "*STEP, NAME=b, INCREMENTS=95\npull, 1\n*SOLVER, METHOD=NEWTON\n")
    out = scale_steps(deck, 2.0, last_target=0.2, last_increments=15)
    assert "*STEP, NAME=a, INCREMENTS=50\npull, 0.0125" in out
    assert "*STEP, NAME=b, INCREMENTS=30\npull, 0.2" in out
    assert scale_steps(deck, 0.01).count("INCREMENTS=1\n") == 2, "at least one increment"
    with pytest.raises(ValueError):
        scale_steps("*NODES\n1, 0, 0\n", 1.0)


def test_timing_text_states_thread_single_runs_and_load():
    from pecplas_py.bench.wp_report import timing_text
    t = timing_text([0.52, float("nan"), 1.49])
    assert "one thread (OMP_NUM_THREADS=1)" in t and "single runs" in t
    assert "load average 0.5 - 1.5 when the runs started" in t
    assert "errors are exact" in t and "not final" not in t
    assert "not final" in timing_text([99.0])


def test_advice_rows_carry_the_load_of_the_chosen_run():
    from pecplas_py.bench.wp_report import advice
    runs = [dict(scene="s2", model="spring", element="Q4", method="NEWTON", level=n,
                 dofs=100 * n, increments=10, status="ok", wall=w, load1=ld,
                 scene_error=e, error_bound=e)
            for n, w, ld, e in ((3, 0.1, 0.7, 0.04), (6, 0.5, 1.2, 0.008))]
    rows = advice(runs, {"s2": "spring"})
    # scope scene, 1 %: the finer run (0.8 % error), its wall and load
    assert rows[0][3:] == [0.01, "spring Q4/SPRING, full Newton", 6, 600, 10, "8.00e-03",
                           "0.500", "1.20"]
    assert rows[1][-2:] == ["0.100", "0.70"]
