#!/usr/bin/env python3
"""Writes the strip-footing decks of the plasticity tests: a smooth rigid strip footing of
half-width b = 1 m on weightless Tresca soil (Mohr-Coulomb with phi = psi = 0, c = 10 kPa),
half model by symmetry, pushed down under displacement control. Prandtl's limit pressure is
q_u = (2 + pi) c = 51.416 kPa.

    python3 -m pecplas_py.decks.make_footing [--elem T6|Q8] [--nf 4] [--bias 1.3] [-o FILE]

The mesh is structured and graded: `nf` elements under the footing, 2 `nf` from its edge
to x = 3b and `nf` down to y = -b (where Prandtl's mechanism lives), their sizes growing by
`bias` away from the footing edge (the stress singularity), then by `grow` to the far
boundaries (x = 5b, y = -4b). T6 splits every quadrangle into two triangles. The defaults
write the test deck footing_t6.inp (run from this directory).
"""
import argparse
import math

from pecplas_py.deck import Deck


def graded(a, b, h, grow, fine_end):
    """Coordinates from a to b: steps h up to fine_end, then growing by `grow` (last step
    stretched to land on b)."""
    xs = [a]
    while xs[-1] + h <= fine_end + 1e-9:
        xs.append(xs[-1] + h)
    step = h
    while xs[-1] < b - 1e-9:
        step *= grow
        if xs[-1] + 1.5 * step >= b:
            xs.append(b)
        else:
            xs.append(xs[-1] + step)
    return xs


def geometric(length, n, ratio):
    """n steps over `length`, each `ratio` times the previous one (first step smallest)."""
    if abs(ratio - 1.0) < 1e-12:
        steps = [length / n] * n
    else:
        first = length * (ratio - 1.0) / (ratio ** n - 1.0)
        steps = [first * ratio ** k for k in range(n)]
    out = [0.0]
    for st in steps:
        out.append(out[-1] + st)
    out[-1] = length
    return out


