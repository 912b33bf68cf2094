"""The plates' section forces when a phase switches the load pattern on them
(doc/theory.md §10 "Load patterns and supports switched by a phase", §12 "Output").

test/data/structures/propped_phases.inp is the propped cantilever (L = 10, EI = 1e5, ten
2-node plate elements of h = 1 under the PLATE_LOAD pattern q = 10 kN/m); here it is loaded
to q, then propped at its tip (a FIXED_END anchor), then the pattern is deactivated (it keeps
its factor and loads nothing) in two increments, then activated again. With the pattern off the
plate carries only the prop's force at its tip, F (the anchor's force per unit width), so
statics of the free body give the section forces exactly: at the free tip M = 0 and Q = -F,
at the clamped root M = -F L, with the root's vertical reaction F (F > 0: the prop pulls). Half-way through
the deactivation the carried out-of-balance still holds half the pattern's load, so the
plate's own load is q/2: Q(root) - Q(tip) = q L / 2 and the tip moment is 0 (the reactions
are checked at the ends of the steps here; test_reaction_pattern_switch.py checks them at
every increment).
The plate's forces are its nodal forces less its own load: the 2-node linked element's
consistent load vector is exact (Tong), so these hold to the solver tolerance (1e-10 here,
1e-6 of the forces of about 100 is a bound far above it). Before, the pattern's load was
subtracted while it no longer acted: the tip moment read -q h^2/12 = -0.833 kN m/m and both
shears were 5 kN/m (q h / 2) off, under 'completed'."""
from pathlib import Path

import numpy as np

from deck_runs import run_text
from pecplas_py.results import Results

DECK = Path(__file__).resolve().parents[1] / "data" / "structures" / "propped_phases.inp"
Q, L = 10.0, 10.0
TOL = 1e-6


def deck():
    text = DECK.read_text()
    steps = text[:text.index("*STEP")]
    steps += ("*STEP, NAME=loaded, INCREMENTS=1\nq, 1.0\n*END STEP\n"
              "*STEP, NAME=propped, INCREMENTS=1\n*ACTIVATE\nprop\n*END STEP\n"
              "*STEP, NAME=unloaded, INCREMENTS=2\n*DEACTIVATE\nq\n*END STEP\n"
              "*STEP, NAME=reloaded, INCREMENTS=2\n*ACTIVATE\nq\n*END STEP\n")
    return steps


def test_plate_forces_follow_pattern_switch(tmp_path):
    _, out = run_text(deck(), tmp_path, "pattern_switch")
    with Results(out) as r:
        assert r.status == "completed"
        for step in (3, 4):
            for i, k in enumerate(r.keys_of(step)):
                g = r.increment(k)
                ef = g["plates/beam/end_forces"][()]        # (nel, 2 ends, N Q M)
                root, tip = ef[0, 0], ef[-1, 1]
                f = g["anchors/prop/force_per_width"][()][0]
                tau = (i + 1) / len(r.keys_of(step))
                on = tau if step == 4 else 1.0 - tau      # fraction of q acting
                assert abs(tip[2]) <= TOL, (step, i, tip)
                assert abs((root[1] - tip[1]) - (-on * Q * L)) <= TOL, (step, i, root, tip)
                if tau == 1.0:
                    ry = g["reaction"][()][:, 1].sum()
                    assert abs(ry - (on * Q * L + f)) <= TOL, (step, i, ry, f)
                if on == 0.0:
                    assert abs(tip[1] + f) <= TOL and abs(root[2] + f * L) <= TOL, (root, tip, f)
