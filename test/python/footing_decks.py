"""Strip-footing decks for the nonlinear-solution tests (test_footing_paths.py), on the graded
half-model mesh of pecplas_py.decks.make_footing: weightless Mohr-Coulomb soil, a
footing of half-width b = 1 m on x in [0, 1] at y = 0, symmetry axis and far side on rollers,
base fixed.

drive = "settle": the footing nodes are pushed down (displacement control, smooth rigid
footing); drive = "pressure": a uniform pressure on the footing's edges (force control). With
stiff_footing the top row of elements under the footing is a stiff elastic plate (E 1000 times
the soil's), so that both drives load the same rigid footing. An optional surcharge q acts on
the surface beyond the footing (and under it, under force control) in a first step.
"""
from pecplas_py.deck import Deck
from pecplas_py.decks import make_footing

B = 1.0


def deck(elem="T6", nf=2, c=10.0, phi=0.0, psi=0.0, q=0.0, drive="settle", settle=0.04,
         pressure=60.0, increments=40, stiff_footing=False, step_options="", solver="*SOLVER"):
    nodes, elements, xs, ids, nx, ny = make_footing.build_mesh(elem, nf, 1.3, 1.5)
    top = 2 * ny
    x_of = {i: make_footing.node_x(xs, i) for i in range(2 * nx + 1)}
    under = [i for i in range(2 * nx + 1) if x_of[i] <= B + 1e-9]
    footing = [ids[(i, top)] for i in under]
    left = [ids[(0, j)] for j in range(2 * ny + 1)]
    right = [ids[(2 * nx, j)] for j in range(2 * ny + 1)]
    base = [ids[(i, 0)] for i in range(2 * nx + 1) if (i, 0) in ids]
    # element sides on y = 0: (end, end, mid) from x = 0 outwards
    sides = [(ids[(i, top)], ids[(i + 2, top)], ids[(i + 1, top)]) for i in range(0, 2 * nx, 2)]
    inner = [s for k, s in enumerate(sides) if x_of[2 * k + 2] <= B + 1e-9]
    outer = [s for k, s in enumerate(sides) if x_of[2 * k] >= B - 1e-9]
    y_first = nodes[ids[(0, top - 2)] - 1][1]  # bottom of the top element row
    soil, plate = [], []
    for e in elements:
        xc = sum(nodes[n - 1][0] for n in e[:3]) / 3.0
        yc = sum(nodes[n - 1][1] for n in e[:3]) / 3.0
        (plate if stiff_footing and xc < B and yc > y_first else soil).append(e)
    d = Deck(fmt=".10g")
    d.title(f"strip footing, {elem}, c = {c:g}, phi = {phi:g}, psi = {psi:g}, q = {q:g}")
    d.units("kN, m, kPa").analysis("PLANE_STRAIN").nodes(list(enumerate(nodes, 1)))
    for name, els in (("soil", soil), ("plate", plate)):
        if els:
            d.elements(elem, name, [(elements.index(e) + 1, *e) for e in els])
    d.material("soil", f"E = 1e4, NU = 0.3, C = {c:g}, PHI = {phi:g}, PSI = {psi:g}",
               type="MOHR_COULOMB")
    d.section("soil", "soil")
    if plate:
        d.material("plate", "E = 1e7, NU = 0.3").section("plate", "plate")
    for name, lst in (("footing", footing), ("axis", left), ("far", right), ("base", base)):
        d.nset(name, lst, per_line=10)
    d.edges("under", inner).edges("beside", outer)
    d.boundary("axis, X", "far, X", "base, XY")
    if q > 0:
        d.load("surcharge", "PRESSURE", f"beside, {q:g}",
               *([f"under, {q:g}"] if drive == "pressure" else []))
    if drive == "settle":
        d.load("settle", "DISPLACEMENT", "footing, Y, -1.0")
    else:
        d.load("press", "PRESSURE", "under, 1.0")
    if q > 0:
        d.step("surcharge", 1, "surcharge, 1")
    target = f"settle, {settle:g}" if drive == "settle" else f"press, {pressure:g}"
    d.line(f"*STEP, NAME=push, INCREMENTS={increments}{step_options}", target)
    d.line(solver).output(STRESSES=False, STRAINS=False)
    return d.text()
