"""pecplas_py.peers.export_abaqus: our decks written as CalculiX input.

Without ccx: node and element counts, the contact surfaces built from the right element faces,
master on the stiff side, the tip tied where both sides touch the axis, materials, initial
stresses. With ccx on the PATH: an oedometric two-block column joined by a compressed penalty
joint, where both codes must give the exact settlement 2 p h / M + p / K_n (uniaxial strain,
linear penalty): the joint stays closed and in stick, so the case is elastic and bonded."""

import math
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.peers import export_abaqus as ex
from pecplas_exe import pecplas_cmd  # noqa: E402

from pecplas_py import script_cmd
from pecplas_py.results import Results

E, NU, KN, P, H = 1.0e4, 0.3, 1.0e5, 100.0, 1.0
M = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
EXACT = 2 * P * H / M + P / KN


def column_deck(axi):
    """Two 1 m blocks stacked, joined by a GOODMAN4 joint, side rollers, bottom fixed, pressure
    P on top. Axisymmetric: a ring 0.5 <= r <= 1.5 (no node on the axis, so CalculiX can use
    the joint faces as contact surfaces)."""
    x0, x1 = (0.5, 1.5) if axi else (0.0, 1.0)
    # Gauss points integrate the joint's 2 pi r weighted stiffness exactly (Lobatto lumps it,
    # which bends the ring); plane strain: either rule is exact
    rule = "GAUSS" if axi else "LOBATTO"
    nodes = [(1, x0, 0), (2, x1, 0), (3, x0, H), (4, x1, H), (5, x0, H), (6, x1, H),
             (7, x0, 2 * H), (8, x1, 2 * H)]
    lines = ["*TITLE", "oedometric column with a joint", "*UNITS", "kN, m, kPa",
             f"*ANALYSIS, TYPE={'AXISYMMETRIC' if axi else 'PLANE_STRAIN'}", "*NODES"]
    lines += [f"{k}, {x}, {y}" for k, x, y in nodes]
    lines += ["*ELEMENTS, TYPE=Q4, SET=lower", "1, 1, 2, 4, 3",
              "*ELEMENTS, TYPE=Q4, SET=upper", "2, 5, 6, 8, 7",
              "*MATERIAL, NAME=soil", f"E = {E:g}, NU = {NU:g}",
              "*SECTION, SET=lower, MATERIAL=soil", "*SECTION, SET=upper, MATERIAL=soil",
              "*INTERFACE_LAW, NAME=j, TYPE=MOHR_COULOMB",
              f"KN = {KN:g}, KT = {KN:g}, PHI = 30, C = 0, PSI = 0",
              f"*JOINTS, TYPE=GOODMAN4, SET=joint, LAW=j, INTEGRATION={rule}", "10, 3, 4, 6, 5",
              "*NSET, NAME=sides", "1, 2, 3, 4, 5, 6, 7, 8", "*NSET, NAME=bottom", "1, 2",
              "*BOUNDARY", "sides, X", "bottom, XY", "*EDGES, NAME=top", "8, 7",
              "*LOAD, NAME=p, TYPE=PRESSURE", f"top, {P:g}",
              "*STEP, NAME=load, INCREMENTS=2", "p, 1"]
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def s2(tmp_path_factory):
    d = tmp_path_factory.mktemp("s2")
    subprocess.run([*script_cmd("decks.make_s2_decks"), "--out", str(d)],
                   check=True, capture_output=True)
    m = ex.parse_deck(d / "s2" / "s2_mohr_coulomb.inp")
    m["nsets"]["PRINT_NODES"] = [1]
    warnings = []
    out = d / "s2_ccx.inp"
    ex.export(m, out, warn=warnings.append)
    return m, out.read_text(), warnings


def blocks(text, keyword):
    """Data lines of every block whose keyword line starts with `keyword`."""
    out, cur = [], None
    for line in text.splitlines():
        if line.startswith("*"):
            cur = [] if line.upper().startswith(keyword) else None
            if cur is not None:
                out.append((line, cur))
        elif cur is not None:
            cur.append(line)
    return out


def test_counts_and_materials(s2):
    m, text, _ = s2
    # the reference S2 mesh: 54 Q4 in three bodies (pile, column, soil) with their own nodes
    assert len(blocks(text, "*NODE")[0][1]) == len(m["nodes"]) == 82
    els = blocks(text, "*ELEMENT,")
    assert all("TYPE=CAX4" in head for head, _ in els)
    assert sum(len(d) for _, d in els) == 54
    mats = {head.split("NAME=")[1]: i for i, (head, _) in enumerate(blocks(text, "*MATERIAL"))}
    assert set(mats) == {"concrete", "sand"}
    elastic = [[float(x) for x in d[0].split(",")] for _, d in blocks(text, "*ELASTIC")]
    assert elastic == [[2.0e7, 0.2], [2.0e4, 0.3]]
    # density = GAMMA / g so that the gravity step balances the geostatic stresses
    assert all(abs(float(d[0]) - 18.0 / 9.81) < 1e-9 for _, d in blocks(text, "*DENSITY"))


