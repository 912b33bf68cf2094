#!/usr/bin/env python3
"""Writes the safety-factor decks of test/data/safety (doc/validation.md, Safety factor by
strength reduction) and the example input/examples/slope_safety.inp:

    python3 -m pecplas_py.decks.make_safety_decks [--out DIR] [--example FILE]

(defaults: test/data/safety and input/examples/slope_safety.inp).

block.inp: a pad on a Mohr-Coulomb joint pushed sideways below its sliding resistance, and its
variants (a budget too small, a push above the resistance, two bad decks).
footing_safety*.inp: Prandtl's footing of test/data/plasticity/footing_t6.inp under a pressure.
taylor_slope.inp: an undrained 60-degree slope on a firm base at the toe (Taylor's chart).

infinite_slope_*.inp: an infinite slope as a column one element wide, the slope turned
horizontal and gravity inclined by beta (direction (sin beta, -cos beta)); the nodes of the
two sides at each height are tied by Katona doublets (stick: C and TENSION huge), so that the
column is periodic along the slope: u = u(y), the infinite slope exactly.
"""
import argparse
import math
import os
import sys
from pathlib import Path

from pecplas_py import ROOT

BLOCK = """** Block on a Mohr-Coulomb joint (doc/validation.md, Safety factor): a pad pressed by
** P = 100 on a width 2 (N = 200) onto a fixed block through Mohr-Coulomb joints with
** c = 5, tan(PHI) = 0.3, pushed sideways by T = 3 x 10 = 30 on its top nodes. The sliding
** resistance is R = c L + N tan(phi) = 10 + 60 = 70: the safety step must find R / T = 7/3.
*TITLE
block on a Mohr-Coulomb joint, strength reduction
*NODES
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
10, 0, 2
11, 1, 2
12, 2, 2
*ELEMENTS, TYPE=Q4, SET=ground
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*ELEMENTS, TYPE=Q4, SET=pad
3, 4, 5, 11, 10
4, 5, 6, 12, 11
*MATERIAL, NAME=soil
E = 1e4, NU = 0.3
*SECTION, SET=ground, MATERIAL=soil
*SECTION, SET=pad, MATERIAL=soil
*INTERFACE_LAW, NAME=friction, TYPE=MOHR_COULOMB
KN = 1e5, KT = 1e5, PHI = 16.69924423399362, C = 5
*EDGES, NAME=interface
4, 5
5, 6
*JOINTS, TYPE=GOODMAN4, SET=contact, LAW=friction, EDGES=interface, SIDE=pad
*NSET, NAME=base
1, 2, 3
*NSET, NAME=pad_top
10, 11, 12
*BOUNDARY
base, XY
*EDGES, NAME=top
10, 11
11, 12
*LOAD, NAME=p, TYPE=PRESSURE
top, 100
*LOAD, NAME=push, TYPE=FORCE
pad_top, X, 10
*SOLVER, METHOD=NEWTON, TOLERANCE=1e-8, MAX_ITERATIONS=50, MAX_CUTS=4
*STEP, NAME=press, INCREMENTS=1
p, 1
*STEP, NAME=push, INCREMENTS=2
push, 1
*STEP, NAME=safety, CONTROL=SAFETY, MSF_STEP=0.2, RESOLUTION=0.002, NODE=11, DOF=X
"""


def column_mesh(height, nel):
    """Nodes and Q4 elements (set soil) of a column one unit wide, `nel` elements over
    `height`: nodes 2i+1 (x = 0) and 2i+2 (x = 1) at level i."""
    dy = height / nel
    lines = []
    for i in range(nel + 1):
        lines.append(f'{2 * i + 1}, 0.0, {i * dy:.12g}')
        lines.append(f'{2 * i + 2}, 1.0, {i * dy:.12g}')
    lines.append('*ELEMENTS, TYPE=Q4, SET=soil')
    for i in range(1, nel + 1):
        lines.append(f'{i}, {2 * i - 1}, {2 * i}, {2 * i + 2}, {2 * i + 1}')
    return lines


def column_ties(nel):
    """Stiff springs tying together the two nodes of each level of column_mesh (both sides
    of the column move alike, as in an infinite slope)."""
    return (['*INTERFACE_LAW, NAME=tie, TYPE=KATONA', 'MU = 0, C = 1e12, TENSION = 1e12',
             '*JOINTS, TYPE=SPRING, SET=tie, LAW=tie, ANGLE=0'] +
            [f'{1000 + i}, {2 * i + 1}, {2 * i + 2}' for i in range(nel + 1)])


