"""The safety step's claim (doc/theory.md §15, "The control"): a factor F is printed with "no
equilibrium found at Msf = F + resolution", the resolution at most the deck's RESOLUTION. The
claim must hold for the deck, not only for the step sequence that the run happened to take.

input/examples/slope_safety.inp (Griffiths & Lane's 2:1 slope, psi = 0, RESOLUTION=0.005)
with MSF_STEP=0.2 instead of 0.1, and with METHOD=MODIFIED_NEWTON instead of NEWTON. The
tolerance is the claim itself: the deck as written finds equilibrium at its factor F_d, so a
variant whose factor lies more than RESOLUTION below F_d claims no equilibrium where the deck
found one. Measured on the release binary before the fix: F_d = 1.2782; MSF_STEP=0.2 1.2672
("no equilibrium at 1.2722") and modified Newton 1.2627 ("no equilibrium at 1.2677): 2.2 and
3.1 RESOLUTION below F_d. A single failed trial of RESOLUTION (every method's residual
stagnating, from a state reached by coarse steps) was taken for the failure where the same
Msf is reached in smaller steps; now such a trial is sought again in steps of RESOLUTION/4
first. Measured after: F_d = 1.2795, MSF_STEP=0.2 1.2773, modified Newton 1.2898.

The converse is still open (strict xfail): modified Newton finds equilibrium at 1.2898, 2.1
RESOLUTION above the deck's claim (1.2795, no equilibrium found at 1.2807). Near its factor the
psi = 0 slope is path dependent: from the deck's state every method stagnates at steps of
RESOLUTION/4 (and with 4 times the iteration cap), while the path of modified Newton's run
goes on to 1.29 (and a run with MAX_ITERATIONS=200 throughout to 1.298).
"""
from pathlib import Path

import pytest

from deck_runs import run_text
from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
DECK = ROOT / "input" / "examples" / "slope_safety.inp"
STEP = "*STEP, NAME=safety, CONTROL=SAFETY, MSF_STEP=0.1, RESOLUTION=0.005"
RESOLUTION = 0.005


def factor_of(text, tmp_path, name):
    p, out = run_text(text, tmp_path, name, timeout=600)
    with Results(out) as r:
        assert r.status == "completed", r.attr("status_message")
        kind = r.file["safety"].attrs["kind"]
        assert kind in (b"factor", "factor"), kind
        f = float(r.file["safety"].attrs["factor"])
        res = float(r.file["safety"].attrs["resolution"])
    # the failed trial lies within the step's resolution above the factor
    assert 0.0 < res <= RESOLUTION * (1.0 + 1e-9), res
    return f


@pytest.fixture(scope="module")
def deck_text():
    text = DECK.read_text()
    assert STEP in text and "*SOLVER, METHOD=NEWTON" in text
    return text


@pytest.fixture(scope="module")
def base_factor(deck_text, tmp_path_factory):
    return factor_of(deck_text, tmp_path_factory.mktemp("slope"), "base")


def variant(text, name):
    if name == "msf_step_0.2":
        return text.replace(STEP, STEP.replace("MSF_STEP=0.1", "MSF_STEP=0.2"))
    return text.replace("*SOLVER, METHOD=NEWTON", "*SOLVER, METHOD=MODIFIED_NEWTON")


@pytest.fixture(scope="module")
def factors(deck_text, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("variants")
    return {name: factor_of(variant(deck_text, name), tmp, name)
            for name in ("msf_step_0.2", "modified_newton")}


@pytest.mark.parametrize("name", ["msf_step_0.2", "modified_newton"])
def test_no_variant_claims_below_the_deck(name, base_factor, factors):
    f = factors[name]
    print(f"slope_safety: deck {base_factor:.4f}, {name} {f:.4f} "
          f"({(f - base_factor) / RESOLUTION:+.2f} RESOLUTION)")
    assert f >= base_factor - RESOLUTION, (name, f, base_factor)


@pytest.mark.parametrize("name", [
    "msf_step_0.2",
    pytest.param("modified_newton", marks=pytest.mark.xfail(
        strict=True, reason="open: the psi = 0 slope's factor depends on the path "
        "(modified Newton reaches 1.2898, the deck's claim is 1.2807)"))])
def test_no_variant_passes_the_deck_claim(name, base_factor, factors):
    f = factors[name]
    assert f <= base_factor + RESOLUTION, (name, f, base_factor)
