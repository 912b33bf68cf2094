#!/usr/bin/env python3
"""Export one of our decks (doc/deck.md) to an Abaqus-style CalculiX input (`ccx`), for the
side-by-side benchmark bench/peer.py (`doc/bench/README.md`).

Covered: *NODES, *ELEMENTS (Q4, Q8, Q8R, T3), *MATERIAL (elastic E, NU, GAMMA), *SECTION, *NSET,
*BOUNDARY (fixed components), *EDGES + *LOAD TYPE=PRESSURE, *LOAD TYPE=FORCE,
*INITIAL_STRESS TYPE=GEOSTATIC, *STEP (proportional patterns, linear increments), and the
joints (*JOINTS SPRING doublets or GOODMAN4 elements) turned into CalculiX contact:

- each joint set becomes a face-to-face (TYPE=SURFACE TO SURFACE) penalty contact pair: its
  slope is pressure per length, the unit of our K_n and K_t, so the penalty joint's stiffnesses
  carry over without a tributary area (node-to-surface contact would scale them by an area that
  CalculiX computes itself, and prefers unequal meshes);
- *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR with slope K_n, *FRICTION mu = tan(PHI) with
  stick slope K_t (from the law, or --kn/--kt for a Katona law, which has no stiffness);
- the master side is the stiffer body's; CalculiX cannot use as master a face with a node on
  the axis of an axisymmetric model (it becomes a collapsed face after the expansion). When both
  sides of a joint set have axis nodes (the pile tip) the doublets are tied by *EQUATION
  (bonded) and a warning says so.

The geostatic state: CalculiX has no "equilibrated initial stress" option, so the stresses are
given at every integration point (*INITIAL CONDITIONS, TYPE=STRESS) and the self-weight that
balances them is applied as *DLOAD GRAV in every step (density GAMMA / g).

    python3 -m pecplas_py.peers.export_abaqus DECK OUT.inp [--kn K] [--kt K] [--pair surface|node]
"""
import argparse
import math
import sys
from pathlib import Path

G = 9.81
Q4_FACES = ((0, 1), (1, 2), (2, 3), (3, 0))
T3_FACES = ((0, 1), (1, 2), (2, 0))
GP = 1.0 / math.sqrt(3.0)


def _params(header):
    out = {}
    for part in header.split(",")[1:]:
        if "=" in part:
            k, v = part.split("=", 1)
            out[k.strip().upper()] = v.strip()
    return out


def _keyvals(lines):
    out = {}
    for line in lines:
        for part in line.split(","):
            if "=" in part:
                k, v = part.split("=", 1)
                out[k.strip().upper()] = float(v)
    return out


def parse_deck(path):
    """Our deck as a dict of plain Python data (only what the exporter needs)."""
    blocks, cur = [], None
    for raw in Path(path).read_text().splitlines():
        line = raw.split("!")[0].strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            cur = (line[1:].split(",")[0].strip().upper(), _params(line), [])
            blocks.append(cur)
        elif cur is not None:
            cur[2].append(line)
    m = {"analysis": "PLANE_STRAIN", "nodes": {}, "elements": [], "materials": {},
         "sections": {}, "laws": {}, "joints": [], "nsets": {}, "boundary": [], "edges": {},
         "initial": [], "loads": {}, "steps": []}
    for key, p, data in blocks:
        rows = [[x.strip() for x in d.split(",") if x.strip()] for d in data]
        if key == "ANALYSIS":
            m["analysis"] = p.get("TYPE", "PLANE_STRAIN").upper()
        elif key == "NODES":
            for r in rows:
                m["nodes"][int(r[0])] = (float(r[1]), float(r[2]))
        elif key == "ELEMENTS":
            for r in rows:
                m["elements"].append((int(r[0]), p["TYPE"].upper(), p.get("SET", "ALL"),
                                      [int(x) for x in r[1:]]))
        elif key == "MATERIAL":
            m["materials"][p["NAME"]] = _keyvals(data)
        elif key == "SECTION":
            m["sections"][p["SET"]] = p["MATERIAL"]
        elif key == "INTERFACE_LAW":
            m["laws"][p["NAME"]] = dict(_keyvals(data), TYPE=p["TYPE"].upper())
        elif key == "JOINTS":
            m["joints"].append({"set": p.get("SET", "joints"), "type": p["TYPE"].upper(),
                                "law": p["LAW"], "rows": [[int(x) for x in r[1:]] for r in rows]})
        elif key == "NSET":
            m["nsets"][p["NAME"]] = [int(x) for r in rows for x in r]
        elif key == "BOUNDARY":
            m["boundary"] += [(r[0], r[1].upper(), float(r[2]) if len(r) > 2 else 0.0)
                              for r in rows]
        elif key == "EDGES":
            m["edges"][p["NAME"]] = [(int(r[0]), int(r[1])) for r in rows]
        elif key == "INITIAL_STRESS":
            if p.get("TYPE", "").upper() != "GEOSTATIC":
                raise ValueError("only *INITIAL_STRESS, TYPE=GEOSTATIC is exported")
            m["initial"] += [(r[0], float(r[1]), float(r[2]), float(r[3]) if len(r) > 3 else 0.0)
                             for r in rows]
        elif key == "LOAD":
            if "MIN" in p:
                raise ValueError("a pressure with MIN= is not exported")
            m["loads"][p["NAME"]] = (p["TYPE"].upper(), rows)
        elif key == "STEP":
            m["steps"].append((p.get("NAME", f"step{len(m['steps']) + 1}"),
                               int(p.get("INCREMENTS", 1)), {r[0]: float(r[1]) for r in rows}))
    return m