def infinite_slope(path, beta, phi, psi, c, gamma=20.0, height=5.0, nel=10, nu=0.4,
                   title='', water=None, steps=None):
    lines = ['** ' + title, '*TITLE', title, '*NODES']
    lines += column_mesh(height, nel)
    lines += ['*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB',
              f'E = 1e5, NU = {nu}, GAMMA = {gamma}',
              f'C = {c}, PHI = {phi}, PSI = {psi}',
              '*SECTION, SET=soil, MATERIAL=soil',
              *column_ties(nel), '*NSET, NAME=base', '1, 2', '*BOUNDARY', 'base, XY',
              '*LOAD, NAME=weight, TYPE=GRAVITY',
              f'soil, {math.sin(math.radians(beta)):.15g}, {-math.cos(math.radians(beta)):.15g}',
              '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-8',
              '*STEP, NAME=gravity, INCREMENTS=2', 'weight, 1']
    lines += steps or [f'*STEP, NAME=safety, CONTROL=SAFETY, RESOLUTION=0.002, '
                       f'NODE={2 * nel + 1}, DOF=X']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def infinite_slope_water(path, beta, phi, psi, c, level, gamma=20.0, gamma_w=10.0,
                         height=5.0, nel=20, nu=0.4, title=''):
    """The infinite slope of `infinite_slope` under a water table parallel to it, `level`
    above the base (normal to the slope), with seepage parallel to the slope: turned
    horizontal, the pore pressure grows by gamma_w cos(beta) per unit depth normal to the
    slope below the table (the head falls along the slope), so the level is a horizontal
    *WATER with GAMMA_W = gamma_w cos(beta). The K0 procedure with the normal weight
    gamma cos(beta) (GAMMA_SAT = GAMMA_UNSAT) gives the effective stresses, then a BODY_FORCE
    gamma sin(beta) along the slope the shear."""
    b = math.radians(beta)
    gn = gamma * math.cos(b)
    lines = ['** ' + title, '*TITLE', title, '*NODES']
    lines += column_mesh(height, nel)
    lines += ['*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB',
              f'E = 1e5, NU = {nu}, GAMMA_UNSAT = {gn:.15g}, GAMMA_SAT = {gn:.15g}',
              f'C = {c}, PHI = {phi}, PSI = {psi}',
              '*SECTION, SET=soil, MATERIAL=soil',
              f'*WATER, NAME=table, GAMMA_W={gamma_w * math.cos(b):.15g}, LEVEL={level:g}',
              *column_ties(nel), '*NSET, NAME=base', '1, 2', '*BOUNDARY', 'base, XY',
              '*INITIAL_STRESS, TYPE=GEOSTATIC', f'ALL, {height:g}, {nu / (1 - nu):.15g}',
              '*LOAD, NAME=along, TYPE=BODY_FORCE', f'soil, {gamma * math.sin(b):.15g}, 0',
              '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-8',
              '*STEP, NAME=k0', '*STEP, NAME=incline, INCREMENTS=2', 'along, 1',
              f'*STEP, NAME=safety, CONTROL=SAFETY, RESOLUTION=0.002, NODE={2 * nel + 1}, DOF=X']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def footing(path, q, safety=True, dp=False):
    """The Prandtl footing of ../plasticity/footing_t6.inp (196 T6, Tresca c = 10, weightless)
    loaded by a uniform pressure q on the half-width b = 1 (a flexible smooth footing), then
    reduced (safety) or pushed to collapse by arc-length (safety=False)."""
    src = (ROOT / 'test/data/plasticity/footing_t6.inp').read_text().splitlines()
    keep = []
    skip = False
    for line in src:
        if line.startswith('*BOUNDARY'):
            break
        if line.startswith('*'):
            # the rigid footing's node set is not used here
            skip = line.startswith('*NSET, NAME=footing')
        if skip or line.startswith('**') or line.startswith('*TITLE'):
            continue
        keep.append(line)
    # drop the old title line (the line after *TITLE)
    title = ('Prandtl footing, Tresca c = 10, pressure q = %g: Msf = (2 + pi) c / q' % q
             if safety else 'Prandtl footing, Tresca c = 10, pressure to collapse')
    keep = [l for l in keep if not l.startswith('smooth strip footing')]
    if dp:
        title += ', Drucker-Prager MATCH = 3'
        keep = [l.replace('TYPE=MOHR_COULOMB', 'TYPE=DRUCKER_PRAGER') for l in keep]
        keep = [l + ', MATCH = 3' if l.startswith('E = 1e4') else l for l in keep]
    lines = ['** ' + title + ' (written by make_safety_decks.py from ../plasticity/footing_t6.inp)',
             '*TITLE', title] + keep
    lines += ['*BOUNDARY', 'axis, X', 'far, X', 'base, XY',
              '*EDGES, NAME=footing_edge',
              '407, 409, 408', '409, 411, 410', '411, 413, 412', '413, 415, 414',
              '*LOAD, NAME=q, TYPE=PRESSURE', 'footing_edge, %g' % q,
              '*SOLVER, METHOD=NEWTON, TOLERANCE=0.0001, MAX_ITERATIONS=15, MAX_CUTS=8',
              '*OUTPUT, STRESSES=NO, STRAINS=NO',
              '*STEP, NAME=load, INCREMENTS=2', 'q, 1']
    if safety:
        lines += ['*STEP, NAME=safety, CONTROL=SAFETY, RESOLUTION=0.002, NODE=407, DOF=Y']
    else:
        lines += ['*STEP, NAME=collapse, INCREMENTS=20, CONTROL=ARC_LENGTH, '
                  'MAX_INCREMENTS=300, NODE=407, DOF=Y, DISPLACEMENT=-0.2', 'q, 4']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def slope_mesh(height, beta, crest, nx, ny, foundation=0.0, nf=0, right=0.0, nr=0):
    """Q8R mesh of a slope of angle beta (degrees) and height `height`: crest from x = 0 to
    `crest`, toe at (crest + height / tan(beta), 0); a foundation layer of depth `foundation`
    (nf element rows) below y = 0 and `right` metres of ground beyond the toe (nr element
    columns), both optional. Returns (nodes {id: (x, y)}, elements [8 ids], node ids on x = 0,
    on the far right, on the base, and the nodes of the surface)."""
    run = height / math.tan(math.radians(beta))
    ids = {}
    nodes = {}

    def node(x, y):
        key = (round(x, 9), round(y, 9))
        if key not in ids:
            ids[key] = len(ids) + 1
            nodes[ids[key]] = (x, y)
        return ids[key]

    elements = []

    def block(corner):
        # corner(i, j) on a (2 ncol + 1) x (2 nrow + 1) grid of points
        pass

    def quad_grid(xy, ncol, nrow):
        for j in range(nrow):
            for i in range(ncol):
                c = [(2 * i, 2 * j), (2 * i + 2, 2 * j), (2 * i + 2, 2 * j + 2), (2 * i, 2 * j + 2)]
                m = [(2 * i + 1, 2 * j), (2 * i + 2, 2 * j + 1), (2 * i + 1, 2 * j + 2), (2 * i, 2 * j + 1)]
                elements.append([node(*xy(a, b)) for a, b in c + m])

    # the slope body: x from 0 to the slope line, y from 0 to height
    def body(a, b):
        eta = b / (2 * ny)
        xr = crest + run * (1 - eta)
        return (a / (2 * nx) * xr, eta * height)
    quad_grid(body, nx, ny)
    if foundation > 0:
        width = crest + run + right
        quad_grid(lambda a, b: (a / (2 * (nx + nr)) * width if nr else a / (2 * nx) * (crest + run),
                                -foundation + b / (2 * nf) * foundation), nx + nr, nf)
    if right > 0 and nr:
        x0 = crest + run
        quad_grid(lambda a, b: (x0 + a / (2 * nr) * right, 0.0 * b), nr, 0)
    left = [k for k, (x, y) in nodes.items() if abs(x) < 1e-9]
    ymin = min(y for x, y in nodes.values())
    base = [k for k, (x, y) in nodes.items() if abs(y - ymin) < 1e-9]
    xmax = max(x for x, y in nodes.values())
    far = [k for k, (x, y) in nodes.items() if abs(x - xmax) < 1e-9 and k not in base]
    return nodes, elements, left, far, base


