"""Scenes S2 (pile under one load cycle, four penalty interface models on one mesh) and S3
(Mohr-Coulomb with dilatancy) at the reference refinement, through the real program.

Physics asserted (SPEC §7, issue: S2/S3 physics): at 2000 kN the head load exceeds the shaft
capacity computed by hand from the initial stresses, Q_s = int_0^L K0 gamma z tan(phi) pi d dz
= 816.2 kN, so the whole shaft slips (points with sigma_n > 1 kPa) and carries Q_s within
15 % (sigma_n moves away from K0 gamma z as the soil deforms); after unloading the settlement
is permanent, the shaft shear has reversed somewhere (negative skin friction) and residual
stresses remain; S3: the head load at a fixed settlement rises with psi."""
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from s2_results import head_curve, last_key, shaft  # noqa: E402

QS = 0.5 * 18.0 * math.tan(math.radians(30.0)) * math.pi * 1.0 * 10.0**2 / 2.0
MODELS = ("goodman", "ghaboussi", "spring", "mohr_coulomb")


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    exe = os.environ.get("PECPLAS_BIN")
    cmd = [exe] if exe else ["fpm", "run", "--target", "pecplas", "--"]
    out = tmp_path_factory.mktemp("s2")
    files = {}
    decks = [ROOT / "input" / "s2" / f"s2_{m}.inp" for m in MODELS]
    decks += [ROOT / "input" / "s3" / f"s3_psi{p}.inp" for p in (0, 1, 5, 15, 30)]
    for d in decks:
        h5 = out / (d.stem + ".h5")
        r = subprocess.run([*cmd, str(d), "-o", str(h5), "--quiet"], cwd=ROOT,
                           capture_output=True, text=True)
        assert r.returncode == 0, d.name + ": " + r.stderr
        files[d.stem] = h5
    return files


@pytest.mark.parametrize("model", MODELS)
def test_s2_full_slip_and_capacity(runs, model):
    h5 = runs[f"s2_{model}"]
    z, s, mode, q = shaft(h5, last_key(h5, 1))
    loaded = s[:, 0] > 1.0
    assert np.all(mode[loaded] == 2), "every compressed shaft point slips at 2000 kN"
    assert abs(q) == pytest.approx(QS, rel=0.15)


@pytest.mark.parametrize("model", MODELS)
def test_s2_unloading(runs, model):
    h5 = runs[f"s2_{model}"]
    load, s, _ = head_curve(h5)
    assert load[-1] == pytest.approx(0.0, abs=1e-9)
    assert s[-1] > 0.2 * s.max(), "permanent settlement after unloading"
    _, s_load, _, _ = shaft(h5, last_key(h5, 1))
    _, s_unl, _, _ = shaft(h5, last_key(h5, 2))
    sign = np.sign(np.sum(s_load[:, 1]))
    assert np.any(np.sign(s_unl[:, 1]) == -sign), "shaft shear reverses on unloading"
    assert np.abs(s_unl[:, 1]).max() > 1.0, "residual shaft shear remains"


def test_s2_models_agree_on_settlement(runs):
    """Same stiffnesses, same mesh: the Goodman, thin-layer and Mohr-Coulomb joints give the
    same head settlement at 2000 kN within 1 %, the springs (one point per doublet) within 5 %."""
    s = {m: head_curve(runs[f"s2_{m}"])[1][19] for m in MODELS}
    for m in ("ghaboussi", "mohr_coulomb"):
        assert s[m] == pytest.approx(s["goodman"], rel=0.01)
    assert s["spring"] == pytest.approx(s["goodman"], rel=0.05)


def test_s3_capacity_rises_with_psi(runs):
    curves = {p: head_curve(runs[f"s3_psi{p}"]) for p in (0, 1, 5, 15, 30)}
    target = min(c[1][19] for c in curves.values())   # settlement reached by every curve
    loads = [np.interp(target, np.r_[0.0, c[1][:20]], np.r_[0.0, c[0][:20]])
             for c in curves.values()]
    assert all(b > a for a, b in zip(loads, loads[1:])), loads


def test_s2_goodman_mesh_convergence(tmp_path):
    """Head settlement at 2000 kN (Goodman joints) on refinements 1, 2, 4: the differences
    shrink with an observed order (Richardson) near 2, as for linear elements."""
    exe = os.environ.get("PECPLAS_BIN")
    cmd = [exe] if exe else ["fpm", "run", "--target", "pecplas", "--"]
    s = []
    for r in (1, 2, 4):
        subprocess.run([sys.executable, str(ROOT / "tools" / "make_s2_decks.py"), "--refine",
                        str(r), "--out", str(tmp_path)], check=True, capture_output=True)
        tag = "" if r == 1 else f"_r{r}"
        deck = tmp_path / "s2" / f"s2_goodman{tag}.inp"
        h5 = tmp_path / f"g{r}.h5"
        run = subprocess.run([*cmd, str(deck), "-o", str(h5), "--quiet"], cwd=ROOT,
                             capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        s.append(head_curve(h5)[1][19])
    order = math.log2(abs((s[1] - s[0]) / (s[2] - s[1])))
    print(f"S2 Goodman head settlement at 2000 kN, refine 1/2/4: "
          f"{s[0] * 1e3:.2f} / {s[1] * 1e3:.2f} / {s[2] * 1e3:.2f} mm, observed order {order:.2f}")
    assert abs(s[2] - s[1]) < abs(s[1] - s[0])
    assert 1.5 < order < 3.0


def test_committed_decks_match_the_generator(tmp_path):
    """input/s2, input/s3 and input/default.inp (what `make run` runs) are what
    tools/make_s2_decks.py writes; default.inp is the Goodman deck under its own header."""
    subprocess.run([sys.executable, str(ROOT / "tools" / "make_s2_decks.py"), "--out",
                    str(tmp_path)], check=True, capture_output=True)
    for new in [*tmp_path.glob("s2/*.inp"), *tmp_path.glob("s3/*.inp")]:
        old = ROOT / "input" / new.parent.name / new.name
        assert old.read_text() == new.read_text(), f"{old} is stale: rerun make_s2_decks.py"
    default = (ROOT / "input" / "default.inp").read_text()
    assert default == (tmp_path / "default.inp").read_text()
    assert default.endswith((ROOT / "input" / "s2" / "s2_goodman.inp").read_text())
