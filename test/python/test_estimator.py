"""Error estimate in the results file of the real `pecplas` executable (*OUTPUT,
ERROR_ESTIMATE=YES) on the Mohr-Coulomb strip footing: datasets, attributes and the XDMF
cell attribute, read back with h5py.

Uses $PECPLAS_BIN (set by `make test` and CTest), else runs through fpm."""

import subprocess
from pathlib import Path

import numpy as np
from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
DECK = "test/data/estimator/footing_mc.inp"


def test_error_indicator_written(tmp_path):
    out = tmp_path / "footing.h5"
    r = subprocess.run([*pecplas_cmd(), DECK, "-o", str(out)], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    with Results(out) as res:
        nel = res.element_set("soil")["connectivity"].shape[0]
        incs = res.keys
        for k in incs:
            g = res.increment(k)
            eta = res.field(k, "sets/soil/error_indicator")
            assert eta.shape == (nel,)
            assert np.all(np.isfinite(eta)) and np.all(eta >= 0)
            # the global estimate is the root sum of squares of the element indicators: the
            # program and numpy add the nel squares in other orders, each sum within nel eps
            # of the exact one (nel - 1 additions, the rounding of the squares), each root
            # within half of that plus one rounding: (nel + 1) eps apart at most
            assert np.isclose(g.attrs["error_estimate"], np.sqrt(np.sum(eta**2)),
                              rtol=(nel + 1) * np.finfo(float).eps, atol=0.0)
            assert g.attrs["energy_norm"] > 0
        # geostatic stresses are linear in depth: recovered exactly, estimate ~ 0
        first = res.increment(incs[0])
        assert first.attrs["error_estimate"] <= 1e-10 * first.attrs["energy_norm"]
        # plastic loading: a non-zero estimate
        assert res.increment(incs[-1]).attrs["error_estimate"] > 0
    xmf = out.with_suffix(".xmf").read_text()
    assert 'Attribute Name="error_indicator" AttributeType="Scalar" Center="Cell"' in xmf
