"""Runs a deck text through the executable and reads what the nonlinear-solution tests look
at: status, history columns, the /limit group and the displacements of every written
increment (test_nonlinear.py, test_footing_paths.py); run_text runs a deck text alone."""
import subprocess
from pathlib import Path

from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]


def run_text(text, tmp_path, name, timeout=300):
    """Writes `text` as tmp_path/name.inp and runs it quietly into name.h5, which must exist:
    (completed process, results path)."""
    deck = tmp_path / f"{name}.inp"
    deck.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=timeout)
    assert out.exists(), p.stderr
    return p, out


def run(text, tmp_path, name):
    """(completed process, status, history dict, limit dict or None, {increment: u})."""
    p, out = run_text(text, tmp_path, name)
    with Results(out) as r:
        status = r.status
        hist = r.history()
        limit = r.limit()
        if limit is not None:
            limit = {"factors": limit["factors"], "increment": limit["global_increment"]}
        u = {k: r.field(k, "displacement") for k in r.keys}
    return p, status, hist, limit, u