def _faces(etype):
    return T3_FACES if etype == "T3" else Q4_FACES


def edge_face(m, a, b):
    """(element id, face number 1..) of the element with the edge a-b (either direction)."""
    for eid, etype, _, conn in m["elements"]:
        for k, (i, j) in enumerate(_faces(etype)):
            if {conn[i], conn[j]} == {a, b}:
                return eid, k + 1
    raise ValueError(f"no element has the edge {a}-{b}")


def joint_sides(joint):
    """Per joint set: (side-1 segments, side-2 segments, doublets) from SPRING doublets (in
    order along the interface) or GOODMAN4 rows (a1, a2, b2, b1)."""
    if joint["type"] == "SPRING":
        pairs = [(r[0], r[1]) for r in joint["rows"]]
        s1 = [(p[0], q[0]) for p, q in zip(pairs[:-1], pairs[1:])]
        s2 = [(p[1], q[1]) for p, q in zip(pairs[:-1], pairs[1:])]
        return s1, s2, pairs
    if joint["type"] in ("GOODMAN4", "THIN_LAYER"):
        s1 = [(r[0], r[1]) for r in joint["rows"]]
        s2 = [(r[3], r[2]) for r in joint["rows"]]
        pairs = sorted({(r[0], r[3]) for r in joint["rows"]} |
                       {(r[1], r[2]) for r in joint["rows"]})
        return s1, s2, pairs
    raise ValueError(f"joint type {joint['type']} is not exported")


def element_material(m):
    return {eid: m["materials"][m["sections"][eset]] for eid, _, eset, _ in m["elements"]}


def _ip_points(xy, etype):
    """In-plane coordinates of the integration points of the 3D element CalculiX expands a 2D
    element into: 2x2 Gauss in plane (first natural coordinate fastest) repeated for the
    2 points through the expansion (C3D8); for T3 the single point (C3D6 has two)."""
    if etype == "T3":
        c = [sum(p[i] for p in xy) / 3.0 for i in range(2)]
        return [c, c]
    pts = []
    for s, t in ((-GP, -GP), (GP, -GP), (-GP, GP), (GP, GP)):
        n = [(1 - s) * (1 - t) / 4, (1 + s) * (1 - t) / 4, (1 + s) * (1 + t) / 4,
             (1 - s) * (1 + t) / 4]
        pts.append([sum(n[k] * xy[k][i] for k in range(4)) for i in range(2)])
    return pts + pts


