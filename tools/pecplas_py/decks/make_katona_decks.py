#!/usr/bin/env python3
"""Writes the Katona joint patch decks of test/data/katona (or --out DIR).

Two blocks of different materials, width 2, lower height H1 = 1, upper height H2 = 0.5, on a
non-uniform mesh, joined by generated Katona doublets (EDGES/SIDE) along y = 0:

- disp_*: the upper block's top is pushed down by DELTA (imposed displacement), the lower
  block's base rests on rollers; one node of each block is held in x. Frictionless contact
  (MU = 0), so each block is in uniaxial stress sigma_yy = -p with
      p = DELTA / (H1 c1 / E1 + H2 c2 / E2),   c = 1 - nu^2 (plane strain), 1 (axisymmetric)
  (lateral expansions differ: the contact slips freely, tau = 0). R is regular.
- float_*: the upper block is held only by its contacts (pressure P on top, nothing else):
  R is singular (augmented path) and sigma_n = P at every doublet, exactly.
"""
import argparse
import os

from pecplas_py import ROOT
from pecplas_py.deck import Deck

HERE = str(ROOT / "test" / "data" / "katona")
XS = [0.0, 0.3, 1.1, 2.0]
YL = [-1.0, -0.4, 0.0]
YU = [0.0, 0.25, 0.5]
E1, NU1, E2, NU2 = 1.0e4, 0.3, 5.0e4, 0.2
DELTA, P = 1.0e-3, 100.0


def block(nodes, xs, ys, quad8, first_node, first_elem, bottom=None):
    """Structured block; returns (elements, node id grid) and appends to nodes. `bottom`:
    ids of an existing bottom row (a conforming mesh, split later by *JOINTS EDGES/SIDE)."""
    step = 2 if quad8 else 1
    gx = []
    for i in range(len(xs) - 1):
        gx.append(xs[i])
        if quad8:
            gx.append(0.5 * (xs[i] + xs[i + 1]))
    gx.append(xs[-1])
    gy = []
    for j in range(len(ys) - 1):
        gy.append(ys[j])
        if quad8:
            gy.append(0.5 * (ys[j] + ys[j + 1]))
    gy.append(ys[-1])
    ids = {}
    n = first_node
    for j, y in enumerate(gy):
        for i, x in enumerate(gx):
            if quad8 and i % 2 == 1 and j % 2 == 1:
                continue
            if j == 0 and bottom is not None:
                ids[i, j] = bottom[i]
                continue
            ids[i, j] = n
            nodes.append((n, x, y))
            n += 1
    elems = []
    e = first_elem
    for j in range(0, len(gy) - 1, step):
        for i in range(0, len(gx) - 1, step):
            c = [ids[i, j], ids[i + step, j], ids[i + step, j + step], ids[i, j + step]]
            if quad8:
                c += [ids[i + 1, j], ids[i + 2, j + 1], ids[i + 1, j + 2], ids[i, j + 1]]
            elems.append((e, c))
            e += 1
    return elems, ids, len(gx), len(gy)


def deck(name, etype, jtype, axi, floating, out_dir=HERE):
    quad8 = etype == 'Q8'
    nodes = []
    low, lid, nx, ny = block(nodes, XS, YL, quad8, 1, 1)
    up, uid, _, nyu = block(nodes, XS, YU, quad8, 1001, 101,
                            bottom=[lid[i, ny - 1] for i in range(nx)])
    step = 2 if quad8 else 1
    d = Deck(fmt='.12g')
    d.comment('Written by make_katona_decks.py (see its docstring for the exact solution).')
    d.title(f'Katona joint patch test, {jtype}, {"axisymmetric" if axi else "plane strain"}, '
            f'{"floating upper block" if floating else "imposed displacement"}')
    d.units('kN, m, kPa')
    if axi:
        d.analysis('AXISYMMETRIC')
    d.nodes(nodes)
    for sname, els in (('lower', low), ('upper', up)):
        d.elements(etype, sname, [(e, *conn) for e, conn in els])
    d.material('soft', E=E1, NU=NU1).material('stiff', E=E2, NU=NU2)
    d.section('lower', 'soft').section('upper', 'stiff')
    d.interface_law('contact', 'KATONA', 'MU = 0')
    d.edges('interface', [[uid[i, 0], uid[i + step, 0]] + ([uid[i + 1, 0]] if quad8 else [])
                          for i in range(0, nx - 1, step)])
    d.keyword('JOINTS', TYPE=jtype, SET='joint', LAW='contact', EDGES='interface', SIDE='upper')
    d.nset('base', [lid[i, 0] for i in range(nx)]).boundary('base, Y')
    if axi:
        d.nset('axis', [lid[0, j] for j in range(ny) if (0, j) in lid]
               + [uid[0, j] for j in range(1, nyu) if (0, j) in uid])
        d.boundary('axis, X')
    else:
        d.boundary(f'{lid[0, 0]}, X')
    top = [uid[i, nyu - 1] for i in range(nx)]
    if floating:
        if not axi:
            # frictionless contact holds nothing in x: one node does (y stays free)
            d.boundary(f'{uid[0, nyu - 1]}, X')
        d.edges('top', [[top[i], top[i + step]] + ([top[i + 1]] if quad8 else [])
                        for i in range(0, nx - 1, step)])
        d.load('p', 'PRESSURE', f'top, {P:g}').step('press', 2, 'p, 1')
    else:
        if not axi:
            d.boundary(f'{uid[0, nyu - 1]}, X')
        d.nset('top', top)
        d.load('push', 'DISPLACEMENT', f'top, Y, {-DELTA:g}').step('push', 2, 'push, 1')
    d.write(os.path.join(out_dir, name + '.inp'))


if __name__ == '__main__':
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--out', default=HERE, help=f'directory (default {HERE})')
    out = ap.parse_args().out
    os.makedirs(out, exist_ok=True)
    for args in (('disp_spring_plane', 'Q4', 'SPRING', False, False),
                 ('disp_goodman4_plane', 'Q4', 'GOODMAN4', False, False),
                 ('disp_goodman6_plane', 'Q8', 'GOODMAN6', False, False),
                 ('disp_spring_axi', 'Q4', 'SPRING', True, False),
                 ('disp_goodman6_axi', 'Q8', 'GOODMAN6', True, False),
                 ('float_spring_plane', 'Q4', 'SPRING', False, True),
                 ('float_goodman6_axi', 'Q8', 'GOODMAN6', True, True)):
        deck(*args, out_dir=out)