def example_slope(path):
    """input/examples/slope_safety.inp: Griffiths & Lane's (1999) homogeneous 2:1 slope on a
    firm base at the toe: H = 10, gamma = 20, c' = 10 (c' / gamma H = 0.05), phi' = 20,
    psi = 0, drained, with a phreatic line falling straight from y = 6 at the back (x = 0)
    to the toe (Bishop and Morgenstern's charts give F = 1.38 for the dry slope)."""
    beta = math.degrees(math.atan(0.5))
    nodes, elements, left, far, base = slope_mesh(10.0, beta, 12.0, 20, 8)
    crest = [k for k, (x, y) in nodes.items() if abs(y - 10.0) < 1e-9 and abs(x - 12.0) < 1e-9]
    lines = ['** Example: factor of safety of a simple drained slope by strength reduction',
             '** (doc/deck.md, Safety; doc/validation.md, Safety factor). Griffiths & Lane (1999),',
             "** Geotechnique 49(3), fig. 4: a 2:1 slope, H = 10 m, on a firm base at the toe (D = 1),",
             "** c' = 10 kPa, phi' = 20 deg, psi = 0, gamma = 20 kN/m3 (c'/(gamma H) = 0.05): Bishop",
             "** and Morgenstern's charts F = 1.38 dry. A phreatic line falls from y = 6 at the back",
             "** to the toe (gamma_sat = gamma = 20, gamma_w = 10); gravity loading brings the water",
             "** in with the weight. Written by pecplas_py.decks.make_safety_decks.",
             '** Run: make run DECK=input/examples/slope_safety.inp; picture:',
             '**   cd tools && python3 -m pecplas_py.plots.plot_safety ../output/slope_safety.h5',
             '*TITLE', 'drained 2:1 slope, H 10, c 10, phi 20, phreatic line to the toe: factor of safety',
             '*UNITS', 'kN, m, kPa', '*ANALYSIS, TYPE=PLANE_STRAIN', '*NODES']
    lines += [f'{k}, {x:.10g}, {y:.10g}' for k, (x, y) in sorted(nodes.items())]
    lines.append('*ELEMENTS, TYPE=Q8, SET=soil')
    lines += [f'{e + 1}, ' + ', '.join(str(n) for n in conn) for e, conn in enumerate(elements)]
    lines += ['*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB',
              'E = 1e5, NU = 0.3, GAMMA = 20', 'C = 10, PHI = 20, PSI = 0',
              '*SECTION, SET=soil, MATERIAL=soil, ELEMENT=Q8R',
              '*WATER, NAME=seepage, GAMMA_W=10', '0, 6', f'{max(x for x, _ in nodes.values()):.10g}, 0',
              '*NSET, NAME=left'] + [', '.join(map(str, left[i:i + 10])) for i in range(0, len(left), 10)]
    lines += ['*NSET, NAME=base'] + [', '.join(map(str, base[i:i + 10])) for i in range(0, len(base), 10)]
    lines += ['*BOUNDARY', 'left, X', 'base, XY',
              '*LOAD, NAME=weight, TYPE=GRAVITY', 'soil',
              '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-5',
              '*OUTPUT, STRESSES=NO, STRAINS=NO',
              '** gravity loading: the slope under its weight',
              '*STEP, NAME=gravity, INCREMENTS=2', 'weight, 1',
              '** strength reduction from that state: c and tan(phi) divided by Msf until no',
              '** equilibrium exists; the curve follows the crest edge',
              f'*STEP, NAME=safety, CONTROL=SAFETY, MSF_STEP=0.1, RESOLUTION=0.005, NODE={crest[0]}, DOF=X']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def taylor_slope(path, c=50.0, gamma=20.0, height=10.0, beta=60.0, steps=None):
    """An undrained (phi = 0) slope of angle beta on a firm base at the toe (Taylor's depth
    factor D = 1): Taylor's chart gives c / (gamma H F) = 0.191 for beta = 60 degrees (a
    toe circle)."""
    nodes, elements, left, far, base = slope_mesh(height, beta, 2 * height, 16, 8)
    title = f'undrained slope beta {beta:g}, H {height:g}, c {c:g}, gamma {gamma:g}, D = 1'
    lines = ['** ' + title + ' (written by make_safety_decks.py)', '*TITLE', title, '*NODES']
    lines += [f'{k}, {x:.12g}, {y:.12g}' for k, (x, y) in sorted(nodes.items())]
    lines.append('*ELEMENTS, TYPE=Q8, SET=soil')
    lines += [f'{e + 1}, ' + ', '.join(str(n) for n in conn) for e, conn in enumerate(elements)]
    lines += ['*MATERIAL, NAME=clay, TYPE=MOHR_COULOMB',
              f'E = 1e5, NU = 0.3, GAMMA = {gamma:g}', f'C = {c:g}, PHI = 0, PSI = 0',
              '*SECTION, SET=soil, MATERIAL=clay, ELEMENT=Q8R',
              '*NSET, NAME=left'] + [', '.join(map(str, left[i:i + 10])) for i in range(0, len(left), 10)]
    lines += ['*NSET, NAME=base'] + [', '.join(map(str, base[i:i + 10])) for i in range(0, len(base), 10)]
    crest = [k for k, (x, y) in nodes.items() if abs(y - height) < 1e-9 and abs(x - 2 * height) < 1e-9]
    lines += ['*BOUNDARY', 'left, X', 'base, XY',
              '*LOAD, NAME=weight, TYPE=GRAVITY', 'soil',
              '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-5',
              '*OUTPUT, STRESSES=NO, STRAINS=NO',
              '*STEP, NAME=gravity, INCREMENTS=2', 'weight, 1']
    lines += steps or [f'*STEP, NAME=safety, CONTROL=SAFETY, RESOLUTION=0.005, '
                       f'NODE={crest[0]}, DOF=X']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def block_variants():
    """Variants of block.inp (written by hand): a budget too small (lower bound), a push
    above the resistance (unstable before reduction), and two bad decks."""
    text = BLOCK
    safety = '*STEP, NAME=safety, CONTROL=SAFETY, MSF_STEP=0.2, RESOLUTION=0.002, NODE=11, DOF=X'
    variants = {
        'block_budget.inp': ('budget of 3 increments: the factor is a lower bound',
                             [(safety, safety + ', MAX_INCREMENTS=3')]),
        'block_unstable.inp': ('pushed by 90 > R = 70: unstable before reduction',
                               [('pad_top, X, 10', 'pad_top, X, 30')]),
        'bad_safety_first.inp': ('bad: the safety step is the first step',
                                 [('*STEP, NAME=press, INCREMENTS=1\np, 1\n'
                                   '*STEP, NAME=push, INCREMENTS=2\npush, 1\n', '')]),
        'bad_reduce_elastic.inp': ('bad: *REDUCE names an elastic material',
                                   [(safety, safety + '\n*REDUCE\nfriction, soil')]),
    }
    for name, (title, subs) in variants.items():
        t = text
        for old, new in subs:
            assert old in t, (name, old)
            t = t.replace(old, new)
        with open(name, 'w') as f:
            f.write('** ' + title + ' (written by make_safety_decks.py from block.inp)\n' + t)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", help="directory of the test decks (default test/data/safety)")
    p.add_argument("--example", help="the example deck (default "
                   "input/examples/slope_safety.inp)")
    a = p.parse_args(argv)
    if a.out is None and a.example is None:
        a.out = str(ROOT / "test/data/safety")
        a.example = str(ROOT / "input/examples/slope_safety.inp")
    here = os.getcwd()
    if a.example:
        example_slope(str(Path(a.example).resolve()))
    if a.out:
        Path(a.out).mkdir(parents=True, exist_ok=True)
        os.chdir(a.out)
        with open('block.inp', 'w') as f:
            f.write(BLOCK)
        block_variants()
        infinite_slope('infinite_slope_dry.inp', 20, 35, 35, 0,
                       title='infinite slope beta 20, phi 35 (associated), c 0: '
                       'F = tan phi / tan beta')
        infinite_slope('infinite_slope_psi0.inp', 20, 35, 0, 0,
                       title='infinite slope beta 20, phi 35, psi 0, c 0: sin(phi_r) = tan(beta)')
        infinite_slope('infinite_slope_c.inp', 25, 30, 30, 10,
                       title='infinite slope beta 25, phi 30 (associated), c 10, H 5')
        infinite_slope_water('infinite_slope_water.inp', 25, 30, 30, 10, 2.5,
                             title="infinite slope beta 25, phi' 30 (associated), c' 10, 5 "
                             'thick, water table parallel to it 2.5 above the base')
        footing('footing_safety.inp', 25.0)
        footing('footing_safety_dp.inp', 25.0, dp=True)
        taylor_slope('taylor_slope.inp')
        os.chdir(here)
    return 0


if __name__ == '__main__':
    sys.exit(main())
