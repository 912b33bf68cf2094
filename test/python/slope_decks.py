"""Decks of slopes for the limit-equilibrium tool's tests (test_slope.py): a structured Q4
mesh under a ground surface given as a polyline (x increasing), from a flat base; columns of
elements between the x of the surface points (each segment cut into `per` columns), `rows`
rows of elements from the base to the surface. `layers` [(level, material), ..., (None,
material)] splits the soil at the levels (from the bottom up; the last layer reaches the
surface), `rows` rows per layer, T3 elements where a layer thins out against the ground;
without layers, one material `soil`."""
import numpy as np

from pecplas_py.deck import Deck


def slope_deck(surface, base, per=4, rows=8, materials=None, layers=None, steps=True,
               extra=""):
    surface = np.asarray(surface, float)
    xs = np.unique(np.concatenate([np.linspace(a, b, per + 1) for a, b in
                                   zip(surface[:-1, 0], surface[1:, 0])]))
    ys_top = np.interp(xs, surface[:, 0], surface[:, 1])
    if layers:
        # rows follow the layer levels so that element tops lie on them
        levels = [base] + [lv for lv, _ in layers[:-1]]
    nodes, ids = [], {}
    for i, x in enumerate(xs):
        if layers:
            col = [base]
            for lo, hi in zip(levels, levels[1:] + [ys_top[i]]):
                lo, hi = min(lo, ys_top[i]), min(hi, ys_top[i])
                col += list(np.linspace(lo, hi, rows + 1)[1:])
            col = np.array(col)
        else:
            col = np.linspace(base, ys_top[i], rows + 1)
        for j, y in enumerate(col):
            if j and abs(y - col[j - 1]) < 1e-12:
                ids[(i, j)] = ids[(i, j - 1)]      # a layer thinned out: one node
                continue
            nodes.append((len(nodes) + 1, x, y))
            ids[(i, j)] = len(nodes)
    nrow = (rows * len(layers)) if layers else rows
    materials = materials or {"soil": "C = 10, PHI = 20, GAMMA = 20"}
    sets = {}
    for i in range(len(xs) - 1):
        for j in range(nrow):
            q = [ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]]
            xy = np.array([nodes[n - 1][1:] for n in q])
            area = 0.5 * np.sum(xy[:, 0] * np.roll(xy[:, 1], -1) - np.roll(xy[:, 0], -1)
                                * xy[:, 1])
            if area <= 1e-12:
                continue        # a layer that thins out to nothing
            name = "soil" if not layers else layers[j // rows][1]
            corners = list(dict.fromkeys(q))
            if len(corners) == 3:
                sets.setdefault((f"{name}_t3", "T3", name), []).append(corners)
            else:
                sets.setdefault((name, "Q4", name), []).append(q)
    d = Deck(fmt=".12g")
    d.title("slope").units("kN, m, kPa").analysis("PLANE_STRAIN")
    d.nodes([n for n in nodes])
    k = 0
    for (name, etype, _), els in sets.items():
        d.elements(etype, name, [(k + e + 1, *q) for e, q in enumerate(els)])
        k += len(els)
    for name, props in materials.items():
        d.material(name, f"E = 1e5, NU = 0.3, PSI = 0, {props}", type="MOHR_COULOMB")
    for name, _, mat in sets:
        d.section(name, mat)
    left = [ids[(0, j)] for j in range(nrow + 1)]
    right = [ids[(len(xs) - 1, j)] for j in range(nrow + 1)]
    bottom = [ids[(i, 0)] for i in range(len(xs))]
    d.nset("left", left, per_line=10).nset("right", right, per_line=10)
    d.nset("bottom", bottom, per_line=10)
    d.boundary("left, X", "right, X", "bottom, XY")
    d.load("weight", "GRAVITY", "ALL")
    if steps:
        d.step("gravity", 2, "weight, 1.0")
    return d.text() + extra
