"""Strip footings through the executable (decks from footing_decks.py): full Newton on a
frictional footing, and a genuine limit load found under force control with and without
arc-length (doc/theory.md §4).

- c-phi footing (phi = psi = 30 deg, c = 10 kPa, surcharge 10 kPa, weightless), T6 mesh refined
  twice from the coarsest (nf = 1 -> 4 elements under the half footing), 0.5 m of settlement in
  50 increments under full Newton with line search: every increment converges without a cut
  in at most 5 iterations on average (measured: 2.0 per increment, 0 cuts, 4 line-search
  residuals; 2.0 without line search. Before the imposed settlement entered the first iteration
  through the tangent, doc/theory.md §4: 13.3 with line search, 128 cuts without), and the
  pressure reaches a plateau (last four within 0.2 %) within
  0.95-1.10 of Prandtl's q_u = c N_c + q N_q = 485.4 kPa (measured 498.9: +2.8 %, the FE mesh's
  overestimate).
- Tresca soil (c = 10 kPa) under a rigid footing (a stiff plate in the top element row): the
  displacement-controlled plateau (68.30 kN/m) is the reference; the same footing under a
  growing pressure with CONTROL=ARC_LENGTH reports 'limit load' within 1 % of it and traces the
  plateau at least two increments beyond the limit; plain force control reports 'limit load'
  within 2 % (the arc-length probe establishes it).
- The c-phi footing (phi = psi = 30 deg, c = 10 kPa, weightless: Prandtl c N_c = 301.4 kPa)
  under a pressure raised to 1.2 N_c c by load control, NEWTON, with 12, 24 and 48 increments
  (T6, nf = 1) and 12 (nf = 3): the run says either 'limit load' within 2 % of the arc-length
  limit of the same mesh (a plateau to 0.1 %), the stored limit being the largest load of the path, or 'diverged'
  naming a last converged load within 2 % below that limit; never a limit more than 2 % below.
  (Measured: every run 'limit load', -0.06 to +0.07 % of the arc-length limits 317.05 and
  308.80 kPa after 60 and 80 increments, plateaus to 0.1 % per doubling of the displacement
  (doc/theory.md §4; before that rule the arc-length steps said 315.92 and 307.54 kPa after
  60 and 40 increments, still creeping up; 40 increments now end 'stopped' on nf = 3); before the
  probe started at its first state and went forward, 24 and 48 increments said 'diverged' at
  the limit without naming a load, and nf = 3 with 12 increments reported a limit of
  86.0 kPa, a load the probe had stepped down to.)
"""
import math
import re

import numpy as np

from footing_decks import deck
from deck_runs import run as run_deck
from pecplas_py.results import Results


def run(text, tmp_path, name):
    """deck_runs.run, with the footing's vertical reaction (kN/m) at every written increment
    instead of the displacements."""
    p, status, hist, limit, _ = run_deck(text, tmp_path, name)
    ids = [int(v) for v in re.search(r"\*NSET, NAME=footing\n([\d, \n]+?)\*", text)
           .group(1).replace("\n", ",").split(",") if v.strip()]
    with Results(tmp_path / f"{name}.h5") as r:
        reaction = [-r.field(k, "reaction")[[i - 1 for i in ids], 1].sum() for k in r.keys]
    return p, status, hist, limit, np.array(reaction)


def test_frictional_footing_line_search(tmp_path):
    phi = math.radians(30.0)
    nq = math.exp(math.pi * math.tan(phi)) * math.tan(math.pi / 4 + phi / 2) ** 2
    qu = 10.0 * (nq - 1.0) / math.tan(phi) + 10.0 * nq
    text = deck(nf=4, c=10.0, phi=30.0, psi=30.0, q=10.0, drive="settle", settle=0.5,
                increments=50, solver="*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=50, MAX_CUTS=8")
    p, status, hist, _, q = run(text, tmp_path, "cphi")
    assert status == "completed", p.stderr
    push = hist["step"] == 2
    n = int(push.sum())
    cuts = n - 50
    mean = hist["iterations"][push].mean()
    print(f"c-phi footing, nf = 4: {n} increments for 50 requested ({cuts} cuts), "
          f"{mean:.1f} iterations per increment, {hist['line_searches'].sum()} line-search "
          f"residuals; plateau {q[-1]:.1f} kPa, Prandtl {qu:.1f} kPa ({q[-1] / qu - 1:+.1%})")
    assert mean <= 5 and cuts == 0
    assert np.ptp(q[-4:]) <= 2e-3 * q[-1]
    assert 0.95 * qu <= q[-1] <= 1.10 * qu


