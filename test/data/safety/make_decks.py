#!/usr/bin/env python3
"""Writes the safety-factor decks of test/data/safety (doc/validation.md, Safety factor).

infinite_slope_*.inp: an infinite slope as a column one element wide, the slope turned
horizontal and gravity inclined by beta (direction (sin beta, -cos beta)); the nodes of the
two sides at each height are tied by Katona doublets (stick: C and TENSION huge), so that the
column is periodic along the slope: u = u(y), the infinite slope exactly.
"""
import math
import sys


def infinite_slope(path, beta, phi, psi, c, gamma=20.0, height=5.0, nel=10, nu=0.4,
                   title='', water=None, steps=None):
    lines = ['** ' + title, '*TITLE', title, '*NODES']
    dy = height / nel
    for i in range(nel + 1):
        lines.append(f'{2 * i + 1}, 0.0, {i * dy:.12g}')
        lines.append(f'{2 * i + 2}, 1.0, {i * dy:.12g}')
    lines.append('*ELEMENTS, TYPE=Q4, SET=soil')
    for i in range(1, nel + 1):
        lines.append(f'{i}, {2 * i - 1}, {2 * i}, {2 * i + 2}, {2 * i + 1}')
    lines += ['*MATERIAL, NAME=soil, TYPE=MOHR_COULOMB',
              f'E = 1e5, NU = {nu}, GAMMA = {gamma}',
              f'C = {c}, PHI = {phi}, PSI = {psi}',
              '*SECTION, SET=soil, MATERIAL=soil',
              '*INTERFACE_LAW, NAME=tie, TYPE=KATONA',
              'MU = 0, C = 1e12, TENSION = 1e12',
              '*JOINTS, TYPE=SPRING, SET=tie, LAW=tie, ANGLE=0']
    for i in range(nel + 1):
        lines.append(f'{1000 + i}, {2 * i + 1}, {2 * i + 2}')
    lines += ['*NSET, NAME=base', '1, 2', '*BOUNDARY', 'base, XY',
              '*LOAD, NAME=weight, TYPE=GRAVITY',
              f'soil, {math.sin(math.radians(beta)):.15g}, {-math.cos(math.radians(beta)):.15g}',
              '*SOLVER, METHOD=NEWTON, TOLERANCE=1e-8',
              '*STEP, NAME=gravity, INCREMENTS=2', 'weight, 1']
    lines += steps or [f'*STEP, NAME=safety, CONTROL=SAFETY, RESOLUTION=0.002, '
                       f'NODE={2 * nel + 1}, DOF=X']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def main():
    infinite_slope('infinite_slope_dry.inp', 20, 35, 35, 0,
                   title='infinite slope beta 20, phi 35 (associated), c 0: F = tan phi / tan beta')
    infinite_slope('infinite_slope_c.inp', 25, 30, 30, 10,
                   title='infinite slope beta 25, phi 30 (associated), c 10, H 5')


if __name__ == '__main__':
    sys.exit(main())
