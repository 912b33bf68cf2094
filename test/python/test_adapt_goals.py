"""Goal-oriented adaptive runs (`doc/adapt.md`) through the release executable.

- S2 pile at 2000 kN (thesis chapter II §2; the decks of doc/bench's work-precision series):
  `--target-error 1% --goal node:1:y` on the head settlement ends within 1 % of the model's
  Richardson reference (doc/bench/work_precision.md) at fewer DOFs than the uniform mesh series
  needs for the same error, for the Mohr-Coulomb interface (Q4 + GOODMAN4), Katona contact (Q4)
  and a Q8 mesh with GOODMAN6 joints. One run per model, shared by its assertions.
- `reaction:SET`: on the strip footing under a uniform pressure q over the half-width b, the
  base reaction equals q b on every level (equilibrium of the weightless soil block).
- `limit`: the strip footing on weightless Tresca soil pushed by a growing pressure under
  arc-length control; the limit of every level is compared with Prandtl's (2 + pi) c.
- A limit goal on a run that reports no limit load stops with exit 3 and says so.

Uses $PECPLAS_BIN (set by `make test` and CTest), else builds with fpm.
"""
import math
import re
import subprocess
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.bench import adapt as bench_adapt
from footing_decks import deck as footing_deck  # noqa: E402

LEVEL = re.compile(r"^\s+(\d+)\s+(\d+)\s+(\d+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$")
NEWTON = "*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8"
C = 10.0  # cohesion of the footing decks [kPa]


def run(deck_text, tmp_path, name, *args):
    """(exit code, stdout, stderr, levels [(dofs, goal, goal error % or None)])."""
    deck = tmp_path / f"{name}.inp"
    deck.write_text(deck_text)
    p = subprocess.run([*pecplas_cmd(), str(deck), *map(str, args), "-o",
                        str(tmp_path / f"{name}.h5")],
                       cwd=ROOT, capture_output=True, text=True, timeout=300)
    levels = []
    for m in map(LEVEL.match, p.stdout.splitlines()):
        if m:
            g = m.groups()
            levels.append((int(g[1]), float(g[4]), None if g[5] == "-" else float(g[5])))
    return p.returncode, p.stdout, p.stderr, levels


def uniform_series(model, element):
    """[(DOFs, error)] of the uniform mesh series of doc/bench/work_precision.csv (the
    Newton-type solvers; every one gives the same values) and the model's Richardson
    reference [m], read as pecplas_py.bench.adapt reads them."""
    rows = [r for r in bench_adapt.csv_runs("s2")
            if (r["model"], r["element"], r["series"]) == (model, element, "mesh")
            and r["status"] == "ok"]
    return sorted({r["dofs"]: r["error"] for r in rows}.items()), rows[-1]["ref"]


# (model, element): the Richardson reference that applies and why.
S2_CASES = {
    ("mohr_coulomb", "Q4"): "its own Q4 reference, 90.52 mm (doc/adapt.md's S2 table)",
    ("katona", "Q4"): "Katona's own Q4 reference, 89.59 mm: another interface model, whose "
                      "exact settlement differs from the Mohr-Coulomb one by 1.0 %",
    ("mohr_coulomb", "Q8"): "the Mohr-Coulomb reference, 90.52 mm: Q8 + GOODMAN6 discretise "
                            "the same continuum problem, so they converge to the same value",
}


@pytest.fixture(scope="module", params=list(S2_CASES), ids=lambda c: f"{c[0]}_{c[1]}")
def s2_run(request, tmp_path_factory):
    model, element = request.param
    tmp = tmp_path_factory.mktemp(f"s2_{model}_{element}")
    rc, out, err, levels = run(bench_adapt.s2_deck(model, element), tmp, "s2",
                               "--target-error", "1%", "--goal", "node:1:y",
                               "--max-dofs", 20000)
    uniform, ref = uniform_series(model, element)
    return model, element, rc, out, err, levels, uniform, ref


def test_s2_goal_run_within_1pct_of_reference(s2_run):
    model, element, rc, out, err, levels, uniform, ref = s2_run
    assert rc == 0 and "target met" in out, out + err
    dofs, value, estimate = levels[-1]
    error = abs(-value - ref) / ref
    print(f"S2 {model} {element}: DOFs {[lv[0] for lv in levels]}, settlement "
          f"{-1e3 * value:.3f} mm, reference {1e3 * ref:.3f} mm ({S2_CASES[(model, element)]}),"
          f" error {100 * error:.3f} %, estimate {estimate:.4f} %")
    # the target the run was given (--target-error 1%), against the reference; its own uncertainty
    # (work_precision.md: 3.3e-4 Mohr-Coulomb, 2.1e-3 Katona) is well below that
    assert error <= 0.01
    # the loop stops on its estimate: an estimate below the true error would stop too early
    # (the runs are deterministic: one thread, same meshes every time)
    assert estimate / 100.0 >= error