def export(m, out, kn=None, kt=None, pair="surface", warn=print):
    axi = m["analysis"].startswith("AXI")
    cpe = {"Q4": "CAX4" if axi else "CPE4", "T3": "CAX3" if axi else "CPE3",
           "Q8": "CAX8" if axi else "CPE8", "Q8R": "CAX8R" if axi else "CPE8R"}
    L = ["** Exported from our deck by tools/pecplas_py/peers/export_abaqus.py for CalculiX (ccx)",
         "*HEADING", "exported deck", "*NODE"]
    L += [f"{k}, {x:.12g}, {y:.12g}, 0" for k, (x, y) in sorted(m["nodes"].items())]
    sets = {}
    for eid, etype, eset, conn in m["elements"]:
        sets.setdefault((eset, etype), []).append((eid, conn))
    for (eset, etype), els in sets.items():
        L.append(f"*ELEMENT, TYPE={cpe[etype]}, ELSET={eset}")
        L += [f"{eid}, " + ", ".join(map(str, conn)) for eid, conn in els]
    L.append("*ELSET, ELSET=EALL")
    L += _wrap(sorted({e[0] for e in m["elements"]}))
    for name, mat in m["materials"].items():
        L += [f"*MATERIAL, NAME={name}", "*ELASTIC", f"{mat['E']:.12g}, {mat['NU']:.12g}"]
        L += ["*DENSITY", f"{mat.get('GAMMA', 0.0) / G:.12g}"]
    for eset, mat in m["sections"].items():
        L += [f"*SOLID SECTION, ELSET={eset}, MATERIAL={mat}"] + ([] if axi else ["1."])
    for name, nodes in m["nsets"].items():
        L += [f"*NSET, NSET={name}"] + _wrap(nodes)
    L += ["*BOUNDARY"]
    for nset, comp, val in m["boundary"]:
        for c in comp:
            d = {"X": 1, "R": 1, "Y": 2, "Z": 2}[c]
            L.append(f"{nset}, {d}, {d}" + (f", {val:.12g}" if val else ""))
    L += _contact(m, kn, kt, axi, pair, warn)
    gravity = bool(m["initial"])
    if gravity:
        L += _initial_stress(m)
    L += _steps(m, gravity)
    Path(out).write_text("\n".join(L) + "\n")
    return out


def _wrap(ids, n=12):
    ids = list(ids)
    return [", ".join(map(str, ids[i:i + n])) for i in range(0, len(ids), n)]


def _contact(m, kn, kt, axi, pair, warn):
    L = []
    emat = element_material(m)
    on_axis = {k for k, (x, _) in m["nodes"].items() if axi and abs(x) < 1e-12}
    for joint in m["joints"]:
        law = m["laws"][joint["law"]]
        k_n = kn if kn is not None else law.get("KN")
        k_t = kt if kt is not None else law.get("KT")
        if k_n is None or k_t is None:
            raise ValueError(f"law {joint['law']} has no KN/KT: give --kn and --kt")
        s1, s2, pairs = joint_sides(joint)
        name = joint["set"]
        axis1 = {n for s in s1 for n in s} & on_axis
        axis2 = {n for s in s2 for n in s} & on_axis
        if not s1 or (axis1 and axis2):
            warn(f"joint set {name}: both sides touch the axis (or a single doublet), "
                 f"CalculiX cannot build a master face there: its {len(pairs)} doublets are tied")
            fixed = _fixed_dofs(m)
            L.append("*EQUATION")
            for a, b in pairs:
                for d in (1, 2):
                    if (a, d) in fixed and (b, d) in fixed:
                        continue
                    if (a, d) in fixed:   # the first term is the dependent one
                        a, b = b, a
                    L += ["2", f"{a}, {d}, 1., {b}, {d}, -1."]
            continue
        faces1 = [edge_face(m, a, b) for a, b in s1]
        faces2 = [edge_face(m, a, b) for a, b in s2]
        e1 = max(emat[f[0]]["E"] for f in faces1)
        e2 = max(emat[f[0]]["E"] for f in faces2)
        sides = [(faces1, s1), (faces2, s2)]
        master = 0 if e1 >= e2 else 1
        if {n for s in sides[master][1] for n in s} & on_axis:
            master = 1 - master
        mf, sf = sides[master][0], sides[1 - master][0]
        L += [f"*SURFACE, NAME={name}_M, TYPE=ELEMENT"] + [f"{e}, S{k}" for e, k in mf]
        if pair == "node":
            snodes = sorted({n for s in sides[1 - master][1] for n in s})
            L += [f"*SURFACE, NAME={name}_S, TYPE=NODE"] + _wrap(snodes)
        else:
            L += [f"*SURFACE, NAME={name}_S, TYPE=ELEMENT"] + [f"{e}, S{k}" for e, k in sf]
        mu = math.tan(math.radians(law.get("PHI", 0.0)))
        typ = "SURFACE TO SURFACE" if pair == "surface" else "NODE TO SURFACE"
        L += [f"*CONTACT PAIR, INTERACTION={name}_I, TYPE={typ}" +
              (", SMALL SLIDING" if pair == "node" else ""), f"{name}_S, {name}_M",
              f"*SURFACE INTERACTION, NAME={name}_I",
              "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
              f"{k_n:.12g}" + (", 1e-3" if pair == "node" else ""),
              "*FRICTION", f"{mu:.12g}, {k_t:.12g}"]
    return L


