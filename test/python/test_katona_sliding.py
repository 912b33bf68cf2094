"""Katona friction under large and small increments (doc/theory.md §6.5): a block on a rigid-ish
ground, pressed by sigma_n = 100 kPa over L = 2 m and pushed 2 mm along the interface by an
imposed displacement, slides at the force

    F = (c + sigma_n tan phi) L = 103.2615 kN/m   (c = 5 kPa, phi = 25 deg; 93.2615 with c = 0)

whatever the number of push increments: once every doublet slips, T = c A + mu N at each and
the sum of N is sigma_n L (vertical equilibrium, the pushed nodes are held in x only), so the
sum of T, the push force, is exact for any distribution of N. Checked for every joint type that
gives Katona doublets (SPRING, GOODMAN4 and GOODMAN6 with Gauss and Lobatto points, THIN_LAYER
on linear and quadratic edges) with c = 5 and c = 0, the MU= and TENSION forms of the law on
GOODMAN4 and GOODMAN6, full Newton and (GOODMAN4, GOODMAN6) modified Newton, and 1, 5, 20 and
100 push increments:

- the force (sum of the x reactions of the pushed nodes) within 1e-6 of F (the runs' residual
  tolerance is 1e-8 of the loads and reactions, so their out-of-balance force is 1e-8 F at
  most; 1e-6 leaves two decades; measured within 3e-12);
- every joint point in slip at the cap, tau = c + sigma_n tan phi to 1e-8 of the cap (the
  points' stresses interpolate the doublets' (N, T)/A linearly with weights summing to 1, so
  the cap holds at a point when it holds at its doublets; the slip rows are solved with the
  equilibrium in one system, certified to the residual tolerance 1e-8), with tau > 0 along the
  slip of the last increment (its relative tangential displacement grows);
- a push below the sliding displacement (1 micrometre: the largest |tau| is 0.24 of the cap
  on linear edges, 0.62 at the oscillating points of the quadratic ones) stays in stick at
  every point of every increment, |tau| below the cap, and its force is the one-increment
  force whatever the increments (the response is linear while nothing slips; 1e-8, the
  residual tolerance);
- a cyclic slide (push to +2 mm, back to -2 mm, again to +2 mm): at every increment the force
  is +F or -F with the sign of the push increment, within 1e-6 (each increment, 0.67 mm or
  more, is far beyond the elastic reversal of the stick, 2 F / K = 2.5e-5 m with the stick
  stiffness K = 8.35e6 kN/m per m of the stick case), every point in slip with tau of the sign
  of its slip increment.

Before the fix of the state iteration one push increment gave -68 % (SPRING, GOODMAN4) and
-35 % (GOODMAN6), 20 increments -16 % and -0.65 %, each run reporting `completed`.
"""
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]

L, H, NX, NY = 2.0, 0.5, 8, 2
SIGMA_N, PHI, C = 100.0, 25.0, 5.0
MU = math.tan(math.radians(PHI))
PUSH = 0.002
TOL_FORCE = 1e-6
TOL_CAP = 1e-8

LAWS = {
    "c_phi": (f"PHI = {PHI}, C = {C}", C),
    "phi": (f"PHI = {PHI}", 0.0),
    "mu_c": (f"MU = {MU!r}, C = {C}", C),
    "tension": (f"PHI = {PHI}, C = {C}, TENSION = 10", C),
}

# (joint type, edge nodes, INTEGRATION or None)
JOINTS = [("SPRING", 2, None), ("GOODMAN4", 2, "GAUSS"), ("GOODMAN4", 2, "LOBATTO"),
          ("GOODMAN6", 3, "GAUSS"), ("GOODMAN6", 3, "LOBATTO"), ("THIN_LAYER", 2, None),
          ("THIN_LAYER", 3, None)]
JOINT_IDS = [f"{j}{'-' + i if i else ''}{'-q' if n == 3 and j == 'THIN_LAYER' else ''}"
             for j, n, i in JOINTS]


def sliding_force(c):
    return (c + SIGMA_N * MU) * L


