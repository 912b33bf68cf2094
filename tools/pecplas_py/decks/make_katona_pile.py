#!/usr/bin/env python3
"""Axisymmetric pile deck for the Katona / penalty speed comparison (doc/validation.md).

Scene S2 geometry (doc/validation.md): pile diameter 1 m embedded 10 m, soil domain radius 10 m and
depth 20 m; soil E = 2e4 kPa, nu = 0.3, pile E = 2e7 kPa, nu = 0.2, gamma = 18 kN/m3 for
both, geostatic initial stresses with K0 = 0.5; bottom fixed, outer side and axis radially
fixed. Interface joints (GOODMAN4, generated with EDGES/SIDE) along the shaft and under the
tip, Coulomb friction phi = 30 deg, c = 0; K_t = E_soil, K_n = E_pile per m for the penalty
law. The law TYPE (--law KATONA or MOHR_COULOMB) is the only difference between the decks.
Head pressure for 2000 kN, 20 increments up and 20 back to 0.

Structured Q4 mesh: pile radial spacing h, vertical spacing h along the pile; soil graded
from h at the shaft and below the tip by GROWTH. h = 0.05 m gives about 3e4 equations.

Usage: make_katona_pile.py [--h 0.05] [--law KATONA] [--method MODIFIED_NEWTON]
       [--out output/pile_katona.inp]
"""
import argparse
import math

from pecplas_py.deck import Deck

GROWTH = 1.05


def graded(start, stop, h, growth):
    sgn = 1.0 if stop > start else -1.0
    pts, d = [start], h
    while abs(stop - pts[-1]) > 1.5 * d:
        pts.append(pts[-1] + sgn * d)
        d *= growth
    pts.append(stop)
    return pts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--h', type=float, default=0.05)
    ap.add_argument('--law', default='KATONA', choices=['KATONA', 'MOHR_COULOMB'])
    ap.add_argument('--method', default='MODIFIED_NEWTON', choices=['MODIFIED_NEWTON', 'NEWTON'])
    ap.add_argument('--out', default='output/pile_katona.inp')
    args = ap.parse_args()
    h = args.h
    npile = int(round(0.5 / h))
    rs = [0.5 * i / npile for i in range(npile + 1)] + graded(0.5, 10.0, h, GROWTH)[1:]
    nlen = int(round(10.0 / h))
    zs = [-10.0 * i / nlen for i in range(nlen + 1)][::-1]  # -10 .. 0 ascending
    zs = graded(-10.0, -20.0, h, GROWTH)[::-1][:-1] + zs   # -20 .. 0 ascending
    nid = {}
    out_nodes = []
    for j, z in enumerate(zs):
        for i, r in enumerate(rs):
            nid[i, j] = len(out_nodes) + 1
            out_nodes.append((r, z))
    jtip = zs.index(-10.0)
    pile, soil = [], []
    for j in range(len(zs) - 1):
        for i in range(len(rs) - 1):
            c = [nid[i, j], nid[i + 1, j], nid[i + 1, j + 1], nid[i, j + 1]]
            (pile if (i < npile and j >= jtip) else soil).append(c)
    top = len(zs) - 1
    d = Deck(fmt='.12g')
    d.comment('Pile for the Katona / penalty speed comparison '
              '(tools/pecplas_py/decks/make_katona_pile.py,',
              'h = %g m, law %s). Assumptions: see the generator docstring.' % (h, args.law))
    d.title('axisymmetric pile, %s interface' % args.law).units('kN, m, kPa')
    d.analysis('AXISYMMETRIC').nodes([(k + 1, r, z) for k, (r, z) in enumerate(out_nodes)])
    eid = 0
    for name, els in (('soil', soil), ('pile', pile)):
        d.elements('Q4', name, [(eid + k + 1, *c) for k, c in enumerate(els)])
        eid += len(els)
    d.material('soil', 'E = 2e4, NU = 0.3, GAMMA = 18')
    d.material('concrete', 'E = 2e7, NU = 0.2, GAMMA = 18')
    d.section('soil', 'soil').section('pile', 'concrete')
    d.initial_stress('GEOSTATIC', 'ALL, 0.0, 0.5')
    d.interface_law('shaft', args.law, 'KN = 2e7, KT = 2e4, PHI = 30, C = 0')
    d.edges('interface', [(nid[npile, j], nid[npile, j + 1]) for j in range(jtip, top)]
            + [(nid[i, jtip], nid[i + 1, jtip]) for i in range(npile)])
    d.keyword('JOINTS', TYPE='GOODMAN4', SET='interface', LAW='shaft', EDGES='interface',
              SIDE='pile')
    d.nset('bottom', [nid[i, 0] for i in range(len(rs))], per_line=12)
    d.nset('outer', [nid[len(rs) - 1, j] for j in range(len(zs))], per_line=12)
    d.nset('axis', [nid[0, j] for j in range(len(zs))], per_line=12)
    d.boundary('bottom, XY', 'outer, X', 'axis, X')
    d.edges('head', [(nid[i, top], nid[i + 1, top]) for i in range(npile)])
    q = 2000.0 / (math.pi * 0.25)
    d.load('head', 'PRESSURE', 'head, %.10g' % q)
    d.solver(METHOD=args.method, MAX_ITERATIONS=500, MAX_CUTS=6)
    d.step('load', 20, 'head, 1').step('unload', 20, 'head, 0').output(EVERY=20)
    d.write(args.out)
    print('%s: %d nodes, %d elements' % (args.out, len(out_nodes), len(pile) + len(soil)))


if __name__ == '__main__':
    main()
