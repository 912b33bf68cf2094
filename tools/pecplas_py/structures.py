"""Plates and anchors of a results file (doc/results.md, "Plates", "Anchors", "Envelopes"):
the force distributions along each plate, the anchor forces, and their envelopes per phase.

    from pecplas_py.results import Results
    from pecplas_py import structures
    with Results("output/excavation_strutted.h5") as r:
        structures.plate_names(r), structures.anchor_names(r)
        line = structures.plate_line(r, "wall")    # nodes in order along the plate, s, x
        f = structures.plate_state(r, key, "wall") # N, Q, M, u, deflection along the line
        env = structures.envelopes(r)              # {phase: {"plates": ..., "anchors": ...}}

The envelope of a phase is the minimum and maximum, node by node (plates: N, Q, M of
node_forces, and the deflection) or bar by bar (anchors: force), over the written increments
of the phase in which the set is active. It is computed here from the increments, so it is
the same whatever the run wrote: an increment not written (*OUTPUT, FREQUENCY=) does not
count. A set not active in any increment of a phase has no envelope in it."""
import numpy as np

from pecplas_py.results import text

NQM = ("N", "Q", "M")


def plate_names(r):
    """Names of the plate sets (groups of /mesh/plates), sorted."""
    return sorted(r.file["mesh/plates"].keys()) if "mesh/plates" in r.file else []


def anchor_names(r):
    """Names of the anchor sets (groups of /mesh/anchors), sorted."""
    return sorted(r.file["mesh/anchors"].keys()) if "mesh/anchors" in r.file else []


def plate_line(r, name):
    """The plate `name` as a line: dict with `order` (rows of the plate's node list, in order
    along the line), `nodes` (0-based mesh nodes in that order), `s` (arc length from the
    first end), `x` (coordinates, (n, 2)), `normal` (unit normal to the chord, first end to
    last: the deflection is measured along it), `vertical` (the chord is steeper than 45°),
    `nen` (nodes per element). The elements follow each other along the line (a plate is
    one line of elements, doc/deck.md, *PLATE)."""
    g = r.file[f"mesh/plates/{name}"]
    nodes = g["nodes"][()]
    conn = g["connectivity"][()]            # (nel, nen) 0-based mesh nodes: end, end[, mid]
    x = r.coordinates
    row = {int(n): i for i, n in enumerate(nodes)}
    s = {}
    for e, el in enumerate(conn):
        a, b = int(el[0]), int(el[1])
        if a not in s and b in s:       # an element walked backwards
            a, b = b, a
        if a not in s:
            s[a] = 0.0 if e == 0 else max(s.values())
        s[b] = s[a] + float(np.linalg.norm(x[b] - x[a]))
        for m in el[2:]:
            s[int(m)] = s[a] + float(np.linalg.norm(x[int(m)] - x[a]))
    ordered = sorted(s, key=lambda n: s[n])
    pts = x[ordered]
    chord = pts[-1] - pts[0]
    length = float(np.linalg.norm(chord))
    t = chord / length if length > 0 else np.array([1.0, 0.0])
    return {"order": np.array([row[n] for n in ordered]), "nodes": np.array(ordered),
            "s": np.array([s[n] for n in ordered]), "x": pts,
            "normal": np.array([-t[1], t[0]]), "vertical": abs(t[1]) > abs(t[0]),
            "nen": conn.shape[1]}


def plate_state(r, key, name, line=None):
    """N, Q, M (node_forces), u (displacement, (n, 2)), rotation and deflection (u along the
    line's normal) of plate `name` in increment `key`, in the order of plate_line; None when
    the plate is not active there (no group)."""
    path = f"increments/{key}/plates/{name}"
    if path not in r.file:
        return None
    line = line if line is not None else plate_line(r, name)
    g = r.file[path]
    nf = g["node_forces"][()][line["order"]]
    u = g["displacement"][()][line["order"]]
    out = {c: nf[:, i] for i, c in enumerate(NQM)}
    out["u"] = u
    out["rotation"] = g["rotation"][()][line["order"]]
    out["deflection"] = u @ line["normal"]
    return out


def anchor_force(r, key, name):
    """Force of each bar of anchor set `name` in increment `key` (tension positive, one
    anchor), None when the set is not active there."""
    path = f"increments/{key}/anchors/{name}/force"
    return r.file[path][()] if path in r.file else None


def units(r):
    """Units of the plate forces and of the anchor force as the file states them."""
    out = {"plate_forces": "", "anchor_force": ""}
    for key in r.keys:
        g = r.increment(key)
        for name in plate_names(r):
            d = f"plates/{name}/node_forces"
            if d in g and not out["plate_forces"]:
                out["plate_forces"] = text(g[d].attrs.get("units", ""))
        for name in anchor_names(r):
            d = f"anchors/{name}/force"
            if d in g and not out["anchor_force"]:
                out["anchor_force"] = text(g[d].attrs.get("units", ""))
    return out


def phase_keys(r):
    """{phase index: [keys of its written increments, in order]}."""
    out = {}
    for k in r.keys:
        out.setdefault(r.phase_of(k), []).append(k)
    return out


def envelopes(r):
    """{phase index: {"plates": {name: {"N": (min, max), "Q": ..., "M": ..., "deflection":
    ..., "keys": [...], "end": state at the phase's last increment where it is active}},
    "anchors": {name: {"min", "max", "end", "keys"}}}}: min and max node by node (bar by
    bar) over the phase's written increments in which the set is active."""
    lines = {n: plate_line(r, n) for n in plate_names(r)}
    out = {}
    for phase, keys in phase_keys(r).items():
        plates, anchors = {}, {}
        for name, line in lines.items():
            states = [(k, plate_state(r, k, name, line)) for k in keys]
            states = [(k, st) for k, st in states if st is not None]
            if not states:
                continue
            env = {"keys": [k for k, _ in states], "end": states[-1][1]}
            for c in (*NQM, "deflection"):
                v = np.array([st[c] for _, st in states])
                env[c] = (v.min(axis=0), v.max(axis=0))
            plates[name] = env
        for name in anchor_names(r):
            forces = [(k, anchor_force(r, k, name)) for k in keys]
            forces = [(k, f) for k, f in forces if f is not None]
            if not forces:
                continue
            v = np.array([f for _, f in forces])
            anchors[name] = {"keys": [k for k, _ in forces], "min": v.min(axis=0),
                             "max": v.max(axis=0), "end": forces[-1][1]}
        out[phase] = {"plates": plates, "anchors": anchors}
    return out