def _fixed_dofs(m):
    fixed = set()
    for nset, comp, _ in m["boundary"]:
        nodes = m["nsets"][nset] if nset in m["nsets"] else [int(nset)]
        for c in comp:
            fixed |= {(n, {"X": 1, "R": 1, "Y": 2, "Z": 2}[c]) for n in nodes}
    return fixed


def _initial_stress(m):
    """sigma_v = q + gamma (y_s - y), sigma_h = K0 sigma_v on xx and zz, compression negative,
    at every integration point of the expanded element."""
    emat = element_material(m)
    rule = {}
    for eset, ys, k0, q in m["initial"]:
        for eid, _, es, _ in m["elements"]:
            if eset.upper() == "ALL" or es == eset:
                rule[eid] = (ys, k0, q)
    L = ["*INITIAL CONDITIONS, TYPE=STRESS"]
    for eid, etype, _, conn in m["elements"]:
        if eid not in rule:
            continue
        ys, k0, q = rule[eid]
        gam = emat[eid].get("GAMMA", 0.0)
        xy = [m["nodes"][n] for n in conn[:4 if etype != "T3" else 3]]
        for ip, (_, y) in enumerate(_ip_points(xy, etype), start=1):
            sv = -(q + gam * (ys - y))
            L.append(f"{eid}, {ip}, {k0 * sv:.10g}, {sv:.10g}, {k0 * sv:.10g}, 0, 0, 0")
    return L


def _steps(m, gravity):
    """A first step with only the geostatic state (self-weight against the initial stresses),
    then our steps: each pattern ramps linearly to its target factor."""
    L = []
    out = ["*NODE PRINT, NSET=PRINT_NODES", "U", "*NODE FILE", "U"]
    if gravity:
        L += ["*STEP", "*STATIC", "1., 1.", "*DLOAD", "EALL, GRAV, 9.81, 0., -1., 0."]
        L += out + ["*END STEP"]
    factors = {}
    for name, n, targets in m["steps"]:
        factors.update(targets)
        dt = 1.0 / n
        L += ["*STEP, INC=1000", "*STATIC", f"{dt:.12g}, 1., {dt * 1e-4:.12g}, {dt:.12g}"]
        L += _loads(m, factors)
        L += out + ["*END STEP"]
    return L


def _loads(m, factors):
    L = []
    for name, (typ, rows) in m["loads"].items():
        f = factors.get(name, 0.0)
        if typ == "PRESSURE":
            L.append("*DLOAD")
            for r in rows:
                if len(r) != 2:
                    raise ValueError(f"pressure '{name}' varies with depth: only uniform "
                                     "pressures are exported")
                for a, b in m["edges"][r[0]]:
                    eid, k = edge_face(m, a, b)
                    L.append(f"{eid}, P{k}, {float(r[1]) * f:.12g}")
        elif typ == "FORCE":
            L.append("*CLOAD")
            L += [f"{r[0]}, {r[1]}, {float(r[2]) * f:.12g}" for r in rows]
        else:
            raise ValueError(f"load type {typ} is not exported")
    return L


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--kn", type=float)
    ap.add_argument("--kt", type=float)
    ap.add_argument("--pair", choices=("surface", "node"), default="surface")
    ap.add_argument("--print-nodes", default="", help="comma-separated nodes for *NODE PRINT")
    a = ap.parse_args()
    m = parse_deck(a.deck)
    nodes = [int(x) for x in a.print_nodes.split(",") if x.strip()]
    m["nsets"]["PRINT_NODES"] = nodes or sorted(m["nodes"])[:1]
    export(m, a.out, a.kn, a.kt, a.pair, warn=lambda s: print("warning:", s, file=sys.stderr))
    print(a.out)


if __name__ == "__main__":
    main()
