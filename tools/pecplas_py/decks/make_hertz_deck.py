#!/usr/bin/env python3
"""Hertz line contact deck (doc/validation.md, NAFEMS FENET D3613 set-up) for Katona contact.

A half cylinder (R = 50 mm, E = 70 GPa, nu = 0.3) pressed on a block (E = 210 GPa,
nu = 0.3) by F = 35 kN/mm, plane strain, units N, mm, MPa. By symmetry only x >= 0 is
meshed: a quarter disk centred at (0, R) on a block [0, W] x [-H, 0]; the load F/2 is a
pressure F / (2 R) on the flat top y = R of the quarter disk; the block's base is fixed and
the plane x = 0 is a symmetry plane. The cylinder is held only by its contacts (R singular:
the augmented path of the Katona solver).

Contact candidates: explicit SPRING doublets (block node, cylinder node) at the same x,
x = 0, h, 2h, ... up to X_CONTACT, with the initial gap R - sqrt(R^2 - x^2) along y; law
TYPE=KATONA, frictionless. Closed form: a = sqrt(4 F R / (pi E*)) = 6.21 mm,
p0 = 2 F / (pi a) = 3585 MPa, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.

Mesh: the cylinder is a polar grid about its centre (T3 around the centre, Q4 elsewhere),
angles from the contact point such that the surface nodes lie above the block's nodes in
the contact zone (spacing h), then growing by GROWTH; radii graded from h at the surface.
The block is a structured Q4 grid graded from h at the contact.

Usage: make_hertz_deck.py [--h 0.1] [--out test/data/katona/hertz.inp]
"""
import argparse
import math

from pecplas_py.deck import Deck

R, E1, E2, NU, F = 50.0, 70.0e3, 210.0e3, 0.3, 35.0e3
GROWTH = 1.15


def graded(start, stop, h, growth):
    """Points from start to stop (|stop - start| > h): first spacing h, growing."""
    sgn = 1.0 if stop > start else -1.0
    pts = [start]
    d = h
    while abs(stop - pts[-1]) > 1.5 * d:
        pts.append(pts[-1] + sgn * d)
        d *= growth
    pts.append(stop)
    return pts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--h', type=float, default=0.1, help='element size at the contact (mm)')
    ap.add_argument('--xc', type=float, default=8.0, help='extent of the candidates (mm)')
    ap.add_argument('--size', type=float, default=150.0, help='block width and depth (mm)')
    ap.add_argument('--out', default='test/data/katona/hertz.inp')
    args = ap.parse_args()
    h = args.h
    nf = int(round(args.xc / h))
    xc = [i * h for i in range(nf + 1)]
    nodes = []

    def add(x, y):
        nodes.append((x, y))
        return len(nodes)

    # block: x grid = contact nodes then graded; y graded downwards
    bx = xc + graded(xc[-1], args.size, h, GROWTH)[1:]
    by = graded(0.0, -args.size, h, GROWTH)
    bid = {}
    for j, y in enumerate(by):
        for i, x in enumerate(bx):
            bid[i, j] = add(x, y)
    belems = []
    for j in range(len(by) - 1):
        for i in range(len(bx) - 1):
            belems.append([bid[i, j + 1], bid[i + 1, j + 1], bid[i + 1, j], bid[i, j]])
    # cylinder: angles phi from the contact point, radii from the surface inwards
    phis = [math.asin(x / R) for x in xc]
    d = phis[-1] - phis[-2]
    while math.pi / 2 - phis[-1] > 1.5 * d * GROWTH:
        d *= GROWTH
        phis.append(phis[-1] + d)
    phis.append(math.pi / 2)
    radii = graded(R, 0.0, h, GROWTH)[:-1]  # the centre is one node
    centre = add(0.0, R)
    cid = {}
    for i, r in enumerate(radii):
        for j, p in enumerate(phis):
            x = r * math.sin(p)
            y = R - r * math.cos(p)
            if j == len(phis) - 1:
                x, y = r, R  # exactly on the flat top
            if j == 0:
                x = 0.0
            cid[i, j] = add(x, y)
    celems, ctri = [], []
    for i in range(len(radii) - 1):
        for j in range(len(phis) - 1):
            # counter-clockwise: outer ring (i) then inner (i+1)
            celems.append([cid[i, j], cid[i, j + 1], cid[i + 1, j + 1], cid[i + 1, j]])
    inner = len(radii) - 1
    for j in range(len(phis) - 1):
        ctri.append([cid[inner, j], cid[inner, j + 1], centre])

    estar = 1.0 / ((1 - NU**2) / E1 + (1 - NU**2) / E2)
    a = math.sqrt(4 * F * R / (math.pi * estar))
    p0 = 2 * F / (math.pi * a)
    d = Deck(fmt='.15g')
    d.comment('Hertz line contact, Katona (written by tools/pecplas_py/decks/make_hertz_deck.py, '
              'h = %g mm).' % h,
              'R = 50 mm, E = 70 GPa on 210 GPa, nu = 0.3, F = 35 kN/mm (F/2 on this half):',
              'a = %.4f mm, p0 = %.2f MPa.' % (a, p0))
    d.title('Hertz line contact (Katona, frictionless)').units('N, mm, MPa')
    d.analysis('PLANE_STRAIN').nodes([(k + 1, x, y) for k, (x, y) in enumerate(nodes)])
    eid = 0
    for name, etype, els in (('block', 'Q4', belems), ('cylinder', 'Q4', celems),
                             ('core', 'T3', ctri)):
        d.elements(etype, name, [(eid + k + 1, *c) for k, c in enumerate(els)])
        eid += len(els)
    d.material('block_steel', E=E2, NU=NU).material('cylinder_al', E=E1, NU=NU)
    d.section('block', 'block_steel').section('cylinder', 'cylinder_al')
    d.section('core', 'cylinder_al')
    d.interface_law('hertz', 'KATONA', 'MU = 0')
    top = len(by) - 1
    d.joints('SPRING', 'contact', 'hertz',
             [(eid + i + 1, bid[i, 0], cid[0, i]) for i in range(nf + 1)])
    sym = [bid[0, j] for j in range(len(by))] + [cid[i, 0] for i in range(len(radii))] + \
        [centre]
    d.nset('base', [bid[i, top] for i in range(len(bx))], per_line=12)
    d.nset('symmetry', sym, per_line=12)
    d.boundary('base, XY', 'symmetry, X')
    jt = len(phis) - 1
    ring = [centre] + [cid[i, jt] for i in reversed(range(len(radii)))]
    d.edges('flat_top', [(ring[k], ring[k + 1]) for k in range(len(ring) - 1)])
    d.load('load', 'PRESSURE', ('flat_top', F / (2 * R)))
    d.step('press', 1, 'load, 1').output(EVERY=1)
    d.write(args.out)
    print('%s: %d nodes, %d elements, %d doublets; a = %.4f mm, p0 = %.2f MPa'
          % (args.out, len(nodes), len(belems) + len(celems) + len(ctri), nf + 1, a, p0))


if __name__ == '__main__':
    main()
