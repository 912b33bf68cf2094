"""Status claims that must hold whatever the method or the increment budget (doc/theory.md §4,
"Convergence, increment cutting and statuses"; §15 for the safety step).

- Safety step on the infinite slope, psi = 0 (test/data/safety/infinite_slope_psi0.inp: Katona
  ties on the column's sides, non-associated Mohr-Coulomb) under METHOD=MODIFIED_NEWTON: the
  factor must be the one full Newton gives, within the 2 % of the closed form (Davis,
  tan(phi) / tan(asin(tan(beta))) = 1.792) that the validation table asserts for that row. The
  Katona Newton fallback used to factorise the non-symmetric consistent tangent with CHOLMOD
  (the modified-Newton run's solver), which reads its upper triangle only: the fallback
  converged linearly and failed at the iteration cap, and the run claimed 'no equilibrium at
  Msf = 1.441' (factor 1.439, -20 %). Measured after the fix: 1.7908, as full Newton.
- An arc-length step that uses its MAX_INCREMENTS after its load has fallen below its largest
  (test/data/modjoin/fe_cnl_force_arc.inp, softening MODJOIN joint: largest load 0.577027 at
  increment 86, one fall beyond the noise at increment 89, the second at 90) is 'stopped', and
  its message names the largest load instead of saying that there was no maximum on the way.
- An arc-length step that ends at a target displacement of a node (NODE=, DOF=, DISPLACEMENT=)
  ends there, as a step ends on its target load: rigid footing on Tresca soil (the stiff-plate
  footing of test_footing_paths.py, T6) pushed by a pressure until its axis node has settled
  0.02 m, 10 arc-length increments. The step used to end on the first increment past the
  target: 0.02358 m (+18 %) at 60.50 kN/m, against 57.245 kN/m at 0.02 m under displacement
  control (+5.7 %; 20 and 40 increments: +3.1 %, +2.6 %). Now the node ends within the landing
  tolerance of the code (1e-6 of the target) and the load within 0.5 % of the displacement-
  controlled one (measured 57.251: +0.01 %; 0.5 % bounds the increment-size error of the
  plastic path: 10, 20 and 40 increments give 57.251, 57.241, 57.263).
  The same under Katona contact (test/data/katona/pad_slip.inp, the push under arc length until
  a top node of the pad has moved 1e-3, before any slip: a linear path): 4 and 8 increments end
  with the node at 1e-3 and the same push factor (measured 0.031206 both; within 2e-6, the
  landing tolerance 1e-6 on a linear path plus the deck's residual tolerance 1e-8). The step
  used to end at 9.25e-3 and 4.63e-3 with factors 0.2887 and 0.1444.
- Every row of /history records a residual at most TOLERANCE (a converged increment): the
  Katona S1 opening-closing (test/data/katona/s1_open_close.inp) passes through a state of nil
  load and reactions (lift 0), converged by the roundoff floor of doc/theory.md 6.5
  (|u| 2e-19 m, reactions 1e-13); its row recorded 1.38, the residual over a roundoff reference,
  13800 times the tolerance. Now the residual relative to the forces it was measured against
  (9.9e-16).
"""
import math
import re
from pathlib import Path

from footing_decks import deck as footing_deck
from deck_runs import run_text
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "test" / "data"


def test_safety_factor_under_modified_newton_with_katona(tmp_path):
    text = (DATA / "safety" / "infinite_slope_psi0.inp").read_text()
    assert "METHOD=NEWTON" in text
    text = text.replace("METHOD=NEWTON", "METHOD=MODIFIED_NEWTON")
    p, out = run_text(text, tmp_path, "psi0_modified")
    beta, phi = math.radians(20.0), math.radians(35.0)
    davis = math.tan(phi) / math.tan(math.asin(math.tan(beta)))
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        assert r.file["safety"].attrs["kind"] in (b"factor", "factor")
        factor = float(r.file["safety"].attrs["factor"])
    print(f"infinite slope psi = 0, modified Newton: Msf {factor:.4f}, Davis {davis:.4f} "
          f"({factor / davis - 1:+.2%})")
    assert abs(factor / davis - 1.0) <= 0.02


