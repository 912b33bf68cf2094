"""Self-describing results: *UNITS is read and checked, and every float dataset of a results
file says its units (and names its components); the XDMF shows the joint sets.

Run from the project root: python3 -m pytest test/python/test_results_units.py
"""

import re
import subprocess
from pathlib import Path

import h5py
import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.checks import check_results

BLOCK = ROOT / "test" / "data" / "decks" / "good_block_q4.inp"
GOODMAN = ROOT / "test" / "data" / "joints" / "patch_goodman4_plane.inp"
THIN = ROOT / "test" / "data" / "joints" / "patch_thin_layer_plane.inp"
SPRING_AXI = ROOT / "test" / "data" / "joints" / "patch_spring_axi.inp"
MOHR_COULOMB = ROOT / "test" / "data" / "plasticity" / "biaxial_mc.inp"


def run(deck, out):
    args = [*pecplas_cmd(), str(deck), "--quiet", "-o", str(out)]
    return subprocess.run(args, cwd=ROOT, capture_output=True, text=True, timeout=120)


def with_units(tmp_path, text, deck=BLOCK):
    """`deck` with its *UNITS data line replaced by `text` (None: *UNITS removed)."""
    lines = deck.read_text().splitlines()
    at = next(i for i, s in enumerate(lines) if s.strip().upper() == "*UNITS")
    lines[at:at + 2] = [] if text is None else ["*UNITS", text]
    path = tmp_path / deck.name
    path.write_text("\n".join(lines) + "\n")
    return path, at + 2


def attr(obj, name):
    value = obj.attrs[name]
    return value.decode() if isinstance(value, bytes) else value


@pytest.mark.parametrize("deck", [GOODMAN, THIN, SPRING_AXI, MOHR_COULOMB],
                         ids=lambda p: p.stem)
def test_every_dataset_described(tmp_path, deck):
    """Every float dataset has units (components where it has a component axis) and the
    XDMF references joint datasets that exist: pecplas_py.checks.check_results walks the file."""
    out = tmp_path / "r.h5"
    r = run(deck, out)
    assert r.returncode == 0, r.stderr
    problems, _ = check_results.check(str(out))
    assert problems == []
    count = 0
    with h5py.File(out) as f:
        def visit(name, obj):
            nonlocal count
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" \
                    and not name.startswith("restart"):
                assert "units" in obj.attrs, name
                count += 1
        f.visititems(visit)
        assert count >= 10  # the walk saw the mesh, history and increment datasets


def test_units_of_a_goodman_joint(tmp_path):
    """kN, m, kPa: displacements and joint relative displacements in m, reactions in kN,
    continuum and interface stresses in kPa, strains and load factors "1"."""
    out = tmp_path / "g.h5"
    assert run(GOODMAN, out).returncode == 0
    with h5py.File(out) as f:
        inc = f["increments"][sorted(f["increments"])[-1]]
        assert (attr(f, "length_unit"), attr(f, "force_unit"), attr(f, "stress_unit")) == \
            ("m", "kN", "kPa")
        assert attr(inc["displacement"], "units") == "m"
        assert list(inc["displacement"].attrs["components"]) == ["x", "y"]
        assert attr(inc["reaction"], "units") == "kN"
        stress = next(iter(inc["sets"].values()))["stress"]
        assert attr(stress, "units") == "kPa"
        assert list(stress.attrs["components"]) == ["xx", "yy", "zz", "xy"]
        joint = next(iter(inc["joints"].values()))
        assert list(joint["stress"].attrs["components"]) == ["sigma_n", "tau"]
        assert list(joint["relative_displacement"].attrs["components"]) == ["eps_n", "eps_t"]
        assert attr(joint["relative_displacement"], "units") == "m"
        assert attr(joint["plastic_slip"], "units") == "m"
        assert attr(f["history/time"], "units") == "1"


def test_thin_layer_and_axisymmetric_springs(tmp_path):
    """A thin layer works with strains ("1"); axisymmetric spring tributaries are areas."""
    assert run(THIN, tmp_path / "t.h5").returncode == 0
    with h5py.File(tmp_path / "t.h5") as f:
        joint = f["increments/000001/joints"]
        assert attr(next(iter(joint.values()))["relative_displacement"], "units") == "1"
    assert run(SPRING_AXI, tmp_path / "s.h5").returncode == 0
    with h5py.File(tmp_path / "s.h5") as f:
        assert attr(next(iter(f["mesh/joint_sets"].values()))["tributary"], "units") == "m2"