def test_s2_goal_run_fewer_dofs_than_uniform(s2_run):
    model, element, rc, out, err, levels, uniform, ref = s2_run
    assert rc == 0, err
    dofs, value, _ = levels[-1]
    error = abs(-value - ref) / ref
    # work_precision.csv counts two DOFs per node (1128 for the coarsest Q4 mesh, the first
    # adaptive level, which prints its 1033 free equations): scale the adaptive count alike
    scale = uniform[0][0] / levels[0][0]
    same = next((d for d, e in uniform if e <= error), math.inf)
    one_pct = next(d for d, e in uniform if e <= 0.01)
    print(f"S2 {model} {element}: adaptive {dofs} DOFs ({scale * dofs:.0f} counted as the "
          f"uniform series), uniform {same} DOFs for the same error, {one_pct} for 1 %")
    assert scale * dofs < one_pct and scale * dofs < same


@pytest.fixture(scope="module")
def pressure_40(tmp_path_factory):
    """Footing pressure 40 kPa (below the limit 51.4 kPa, plastic zone at the edge)."""
    return footing_deck(elem="T6", nf=2, c=C, drive="pressure", pressure=40.0, increments=4,
                        solver=NEWTON), tmp_path_factory.mktemp("p40")


def test_reaction_goal_equals_applied_load(pressure_40):
    text, tmp = pressure_40
    rc, out, err, levels = run(text, tmp, "base", "--target-error", "1%",
                               "--goal", "reaction:base", "--max-dofs", 6000)
    assert rc == 0, out + err
    assert "reaction on node set 'base' (the loaded direction)" in out
    # equilibrium: the base carries q b = 40 kN/m (rollers on the sides carry only x);
    # tolerance: Newton's residual tolerance 1e-4 of the applied load
    assert len(levels) >= 3 and len({lv[0] for lv in levels}) == len(levels)
    for dofs, value, _ in levels:
        assert abs(value - 40.0) <= 1e-4 * 40.0, (dofs, value)
    # a constant sequence is its own extrapolation: the estimated error is zero
    assert levels[-1][2] <= 1e-3


def test_reaction_goal_on_a_free_set_is_refused(pressure_40):
    text, tmp = pressure_40
    rc, out, err, levels = run(text, tmp, "free", "--target-error", "1%",
                               "--goal", "reaction:footing:y")
    assert rc == 3 and "has no support or imposed displacement in y" in err, err
    assert not levels


def test_limit_goal_without_limit_load_stops_truthfully(pressure_40):
    text, tmp = pressure_40
    rc, out, err, levels = run(text, tmp, "nolimit", "--target-error", "1%", "--goal", "limit")
    assert rc == 3, out + err
    assert "level 1: the run ended with status 'completed'" in err
    assert "reports no limit load" in err and "target met" not in out


def test_limit_goal_converges_to_prandtl(tmp_path):
    text = footing_deck(elem="T6", nf=2, c=C, drive="pressure", pressure=60.0, increments=10,
                        step_options=", CONTROL=ARC_LENGTH, MAX_INCREMENTS=40", solver=NEWTON)
    rc, out, err, levels = run(text, tmp_path, "limit", "--target-error", "2%",
                               "--goal", "limit", "--max-dofs", 6000)
    assert rc == 0, out + err
    prandtl = (2.0 + math.pi) * C
    errors = [abs(q / prandtl - 1.0) for _, q, _ in levels]
    print("footing limit goal: " + ", ".join(f"{d} DOFs {q:.3f} kPa ({100 * e:.2f} %)"
                                            for (d, q, _), e in zip(levels, errors)))
    # the adaptive meshes approach Prandtl's (2 + pi) c = 51.42 kPa: every level closer
    assert len(levels) >= 3
    assert all(b < a for a, b in zip(errors, errors[1:]))
    # 2 %: the target of the run; its estimate (extrapolation) must not claim more than the
    # true error allows by a wide margin (within a factor 3 of it, both ways)
    assert errors[-1] <= 0.02
    estimate = levels[-1][2] / 100.0
    assert errors[-1] / 3.0 <= estimate <= 3.0 * errors[-1]


def test_strip_footing_example(tmp_path):
    """input/examples/strip_footing.inp (elastic, Q8, self-weight then 100 kPa): the energy
    goal is met at 1 % with one line per level; the base reaction is the weight plus the
    footing load on every level."""
    text = (ROOT / "input/examples/strip_footing.inp").read_text()
    rc, out, err, levels = run(text, tmp_path, "energy", "--target-error", "1%")
    assert rc == 0 and "target met" in out, out + err
    dofs = [lv[0] for lv in levels]
    assert len(levels) >= 3 and dofs == sorted(set(dofs))
    # the energy estimate is the goal error: only the last level is below 1 %
    assert levels[-1][2] <= 1.0 and all(lv[2] > 1.0 for lv in levels[:-1])
    rc, out, err, levels = run(text, tmp_path, "base", "--target-error", "1%",
                               "--goal", "reaction:base")
    assert rc == 0, out + err
    # equilibrium: 18 kN/m3 x 4 m x 2 m + 100 kPa x 1 m = 244 kN/m; elastic runs converge
    # in one iteration, so only round-off (1e-9 relative) separates the two
    assert all(abs(value - 244.0) <= 1e-9 * 244.0 for _, value, _ in levels), levels
