"""Runs a deck text through the executable and reads what the nonlinear-solution tests look
at: status, history columns, the /limit group and the displacements of every written
increment (test_nonlinear.py, test_footing_paths.py)."""
import subprocess
from pathlib import Path

from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]


def run(text, tmp_path, name):
    """(completed process, status, history dict, limit dict or None, {increment: u})."""
    deck = tmp_path / f"{name}.inp"
    deck.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert out.exists(), p.stderr
    with Results(out) as r:
        status = r.status
        hist = r.history()
        limit = r.limit()
        if limit is not None:
            limit = {"factors": limit["factors"], "increment": limit["global_increment"]}
        u = {k: r.field(k, "displacement") for k in r.keys}
    return p, status, hist, limit, u
