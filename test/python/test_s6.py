"""Scene S6 (model pile pull-out, thesis figs IV.4-IV.10, table IV.1) at the reference mesh,
through the real program: Mohr-Coulomb (psi = 6, pull 0 -> 6.28 kN) and MODJOIN initial
(table III.1) with the four table IV.1 variants (head uplift imposed 0 -> 40 mm).

Physics asserted: the Mohr-Coulomb interface carries the full 6.28 kN, its shaft resultant is
the pull less the tip's initial support, its elastic head stiffness is the joint and sand
springs in series (hand estimate, 10 %); MODJOIN reaches a genuine limit load (the curve levels
off, the shaft carries the pull with every closed point at the failure ratio) above the shaft
capacity at the initial stresses Q_s0 = int_0^L K0 gamma z tan(phi) pi d dz = 1.675 kN and
below 6.28 kN; every variant runs to the end; a stiffer shear modulus (G0 +50 %) gives a
smaller uplift at a common pull; K0 +50 % does not change the elastic branch and, past the
early contraction peak, gives a larger uplift (against the thesis's -36 %: doc/validation.md);
the MODJOIN / Mohr-Coulomb difference is printed. Stored regression values with their checks:
test/reference/s5_s6.json."""
import json
import math
import subprocess
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.scenes.s6_results import head_curve, keys_and_loads, shaft, uplift_at
from pecplas_exe import pecplas_cmd  # noqa: E402

A, L, GAMMA, PHI = 0.0275, 1.62, 17.0, 41.0
QS0 = 0.5 * GAMMA * math.tan(math.radians(PHI)) * math.pi * 2 * A * L**2 / 2.0
W_TIP0 = math.pi * A**2 * GAMMA * L      # the tip's initial normal force (geostatic)
Q_COMMON = 1.0                           # kN: every run carries it (beta +50 %: 1.15 at most)
VARIANTS = ("s6_modjoin_g0", "s6_modjoin_k0", "s6_modjoin_beta", "s6_modjoin_ag")
DECKS = ("s6_modjoin", *VARIANTS, "s6_mohr_coulomb")
REF = json.loads((ROOT / "test/reference/s5_s6.json").read_text())["s6"]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    cmd = pecplas_cmd()
    out = tmp_path_factory.mktemp("s6")
    files = {}
    for name in DECKS:
        h5 = out / (name + ".h5")
        r = subprocess.run([*cmd, str(ROOT / "input" / "s6" / (name + ".inp")), "-o", str(h5),
                            "--quiet"], cwd=ROOT, capture_output=True, text=True)
        assert r.returncode == 0, name + " did not run to the end: " + r.stderr
        files[name] = h5
    return files


def shaft_resultant(h5, key):
    """sum of tau over the shaft area (Lobatto points on the element ends, weight dz / 2),
    the same with |tau| replaced by tan(phi) sigma_n, and the shaft points' stresses."""
    z, s, mode = shaft(h5, key)
    dz = np.abs(np.diff(z.reshape(-1, 2), axis=1)).repeat(2) / 2.0
    area = 2 * math.pi * A * dz
    return (np.sum(s[:, 1] * area), np.sum(math.tan(math.radians(PHI)) * s[:, 0] * area),
            s, mode)


def test_hand_capacity():
    assert QS0 == pytest.approx(1.675, abs=0.001)


def test_mohr_coulomb_carries_the_full_pull(runs):
    h5 = runs["s6_mohr_coulomb"]
    load, u = head_curve(h5)
    assert load[-1] == pytest.approx(6.28, rel=1e-9)
    assert all(b > a for a, b in zip(u, u[1:])), "uplift grows with the pull"
    keys, _ = keys_and_loads(h5)
    t, cap, _, _ = shaft_resultant(h5, keys[-1])
    assert t == pytest.approx(load[-1] - W_TIP0, rel=0.005)
    assert t == pytest.approx(cap, rel=0.002), "every shaft point slips at tan(phi)"
    # elastic first increment against the joint (G0 pi d L) and sand (2 pi G L / ln(R/a))
    # springs in series; the steel's axial compliance is 0.3 % of it
    k_joint = 40.0e3 * math.pi * 2 * A * L
    k_sand = 2 * math.pi * 3.0e4 / 2.6 * L / math.log(1.0 / A)
    k_fe = load[1] / u[1]
    assert k_fe == pytest.approx(1.0 / (1.0 / k_joint + 1.0 / k_sand), rel=0.10)
    ref = REF["mohr_coulomb_uplift_at_6.28kN_mm"]
    assert u[-1] * 1e3 == pytest.approx(ref["value"], rel=ref["tol"])
    ref = REF["mohr_coulomb_head_stiffness_kN_per_mm"]
    assert k_fe * 1e-3 == pytest.approx(ref["value"], rel=ref["tol"])


