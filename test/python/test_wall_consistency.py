"""The same wall in soil as a continuum strip and as a plate (pecplas_py.decks.wall_pair,
doc/validation.md, Structures: plate against strip): a cantilever 8 m long, steel t = 0.1 m
(E_w = 2.1e8 kPa, nu_w = 0.2), in elastic soil (E = 3e4 kPa, K0 = 0.5) under one excavation
phase (3 m in front), elastic joints on both faces (K_n = 1e6, K_t = 1 kPa/m: smooth), its toe
held (the plate's toe node in x, y and rotation, the strip's base in x and y). The strip: two
Q8 across, 0.125 m rows; the plate: EA = E_w t, EI = E_w t^3/12, NU = nu_w (the strip's
plane-strain stiffnesses). This is the pair for which the two models should agree: thin
(t/L = 1/80: the difference of the head displacements grows in proportion to t/L), smooth
(the friction on the strip's faces, t/2 off its axis, adds a moment the plate ignores), the
toe held (the strip's bonded base carries a moment the plate's toe node cannot).

Measured (debug build): largest |M| 31.45 (plate) vs 30.74 kN m/m (strip), +2.3 %; the
plate's moment interpolated to the strip's Gauss levels differs from the strip's by at most
1.3 % of the largest; head u_x -2.589 vs -2.636 mm, -1.8 %. The problem is linear (elastic
soil and joints, one increment): these numbers depend on the build only at round-off.

That the plate's shear jump equals the joint forces at each plate node (to the solver
tolerance) is the Fortran suite joint_faces, test plate_wall_equilibrium.
"""
import subprocess

import pytest

from pecplas_exe import pecplas_cmd
from pecplas_py.decks.wall_pair import deck
from pecplas_py.scenes.wall_consistency import TEST as PAIR, measure


def _run(text, path):
    path.write_text(text)
    out = path.with_suffix(".h5")
    p = subprocess.run(pecplas_cmd() + [str(path), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    return out


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    d = tmp_path_factory.mktemp("wall_pair")
    hp = _run(deck(PAIR, plate=True), d / "plate.inp")
    hs = _run(deck(PAIR, plate=False), d / "strip.inp")
    (r,) = measure(hp, hs, PAIR.t)
    return r


def test_moment(pair):
    """The agreement doc/validation.md (Structures, plate against strip) states for a thin,
    smooth wall held at its toe: the same largest moment within 5 %, and the whole profile
    within 5 % of the largest moment (the plate's moment linear between its nodes, 0.125 m
    apart, against the strip's at its Gauss levels). Its table gives 1.8-2.9 % and 1.1-2.9 %
    for such walls (the wall's thickness: cause (4) there); measured here 2.3 % and 1.3 %."""
    assert pair["m_plate"] == pytest.approx(pair["m_strip"], rel=0.05)
    assert pair["profile_diff"] <= 0.05 * pair["m_strip"]


def test_head_displacement(pair):
    """The same head displacement within 2 %, towards the excavation in both: with smooth
    faces and the toe held the difference grows in proportion to t/L (doc/validation.md,
    plate against strip, cause (4): 1.3 % at t/L = 1/80 with EI kept); measured 1.8 %."""
    assert pair["head_plate"] == pytest.approx(pair["head_strip"], rel=0.02)
    assert pair["head_plate"] < 0 and pair["head_strip"] < 0


def test_plate_line_ending_on_the_held_bottom(tmp_path):
    """A plate line whose end lies on the held bottom of the mesh (joints on both faces: the
    end node is split per body, every copy on the support): the deck runs and each copy of the
    end node stays put (the supports hold them exactly)."""
    from pecplas_py.decks.wall_pair import WallPair
    from pecplas_py.results import Results
    import numpy as np
    p = WallPair(below=(), element="Q4", row=1.0, away=(1.0, 2.0, 3.0))
    out = _run(deck(p, plate=True), tmp_path / "bottom.inp")
    with Results(out) as r:
        assert r.status == "completed"
        x = r.coordinates
        toe = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1] + p.wall_l) < 1e-9))[0]
        # the original (the plate's) and a copy per body: on the boundary the two bodies
        # meet only across the line
        assert len(toe) == 3
        u = r.field(r.last_key(), "displacement")
        assert np.all(u[toe] == 0.0)
