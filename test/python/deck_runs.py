"""Runs a deck text through the executable and reads what the nonlinear-solution tests look
at: status, history columns, the /limit group and the displacements of every written
increment (test_nonlinear.py, test_footing_paths.py)."""
import subprocess
from pathlib import Path

import h5py

from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]


def run(text, tmp_path, name):
    """(completed process, status, history dict, limit dict or None, {increment: u})."""
    deck = tmp_path / f"{name}.inp"
    deck.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert out.exists(), p.stderr
    with h5py.File(out, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        hist = {k: f["history"][k][()] for k in f["history"]}
        limit = None
        if "limit" in f:
            limit = {"factors": f["limit/pattern_factors"][()],
                     "increment": int(f["limit"].attrs["global_increment"])}
        u = {k: f["increments"][k]["displacement"][()] for k in sorted(f["increments"])}
    return p, status, hist, limit, u
