"""A phase whose changes leave a mechanism (here it removes the only support of a loaded
block): the stiffness at the phase's start is singular, no equilibrium exists, and the run
stops with status `diverged` and exit code 3 (README, exit codes; doc/results.md, status),
its message naming the step, the free node and direction, the results file finished with
every increment converged before (none when it is step 1). Before, the singular matrix came
out as 'cannot write results: ...' (exit 3) and the results stayed in the `.tmp` file with
status `running`. Counts and names only: no tolerance needed."""
import subprocess

from deck_runs import ROOT
from pecplas_exe import pecplas_cmd
from pecplas_py.results import Results

HEAD = """*TITLE
block whose only support a phase removes
*NODES
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENTS, TYPE=Q4, SET=block
1, 1, 2, 3, 4
*MATERIAL, NAME=soil
E = 1e4, NU = 0.3
*SECTION, SET=block, MATERIAL=soil
*BOUNDARY, NAME=base
1, XY
2, Y
*LOAD, NAME=p, TYPE=FORCE
3, Y, -1
"""
LOAD = "*STEP, NAME=load, INCREMENTS=2\np, 1.0\n*END STEP\n"
RELEASE = "*STEP, NAME=release, INCREMENTS=2\n*DEACTIVATE\nbase\n*END STEP\n"


def run(tmp_path, text, name):
    deck = tmp_path / f"{name}.inp"
    deck.write_text(text)
    out = tmp_path / f"{name}.h5"
    p = subprocess.run(pecplas_cmd() + [str(deck), "-o", str(out), "--quiet"],
                       capture_output=True, text=True, cwd=ROOT, timeout=120)
    leftovers = [f.name for f in tmp_path.iterdir() if f.name.endswith(".tmp")]
    return p, out, leftovers


def check(p, out, leftovers, step, name, increments):
    assert p.returncode == 3, (p.returncode, p.stderr)
    assert "cannot write results" not in p.stderr, p.stderr
    assert f"step {step} ({name}): no equilibrium" in p.stderr, p.stderr
    assert "singular" in p.stderr and "node " in p.stderr and "direction " in p.stderr, p.stderr
    assert out.exists() and not leftovers, (out.exists(), leftovers)
    with Results(out) as r:
        assert r.status == "diverged" and not r.complete, (r.status, r.complete)
        assert "mechanism" in r.attr("status_message")
        assert len(r.keys) == increments
        assert all(r.step_of(k) < step for k in r.keys)


def test_mechanism_in_a_later_step_keeps_the_converged_increments(tmp_path):
    p, out, left = run(tmp_path, HEAD + LOAD + RELEASE, "later")
    check(p, out, left, 2, "release", 2)
    assert "last converged state: increment 2" in p.stderr, p.stderr


def test_mechanism_in_step_one(tmp_path):
    p, out, left = run(tmp_path, HEAD + RELEASE + LOAD, "first")
    check(p, out, left, 1, "release", 0)
    assert "last converged state: the initial state" in p.stderr, p.stderr
