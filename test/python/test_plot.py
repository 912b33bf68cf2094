"""pecplas-plot (programs/pecplas_plot.py, installed stand-alone by `make install`): from a
results file, a PNG of the deformed mesh with a chosen field and the plastic points, and the
load-displacement curve of the node or set the step is controlled by, whatever drives it.

The program is run as it is installed: the file copied alone to `bin/pecplas-plot`, run with
no PYTHONPATH from outside the source tree. `--data` gives the numbers it drew, which must be
the results file's own:
- the S2 pile (input/s2/s2_goodman.inp, head pressure, load then unload): the colour scale
  spans the soil's stresses (not the pile's alone, which left the soil one colour); the
  curve is the head node's settlement against the head load, whose resultant is the thesis's
  2000 kN at factor 1;
- a strip footing on Tresca soil under an imposed settlement (test/python/footing_decks.py):
  the curve is the imposed settlement against the sum of the footing's reactions, and the
  plastic points of the collapse mechanism are drawn;
- an arc-length step with a stop node (test/data/progress/arc.inp): the curve follows the
  stop node.
"""
import json
import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from footing_decks import deck as footing_deck
from pecplas_exe import pecplas_cmd
from pecplas_py.programs.pecplas_plot import polygon_areas
from pecplas_py.results import Results, text

ROOT = Path(__file__).resolve().parents[2]
PROGRAM = ROOT / "tools/pecplas_py/programs/pecplas_plot.py"
EPS = np.finfo(float).eps


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """The program as `make install` puts it: one file named pecplas-plot."""
    bindir = tmp_path_factory.mktemp("bin")
    target = bindir / "pecplas-plot"
    shutil.copy(PROGRAM, target)
    target.chmod(0o755)
    return target


def run_pecplas(deck, out, cwd):
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"], cwd=ROOT,
                       capture_output=True, text=True, timeout=300)
    assert out.exists(), p.stdout + p.stderr
    return p


