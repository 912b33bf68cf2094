"""A small sample of pecplas_py.checks.mutate_decks (the full run of 10 000 decks is a tool, not a
test): 40 mutated copies of three fast decks must give no crash, no hang beyond the 20 s
bound, no input error without file:line and no results file after an input error."""
import json
import subprocess
from pathlib import Path

from pecplas_exe import exe_path

from pecplas_py import script_cmd

ROOT = Path(__file__).resolve().parents[2]


def test_mutation_sample(tmp_path):
    # the binary of this make test (a stale build is refused, never picked)
    exe = exe_path()
    out = tmp_path / "counts.json"
    r = subprocess.run([*script_cmd("checks.mutate_decks"), "-n", "40",
                        "--seed", "7", "--exe", exe, "--keep", str(tmp_path / "keep"),
                        "--json", str(out), "--sources", "input/default.inp",
                        "test/data/cli/oedometer.inp", "test/data/trust/warn_all.inp"],
                       cwd=ROOT, capture_output=True, text=True, timeout=300)
    counts = json.loads(out.read_text())["counts"]
    assert r.returncode == 0, (counts, r.stdout[-2000:])
    assert sum(counts.values()) == 40
    for bad in ("crash", "hang", "no line", "file left"):
        assert counts.get(bad, 0) == 0, counts


def test_sources_too_slow_or_of_a_missing_mesh(tmp_path):
    # a deck whose *MESH file does not exist (an error test) is a source like any other: its
    # text is mutated (the tool stopped on it before); a source slower than
    # --max-source-seconds is left out, also when given with --sources
    exe = exe_path()
    missing = ROOT / "test" / "data" / "decks" / "bad_missing_mesh.inp"
    assert "nowhere.msh" in missing.read_text()
    out = tmp_path / "counts.json"
    r = subprocess.run([*script_cmd("checks.mutate_decks"), "-n", "6",
                        "--seed", "3", "--exe", exe, "--keep", str(tmp_path / "keep"),
                        "--json", str(out), "--sources", str(missing)],
                       cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    summary = json.loads(out.read_text())
    assert summary["sources"] == 1 and sum(summary["counts"].values()) == 6
    r = subprocess.run([*script_cmd("checks.mutate_decks"), "-n", "1",
                        "--exe", exe, "--keep", str(tmp_path / "keep"), "--json", str(out),
                        "--max-source-seconds", "0", "--sources", "input/default.inp"],
                       cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert r.returncode != 0 and "no source deck" in r.stderr
