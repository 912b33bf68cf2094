"""The reactions inside a step that switches a load pattern (doc/theory.md §10): at every
increment they balance the loads acting at that increment, the switched pattern's share
included, not only at the step's end.

The deck of test_plate_pattern_switch.py: the propped cantilever (L = 10) under the plate
load q = 10 kN/m, propped at its tip by a FIXED_END anchor (its far end fixed: its force per
width F is not among the reactions), then q deactivated over 2 increments and activated again
over 2. Vertical equilibrium of the whole model at step fraction tau: sum R_y = on q L + F,
with on = 1 - tau while q goes and tau while it comes back. Before, the pattern's share on
the clamped node left the reaction at the step's start (the carried out-of-balance acted on
the free equations only): sum R_y 66.23 against 68.73 half-way through the deactivation.
The problem is linear and solved to 1e-10 (the deck's TOLERANCE) against forces of about
100: 1e-6 is a bound far above the solver's error."""
from deck_runs import run_text
from pecplas_py.results import Results
from test_plate_pattern_switch import deck, Q, L

TOL = 1e-6


def test_reactions_follow_the_pattern_at_every_increment(tmp_path):
    p, out = run_text(deck(), tmp_path, "reaction_switch")
    with Results(out) as r:
        assert r.status == "completed", p.stderr
        assert [len(r.keys_of(s)) for s in (3, 4)] == [2, 2]
        for step in (3, 4):
            for i, k in enumerate(r.keys_of(step)):
                g = r.increment(k)
                tau = (i + 1) / len(r.keys_of(step))
                on = tau if step == 4 else 1.0 - tau
                f = g["anchors/prop/force_per_width"][()][0]
                ry = g["reaction"][()][:, 1].sum()
                assert abs(ry - (on * Q * L + f)) <= TOL, (step, i, ry, on * Q * L + f)
