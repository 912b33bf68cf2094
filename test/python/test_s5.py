"""Scene S5 (`doc/validation.md`, thesis figs IV.1-IV.3): FE interface shear box, MODJOIN cyclic III.6
Dr 80 %, one cycle of +-2 mm of the plate under sigma_n0 = 100 kPa, through the real programs.

Physics asserted: (1) the interface stresses are uniform within 2 % away from the ends at the
reversal points: beyond END = 0.02 m from each wall (one wall thickness, a fifth of the sample
height: the sand is bonded to the walls, so the slip there is the plate's whole displacement and
falls to the mid value over a few centimetres) sigma_n stays within 2 % of sigma_n0 of the
mid-interface value, tau and tau/sigma_n within 2 % of theirs (measured 0.2 %, 1.6 %, 1.6 %;
over the middle 60 % 0.05 %, 0.3 %, 0.3 %); (2) the top pressure is a dead load, so
mid-interface sigma_n stays at 100 kPa within 2 % (CNL) and (3) the mid-interface tau equals the
point driver's (pecplas-path, same law, CNL 100 kPa) on the same slip path within 2 % of the peak
|tau|; eps_n within 2 % (measured 0.95 %). Stored regression values with their checks:
test/reference/s5_s6.json."""
import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.scenes.s5_results import (L, SIGMA_N0, compare, interface, keys_and_steps,
                                          mid_history, point_driver, step_ends)
from pecplas_exe import pecplas_cmd  # noqa: E402

END = 0.02    # m: 'away from the ends' = beyond one wall thickness (H / 5) from each wall


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    cmd = pecplas_cmd()
    out = tmp_path_factory.mktemp("s5")
    h5 = out / "s5_shear_box.h5"
    r = subprocess.run([*cmd, str(ROOT / "input/s5/s5_shear_box.inp"), "-o", str(h5),
                        "--quiet"], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return h5, out


def test_uniform_stresses(run):
    h5, _ = run
    for k in step_ends(h5):
        x, sn, tau, _, _ = interface(h5, k)
        i = int(np.argmin(np.abs(x - L / 2)))
        m = (x >= END - 1e-9) & (x <= L - END + 1e-9)
        assert abs(tau[i]) > 0.4 * SIGMA_N0, "the reversal points are well into the mechanism"
        assert np.abs(sn[m] - sn[i]).max() <= 0.02 * SIGMA_N0
        assert np.abs(tau[m] - tau[i]).max() <= 0.02 * abs(tau[i])
        r = tau / sn
        assert np.abs(r[m] - r[i]).max() <= 0.02 * abs(r[i])


def test_mid_interface_equals_point_driver(run):
    h5, out = run
    fe = mid_history(h5)
    et, en, sn, tau = fe
    keys, _ = keys_and_steps(h5)
    targets = et[[keys.index(k) + 1 for k in step_ends(h5)]]
    assert len(targets) == 3 and np.all(np.abs(targets) > 1.5e-3), "cycle of about +-2 mm"
    pd = point_driver(targets, out)
    tau_pd, en_pd = compare(fe, pd, len(targets))
    assert np.abs(sn - SIGMA_N0).max() <= 0.02 * SIGMA_N0
    assert np.abs(tau - tau_pd).max() <= 0.02 * np.abs(pd[3]).max()
    assert np.abs(en - en_pd).max() <= 0.02 * np.abs(pd[1]).max()


def test_regression_values(run):
    """Stored values (test/reference/s5_s6.json, with the physics check each passed) at the
    reversal points of the mid-interface history."""
    h5, _ = run
    ref = json.loads((ROOT / "test/reference/s5_s6.json").read_text())["s5"]
    et, en, sn, tau = mid_history(h5)
    keys, _ = keys_and_steps(h5)
    rows = [keys.index(k) + 1 for k in step_ends(h5)]
    for name, got in (("mid_tau_at_reversals_kPa", tau[rows]),
                      ("mid_eps_n_at_reversals_mm", en[rows] * 1e3),
                      ("mid_sigma_n_at_reversals_kPa", sn[rows])):
        r = ref[name]
        assert got == pytest.approx(np.array(r["value"]), rel=r["tol"]), name


def test_docs_match_fresh_run(run):
    """The S5 numbers of doc/validation.md (generated block written by pecplas_py.scenes.s5_report)
    equal those of this fresh run to the last printed digit."""
    from pecplas_py.scenes import s5_report
    h5, out = run
    diff = s5_report.check_doc(h5, out)
    assert not diff, diff + ("\nregenerate: make s5 (python3 -m pecplas_py.scenes.s5_report "
                             "output/s5)")
