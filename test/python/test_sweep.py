"""pecplas-sweep (programs/pecplas_sweep.py): decks from a template and a table, the local runner,
the collector, the Slurm job-array script and the input errors (doc/sweep.md)."""
import csv
import json
import re
import subprocess
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_exe import pecplas_cmd

from pecplas_py import script_cmd

ROOT = Path(__file__).resolve().parents[2]
TOOL = [*script_cmd("programs.pecplas_sweep")]
SOIL_E = ("4e4", "2e4", "1e4")


def sweep(*args, cwd=ROOT):
    return subprocess.run(TOOL + [str(a) for a in args], cwd=cwd, capture_output=True, text=True)


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """The default deck (S2 pile) with the soil modulus as a placeholder and only the loading
    step, in 5 increments, in a template directory whose relative *INCLUDE must survive."""
    tmp = tmp_path_factory.mktemp("sweep")
    tdir = tmp / "template"
    tdir.mkdir()
    text = (ROOT / "input/default.inp").read_text()
    text = text.replace("E = 20000, NU = 0.3, GAMMA = 18", "E = {{E_SOIL}}, NU = 0.3, GAMMA = 18")
    (tdir / "deck.inp").write_text(text.split("*STEP, NAME=load")[0]
                                   + "*INCLUDE, FILE=steps.inp\n")
    (tdir / "steps.inp").write_text("*STEP, NAME=load, INCREMENTS=5\nhead, 1\n"
                                    "*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=50\n")
    table = tmp / "table.csv"
    table.write_text("case,E_SOIL\n" + "".join(f"e{i},{e}\n" for i, e in enumerate(SOIL_E)))
    out = tmp / "cases"
    r = sweep("make", tdir / "deck.inp", table, "-o", out)
    assert r.returncode == 0, r.stderr
    return out


def test_make_writes_one_deck_per_row(made):
    """3 rows -> 3 decks, each with its own value substituted and no placeholder left."""
    m = json.loads((made / "sweep.json").read_text())
    assert [c["name"] for c in m["cases"]] == ["e0", "e1", "e2"]
    for i, e in enumerate(SOIL_E):
        deck = (made / f"e{i}.inp").read_text()
        assert f"E = {e}, NU = 0.3, GAMMA = 18" in deck
        assert "{{" not in deck
        assert m["cases"][i]["parameters"] == {"E_SOIL": e}


