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
    out = ['** Hertz line contact, Katona (written by tools/make_hertz_deck.py, h = %g mm).' % h,
           '** R = 50 mm, E = 70 GPa on 210 GPa, nu = 0.3, F = 35 kN/mm (F/2 on this half):',
           '** a = %.4f mm, p0 = %.2f MPa.' % (a, p0),
           '*TITLE', 'Hertz line contact (Katona, frictionless)', '*UNITS', 'N, mm, MPa',
           '*ANALYSIS, TYPE=PLANE_STRAIN', '*NODES']
    out += ['%d, %.15g, %.15g' % (k + 1, x, y) for k, (x, y) in enumerate(nodes)]
    eid = 0
    for name, etype, els in (('block', 'Q4', belems), ('cylinder', 'Q4', celems),
                             ('core', 'T3', ctri)):
        out.append('*ELEMENTS, TYPE=%s, SET=%s' % (etype, name))
        for c in els:
            eid += 1
            out.append('%d, %s' % (eid, ', '.join(str(v) for v in c)))
    out += ['*MATERIAL, NAME=block_steel', 'E = %g, NU = %g' % (E2, NU),
            '*MATERIAL, NAME=cylinder_al', 'E = %g, NU = %g' % (E1, NU),
            '*SECTION, SET=block, MATERIAL=block_steel',
            '*SECTION, SET=cylinder, MATERIAL=cylinder_al',
            '*SECTION, SET=core, MATERIAL=cylinder_al',
            '*INTERFACE_LAW, NAME=hertz, TYPE=KATONA', 'MU = 0',
            '*JOINTS, TYPE=SPRING, SET=contact, LAW=hertz']
    top = len(by) - 1
    for i in range(nf + 1):
        eid += 1
        out.append('%d, %d, %d' % (eid, bid[i, 0], cid[0, i]))
    out.append('*NSET, NAME=base')
    out += [', '.join(str(bid[i, top]) for i in range(k, min(k + 12, len(bx))))
            for k in range(0, len(bx), 12)]
    sym = [bid[0, j] for j in range(len(by))] + [cid[i, 0] for i in range(len(radii))] + \
        [centre]
    out.append('*NSET, NAME=symmetry')
    out += [', '.join(str(v) for v in sym[k:k + 12]) for k in range(0, len(sym), 12)]
    out += ['*BOUNDARY', 'base, XY', 'symmetry, X']
    jt = len(phis) - 1
    ring = [centre] + [cid[i, jt] for i in reversed(range(len(radii)))]
    out.append('*EDGES, NAME=flat_top')
    out += ['%d, %d' % (ring[k], ring[k + 1]) for k in range(len(ring) - 1)]
    out += ['*LOAD, NAME=load, TYPE=PRESSURE', 'flat_top, %.15g' % (F / (2 * R)),
            '*STEP, NAME=press, INCREMENTS=1', 'load, 1', '*OUTPUT, EVERY=1']
    with open(args.out, 'w') as f:
        f.write('\n'.join(out) + '\n')
    print('%s: %d nodes, %d elements, %d doublets; a = %.4f mm, p0 = %.2f MPa'
          % (args.out, len(nodes), len(belems) + len(celems) + len(ctri), nf + 1, a, p0))


if __name__ == '__main__':
    main()
