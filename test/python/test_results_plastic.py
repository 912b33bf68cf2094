"""The plastic zone in the XDMF sidecar (doc/results.md): every element set of a soil with a
plastic history (Mohr-Coulomb, Drucker-Prager) has, at each increment with fields, the cell
values `eps_p_eq` (the mean of its Gauss points' equivalent plastic strain) and
`plastic_fraction` (the fraction of its Gauss points yielding at this increment), so that
ParaView shows the plastic zone without reading the Gauss-point histories.

The sidecar is read back as an XDMF reader reads it (the XML, then each attribute's HDF5
dataset through its `file.h5:/path` reference, its dimensions checked against the grid's
topology), on a strip footing on Tresca soil pushed past its collapse load by an imposed
settlement (test/python/footing_decks.py): the values must be those of the Gauss-point
histories, and the collapse mechanism must show up as yielding elements."""
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np

from footing_decks import deck as footing_deck
from deck_runs import run as run_deck
from pecplas_py.checks import check_results
from pecplas_py.results import Results, text

EPS = np.finfo(float).eps


def read_cell_attribute(xmf, grid, name):
    """The values of cell attribute `name` of `grid`, as an XDMF reader resolves them."""
    attr = grid.find(f"Attribute[@Name='{name}']")
    assert attr is not None, f"no attribute {name} in grid {grid.get('Name')}"
    assert attr.get("Center") == "Cell" and attr.get("AttributeType") == "Scalar"
    item = attr.find("DataItem")
    assert item.get("Format") == "HDF"
    fname, path = item.text.strip().split(":", 1)
    nel = int(grid.find("Topology").get("NumberOfElements"))
    assert [int(d) for d in item.get("Dimensions").split()] == [nel]
    with h5py.File(Path(xmf).parent / fname, "r") as f:
        values = f[path][()]
    assert values.shape == (nel,)
    return values


def test_sidecar_plastic_indicators(tmp_path):
    text_deck = footing_deck(nf=1, c=10.0, drive="settle", settle=0.1, increments=10,
                             solver="*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8")
    text_deck = text_deck.replace("*OUTPUT, STRESSES=NO, STRAINS=NO", "*OUTPUT")
    p, status, _, _, _ = run_deck(text_deck, tmp_path, "footing")
    assert status == "completed", p.stderr
    h5 = tmp_path / "footing.h5"
    xmf = h5.with_suffix(".xmf")
    problems, _ = check_results.check(str(h5), "completed", str(xmf))
    assert not problems, problems
    root = ET.parse(xmf).getroot()
    steps = root.find("Domain/Grid[@CollectionType='Temporal']")
    increments = steps.findall("Grid[@CollectionType='Spatial']")
    with Results(h5) as r:
        names = text(r.element_set("soil").attrs["state_names"])
        keys = r.keys
        assert len(increments) == len(keys)
        yielding = []
        for key, inc in zip(keys, increments):
            grid = inc.find("Grid[@Name='soil']")
            eps = read_cell_attribute(xmf, grid, "eps_p_eq")
            fraction = read_cell_attribute(xmf, grid, "plastic_fraction")
            state = r.field(key, "sets/soil/state")          # (nel, ngauss, nstate)
            ngauss = state.shape[1]
            # the mean of ngauss values summed in order: ngauss ulp of the largest
            expected = state[:, :, names.index("eps_p_eq")].mean(axis=1)
            bound = ngauss * EPS * np.abs(expected).max()
            assert np.all(np.abs(eps - expected) <= bound)
            kind = state[:, :, names.index("return_kind")]
            np.testing.assert_array_equal(fraction, (kind > 0).sum(axis=1) / ngauss)
            assert np.all((fraction >= 0) & (fraction <= 1)) and np.all(eps >= 0)
            yielding.append(int((fraction > 0).sum()))
    # at the end the footing pushes a collapse mechanism (its load has levelled off): elements
    # yield, and plastic strain has accumulated
    assert yielding[-1] > 0
    assert eps.max() > 0
