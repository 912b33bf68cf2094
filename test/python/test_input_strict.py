"""Every deck shipped in input/ passes `pecplas --strict` (doc/deck.md, Warnings): no warning
about an unused set or material, a suspicious value or a distorted element, so a user who
copies an example is not taught to ignore warnings.

The reading is all that is checked: pecplas prints the warnings and, with --strict, refuses the
deck (exit 2, no results file) before it creates the results file (its working copies,
`.NAME.h5.<pid>.*`, in the output folder, doc/results.md); once a file appears there the deck
has passed and the run is killed (a few tenths of a second per deck, whatever the run would
cost). Decides on what the program did, not on a clock: the time limit only catches a
hung program.

Not pecplas's decks, hence not here: the point driver's (*PATH: input/paths, input/s4, run by
pecplas-path) and the sweep templates and their mesh parts (input/sweeps: pecplas-sweep makes
the decks from them). A deck that reads a mesh file (*MESH) the repository does not hold (the
gmsh examples: doc/gmsh.md meshes them first) is skipped with its reason.
"""
import re
import subprocess
import time
from pathlib import Path

import pytest
from pecplas_exe import exe_path

ROOT = Path(__file__).resolve().parents[2]
INPUT = ROOT / "input"
HUNG_S = 120  # no deck of input/ takes more than a few seconds to read


def pecplas_decks():
    """The decks of input/ that pecplas runs (the point driver's and the sweeps' excepted)."""
    decks = []
    for deck in sorted(INPUT.rglob("*.inp")):
        if deck.relative_to(INPUT).parts[0] == "sweeps":
            continue
        if re.search(r"^\*PATH\b", deck.read_text(), flags=re.M | re.I):
            continue
        decks.append(deck)
    return decks


def missing_mesh(deck):
    """The mesh file a *MESH line of `deck` names when it is not there, else None."""
    for m in re.finditer(r"^\*MESH\b.*?FILE\s*=\s*([^,\s]+)", deck.read_text(),
                         flags=re.M | re.I):
        path = deck.parent / m.group(1)
        if not path.exists():
            return path
    return None


def meshed_copy(deck, mesh, folder):
    """`deck` copied into `folder` beside its mesh, made by gmsh from the .geo file of the
    same name (as doc/gmsh.md does); skipped, saying so, without the gmsh module."""
    gmsh = pytest.importorskip(
        "gmsh", reason=f"{mesh.relative_to(ROOT)} is made by gmsh (doc/gmsh.md), and the gmsh "
        "Python module is not installed (pip install gmsh, or tools/install_deps.sh)")
    folder.mkdir()
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.open(str(mesh.with_suffix(".geo")))
        gmsh.model.mesh.generate(2)
        gmsh.write(str(folder / mesh.name))
    finally:
        gmsh.finalize()
    copy = folder / deck.name
    copy.write_text(deck.read_text())
    return copy


def read_strict(exe, deck, folder):
    """Runs `exe deck --strict` until it creates a file in the empty `folder` (its results:
    the deck passed, the run is killed) or exits; returns (passed, exit code or None, stderr)."""
    folder.mkdir()
    out = folder / "strict.h5"
    started = lambda: any(folder.iterdir())  # noqa: E731
    proc = subprocess.Popen([str(exe), str(deck), "--strict", "--quiet", "-o", str(out)],
                            cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True)
    start = time.monotonic()
    try:
        while proc.poll() is None and not started():
            if time.monotonic() - start > HUNG_S:
                raise AssertionError(f"{deck}: neither refused nor started in {HUNG_S} s")
            time.sleep(0.02)
    finally:
        if proc.poll() is None:
            proc.kill()
        _, err = proc.communicate()
    code = proc.returncode if proc.returncode is not None and proc.returncode >= 0 else None
    passed = started() or code in (0, 3)
    return passed, code, err


def test_decks_found():
    """The selection is not empty and holds the examples and the scene decks."""
    names = {d.relative_to(INPUT).as_posix() for d in pecplas_decks()}
    assert {"default.inp", "examples/excavation_strutted.inp", "examples/excavation_wet.inp",
            "s6/s6_modjoin.inp", "s1/s1_open_close_kn1e5.inp"} <= names, sorted(names)
    assert not any(n.startswith(("s4/", "paths/", "sweeps/")) for n in names)


@pytest.mark.parametrize("deck", pecplas_decks(), ids=lambda d: d.relative_to(INPUT).as_posix())
def test_deck_passes_strict(tmp_path, deck):
    absent = missing_mesh(deck)
    if absent is not None:
        deck = meshed_copy(deck, absent, tmp_path / "mesh")
    passed, code, err = read_strict(exe_path("pecplas"), deck, tmp_path / "run")
    # a deck warning is "FILE:LINE: warning: ..." (refused under --strict); a debug build's
    # Fortran runtime notes ("Fortran runtime warning: An array temporary ...") are none
    warned = re.findall(r"^.*\.inp:\d+: warning.*$", err, flags=re.M)
    assert passed and not warned, f"exit {code}\n{err}"