def build_mesh(elem, nf, bias, grow):
    """Structured graded mesh of the half model: nodes [(x, y)], elements (node ids), the
    grid coordinates xs, the id map ids[(i, j)] of the quadratic grid and its top row index."""
    b, width, depth = 1.0, 5.0, 4.0
    # fine zone: nf elements under the footing, 2 nf beyond its edge to x = 3b, nf down
    # to y = -b, sizes growing by `bias` away from the footing edge (b, 0)
    under = [b - x for x in geometric(b, nf, bias)][::-1]
    beyond = [b + x for x in geometric(2.0 * b, 2 * nf, bias)]
    last = beyond[-1] - beyond[-2]
    far = graded(3.0 * b, width, last, grow, 3.0 * b)
    xs = under + beyond[1:] + far[1:]
    down = geometric(b, nf, bias)
    deep = graded(b, depth, down[-1] - down[-2], grow, b)
    ys = [-y for y in down + deep[1:]][::-1]  # bottom to top
    nx, ny = len(xs) - 1, len(ys) - 1

    # quadratic grid: (2nx+1) x (2ny+1) points; Q8 skips the element centres
    ids = {}
    nodes = []
    for j in range(2 * ny + 1):
        for i in range(2 * nx + 1):
            if elem == "Q8" and i % 2 == 1 and j % 2 == 1:
                continue
            x = xs[i // 2] if i % 2 == 0 else 0.5 * (xs[i // 2] + xs[i // 2 + 1])
            y = ys[j // 2] if j % 2 == 0 else 0.5 * (ys[j // 2] + ys[j // 2 + 1])
            ids[(i, j)] = len(nodes) + 1
            nodes.append((x, y))
    elements = []
    for ej in range(ny):
        for ei in range(nx):
            i, j = 2 * ei, 2 * ej
            if elem == "Q8":
                corners = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
                mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
                elements.append([ids[p] for p in corners + mids])
            else:
                # alternate the diagonal so that the mesh has no preferred direction
                if (ei + ej) % 2 == 0:
                    tris = [[(i, j), (i + 2, j), (i + 2, j + 2)], [(i, j), (i + 2, j + 2), (i, j + 2)]]
                else:
                    tris = [[(i, j), (i + 2, j), (i, j + 2)], [(i + 2, j), (i + 2, j + 2), (i, j + 2)]]
                for t in tris:
                    mids = [((t[k][0] + t[(k + 1) % 3][0]) // 2, (t[k][1] + t[(k + 1) % 3][1]) // 2)
                            for k in range(3)]
                    elements.append([ids[p] for p in t + mids])
    return nodes, elements, xs, ids, nx, ny


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--elem", choices=["Q8", "T6"], default="T6")
    ap.add_argument("--nf", type=int, default=4, help="elements under the half footing")
    ap.add_argument("--grow", type=float, default=1.5)
    ap.add_argument("--bias", type=float, default=1.3,
                    help="size ratio of neighbouring elements away from the footing edge")
    ap.add_argument("--settle", type=float, default=0.04, help="imposed settlement (m)")
    ap.add_argument("--increments", type=int, default=100)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--tol", type=float, default=1e-4)
    ap.add_argument("--maxit", type=int, default=15)
    ap.add_argument("-o", "--output", default="footing_t6.inp")
    a = ap.parse_args()

    b = 1.0
    nodes, elements, xs, ids, nx, ny = build_mesh(a.elem, a.nf, a.bias, a.grow)
    top = 2 * ny
    footing = [ids[(i, top)] for i in range(2 * nx + 1) if node_x(xs, i) <= b + 1e-9]
    left = [ids[(0, j)] for j in range(2 * ny + 1)]
    right = [ids[(2 * nx, j)] for j in range(2 * ny + 1)]
    base = [ids[(i, 0)] for i in range(2 * nx + 1) if (i, 0) in ids]

    qu = (2.0 + math.pi) * 10.0
    d = Deck(fmt=".10g")
    d.line(f"""** Smooth rigid strip footing on weightless Tresca soil (written by make_footing.py:
**   python3 -m pecplas_py.decks.make_footing --elem {a.elem} --nf {a.nf} --bias {a.bias}
**     --grow {a.grow} --settle {a.settle} --increments {a.increments} --nu {a.nu} \
--tol {a.tol:g} --maxit {a.maxit}).
** Half model: footing half-width b = 1 m on x in [0, 1] at y = 0, domain 5 m x 4 m,
** {len(elements)} {a.elem} elements: {a.nf} under the half footing, {2 * a.nf} from its edge \
to x = 3 m and
** {a.nf} down to y = -1 m (Prandtl's mechanism), sizes growing by {a.bias} away from the footing
** edge, then by {a.grow} to the far boundaries. Symmetry axis and right side on rollers
** (u_x = 0), base fixed. The footing nodes are pushed down by {a.settle} m in {a.increments}
** increments, free to slide horizontally (smooth footing).
** Soil: Mohr-Coulomb with phi = psi = 0 (Tresca), c = 10 kPa, E = 1e4 kPa, NU = {a.nu}.
** Prandtl: q_u = (2 + pi) c = {qu:.3f} kPa, i.e. a footing reaction of {qu:.3f} kN per m on
** the half model.""")
    d.title(f"smooth strip footing, Tresca, {a.elem} mesh").units("kN, m, kPa")
    d.analysis("PLANE_STRAIN").nodes(list(enumerate(nodes, 1)))
    d.elements(a.elem, "soil", [(k, *e) for k, e in enumerate(elements, 1)])
    d.material("clay", f"E = 1e4, NU = {a.nu}, C = 10, PHI = 0, PSI = 0", type="MOHR_COULOMB")
    d.section("soil", "clay")
    for name, lst in (("footing", footing), ("axis", left), ("far", right), ("base", base)):
        d.nset(name, lst, per_line=10)
    d.boundary("axis, X", "far, X", "base, XY")
    d.load("settle", "DISPLACEMENT", "footing, Y, -1.0")
    d.step("push", a.increments, f"settle, {a.settle}")
    d.solver(METHOD="NEWTON", TOLERANCE=f"{a.tol:g}", MAX_ITERATIONS=a.maxit, MAX_CUTS=8)
    d.output(STRESSES=False, STRAINS=False)
    d.write(a.output)


def node_x(xs, i):
    return xs[i // 2] if i % 2 == 0 else 0.5 * (xs[i // 2] + xs[i // 2 + 1])


if __name__ == "__main__":
    main()
