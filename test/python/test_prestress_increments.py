"""The force of an anchor inside a `*PRESTRESS` step is the force acting at each increment
(doc/theory.md §13, doc/results.md anchors): N0 + tau (P - N0) at step fraction tau, N0 its
force at the step's start; the rest of P - N0 is still the phase's carried out-of-balance.

test/data/structures/propped_phases.inp is a clamped cantilever plate with a FIXED_END prop
at its tip (its far end is fixed: its force is not among the reactions). Here the plate is
never loaded: the prop is activated (no force), prestressed to P over 4 increments, then
prestressed again to P2 over 2 increments (from N0 = P). With nothing else loading the
plate, vertical equilibrium says that the support's reaction sum R_y equals the prop's
force per unit width at every increment; so the reported force must be that one. Before,
the file said N = P from the first increment while R_y rose with tau (at tau = 0.25:
R_y = 12.5 against a reported 50 kN/m). The problem is linear and solved to 1e-10 (the
deck's TOLERANCE) against forces of about 50: 1e-6 is a bound far above the solver's error."""
from pathlib import Path

from deck_runs import run_text
from pecplas_py.results import Results

DECK = Path(__file__).resolve().parents[1] / "data" / "structures" / "propped_phases.inp"
P, P2, SPACING = 100.0, 60.0, 2.0
TOL = 1e-6


def deck():
    text = DECK.read_text()
    return text[:text.index("*STEP")] + (
        "*STEP, NAME=propped, INCREMENTS=1\n*ACTIVATE\nprop\n*END STEP\n"
        f"*STEP, NAME=prestressed, INCREMENTS=4\n*PRESTRESS\nprop, {P}\n*END STEP\n"
        f"*STEP, NAME=eased, INCREMENTS=2\n*PRESTRESS\nprop, {P2}\n*END STEP\n")


def test_prestress_force_is_the_acting_one_at_every_increment(tmp_path):
    p, out = run_text(deck(), tmp_path, "prestress")
    with Results(out) as r:
        assert r.status == "completed", p.stderr
        assert [len(r.keys_of(s)) for s in (1, 2, 3)] == [1, 4, 2]
        for step, n0, target in ((2, 0.0, P), (3, P, P2)):
            for i, k in enumerate(r.keys_of(step)):
                g = r.increment(k)
                tau = (i + 1) / len(r.keys_of(step))
                n = g["anchors/prop/force"][()][0]
                f = g["anchors/prop/force_per_width"][()][0]
                ry = g["reaction"][()][:, 1].sum()
                assert abs(n - (n0 + tau * (target - n0))) <= TOL, (step, i, n)
                assert abs(f - n / SPACING) <= TOL, (step, i, f, n)
                assert abs(ry - f) <= TOL, (step, i, ry, f)


def test_restart_inside_the_prestress_step_reports_the_same_forces(tmp_path):
    """A run stopped after increment 2 (tau = 0.25 of the prestress) and restarted reports the
    forces of the uninterrupted run: the force the step started from is in the restart data
    (it reported P from the restart on when it was not). Same linear problem, same bound."""
    import subprocess
    from deck_runs import ROOT
    from pecplas_exe import pecplas_cmd
    _, full = run_text(deck(), tmp_path, "full")
    deck_path = tmp_path / "full.inp"
    part, rest = tmp_path / "part.h5", tmp_path / "rest.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck_path), "-o", str(part), "--quiet",
                                        "--stop-after-increments", "2"],
                       capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert p.returncode == 4, p.stderr
    p = subprocess.run(pecplas_cmd() + [str(deck_path), "--restart", str(part), "-o", str(rest),
                                        "--quiet"], capture_output=True, text=True, cwd=ROOT,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    with Results(full) as a, Results(rest) as b:
        assert b.status == "completed" and len(b.keys) == 5
        for k in b.keys:
            na = a.increment(k)["anchors/prop/force"][()][0]
            nb = b.increment(k)["anchors/prop/force"][()][0]
            assert abs(na - nb) <= TOL, (k, na, nb)