def test_arc_budget_after_a_fall_names_the_peak(tmp_path):
    text = (DATA / "modjoin" / "fe_cnl_force_arc.inp").read_text()
    text = text.replace("FILE=block_mesh.inc", f"FILE={DATA / 'modjoin' / 'block_mesh.inc'}")
    assert "MAX_INCREMENTS=600" in text
    p, out = run_text(text.replace("MAX_INCREMENTS=600", "MAX_INCREMENTS=89"), tmp_path, "budget89")
    assert p.returncode == 3
    with Results(out) as r:
        message = r.attr("status_message")
        assert r.status == "stopped", message
        loads = r.pattern_factors()[:, 0]
    assert "no maximum of the load on the way" not in message, message
    m = re.search(r"the largest load, at step fraction ([-+.\deE]+) \(increment (\d+)\), was "
                  r"followed by (\d+) fall", message)
    assert m, message
    # the message prints 6 significant digits of the largest load of the path
    assert abs(float(m.group(1)) - loads.max()) <= 1e-5 * loads.max()
    assert int(m.group(2)) == int(loads.argmax()) + 1 and int(m.group(3)) == 1


def test_arc_step_ends_on_its_node_displacement(tmp_path):
    solver = "*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8"
    settle = footing_deck(nf=2, stiff_footing=True, drive="settle", settle=0.03, increments=6,
                          solver=solver)
    p, out = run_text(settle, tmp_path, "settle")
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        ids = [int(v) for v in re.search(r"\*NSET, NAME=footing\n([\d, \n]+?)\*", settle)
               .group(1).replace("\n", ",").split(",") if v.strip()]
        rows = [r.node_index(i) for i in ids]
        loads = {round(-r.field(k, "displacement")[rows[0], 1], 9):
                 -r.field(k, "reaction")[rows, 1].sum() for k in r.keys}
    reference = loads[0.02]
    arc = footing_deck(nf=2, stiff_footing=True, drive="pressure", pressure=70.0, increments=10,
                       solver=solver, step_options=", CONTROL=ARC_LENGTH, MAX_INCREMENTS=200, "
                       f"NODE={ids[0]}, DOF=Y, DISPLACEMENT=-0.02")
    p, out = run_text(arc, tmp_path, "arc_node")
    assert p.returncode == 0, p.stderr
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        u = r.field(r.keys[-1], "displacement")[r.node_index(ids[0]), 1]
        load = r.pattern_factors()[-1, 0]
    print(f"arc-length step to u = -0.02 m: node at {u:.9f} m, pressure {load:.3f} kPa; "
          f"displacement control at 0.02 m: {reference:.3f} kN/m ({load / reference - 1:+.3%})")
    assert abs(u + 0.02) <= 1e-6 * 0.02
    assert abs(load / reference - 1.0) <= 5e-3


def test_katona_arc_step_ends_on_its_node_displacement(tmp_path):
    text = (DATA / "katona" / "pad_slip.inp").read_text()
    assert "*STEP, NAME=push, INCREMENTS=4\npush, 1" in text
    factors = []
    for n in (4, 8):
        deck = text.replace("*STEP, NAME=push, INCREMENTS=4\npush, 1",
                            f"*STEP, NAME=push, INCREMENTS={n}, CONTROL=ARC_LENGTH, "
                            "MAX_INCREMENTS=100, NODE=11, DOF=X, DISPLACEMENT=1e-3\npush, 1")
        p, out = run_text(deck, tmp_path, f"pad_node_{n}")
        with Results(out) as r:
            assert r.status == "completed", r.attr("status_message")
            u = r.field(r.keys[-1], "displacement")[r.node_index(11), 0]
            factors.append(r.pattern_factors()[-1, list(r.patterns).index("push")])
        print(f"Katona pad, {n} arc increments: node 11 u_x = {u:.9e}, push {factors[-1]:.6f}")
        assert abs(u - 1e-3) <= 1e-6 * 1e-3
    assert abs(factors[1] / factors[0] - 1.0) <= 2e-6


def test_history_residuals_within_the_tolerance(tmp_path):
    text = (DATA / "katona" / "s1_open_close.inp").read_text()
    assert "*SOLVER, TOLERANCE=1e-4" in text
    p, out = run_text(text, tmp_path, "katona_open_close")
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        residual = r.history("residual")
    print(f"Katona S1 opening-closing: largest recorded residual {residual.max():.3g}")
    assert residual.max() <= 1e-4
