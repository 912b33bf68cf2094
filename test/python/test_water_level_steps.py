"""A phreatic level changed by *CHANGE_WATER stays in force in every later step
(doc/deck.md, Groundwater; doc/theory.md §14, Phases).

test/data/water/level_steps.inp: a column 1 m wide and 10 m high (gamma_unsat = 18,
gamma_sat = 20, gamma_w = 10) under a level at y = -2, lowered to y = -6 in step 1 and held
through four nil steps. At the end of every step the steady pore pressure at each Gauss point
is the hydrostatic one of the lowered level, 10 (-6 - y)+ (it is set from the level, not
solved: exact to rounding), the base carries the effective weight 18 x 6 + (20 - 10) x 4 =
148 kN/m (the pore pressure on the base goes into the reactions; the K0 state of the level
is in equilibrium, so the reaction sum is the weight to the solver's residual: 1e-3 kN/m is
a bound far above it and far below the 32 kN/m of the other level), and the nil steps move
nothing (below 1e-9 m; the other level heaves the column by 4.8 mm).

The release build of gfortran 12 (-O3) vectorised the search of the level in force wrongly:
from step 4 on it returned the deck's first level, so the column went back under y = -2
(reaction 116 kN/m, pore pressures 40 kPa off) while the run said 'completed'."""
from pathlib import Path

import numpy as np

from deck_runs import run_text
from pecplas_py.results import Results

DECK = Path(__file__).resolve().parents[1] / "data" / "water" / "level_steps.inp"


def test_changed_level_holds_in_later_steps(tmp_path):
    _, out = run_text(DECK.read_text(), tmp_path, "level_steps")
    with Results(out) as r:
        assert r.status == "completed"
        steps = sorted({r.step_of(k) for k in r.keys})
        assert steps == [1, 2, 3, 4, 5]
        gp = r.element_set("soil")["gauss_coordinates"][()]
        hydro = 10.0 * np.maximum(-6.0 - gp[..., 1], 0.0)
        for step in steps:
            k = r.last_key(step)
            p = r.field(k, "sets/soil/pore_steady")
            assert np.abs(p - hydro).max() <= 1e-9, (step, np.abs(p - hydro).max())
            ry = r.field(k, "reaction")[:, 1].sum()
            assert abs(ry - 148.0) <= 1e-3, (step, ry)
            assert np.abs(r.field(k, "displacement")).max() <= 1e-9, step