def test_modjoin_genuine_limit_load(runs):
    h5 = runs["s6_modjoin"]
    load, u = head_curve(h5)
    q = load[-1]
    print(f"S6 MODJOIN limit load {q:.3f} kN at {u[-1] * 1e3:.0f} mm, Q_s0 = {QS0:.3f} kN")
    assert QS0 < q < 6.28
    assert q == pytest.approx(load.max(), rel=1e-9)
    assert q - np.interp(u[-1] - 0.01, u, load) < 0.01 * q, "levelled off over the last 10 mm"
    keys, _ = keys_and_loads(h5)
    t, _, s, _ = shaft_resultant(h5, keys[-1])
    assert t == pytest.approx(q - W_TIP0, rel=0.01)
    closed = s[:, 0] > 0.0
    assert np.all(s[closed, 1] >= 0.97 * math.tan(math.radians(PHI)) * s[closed, 0])


def test_variants_limit_loads_regression(runs):
    ref = REF["modjoin_limit_load_kN"]
    for name, v in ref["value"].items():
        assert head_curve(runs[name])[0].max() == pytest.approx(v, rel=ref["tol"]), name


def test_table_iv1(runs):
    """Head uplift at a pull every run carries, each variant against the base run."""
    base = uplift_at(runs["s6_modjoin"], Q_COMMON)
    thesis = {"g0": "-13 %", "k0": "-36 %", "beta": "strong", "ag": "hardly any"}
    ref = REF["modjoin_uplift_at_1kN_mm"]
    change = {}
    for name in VARIANTS:
        var = uplift_at(runs[name], Q_COMMON)
        tag = name.split("_")[-1]
        change[tag] = var / base - 1
        print(f"S6 {tag} +50 %: uplift at {Q_COMMON} kN {base * 1e3:.3f} -> {var * 1e3:.3f} mm "
              f"({100 * change[tag]:+.1f} %; thesis at the end of loading {thesis[tag]})")
        assert var * 1e3 == pytest.approx(ref["value"][name], rel=ref["tol"]), name
    assert base * 1e3 == pytest.approx(ref["value"]["s6_modjoin"], rel=ref["tol"])
    assert change["g0"] < 0.0, "a stiffer shear modulus lowers the uplift"
    assert change["k0"] > 0.0, "K0 turns the law's contraction into a faster loss of sigma_n"
    assert change["beta"] > change["k0"] and abs(change["ag"]) < 0.5 * change["k0"]


def test_k0_no_effect_on_the_elastic_branch(runs):
    """K acts only through the dilatancy: before the law's plastic slip spreads (0.3 kN) the
    uplift of the K0 +50 % run equals the base run's within 3 %."""
    a, b = (np.interp(0.3, head_curve(runs[n])[0][:5], head_curve(runs[n])[1][:5])
            for n in ("s6_modjoin", "s6_modjoin_k0"))
    assert b == pytest.approx(a, rel=0.03)


def test_modjoin_vs_mohr_coulomb_reported(runs):
    q = 0.9 * head_curve(runs["s6_modjoin"])[0].max()
    a, b = (uplift_at(runs[n], q) for n in ("s6_modjoin", "s6_mohr_coulomb"))
    print(f"S6 at {q:.2f} kN: MODJOIN {a * 1e3:.2f} mm, Mohr-Coulomb {b * 1e3:.2f} mm "
          f"({100 * (a / b - 1):+.0f} %, thesis 6 % at the end)")
    assert a > b > 0, "MODJOIN near its limit, Mohr-Coulomb still rising linearly"


def test_docs_match_fresh_runs(runs):
    """The S6 numbers of doc/validation.md (generated blocks written by pecplas_py.scenes.s6_report)
    equal those of these fresh runs to the last printed digit."""
    from pecplas_py.scenes import s6_report
    diff = s6_report.check_doc(runs)
    assert not diff, diff + ("\nregenerate: make s6 (python3 -m pecplas_py.scenes.s6_report "
                             "output/s6)")