def test_soil_state_names(tmp_path):
    """Mohr-Coulomb history: names on the set (like the joints') and as components."""
    assert run(MOHR_COULOMB, tmp_path / "m.h5").returncode == 0
    names = ["eps_p_xx", "eps_p_yy", "eps_p_zz", "eps_p_xy", "eps_p_eq", "return_kind"]
    with h5py.File(tmp_path / "m.h5") as f:
        sets = list(f["mesh/sets"])
        assert list(f["mesh/sets"][sets[0]].attrs["state_names"]) == names
        state = f["increments/000001/sets"][sets[0]]["state"]
        assert list(state.attrs["components"]) == names and attr(state, "units") == "1"


def test_not_stated(tmp_path):
    """A deck without *UNITS runs; its dimensional datasets say "(not stated)"."""
    deck, _ = with_units(tmp_path, None)
    out = tmp_path / "n.h5"
    r = run(deck, out)
    assert r.returncode == 0, r.stderr
    with h5py.File(out) as f:
        assert attr(f, "length_unit") == "(not stated)"
        assert attr(f["increments/000001/displacement"], "units") == "(not stated)"
        assert attr(f["history/time"], "units") == "1"


@pytest.mark.parametrize("text, phrase", [
    ("kN, m, MPa", "stress unit MPa is not force/length**2 = kN/m2; expected kPa"),
    ("kip, in, ksi", 'unknown unit "kip"; known units: length m, cm, mm; force N, kN, MN'),
    ("kN, kPa", "no length unit"),
])
def test_bad_units_line(tmp_path, text, phrase):
    """A *UNITS line that does not parse: exit 2, file:line: [*UNITS] message, no results."""
    deck, line = with_units(tmp_path, text)
    out = tmp_path / "bad.h5"
    r = run(deck, out)
    assert r.returncode == 2
    assert re.search(rf"{re.escape(deck.name)}:{line}: \[\*UNITS\] .*{re.escape(phrase)}",
                     r.stderr), r.stderr
    assert not out.exists()


def committed_units():
    """{*UNITS text: is a path deck} of the decks in input/ and test/data."""
    texts = {}
    for deck in list((ROOT / "input").rglob("*.inp")) + list((ROOT / "test/data").rglob("*.inp")):
        lines = deck.read_text(errors="replace").splitlines()
        path = any(s.strip().upper().startswith("*PATH") for s in lines)
        for i, s in enumerate(lines[:-1]):
            if s.strip().upper() == "*UNITS":
                texts[(lines[i + 1].strip(), path)] = deck
    return texts


def test_committed_decks_units_parse(tmp_path):
    """Every *UNITS line of the decks in input/ and test/data is understood: each distinct
    text runs in the small block deck (path decks: in the example path deck)."""
    texts = committed_units()
    assert any(not path for _, path in texts)  # the decks do state their units
    for text, path in sorted(texts):
        if path:
            deck = tmp_path / "p.inp"
            deck.write_text(PATH_DECK.read_text().replace("mm, kPa", text))
            r = run_path(deck, tmp_path / "p")
        else:
            deck, _ = with_units(tmp_path, text)
            r = run(deck, tmp_path / "ok.h5")
        assert r.returncode == 0, (text, texts[(text, path)], r.stderr)


# ---- pecplas-path: *UNITS names a length and a stress (a point has no force) ----
from pecplas_exe import program_cmd  # noqa: E402

PATH_DECK = ROOT / "input" / "paths" / "cnl_mohr_coulomb.inp"


def run_path(deck, out):
    return subprocess.run([*program_cmd("pecplas-path"), str(deck), "-o", str(out), "--quiet"],
                          cwd=ROOT, capture_output=True, text=True, timeout=120)


def test_path_units_as_text(tmp_path):
    """The example path deck says "mm, kPa": its columns carry those units as text."""
    r = run_path(PATH_DECK, tmp_path / "p")
    assert r.returncode == 0, r.stderr
    with h5py.File(tmp_path / "p.h5") as f:
        assert (attr(f, "length_unit"), attr(f, "stress_unit")) == ("mm", "kPa")
        assert attr(f, "force_unit") == "(not stated)"
        units = {k: attr(f[k], "units") for k in ("eps_t", "eps_n", "plastic_slip", "targets",
                                                    "sigma_n", "tau")}
        assert units == {"eps_t": "mm", "eps_n": "mm", "plastic_slip": "mm", "targets": "mm",
                         "sigma_n": "kPa", "tau": "kPa"}


def test_path_units_with_a_force(tmp_path):
    """A force in a path deck's *UNITS is an input error at its line; nothing is written."""
    text = PATH_DECK.read_text().replace("mm, kPa", "kN, m, kPa")
    deck = tmp_path / "p.inp"
    deck.write_text(text)
    line = text.splitlines().index("kN, m, kPa") + 1
    r = run_path(deck, tmp_path / "p")
    assert r.returncode == 2
    assert f"p.inp:{line}: [*UNITS] a path deck has no force" in r.stderr, r.stderr
    assert not (tmp_path / "p.h5").exists()
