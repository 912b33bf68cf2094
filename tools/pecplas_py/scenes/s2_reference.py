#!/usr/bin/env python3
"""Writes test/reference/s2_s3.json, the stored regression values of scenes S2 (five
interface models) and S3 (Mohr-Coulomb, psi = 0, 1, 5, 15, 30°) at refinement 1, from the
results of `make s2 s3` (OUTPUT_DIR/s2/*.h5, OUTPUT_DIR/s3/*.h5). Each value carries the
physics check it passed; test/python/test_s2_s3.py compares fresh runs with the values and
asserts the same checks on them, so regenerate only after the checks pass (run the test).

    python3 -m pecplas_py.scenes.s2_reference [OUTPUT_DIR] [-o test/reference/s2_s3.json]
"""
import argparse
import json
import math
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.scenes.s2_results import scene_values

S2 = ("goodman", "ghaboussi", "spring", "mohr_coulomb", "katona")
PSI = (0, 1, 5, 15, 30)
K0, GAMMA, PHI, D, L = 0.5, 18.0, 30.0, 1.0, 10.0
#: hand shaft capacity from the initial stresses, int_0^L K0 gamma z tan(phi) pi d dz [kN]
QS_HAND = K0 * GAMMA * math.tan(math.radians(PHI)) * math.pi * D * L**2 / 2.0


def randolph_wroth(load, e_soil=2.0e4, nu=0.3, e_pile=2.0e7, r0=0.5, length=L):
    """Head settlement [m] of a compressible pile bonded to a homogeneous elastic soil
    (Randolph & Wroth 1978, rho = xi = eta = 1): the elastic estimate for small loads."""
    g = e_soil / (2.0 * (1.0 + nu))
    lam = e_pile / g
    rm = (0.25 + (2.5 * (1.0 - nu) - 0.25)) * length
    zeta = math.log(rm / r0)
    mul = (length / r0) * math.sqrt(2.0 / (zeta * lam))
    t = math.tanh(mul) / mul
    base = 4.0 / (1.0 - nu)
    ratio = (base + 2.0 * math.pi / zeta * t * length / r0) / \
        (1.0 + base * t * length / (math.pi * lam * r0))
    return load / (g * r0 * ratio)


W_RW = randolph_wroth(1000.0) * 1e3   # mm, 6.58

UNITS = {"settlement_1000": "mm", "settlement_2000": "mm", "permanent_settlement": "mm",
         "peak_sigma_n": "kPa", "shaft_resultant": "kN", "capacity_15mm": "kN"}


def checks(case):
    """The physics check of each value of `case` (s2_<model> or s3_psi<psi>), in words; the
    test asserts each of them on the stored values."""
    s3 = case.startswith("s3")
    c = {"settlement_1000": f"elastic bonded-pile estimate (Randolph & Wroth 1978) "
                            f"{W_RW:.2f} mm: within 0.8-1.4 x (finite, coarse mesh stiffer; "
                            f"partial slip near the top and the penalty joints' 1/K_t softer)",
         "settlement_2000": "more than twice the settlement at 1000 kN: 2000 kN exceeds the "
                            f"shaft capacity {QS_HAND:.1f} kN, the curve has bent (full slip)",
         "permanent_settlement": "> 0.2 x the settlement at 2000 kN: the reversed skin "
                                 "friction holds the pile down after unloading",
         "peak_sigma_n": f"0.8-1.25 x K0 gamma L = {K0 * GAMMA * L:g} kPa: elastic soil "
                         "without dilatancy keeps sigma_n near its initial value",
         "shaft_resultant": f"hand capacity int K0 gamma z tan(phi) pi d dz = {QS_HAND:.1f} kN "
                            "within 5 % (full slip; sigma_n drifts as the soil deforms)",
         "capacity_15mm": f"above the hand shaft capacity {QS_HAND:.1f} kN (the shaft has "
                          "slipped at 15 mm, the tip carries the rest) and below 2000 kN"}
    if case == "s2_katona":
        c["settlement_1000"] += "; below the penalty models' (rigid contact is stiffer " \
                                "before full slip)"
        c["settlement_2000"] += "; within 1 % of the stiff-penalty limit (springs with " \
                                "K_t = 1e4 E_soil, test_s2_katona_is_the_stiff_penalty_limit)"
    elif case.startswith("s2_") and case != "s2_goodman":
        c["settlement_2000"] += "; Goodman's within 1 % (springs 5 %): same stiffnesses"
    if s3:
        psi = case[6:]
        if psi != "0":
            c["settlement_1000"] += "; decreases with psi"
            c["settlement_2000"] = "decreases with psi (blocked dilatancy raises sigma_n, " \
                                   "thesis fig. II.13)"
            c["permanent_settlement"] = "> 0 and decreases with psi"
            c["peak_sigma_n"] = "rises with psi (blocked dilatancy, thesis fig. II.13)"
            c["shaft_resultant"] = "above the psi = 0 hand capacity and rising with psi " \
                                   "(dilatancy raises sigma_n)"
        c["capacity_15mm"] += "; rises monotonically with psi (scene S3)"
        if psi == "0":
            c["settlement_2000"] += "; equals S2 Mohr-Coulomb (same deck, psi = 0)"
    return c


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", nargs="?", default="output")
    ap.add_argument("-o", "--output", default=str(ROOT / "test" / "reference" / "s2_s3.json"))
    a = ap.parse_args()
    out = Path(a.out)
    cases = {}
    for name, h5 in [*((f"s2_{m}", out / "s2" / f"s2_{m}.h5") for m in S2),
                     *((f"s3_psi{p}", out / "s3" / f"s3_psi{p}.h5") for p in PSI)]:
        v, c = scene_values(h5), checks(name)
        cases[name] = {"deck": f"input/{name[:2]}/{name}.inp",
                       "values": {k: {"value": round(x, 6), "unit": UNITS[k], "check": c[k]}
                                  for k, x in v.items()}}
    doc = {"about": "Scenes S2 and S3 at refinement 1 (tools/pecplas_py/decks/make_s2_decks.py): "
                    "stored "
                    "results of the program, each checked against the physics written "
                    "beside it (test/python/test_s2_s3.py asserts the checks and compares "
                    "fresh runs). Written by tools/pecplas_py/scenes/s2_reference.py.",
           "tolerance": {"rel": 1e-3,
                         "why": "same code and decks: Newton stops at a residual of 1e-4 "
                                "of the load, so builds (debug/release, BLAS, solver "
                                "ordering) differ by far less than 1e-3 (debug against "
                                "release: 7e-8 at most); a larger change is a change of "
                                "the method or of the deck"},
           "cases": cases}
    Path(a.output).parent.mkdir(parents=True, exist_ok=True)
    Path(a.output).write_text(json.dumps(doc, indent=1, ensure_ascii=False) + "\n")
    print(a.output)


if __name__ == "__main__":
    main()