def test_contact_surfaces_from_the_joint_faces(s2):
    m, text, warnings = s2
    surf = {h.split("NAME=")[1].split(",")[0]: d for h, d in blocks(text, "*SURFACE,")}
    sets = {e[0]: e[2] for e in m["elements"]}
    conn = {e[0]: e[3] for e in m["elements"]}
    for name, master_set, slave_sets in (("shaft", "pile", {"soil"}),
                                         ("below", "column", {"soil"})):
        # master on the stiffer side (the pile) for the shaft; the column and the soil are the
        # same sand: the first side (the column) is the master
        for side, want in (("M", {master_set}), ("S", slave_sets)):
            rows = [x.split(",") for x in surf[f"{name}_{side}"]]
            faces = [(int(a), int(b.strip()[1:])) for a, b in rows]
            assert {sets[e] for e, _ in faces} == want
            for e, k in faces:     # every face lies on r = 0.5, the joint's line
                i, j = ex.Q4_FACES[k - 1]
                assert abs(m["nodes"][conn[e][i]][0] - 0.5) < 1e-12
                assert abs(m["nodes"][conn[e][j]][0] - 0.5) < 1e-12
        # one face per joint segment: 5 pile rows on the shaft, 4 column rows below the tip
        assert len(surf[f"{name}_M"]) == {"shaft": 5, "below": 4}[name]
    friction = [d[0] for _, d in blocks(text, "*FRICTION")]
    assert friction == [f"{math.tan(math.radians(30)):.12g}, 20000"] * 2
    behaviour = [d[0] for _, d in blocks(text, "*SURFACE BEHAVIOR")]
    assert behaviour == ["20000000"] * 2
    # the tip: pile base and column top both touch the axis -> tied, with a warning
    assert any("tip" in w and "tied" in w for w in warnings)
    eq = blocks(text, "*EQUATION")[0][1]
    # 2 doublets x 2 dofs, minus the radial dof of the axis doublet (fixed on both sides)
    assert len(eq) == 2 * 3


def test_initial_stress_is_geostatic(s2):
    m, text, _ = s2
    rows = blocks(text, "*INITIAL CONDITIONS")[0][1]
    assert len(rows) == 54 * 8          # every integration point of the expanded C3D8
    e1 = next(e for e in m["elements"] if e[0] == 1)
    ys = [m["nodes"][n][1] for n in e1[3]]
    for r in rows[:8]:
        v = [float(x) for x in r.split(",")]
        assert int(v[0]) == 1
        # element, ip, sxx, syy, szz, sxy, sxz, syz: K0 = 0.5 on xx and on the hoop zz
        # (10 significant digits are written)
        assert v[3] < 0 and v[2] == pytest.approx(0.5 * v[3], rel=1e-9) and v[4] == v[2]
        assert v[5:] == [0.0, 0.0, 0.0]
        # sigma_yy = gamma * y (surface y = 0, compression negative) at a point inside the
        # element, at a Gauss level 0.211 h from its top or bottom
        y = v[3] / 18.0
        h = max(ys) - min(ys)
        gauss = h * (1 - 1 / math.sqrt(3)) / 2
        assert min(abs(y - min(ys)), abs(max(ys) - y)) == pytest.approx(gauss)


def ours(deck, out):
    r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(out), "--quiet"], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with Results(out) as r:
        return -r.field(r.last_key(), "displacement")[7, 1]


@pytest.mark.skipif(shutil.which("ccx") is None, reason="CalculiX (ccx) is not on the PATH")
@pytest.mark.parametrize("axi", [False, True], ids=["plane_strain", "axisymmetric"])
def test_ccx_matches_ours_on_a_compressed_joint(tmp_path, axi):
    deck = tmp_path / "column.inp"
    deck.write_text(column_deck(axi))
    m = ex.parse_deck(deck)
    m["nsets"]["PRINT_NODES"] = [8]
    ex.export(m, tmp_path / "column_ccx.inp")
    r = subprocess.run(["ccx", "-i", "column_ccx"], cwd=tmp_path, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stdout[-2000:]
    lines = (tmp_path / "column_ccx.dat").read_text().splitlines()
    u_ccx = -float([ln for ln in lines if ln.split()[:1] == ["8"]][-1].split()[2])
    u_ours = ours(deck, tmp_path / "column.h5")
    # uniaxial strain + a linear penalty joint: both codes are exact (Q4, face-to-face
    # penalty); 1e-6 leaves room for ccx's printed 7 digits and its contact tolerances
    assert u_ours == pytest.approx(EXACT, rel=1e-9)
    assert u_ccx == pytest.approx(EXACT, rel=1e-6)
