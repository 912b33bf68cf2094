"""Status claims that must hold whatever the method or the increment budget (doc/theory.md §4,
"Convergence, increment cutting and statuses"; §15 for the safety step).

- Safety step on the infinite slope, psi = 0 (test/data/safety/infinite_slope_psi0.inp: Katona
  ties on the column's sides, non-associated Mohr-Coulomb) under METHOD=MODIFIED_NEWTON: the
  factor must be the one full Newton gives, within the 2 % of the closed form (Davis,
  tan(phi) / tan(asin(tan(beta))) = 1.792) that the validation table asserts for that row. The
  Katona Newton fallback used to factorise the non-symmetric consistent tangent with CHOLMOD
  (the modified-Newton run's solver), which reads its upper triangle only: the fallback
  converged linearly and failed at the iteration cap, and the run claimed 'no equilibrium at
  Msf = 1.441' (factor 1.439, -20 %). Measured after the fix: 1.7908, as full Newton.
- An arc-length step that uses its MAX_INCREMENTS after its load has fallen below its largest
  (test/data/modjoin/fe_cnl_force_arc.inp, softening MODJOIN joint: largest load 0.577027 at
  increment 86, one fall beyond the noise at increment 89, the second at 90) is 'stopped', and
  its message names the largest load instead of saying that there was no maximum on the way.
"""
import math
import re
import subprocess
from pathlib import Path

from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "test" / "data"


def run(text, tmp_path, name):
    deck = tmp_path / f"{name}.inp"
    deck.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert out.exists(), p.stderr
    return p, out


def test_safety_factor_under_modified_newton_with_katona(tmp_path):
    text = (DATA / "safety" / "infinite_slope_psi0.inp").read_text()
    assert "METHOD=NEWTON" in text
    text = text.replace("METHOD=NEWTON", "METHOD=MODIFIED_NEWTON")
    p, out = run(text, tmp_path, "psi0_modified")
    beta, phi = math.radians(20.0), math.radians(35.0)
    davis = math.tan(phi) / math.tan(math.asin(math.tan(beta)))
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        assert r.file["safety"].attrs["kind"] in (b"factor", "factor")
        factor = float(r.file["safety"].attrs["factor"])
    print(f"infinite slope psi = 0, modified Newton: Msf {factor:.4f}, Davis {davis:.4f} "
          f"({factor / davis - 1:+.2%})")
    assert abs(factor / davis - 1.0) <= 0.02


def test_arc_budget_after_a_fall_names_the_peak(tmp_path):
    text = (DATA / "modjoin" / "fe_cnl_force_arc.inp").read_text()
    text = text.replace("FILE=block_mesh.inc", f"FILE={DATA / 'modjoin' / 'block_mesh.inc'}")
    assert "MAX_INCREMENTS=600" in text
    p, out = run(text.replace("MAX_INCREMENTS=600", "MAX_INCREMENTS=89"), tmp_path, "budget89")
    assert p.returncode == 3
    with Results(out) as r:
        message = r.attr("status_message")
        assert r.status == "stopped", message
        loads = r.pattern_factors()[:, 0]
    assert "no maximum of the load on the way" not in message, message
    m = re.search(r"the largest load, at step fraction ([-+.\deE]+) \(increment (\d+)\), was "
                  r"followed by (\d+) fall", message)
    assert m, message
    # the message prints 6 significant digits of the largest load of the path
    assert abs(float(m.group(1)) - loads.max()) <= 1e-5 * loads.max()
    assert int(m.group(2)) == int(loads.argmax()) + 1 and int(m.group(3)) == 1
