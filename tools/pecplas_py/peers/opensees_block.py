#!/usr/bin/env python3
"""The elastic plane-strain block of the OpenSees peer bench (bench/peer_opensees.py).

A cantilever block W x H = 2 m x 1 m of nx x ny bilinear quadrangles (Q4, nx = 2 ny), clamped
on its left edge (x = 0, both dofs), loaded on its right edge (x = W) by a vertical force of
P = -100 kN in all, shared as a consistent edge load (P/ny per node, half at the two corners).
Linear elastic, plane strain, E = 1e5 kPa, nu = 0.3, thickness 1. The "tip" is the top
right corner; its vertical displacement is the number both codes must agree on.

The same mesh is given to both codes: a PECPLAS deck (`pecplas_deck`) and a binary mesh file
(`save_mesh`, numpy .npz) that the OpenSees runner below reads. OpenSees: `quad` elements
(2 x 2 Gauss points, as our Q4) with an `ElasticIsotropic` nDMaterial, `PlaneStrain`; UmfPack
system, one `LoadControl` step of 1, `Linear` algorithm.

Only `run_opensees` needs OpenSees (openseespy); the rest is plain numpy.

    python3 -m pecplas_py.peers.opensees_block MESH.npz OUT.npz  # run OpenSees on a saved mesh
"""
import json
import sys
import time

import numpy as np

WIDTH, HEIGHT = 2.0, 1.0
E, NU = 1.0e5, 0.3
LOAD = -100.0          # kN, total vertical force on the right edge


def size_for(target):
    """(nx, ny) with nx = 2 ny whose total dof count 2 (nx+1)(ny+1) is closest to `target`."""
    ny = max(1, round((-3 + (9 - 8 * (1 - target / 2)) ** 0.5) / 4))
    best = min((abs(2 * (2 * n + 1) * (n + 1) - target), n) for n in (ny - 1, ny, ny + 1)
               if n >= 1)
    return 2 * best[1], best[1]


def block_mesh(nx, ny):
    """dict(xy (N, 2) node coordinates, quads (M, 4) 1-based node ids counter-clockwise,
    left (ids on x = 0), right (ids on x = W, bottom to top), forces (vertical force per
    right node), tip (id of the top right corner)). Node id = j (nx + 1) + i + 1."""
    i, j = np.meshgrid(np.arange(nx + 1), np.arange(ny + 1))
    xy = np.column_stack([(WIDTH * i / nx).ravel(), (HEIGHT * j / ny).ravel()])
    ei, ej = np.meshgrid(np.arange(nx), np.arange(ny))
    n1 = (ej * (nx + 1) + ei + 1).ravel()
    quads = np.column_stack([n1, n1 + 1, n1 + nx + 2, n1 + nx + 1])
    left = np.arange(ny + 1) * (nx + 1) + 1
    right = left + nx
    forces = np.full(ny + 1, LOAD / ny)
    forces[[0, -1]] *= 0.5
    return {"nx": nx, "ny": ny, "xy": xy, "quads": quads, "left": left, "right": right,
            "forces": forces, "tip": int(right[-1])}


def dofs(mesh):
    """(total, free) dof counts."""
    n = len(mesh["xy"])
    return 2 * n, 2 * n - 2 * len(mesh["left"])


def pecplas_deck(mesh):
    """Text of the PECPLAS deck of the block: one increment, displacements only in the
    results (OpenSees writes displacements only too)."""
    out = ["** Elastic plane-strain cantilever block for the OpenSees peer bench",
           "** (tools/pecplas_py/peers/opensees_block.py)", "*TITLE",
           f"elastic Q4 block {mesh['nx']} x {mesh['ny']}", "*UNITS", "kN, m, kPa", "*NODES"]
    out += [f"{k},{x:.17g},{y:.17g}" for k, (x, y) in enumerate(mesh["xy"], 1)]
    out.append("*ELEMENTS, TYPE=Q4, SET=block")
    out += [f"{e},{a},{b},{c},{d}" for e, (a, b, c, d) in enumerate(mesh["quads"], 1)]
    out += ["*MATERIAL, NAME=elastic", f"E = {E:g}, NU = {NU:g}",
            "*SECTION, SET=block, MATERIAL=elastic", "*NSET, NAME=left"]
    out += [", ".join(map(str, mesh["left"][k:k + 16])) for k in range(0, len(mesh["left"]), 16)]
    out += ["*BOUNDARY", "left, XY", "*LOAD, NAME=edge, TYPE=FORCE"]
    out += [f"{n}, Y, {f:.17g}" for n, f in zip(mesh["right"], mesh["forces"])]
    out += ["*STEP, NAME=load, INCREMENTS=1", "edge, 1.0",
            "*OUTPUT, STRESSES=NO, STRAINS=NO, REACTIONS=NO", ""]
    return "\n".join(out)


def save_mesh(mesh, path):
    np.savez(path, **{k: np.asarray(v) for k, v in mesh.items()})


def load_mesh(path):
    with np.load(path) as f:
        m = {k: f[k] for k in f.files}
    for k in ("nx", "ny", "tip"):
        m[k] = int(m[k])
    return m


def run_opensees(mesh):
    """Build and solve the block in OpenSees; returns (displacements (N, 2), phase times)."""
    import openseespy.opensees as ops
    t = {"start": time.perf_counter()}
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    node, element, fix, load = ops.node, ops.element, ops.fix, ops.load
    for k, (x, y) in enumerate(mesh["xy"].tolist(), 1):
        node(k, x, y)
    ops.nDMaterial("ElasticIsotropic", 1, E, NU)
    for e, (a, b, c, d) in enumerate(mesh["quads"].tolist(), 1):
        element("quad", e, a, b, c, d, 1.0, "PlaneStrain", 1)
    for n in mesh["left"].tolist():
        fix(n, 1, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    for n, f in zip(mesh["right"].tolist(), mesh["forces"].tolist()):
        load(n, 0.0, f)
    t["build"] = time.perf_counter()
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.integrator("LoadControl", 1.0)
    ops.algorithm("Linear")
    ops.analysis("Static")
    rc = ops.analyze(1)
    t["analyze"] = time.perf_counter()
    if rc != 0:
        raise RuntimeError(f"OpenSees analyze returned {rc}")
    u = np.array([ops.nodeDisp(k) for k in range(1, len(mesh["xy"]) + 1)])
    t["output"] = time.perf_counter()
    ops.wipe()
    return u, {"build_s": t["build"] - t["start"], "analyze_s": t["analyze"] - t["build"],
               "output_s": t["output"] - t["analyze"]}


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__.splitlines()[-1].strip())
    t0 = time.perf_counter()
    mesh = load_mesh(argv[1])
    t_read = time.perf_counter() - t0
    u, phases = run_opensees(mesh)
    np.savez(argv[2], displacement=u)
    print(json.dumps(dict(phases, read_s=t_read, tip_uy=float(u[mesh["tip"] - 1, 1]))))


if __name__ == "__main__":
    main(sys.argv)
