"""Plates and anchors in the output of the real `pecplas` executable: the XDMF sidecar draws
them as polylines with their forces, only in the increments where they are active; the
envelopes per phase (pecplas_py.structures) are the min/max of the increments read here
independently with h5py; the plot (pecplas_py.plots.plot_structures) is written.

The deck (test/data/structures/propped_phases.inp): a cantilever plate of 10 elements
(L = 10, q = 10 per unit length at the end), a fixed-end prop at its tip active in phase 2
only, beside a soil block that does not touch it. Phase 1: q to 0.5 (2 increments); phase 2:
the prop, q to 1 (3 increments); phase 3: the prop removed (1 increment).

Uses $PECPLAS_BIN (set by `make test` and CTest), else runs through fpm."""

import json
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_exe import pecplas_cmd
from pecplas_py import script_cmd, structures
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
DECK = "test/data/structures/propped_phases.inp"
NEL, NBAR = 10, 1
# phase -> its written increments (global numbers), as the deck's steps give them
PHASES = {1: [1, 2], 2: [3, 4, 5], 3: [6]}
PROP_PHASES = {2}


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    out = tmp_path_factory.mktemp("structures") / "propped.h5"
    r = subprocess.run([*pecplas_cmd(), DECK, "-o", str(out), "-q"], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    return out


def spatial_grids(xmf):
    """{collection name: {grid name: grid element}} of the XDMF's temporal collection."""
    root = ET.parse(xmf).getroot()
    assert root.tag == "Xdmf"
    out = {}
    for g in root.iter("Grid"):
        if g.get("CollectionType") == "Spatial":
            out[g.get("Name")] = {c.get("Name"): c for c in g.findall("Grid")}
    return out


def test_xdmf_polylines_of_the_active_structures(results):
    grids = spatial_grids(results.with_suffix(".xmf"))
    assert sorted(grids) == [f"{g:06d}" for g in range(1, 7)]
    with h5py.File(results, "r") as f:
        for key, names in grids.items():
            g = int(key)
            assert "block" in names
            assert "plates_beam" in names                     # active in every phase
            prop = next(p for p, incs in PHASES.items() if g in incs) in PROP_PHASES
            assert ("anchors_prop" in names) == prop, key
            assert (f"increments/{key}/anchors/prop" in f) == prop
            plate = names["plates_beam"]
            topo = plate.find("Topology")
            assert topo.get("TopologyType") == "Polyline"
            assert (int(topo.get("NumberOfElements")), int(topo.get("NodesPerElement"))) \
                == (NEL, 2)
            attrs = {a.get("Name"): a for a in plate.findall("Attribute")}
            assert {"N", "Q", "M"} <= set(attrs)
            # M is column 2 of element_forces (nel, 3): read it through the XDMF's references
            slab = attrs["M"].find("DataItem")
            sel, ref = slab.findall("DataItem")
            start, stride, count = np.array(sel.text.split(), dtype=int).reshape(3, 2)
            path = ref.text.split(":", 1)[1]
            m = f[path][()][start[0]::stride[0], start[1]]
            assert len(m) == count[0] == NEL
            ends = f[f"increments/{key}/plates/beam/end_forces"][()]     # (nel, 2, 3)
            # 0.5 (a + b) as the program forms it: one rounded sum, an exact halving
            assert np.array_equal(m, 0.5 * (ends[:, 0, 2] + ends[:, 1, 2]))
            if prop:
                anchor = names["anchors_prop"]
                topo = anchor.find("Topology")
                assert (topo.get("TopologyType"), int(topo.get("NumberOfElements")),
                        int(topo.get("NodesPerElement"))) == ("Polyline", NBAR, 2)
                a = {x.get("Name"): x for x in anchor.findall("Attribute")}
                assert sorted(a) == ["force", "force_per_width"]
                assert a["force"].get("Center") == "Cell"
                # the prop's fixed end: LENGTH = 5 below the tip node (10, 0)
                pts = f[anchor.find("Geometry/DataItem").text.split(":", 1)[1]][()]
                assert np.allclose(pts, [[10.0, 0.0], [10.0, -5.0]], rtol=0, atol=1e-14)


def test_checker_accepts_the_file(results):
    r = subprocess.run([*script_cmd("checks.check_results"), str(results)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr


def independent_phases(f):
    """{phase: [increment keys]} from /phases/<k>/first_global_increment."""
    firsts = sorted((int(g.attrs["first_global_increment"]), int(g.attrs["index"]))
                    for g in f["phases"].values())
    out = {}
    for key in sorted(f["increments"]):
        g = int(f[f"increments/{key}"].attrs["global_increment"])
        phase = max(p for first, p in firsts if first <= g)
        out.setdefault(phase, []).append(key)
    return out


def test_envelopes_are_min_max_over_the_increments(results):
    with h5py.File(results, "r") as f:
        by_phase = independent_phases(f)
        assert {p: [int(k) for k in ks] for p, ks in by_phase.items()} == PHASES
        nodes = f["mesh/plates/beam/nodes"][()]
        with Results(results) as r:
            env = structures.envelopes(r)
            line = structures.plate_line(r, "beam")
        assert sorted(env) == sorted(PHASES)
        # the plate lies along x: its line order is the order of x
        assert np.array_equal(line["nodes"], nodes[np.argsort(f["mesh/coordinates"][()][nodes, 0])])
        for phase, keys in by_phase.items():
            nf = np.array([f[f"increments/{k}/plates/beam/node_forces"][()] for k in keys])
            for i, c in enumerate("NQM"):
                lo, hi = env[phase]["plates"]["beam"][c]
                # min and max select values: equal exactly, in the line's order
                assert np.array_equal(lo, nf[:, line["order"], i].min(axis=0))
                assert np.array_equal(hi, nf[:, line["order"], i].max(axis=0))
            u = np.array([f[f"increments/{k}/plates/beam/displacement"][()] for k in keys])
            lo, hi = env[phase]["plates"]["beam"]["deflection"]
            # the plate's chord is +x, its normal +y: the deflection is u_y
            assert np.array_equal(hi, u[:, line["order"], 1].max(axis=0))
            assert np.array_equal(lo, u[:, line["order"], 1].min(axis=0))
            forces = [f[f"increments/{k}/anchors/prop/force"][()] for k in keys
                      if f"increments/{k}/anchors/prop" in f]
            if phase in PROP_PHASES:
                a = env[phase]["anchors"]["prop"]
                assert np.array_equal(a["min"], np.min(forces, axis=0))
                assert np.array_equal(a["max"], np.max(forces, axis=0))
                assert np.array_equal(a["end"], forces[-1])
                assert a["min"][0] < a["max"][0]        # the prop's force grows in phase 2
            else:
                assert not forces and "prop" not in env[phase]["anchors"]
        # the clamp moment at the end of phase 3 (a cantilever again): -q L^2 / 2 = -500; the
        # element gives the nodal forces of a uniform load exactly, the linear solve reaches
        # its residual 1e-10: 1e-6 relative is a loose bound
        m0 = env[3]["plates"]["beam"]["end"]["M"][0]
        assert abs(m0 / -500.0 - 1.0) < 1e-6


def test_plot_is_written(results, tmp_path):
    png, data = tmp_path / "structures.png", tmp_path / "structures.json"
    r = subprocess.run([*script_cmd("plots.plot_structures"), str(results), "-o", str(png),
                        "--data", str(data)], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "(1 plate sets, 1 anchor sets, 3 phases)" in r.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    d = json.loads(data.read_text())
    assert sorted(d["plates"]["beam"]["phases"]) == ["1", "2", "3"]
    assert [row[:3] for row in d["anchors"]] == [["phase 2 propped", "prop", 1]]


def test_plot_refuses_a_file_without_structures(tmp_path):
    h5 = tmp_path / "bare.h5"
    with h5py.File(h5, "w") as f:
        f.create_dataset("mesh/coordinates", data=np.zeros((1, 2)))
    r = subprocess.run([*script_cmd("plots.plot_structures"), str(h5)], capture_output=True,
                       text=True)
    assert r.returncode == 2 and "no plates or anchors" in r.stderr