def test_run_and_collect(made):
    """The local runner runs the 3 decks 2 at a time; the collector reads the head settlement
    at 2000 kN (factor 1) and the largest load factor. Elastic soil dominates the settlement,
    so halving E must raise it (monotone in E, a physical invariant), and every run reaches
    factor 1 exactly (the step's target)."""
    exe = pecplas_cmd()
    if len(exe) != 1:
        pytest.skip("needs the pecplas executable (PECPLAS_BIN)")
    r = sweep("run", made, "-j", "2", "--pecplas", exe[0])
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.count(" exit 0 ") == 3
    r = sweep("collect", made, "-q", "settlement=disp:0,0:y@head=1", "-q",
              "peak=max:factor:head", "-q", "never=disp:0,0:y@head=5")
    assert r.returncode == 0, r.stderr
    with (made / "collected.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert [row["case"] for row in rows] == ["e0", "e1", "e2"]
    assert all(row["status"] == "completed" for row in rows)
    s = [-float(row["settlement"]) for row in rows]
    assert 0.0 < s[0] < s[1] < s[2]
    assert all(abs(float(row["peak"]) - 1.0) < 1e-12 for row in rows)
    assert all(row["never"] == "" for row in rows)  # factor 5 is never reached
    with h5py.File(made / "collected.h5") as f:
        np.testing.assert_allclose(-f["quantities/settlement"][:], s, rtol=1e-15)
        np.testing.assert_array_equal(f["quantities/never_found"][:], [0, 0, 0])
        np.testing.assert_allclose(f["parameters/E_SOIL"][:], [4e4, 2e4, 1e4], rtol=0)


def test_slurm_script(made):
    """The job-array script: --array=0-2 (one task per deck), the case list in table order,
    each task running its own deck, and the options passed through."""
    r = sweep("slurm", made, "--partition", "debug", "--time", "00:10:00",
              "--max-parallel", "2", "--pecplas", "/opt/pecplas/bin/pecplas")
    assert r.returncode == 0, r.stderr
    text = (made / "sweep.sbatch").read_text()
    assert "#SBATCH --array=0-2%2\n" in text
    assert "#SBATCH --partition=debug\n" in text
    assert "#SBATCH --time=00:10:00\n" in text
    assert "cases=(e0 e1 e2)\n" in text
    assert 'case=${cases[$SLURM_ARRAY_TASK_ID]}' in text
    assert '/opt/pecplas/bin/pecplas "$case.inp" -o "$case.h5" --quiet' in text
    assert subprocess.run(["bash", "-n", str(made / "sweep.sbatch")]).returncode == 0


def test_bad_input(tmp_path):
    """A placeholder without a column and a short CSV row: exit 2, file:line, no deck."""
    t = tmp_path / "t.inp"
    t.write_text("*TITLE\n{{A}}\n*NODES\n1, {{B}}, 0\n")
    (tmp_path / "a.csv").write_text("A\n1\n")
    r = sweep("make", t, tmp_path / "a.csv", "-o", tmp_path / "out")
    assert r.returncode == 2
    assert f"{t}:4: [TEMPLATE] placeholder {{{{B}}}} has no column" in r.stderr
    assert not list((tmp_path / "out").glob("*.inp"))
    (tmp_path / "b.csv").write_text("A,B\n1,2\n3\n")
    r = sweep("make", t, tmp_path / "b.csv", "-o", tmp_path / "out")
    assert r.returncode == 2 and "b.csv:3: [CSV] expected 2 values (A, B), found 1" in r.stderr


def test_toml_table(tmp_path):
    """A TOML table ([[case]] per row) gives the same decks as the CSV one."""
    t = tmp_path / "t.inp"
    t.write_text("*TITLE\nE={{E}} nu={{NU}}\n")
    (tmp_path / "t.toml").write_text('[[case]]\ncase = "soft"\nE = 1e4\nNU = 0.3\n'
                                     '[[case]]\nE = 2e4\nNU = 0.25\n')
    r = sweep("make", t, tmp_path / "t.toml", "-o", tmp_path / "out")
    assert r.returncode == 0, r.stderr
    assert "E=10000.0 nu=0.3" in (tmp_path / "out/soft.inp").read_text()
    assert "E=20000.0 nu=0.25" in (tmp_path / "out/case_001.inp").read_text()


def test_examples_are_in_sync(tmp_path):
    """input/sweeps/ is what decks/make_sweep_examples.py writes (regenerated byte for byte)."""
    subprocess.run([*script_cmd("decks.make_sweep_examples"), "--out",
                    str(tmp_path)], check=True, capture_output=True)
    for p in sorted(tmp_path.rglob("*.*")):
        rel = p.relative_to(tmp_path)
        assert p.read_text() == (ROOT / "input/sweeps" / rel).read_text(), rel


def test_run_reports_each_case(tmp_path):
    """`run` says when each case starts, how it progresses and how it ends, one line each,
    before the sweep ends: with --progress 0 every increment of a case is reported, so each
    of the 2 cases (2 and 3 increments of one force step, one at a time) has its start line,
    then one progress line per increment (its step, increment and fraction: 1/n ... 1), then
    its end line with the exit code and the run's status."""
    exe = pecplas_cmd()
    if len(exe) != 1:
        pytest.skip("needs the pecplas executable (PECPLAS_BIN)")
    src = ROOT / "test/data/progress"
    template = tmp_path / "deck.inp"
    template.write_text((src / "load.inp").read_text()
                        .replace("FILE=block.inc", f"FILE={src / 'block.inc'}")
                        .replace("*STEP, NAME=first, INCREMENTS=4", "*STEP, NAME=first, "
                                 "INCREMENTS={{N}}")
                        .split("*STEP, NAME=second")[0])
    table = tmp_path / "table.csv"
    table.write_text("case,N\ntwo,2\nthree,3\n")
    r = sweep("make", template, table, "-o", tmp_path / "cases")
    assert r.returncode == 0, r.stderr
    r = sweep("run", tmp_path / "cases", "--pecplas", exe[0], "--progress", "0")
    assert r.returncode == 0, r.stdout + r.stderr
    # (a case that runs past 10 s, on a loaded machine, also passes on the run's own
    # `progress:` lines, which name the increment otherwise: they are left out here)
    lines = [ln for ln in r.stdout.splitlines() if ln.startswith("pecplas-sweep: [")
             and (" started " in ln or " exit " in ln or re.search(r"increment \d+, fraction", ln))]
    expected = []
    for i, (name, n) in enumerate((("two", 2), ("three", 3)), start=1):
        tag = f"pecplas-sweep: [{i}/2] {name}"
        expected.append((tag + " started", None))
        expected += [(tag, f"step 1 'first', increment {k}, fraction {k / n:.4f}")
                     for k in range(1, n + 1)]
        expected.append((tag + " exit 0 (completed, ", f"[{i} of 2 done]"))
    assert len(lines) == len(expected), r.stdout
    for line, (start, part) in zip(lines, expected):
        assert line.startswith(start), (line, start)
        if part and "increment" in part:
            # the fraction as pecplas prints it (f7.4), read back with %g
            step, frac = part.rsplit(", fraction ", 1)
            assert step in line and f"fraction {float(frac):g} of the step" in line, line
        elif part:
            assert part in line, line