def deck(joint, edge_nodes, integration, law, steps, push=PUSH, method="NEWTON"):
    """The block deck: ground and block of NX x NY Q4 (2-node edges) or Q8 elements each,
    split along y = 0 by generated joints (SIDE=block); pressure on top, then the push steps
    [(factor of `push`, increments), ...] on every block node above the interface row."""
    quad8 = edge_nodes == 3
    m = 2 if quad8 else 1
    xs = np.linspace(0.0, L, m * NX + 1)
    ys = np.linspace(-H, H, 2 * m * NY + 1)
    ids, lines = {}, ["*NODES"]
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            if quad8 and i % 2 == 1 and j % 2 == 1:
                continue
            ids[i, j] = len(ids) + 1
            lines.append(f"{ids[i, j]}, {float(x)!r}, {float(y)!r}")
    eid = 0
    for name, rows in (("ground", range(NY)), ("block", range(NY, 2 * NY))):
        lines.append(f"*ELEMENTS, TYPE={'Q8' if quad8 else 'Q4'}, SET={name}")
        for r in rows:
            for c in range(NX):
                i, j = m * c, m * r
                conn = [ids[i, j], ids[i + m, j], ids[i + m, j + m], ids[i, j + m]]
                if quad8:
                    conn += [ids[i + 1, j], ids[i + 2, j + 1], ids[i + 1, j + 2], ids[i, j + 1]]
                eid += 1
                lines.append(", ".join(map(str, [eid] + conn)))

    def edge(i, k, j):
        e = [ids[i, j], ids[k, j]] + ([ids[(i + k) // 2, j]] if quad8 else [])
        return ", ".join(map(str, e))

    mid, top = m * NY, 2 * m * NY
    options = ", THICKNESS=0.01" if joint == "THIN_LAYER" else ""
    if integration:
        options += f", INTEGRATION={integration}"
    text = ["*TITLE", f"Block sliding on a Katona {joint} interface", "*UNITS", "kN, m, kPa",
            "*ANALYSIS, TYPE=PLANE_STRAIN"] + lines + [
        "*MATERIAL, NAME=stiff", "E = 1e7, NU = 0.3",
        "*SECTION, SET=ground, MATERIAL=stiff", "*SECTION, SET=block, MATERIAL=stiff",
        "*INTERFACE_LAW, NAME=iface, TYPE=KATONA", law,
        "*EDGES, NAME=iface"] + [edge(m * c, m * c + m, mid) for c in range(NX)] + [
        f"*JOINTS, TYPE={joint}, SET=joint, LAW=iface, EDGES=iface, SIDE=block{options}",
        "*EDGES, NAME=top"] + [edge(m * c + m, m * c, top) for c in range(NX)] + [
        "*NSET, NAME=base", ", ".join(str(v) for (i, j), v in ids.items() if j == 0),
        "*NSET, NAME=pushed", ", ".join(str(v) for (i, j), v in ids.items() if j > mid),
        "*BOUNDARY", "base, XY",
        "*LOAD, NAME=press, TYPE=PRESSURE", f"top, {SIGMA_N}",
        "*LOAD, NAME=push, TYPE=DISPLACEMENT", f"pushed, X, {push!r}",
        "*STEP, NAME=press, INCREMENTS=1", "press, 1"]
    for k, (factor, n) in enumerate(steps):
        text += [f"*STEP, NAME=push{k + 1}, INCREMENTS={n}", f"push, {factor}"]
    text.append(f"*SOLVER, METHOD={method}, TOLERANCE=1e-8, MAX_ITERATIONS=60")
    return "\n".join(text) + "\n"


def run(text, tmp_path, name):
    """Status and, per written increment: push force, joint point modes, (sigma_n, tau) and
    (eps_n, eps_t)."""
    path = tmp_path / f"{name}.inp"
    path.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(path), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert out.exists(), p.stdout + p.stderr
    with Results(out) as res:
        status = res.status
        pushed = res.node_set("pushed")
        incs = []
        for key in res.keys:
            incs.append({"force": res.field(key, "reaction")[pushed, 0].sum(),
                         "mode": res.field(key, "joints/joint/mode").ravel(),
                         "stress": res.field(key, "joints/joint/stress").reshape(-1, 2),
                         "eps": res.field(key, "joints/joint/relative_displacement")
                         .reshape(-1, 2)})
    return status, incs


def check_slip(inc, prev, c, sign, what):
    """Every point in slip at the cap, tau of the sign of its slip increment (= sign)."""
    cap = c + MU * inc["stress"][:, 0]
    tau = inc["stress"][:, 1]
    slip = inc["eps"][:, 1] - prev["eps"][:, 1]
    assert np.all(inc["mode"] == 2), f"{what}: modes {inc['mode']} (2 = slip)"
    assert np.all(np.abs(np.abs(tau) - cap) <= TOL_CAP * cap), \
        f"{what}: |tau| - cap {np.abs(tau) - cap}"
    assert np.all(sign * tau > 0) and np.all(sign * slip > 0), \
        f"{what}: tau {tau}, slip of the increment {slip}"


# every joint variant with c > 0 and c = 0; the MU= and TENSION forms of the law on the linear
# and the quadratic Goodman joint (the law form only changes the doublets' mu, c A and T A)
CASES = [(j, law) for j in range(len(JOINTS)) for law in ("c_phi", "phi")] + \
    [(j, law) for j in (1, 3) for law in ("mu_c", "tension")]


@pytest.mark.parametrize("joint, law", [(JOINTS[j], law) for j, law in CASES],
                         ids=[f"{JOINT_IDS[j]}-{law}" for j, law in CASES])
def test_sliding_force_does_not_depend_on_the_increments(tmp_path, joint, law):
    text, c = LAWS[law]
    force = sliding_force(c)
    errors = []
    for n in (1, 5, 20, 100):
        status, incs = run(deck(*joint, text, [(1.0, n)]), tmp_path, f"push{n}")
        assert status == "completed"
        errors.append((incs[-1]["force"] - force) / force)
        assert abs(errors[-1]) <= TOL_FORCE, f"{n} increments: force {incs[-1]['force']}"
        check_slip(incs[-1], incs[-2], c, 1.0, f"{n} increments, last")
    print(f"{joint} {law}: force error for 1/5/20/100 increments "
          + " ".join(f"{e:.1e}" for e in errors))


@pytest.mark.parametrize("joint", [JOINTS[1], JOINTS[3]], ids=[JOINT_IDS[1], JOINT_IDS[3]])
def test_sliding_force_under_modified_newton(tmp_path, joint):
    force = sliding_force(C)
    for n in (1, 5, 20, 100):
        status, incs = run(deck(*joint, LAWS["c_phi"][0], [(1.0, n)], method="MODIFIED_NEWTON"),
                           tmp_path, f"mn{n}")
        assert status == "completed"
        assert abs(incs[-1]["force"] - force) <= TOL_FORCE * force, f"{n} increments"
        check_slip(incs[-1], incs[-2], C, 1.0, f"modified Newton, {n} increments")


@pytest.mark.parametrize("joint", JOINTS, ids=JOINT_IDS)
def test_a_push_below_sliding_stays_in_stick(tmp_path, joint):
    forces, ratio = [], 0.0
    for n in (1, 5, 20, 100):
        status, incs = run(deck(*joint, LAWS["c_phi"][0], [(1.0, n)], push=1e-6), tmp_path,
                           f"stick{n}")
        assert status == "completed"
        for k, inc in enumerate(incs[1:]):
            cap = C + MU * inc["stress"][:, 0]
            assert np.all(inc["mode"] == 1), f"{n} increments, increment {k + 1}: {inc['mode']}"
            ratio = max(ratio, np.max(np.abs(inc["stress"][:, 1]) / cap))
        forces.append(incs[-1]["force"])
    print(f"{joint}: stick force {forces[0]:.6f}, largest |tau| / cap {ratio:.3f}")
    assert ratio < 1.0
    assert 0.0 < forces[0] < sliding_force(C)
    assert np.allclose(forces, forces[0], rtol=1e-8, atol=0.0), forces


@pytest.mark.parametrize("joint", JOINTS, ids=JOINT_IDS)
def test_cyclic_slide_follows_the_slip_rate(tmp_path, joint):
    force = sliding_force(C)
    steps = [(1.0, 3), (-1.0, 6), (1.0, 3)]
    status, incs = run(deck(*joint, LAWS["c_phi"][0], steps), tmp_path, "cyclic")
    assert status == "completed"
    signs = [s for factor, n in steps for s in [1.0 if factor > 0 else -1.0] * n]
    # the first push increment starts from the pressed state, the reversals from the opposite
    # slip: each increment's push has the sign of its step's direction
    assert len(incs) == 1 + len(signs)
    for k, sign in enumerate(signs, start=1):
        assert abs(incs[k]["force"] - sign * force) <= TOL_FORCE * force, \
            f"increment {k}: force {incs[k]['force']}, expected {sign * force}"
        check_slip(incs[k], incs[k - 1], C, sign, f"cyclic increment {k}")
