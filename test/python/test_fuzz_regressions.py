"""Mutants found by the deck fuzzer (pecplas_py.checks.mutate_decks, doc/tools.md) that the
program once answered badly, kept as fixed edits of their source deck or mesh: each must now
be refused with exit code 2, one message `file:line: [KEYWORD] ...` that says what was
expected, and nothing written to the output folder (README.md, exit codes)."""
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]

# name: (source, file edited ("deck" or the mesh the deck reads), old text, new text,
#        text the message must hold, file the message must name)
MUTANTS = {
    # a huge Poisson ratio was printed by an F10.4 edit: "got **********"
    "elastic_nu_huge": ("test/data/cli/oedometer.inp", "deck", "E = 1e4, NU = 0.3",
                        "E = 1e4, NU = 1e300", "NU must satisfy -1 < NU < 0.5, got 0.1",
                        "deck"),
    # a stray token between two mesh sections: the message named no section ("[...]")
    "gmsh_stray_token": ("test/data/user/good_gmsh_group_phase.inp", "mesh",
                         "$EndMeshFormat\n", "$EndMeshFormat\n100000000\n",
                         "[$MeshFormat] expected a section name ($Name) after $EndMeshFormat, "
                         "got '100000000'", "mesh"),
    # a quadratic axisymmetric joint whose midside node was moved onto its end node: its
    # negative radius at an integration point was an error naming no file or line
    "joint_negative_radius": ("test/data/katona/float_goodman6_axi.inp", "deck",
                              "\n25, 0.3, 0\n", "\n25, 0.7, 0\n",
                              "joint element 107 of set joint: axisymmetric joint element with a "
                              "negative radius", "deck"),
    # the same with the midside node of a loaded edge: 'axisymmetric edge load at r < 0'
    # named no file, line, load or element
    "edge_load_negative_radius": ("test/data/katona/float_goodman6_axi.inp", "deck",
                                  "\n1018, 0.3, 0.5\n", "\n1018, 0.7, 0.5\n",
                                  "axisymmetric edge load at r < 0", "deck"),
    # a step left without its data line makes the deck phased: its *ADAPT was refused
    # naming the deck but no line
    "adapt_phased": ("test/data/user/good_node_forms.inp", "deck",
                     "INCREMENTS=1\npull, 1.0\n", "INCREMENTS=1\n",
                     "[*ADAPT] adaptive refinement is not available for a phased deck", "deck"),
    # the mesh of the stray token above with classic Mac OS line ends (a carriage return
    # alone): its line numbers stayed 1
    "gmsh_cr_only_line": ("test/data/user/good_gmsh_group_phase.inp", "mesh-cr",
                          "$EndMeshFormat\n", "$EndMeshFormat\n100000000\n",
                          ".msh:4: [$MeshFormat] expected a section name", "mesh"),
}


def _mesh_of(deck_text, src):
    m = re.search(r"^\*MESH\s*,\s*FILE\s*=\s*(\S+)", deck_text, flags=re.M | re.I)
    return (src.parent / m.group(1)).resolve(), m


@pytest.mark.parametrize("name", sorted(MUTANTS))
def test_fuzz_mutant_refused_cleanly(tmp_path, name):
    source, where, old, new, expected, named = MUTANTS[name]
    src = ROOT / source
    text = src.read_text()
    deck = tmp_path / src.name
    mesh = None
    if where.startswith("mesh"):
        path, m = _mesh_of(text, src)
        mtext = path.read_text()
        assert old in mtext
        mesh = tmp_path / ("mutated_" + path.name)
        mtext = mtext.replace(old, new, 1)
        if where == "mesh-cr":
            mtext = mtext.replace("\n", "\r")
        mesh.write_text(mtext, newline="")
        text = text[:m.start(1)] + str(mesh) + text[m.end(1):]
    else:
        assert old in text
        text = text.replace(old, new, 1)
    # meshes and includes named relative to the source stay reachable
    text = re.sub(r"^(\*(?:MESH|INCLUDE)\b.*?FILE\s*=\s*)([^/,\s][^,\s]*)",
                  lambda q: q.group(1) + str((src.parent / q.group(2)).resolve()), text,
                  flags=re.M | re.I)
    deck.write_text(text)
    out = tmp_path / "out"
    out.mkdir()
    r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(out / "r.h5"), "--quiet"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert r.returncode == 2, (r.returncode, r.stderr[-2000:])
    errors = [s for s in r.stderr.splitlines() if "error:" in s]
    assert len(errors) == 1, r.stderr
    file = deck if named == "deck" else mesh
    assert re.search(re.escape(str(file)) + r":\d+: \[[^\]]+\] ", errors[0]), errors[0]
    assert expected in errors[0], errors[0]
    assert "*****" not in errors[0]
    assert list(out.iterdir()) == []


def test_deck_with_carriage_returns_alone_runs(tmp_path):
    """A deck saved with classic Mac OS line ends (a carriage return alone) reads as the same
    deck: it was one line of blanks, refused as 'the deck is empty'."""
    src = ROOT / "test/data/cli/oedometer.inp"
    runs = {}
    for name, end in (("lf", "\n"), ("cr", "\r"), ("crlf", "\r\n")):
        deck = tmp_path / f"{name}.inp"
        deck.write_text(src.read_text().replace("\n", end), newline="")
        out = tmp_path / f"{name}.h5"
        r = subprocess.run([*pecplas_cmd(), str(deck), "-o", str(out)], cwd=tmp_path,
                           capture_output=True, text=True, timeout=60)
        assert r.returncode == 0, (name, r.stderr[-2000:])
        with Results(out) as res:
            runs[name] = [res.field(k, "displacement") for k in res.keys]
    # the same model read from the same numbers: the same displacements, bit for bit
    assert len(runs["lf"]) == 6
    for name in ("cr", "crlf"):
        assert all(np.array_equal(a, b) for a, b in zip(runs[name], runs["lf"], strict=True))
