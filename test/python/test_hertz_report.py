"""The finer Hertz line contact of doc/validation.md (h = 0.05 mm, about 3 s) is written by
pecplas_py.docs.hertz_report from its run: here the deck is written and run afresh, its physics
checked against the closed form, and the committed block must equal the one rendered from the
run (to the last printed digit: doc_blocks.rounding_diff)."""
from pathlib import Path

import pytest
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.docs import hertz_report as hr


@pytest.fixture(scope="module")
def values(tmp_path_factory):
    out = tmp_path_factory.mktemp("hertz")
    hr.run(out, pecplas_cmd())
    return hr.values(out)


def test_hertz_fine_physics(values):
    """The checks of the h = 0.1 mm test, on the finer mesh: a and p0 within 2 % of the closed
    form (a is read midway between the last closed and first open doublet: +-h/2 = 0.4 %),
    p(x) within 5 % of p0 of the elliptic profile, the resultant F/2 to 1e-8 (equilibrium of the
    floating cylinder), one factorisation (the massif is elastic)."""
    assert abs(values["a_fe"] / values["a"] - 1) < 0.02, values
    assert abs(values["p_fe"] / values["p0"] - 1) < 0.02, values
    assert values["p_err"] < 0.05, values
    assert abs(values["resultant"]) < 1e-8, values
    assert values["factorisations"] == 1 and values["doublets"] == 161, values


def test_doc_matches_the_run(values):
    diff = hr.check_doc(values)
    assert not diff, diff + ("\nregenerate: python3 -m pecplas_py.docs.hertz_report DIR --run (or "
                             "make docs)")


def test_a_changed_value_is_caught(values):
    """The check can fail: a moved by 0.01 mm (ten units of its last printed digit)."""
    moved = dict(values, a_fe=values["a_fe"] + 0.01)
    assert "a = " in hr.check_doc(moved)
