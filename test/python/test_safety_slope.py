"""The safety step (strength reduction, doc/theory.md "Factor of safety by strength reduction")
beside the project's own limit-equilibrium tool (pecplas-slope, Bishop's simplified method with
a search of circles) on the same slope: the undrained 60-degree slope of test/data/safety
(phi = 0, H = 10, c = 50, gamma = 20, firm base at the toe), whose factor Taylor's chart puts at
c / (0.191 gamma H) = 1.309. The finite-element factor must be within 5 % of Bishop's (the
circle is an assumed mechanism, the finite elements find their own), Bishop's within 2 % of
Taylor's chart (both are circular-surface limit equilibrium with phi = 0, read to three
digits), and pecplas-slope must read the factor the safety step wrote.
"""
import json
import subprocess
import sys
from pathlib import Path

from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
PROGRAM = ROOT / "tools/pecplas_py/programs/pecplas_slope.py"


def test_taylor_slope_fe_against_bishop(tmp_path):
    h5 = tmp_path / "taylor.h5"
    p = subprocess.run(pecplas_cmd() + [str(ROOT / "test/data/safety/taylor_slope.inp"), "-o",
                                        str(h5), "--quiet"], cwd=ROOT, capture_output=True,
                       text=True, timeout=600)
    assert p.returncode == 0 and h5.exists(), p.stdout + p.stderr
    data = tmp_path / "taylor.json"
    q = subprocess.run([sys.executable, str(PROGRAM), str(h5), "--data", str(data), "-o",
                        str(tmp_path / "taylor.png")], cwd=tmp_path, capture_output=True,
                       text=True, timeout=600)
    assert q.returncode == 0, q.stdout + q.stderr
    r = json.loads(data.read_text())
    fe, bishop = r["finite_elements"], r["bishop"]
    assert fe["kind"] == "factor" and fe["resolution"] <= 0.005 + 1e-12, fe
    taylor = 50.0 / (0.191 * 20.0 * 10.0)
    assert abs(bishop / taylor - 1) < 0.02, (bishop, taylor)
    assert abs(fe["factor"] / bishop - 1) < 0.05, (fe["factor"], bishop)
    assert (tmp_path / "taylor.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