def plot(installed, h5, tmp_path, *args):
    """Runs the installed program; (PNG path, the numbers drawn)."""
    png, data = tmp_path / f"{h5.stem}.png", tmp_path / f"{h5.stem}.json"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    r = subprocess.run([sys.executable, str(installed), str(h5), "-o", str(png), "--data",
                        str(data), *map(str, args)], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip() == f"pecplas-plot: {png}"
    return png, json.loads(data.read_text())


def check_png(png, min_colours):
    """A PNG of a readable size with at least `min_colours` distinct saturated colours (the
    field's colour map, the curve, the plastic points; greys are text and lines)."""
    import matplotlib.image as mpimg
    head = png.read_bytes()[:24]
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    assert width >= 600 and height >= 400, (width, height)
    rgb = (mpimg.imread(png)[..., :3] * 255).astype(int).reshape(-1, 3)
    saturated = rgb[rgb.max(axis=1) - rgb.min(axis=1) > 40]
    colours = len(np.unique(saturated, axis=0))
    assert colours >= min_colours, colours
    return colours


def test_pile(installed, tmp_path):
    h5 = tmp_path / "s2_goodman.h5"
    run_pecplas(ROOT / "input/s2/s2_goodman.inp", h5, tmp_path)
    with Results(h5) as r:
        key = r.last_key(step=1)                 # the full head load, 2000 kN
        n = r.keys.index(key) + 1
        soil = r.field(key, "sets/soil/stress_mean")[:, 1]
        pile = r.field(key, "sets/pile/stress_mean")[:, 1]
        factors = r.pattern_factors(r.field_rows())[:n, 0]
        u = r.fields("displacement")[:n]
        ndof = u[0].size
        areas = {name: polygon_areas(r.coordinates, s["connectivity"][()],
                                     text(s.attrs["etype"]))
                 for name, s in r.file["mesh/sets"].items()}
    png, d = plot(installed, h5, tmp_path, "--increment", int(key))
    check_png(png, 50)
    lo, hi = d["colour_range"]
    # the soil's stresses spread over the scale: the old scale (the pile's range, down to
    # -2546 kPa under the head) put them all in its top 15 %
    # (by construction the default scale leaves 5 % of the model's area below and 5 % above,
    # each to half an element's area (the percentiles interpolate between element midpoints))
    inside = (soil >= lo) & (soil <= hi)
    total = sum(a.sum() for a in areas.values())
    largest = max(a.max() for a in areas.values())
    assert areas["soil"][~inside].sum() <= 0.10 * total + largest
    assert np.ptp(soil[inside]) >= 0.5 * (hi - lo)
    assert pile.min() < lo  # the pile's peak stress lies beyond the scale (arrow)
    # --range-set soil: exactly the soil's range
    _, ds = plot(installed, h5, tmp_path, "--increment", int(key), "--range-set", "soil")
    assert ds["colour_range"] == [soil.min(), soil.max()]
    c = d["curve"]
    assert c["pattern"] == "head" and c["keys"][0] is None
    node = int(c["label"].split()[1])
    with Results(h5) as r:
        row = r.node_index(node)
    # the settlement of the head node (along the load, -y) at every written increment
    assert c["displacement"][1:] == [-float(x) for x in u[:, row, 1]]
    # load = factor x resultant at factor 1: the 2000 kN of the thesis's pile (the
    # pressure 2546.479 kPa on the head of radius 0.5 m); the fit of the reactions is off
    # by at most the out-of-balance force the convergence test leaves, sqrt(ndof) x TOL x
    # 2000 kN with TOL = 1e-4 (the deck's default)
    # (load / factor gives it back to two roundings: 2 eps relative each, where loaded)
    loaded = factors != 0
    resultant = np.array(c["load"][1:])[loaded] / factors[loaded]
    assert np.ptp(resultant) <= 4 * EPS * 2000.0
    assert abs(resultant[0] - 2000.0) <= math.sqrt(ndof) * 1e-4 * 2000.0
    assert max(c["load"]) == pytest.approx(2000.0, abs=math.sqrt(ndof) * 1e-4 * 2000.0)


def test_footing_imposed_settlement(installed, tmp_path):
    text = footing_deck(nf=1, c=10.0, drive="settle", settle=0.1, increments=10,
                        solver="*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8")
    text = text.replace("*OUTPUT, STRESSES=NO, STRAINS=NO", "*OUTPUT")
    deck = tmp_path / "footing.inp"
    deck.write_text(text)
    h5 = tmp_path / "footing.h5"
    run_pecplas(deck, h5, tmp_path)
    png, d = plot(installed, h5, tmp_path, "--field", "eps_p")
    check_png(png, 50)
    c = d["curve"]
    assert c["pattern"] == "settle" and c["how"] == "displacement pattern"
    with Results(h5) as r:
        assert r.status == "completed"
        nodes = r.node_set("footing")
        factors = r.pattern_factors(r.field_rows())[:, 0]
        reaction = r.fields("reaction")[:, nodes, 1]
        u = r.fields("displacement")[:, nodes, 1]
        eps_p = r.field(r.keys[-1], "sets/soil/state")
    # the imposed settlement (factor x 1 m downwards at each footing node; the mean of equal
    # values is within 2 ulp of them) against the force imposing it, the sum of the footing
    # nodes' vertical reactions taken downwards (summed in another order: a few ulp)
    disp, load = np.array(c["displacement"][1:]), np.array(c["load"][1:])
    np.testing.assert_allclose(disp, factors, rtol=4 * EPS)
    np.testing.assert_allclose(disp, -u.mean(axis=1), rtol=4 * EPS)
    np.testing.assert_allclose(load, -reaction.sum(axis=1), rtol=8 * EPS * len(nodes))
    assert c["displacement"][0] == 0.0 and c["load"][0] == 0.0
    # past the collapse load the footing pushes a mechanism: points yield now
    assert d["yielding_points"] > 0
    assert max(d["values"]["soil"]) == pytest.approx(eps_p[:, :, 4].mean(axis=1).max(),
                                                     rel=4 * EPS)


def test_arc_length_stop_node(installed, tmp_path):
    h5 = tmp_path / "arc.h5"
    run_pecplas(ROOT / "test/data/progress/arc.inp", h5, tmp_path)
    with Results(h5) as r:
        first = [k for k in r.keys if r.step_of(k) == 1]
        u4 = [float(r.field(k, "displacement")[r.node_index(4), 1]) for k in first]
    _, d = plot(installed, h5, tmp_path, "--increment", int(first[-1]))
    c = d["curve"]
    assert c["how"] == "arc-length stop node" and "stop node 4" in c["label"]
    # node 4's u_y, taken along the load (downwards): positive settlements
    assert c["displacement"][1:] == [-x for x in u4]
    # an elastic block under a growing pressure settles more at each increment
    assert np.all(np.diff(c["displacement"]) > 0)


def test_bad_input(installed, tmp_path):
    """A file that is not a results file: exit 2 with the file named."""
    bad = tmp_path / "bad.h5"
    bad.write_text("not hdf5")
    r = subprocess.run([sys.executable, str(installed), str(bad)], capture_output=True,
                       text=True)
    assert r.returncode == 2 and str(bad) in r.stderr


def test_without_element_fields(installed, tmp_path):
    """A deck whose *OUTPUT writes no element fields (STRESSES=NO, STRAINS=NO): the default
    picture colours the displacement instead; a stress or plastic field asked for is an input
    error that says why (exit 2), not a uniform picture."""
    text = footing_deck(nf=1, c=10.0, drive="settle", settle=0.05, increments=5)
    assert "*OUTPUT, STRESSES=NO, STRAINS=NO" in text
    deck = tmp_path / "bare.inp"
    deck.write_text(text)
    h5 = tmp_path / "bare.h5"
    run_pecplas(deck, h5, tmp_path)
    png, d = plot(installed, h5, tmp_path)
    assert d["field"] == "u" and len(d["curve"]["load"]) == 6
    check_png(png, 20)
    r = subprocess.run([sys.executable, str(installed), str(h5), "--field", "eps_p", "-o",
                        str(tmp_path / "no.png")], capture_output=True, text=True)
    assert r.returncode == 2 and "STRESSES=NO" in r.stderr
    assert not (tmp_path / "no.png").exists()