def test_limit_under_force_control(tmp_path):
    solver = "*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8"
    _, status, _, _, ref = run(deck(nf=2, stiff_footing=True, drive="settle", settle=0.15,
                                    increments=30, solver=solver), tmp_path, "settle")
    assert status == "completed"
    reference = ref[-1]
    assert np.ptp(ref[-4:]) <= 1e-3 * reference  # the plateau of the displacement control

    arc = deck(nf=2, stiff_footing=True, drive="pressure", pressure=70.0, increments=20,
               step_options=", CONTROL=ARC_LENGTH, MAX_INCREMENTS=60", solver=solver)
    p, status, hist, limit, _ = run(arc, tmp_path, "arc")
    assert status == "limit load", p.stderr
    peak = limit["factors"][0]
    beyond = int(np.sum(hist["global_increment"] > limit["increment"]))
    print(f"rigid footing on Tresca soil: displacement control {reference:.3f} kN/m, "
          f"arc-length limit {peak:.3f} ({peak / reference - 1:+.2%}), {beyond} increments "
          "beyond it")
    assert abs(peak / reference - 1.0) <= 0.01 and beyond >= 2

    force = arc.replace(", CONTROL=ARC_LENGTH, MAX_INCREMENTS=60", "")
    p, status, _, limit, _ = run(force, tmp_path, "force")
    assert status == "limit load", p.stderr
    peak = limit["factors"][0]
    print(f"plain force control: limit {peak:.3f} ({peak / reference - 1:+.2%})")
    assert abs(peak / reference - 1.0) <= 0.02


def test_limit_probe_under_load_control(tmp_path):
    nq = math.exp(math.pi * math.tan(math.radians(30.0))) * math.tan(math.radians(60.0)) ** 2
    nc = (nq - 1.0) / math.tan(math.radians(30.0))
    pressure = round(1.2 * nc * 10.0, 3)
    solver = "*SOLVER, METHOD=NEWTON"
    for nf, cases, arc_increments in ((1, (12, 24, 48), 60), (3, (12,), 80)):
        arc = deck(nf=nf, c=10.0, phi=30.0, psi=30.0, drive="pressure", pressure=pressure,
                   increments=24, solver=solver,
                   step_options=f", CONTROL=ARC_LENGTH, MAX_INCREMENTS={arc_increments}")
        p, status, _, limit, _ = run_deck(arc, tmp_path, f"arc{nf}")
        assert status == "limit load", p.stderr
        reference = limit["factors"][0]
        for n in cases:
            text = deck(nf=nf, c=10.0, phi=30.0, psi=30.0, drive="pressure",
                        pressure=pressure, increments=n, solver=solver)
            p, status, hist, limit, _ = run_deck(text, tmp_path, f"load{nf}_{n}")
            loads = hist["pattern_factors"][:, 0]
            with Results(tmp_path / f"load{nf}_{n}.h5") as f:
                message = f.attr("status_message")
            if status == "limit load":
                peak = limit["factors"][0]
                print(f"nf = {nf}, {n} increments: limit load {peak:.3f} kPa "
                      f"({peak / reference - 1:+.2%} of the arc-length {reference:.3f})")
                # the stored limit is the largest load of the path: the same factors
                # f0 + (ftarget - f0) tau of the same fraction, so equal to rounding
                assert abs(peak - loads.max()) <= 1e-12 * peak
                assert abs(peak / reference - 1.0) <= 0.02, message
            else:
                assert status == "diverged", message
                m = re.search(r"last converged state: increment (\d+), load factors "
                              r"press = ([-+.\deE]+)", message)
                assert m, message
                last = float(m.group(2))
                print(f"nf = {nf}, {n} increments: diverged, last converged {last:.3f} kPa "
                      f"({last / reference - 1:+.2%} of the arc-length {reference:.3f})")
                # the message prints 6 significant digits
                assert int(m.group(1)) == len(loads) and abs(last - loads[-1]) <= 1e-5 * last
                assert last >= 0.98 * reference, message
