#!/usr/bin/env python3
"""Check a PECPLAS results file (HDF5) and its XDMF sidecar.

Usage:
    python3 -m pecplas_py.checks.check_results RESULTS.h5 [--expect-status STATUS]
                                               [--xmf FILE | --no-xdmf]
    python3 -m pecplas_py.checks.check_results --left RESULTS.h5

Checks that the required attributes, groups and datasets exist, that every /history
dataset has the same number of rows, that no float dataset or attribute holds NaN or Inf,
that the status attribute is a known value consistent with `complete`, that each history
row flagged with fields has its /increments group, that joint sets (/mesh/joint_sets, when
present) have their datasets and, in every field increment, joint fields of matching shapes
with modes 1 (stick), 2 (slip) or 3 (open), that every float dataset (except the driver's
packed /restart state) carries a `units` attribute and, where it has a component axis (its
last), a `components` attribute of that length, with displacements, reactions and stresses
in the root length_unit, force_unit and stress_unit, that every dataset's `checksum` and the
root `deck_text_checksum` match (doc/results.md, Checksums), and that the .xmf parses as XML, each
"file.h5:/path" DataItem names an existing dataset of the declared dimensions, HyperSlab
items select inside their dataset, and every joint set has its grid in each increment. In a
staged run (/phases), an increment holds the fields of the sets active in its phase and of no
other, and its XDMF grids are those of the active sets; a plate or anchor set has its grid
(plates_<set>, anchors_<set>) in exactly the increments that hold its fields.
Exit status 0 when everything holds, 1 otherwise (each problem is printed).

--left RESULTS.h5: what runs killed before their end (kill -9, out-of-memory) left beside
that target, one line per run: its results `.NAME.h5.<pid>.tmp` checked as above with its
sidecar, the file to keep, and the temporary files to delete (doc/results.md, "Safety").
"""

import argparse
import os
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

ROOT_ATTRS = ["program", "version", "title", "units", "length_unit", "force_unit",
              "stress_unit", "deck_file", "deck_text", "analysis", "created", "status",
              "complete", "status_message"]
STATUSES = ["running", "completed", "limit load", "diverged", "failed", "interrupted"]
HISTORY_1D = ["step", "increment", "global_increment", "time", "iterations", "residual",
              "cpu_time", "fields", "method", "line_searches", "control"]
SET_DATASETS = ["connectivity", "element_ids", "gauss_coordinates"]
JOINT_SET_DATASETS = ["connectivity", "element_ids", "point_coordinates", "point_tangents"]
JOINT_FIELDS = ["relative_displacement", "stress", "mode", "plastic_slip"]


def as_text(value):
    """Attribute value as str (h5py gives str for variable-length strings)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray) and value.shape == ():
        return as_text(value[()])
    return value


def check_structure(f, problems):
    for name in ROOT_ATTRS:
        if name not in f.attrs:
            problems.append(f"missing root attribute '{name}'")
    if f.attrs.get("program") is not None and as_text(f.attrs["program"]) != "PECPLAS":
        problems.append(f"program attribute is {f.attrs['program']!r}, not 'PECPLAS'")
    for path in ["mesh/coordinates", "mesh/node_ids", "mesh/sets", "mesh/node_sets",
                 "mesh/edge_sets", "history", "increments"]:
        if path not in f:
            problems.append(f"missing /{path}")
    if "mesh/sets" in f:
        # a model of plates alone (a beam, a frame) has no element set
        if len(f["mesh/sets"]) == 0 and "mesh/plates" not in f:
            problems.append("/mesh/sets holds no element set")
        nnode = f["mesh/coordinates"].shape[0] if "mesh/coordinates" in f else None
        for name, group in f["mesh/sets"].items():
            for ds in SET_DATASETS:
                if ds not in group:
                    problems.append(f"missing /mesh/sets/{name}/{ds}")
            for attr in ["etype", "material"]:
                if attr not in group.attrs:
                    problems.append(f"missing attribute '{attr}' of /mesh/sets/{name}")
            if "connectivity" in group and nnode is not None:
                conn = group["connectivity"][...]
                if conn.size and (conn.min() < 0 or conn.max() >= nnode):
                    problems.append(f"/mesh/sets/{name}/connectivity outside 0..{nnode - 1}")


def joint_shapes(f, problems):
    """{set: (nel, npoint)} of /mesh/joint_sets, checking each set's datasets."""
    shapes = {}
    if "mesh/joint_sets" not in f:
        return shapes
    nnode = f["mesh/coordinates"].shape[0] if "mesh/coordinates" in f else None
    for name, group in f["mesh/joint_sets"].items():
        where = f"/mesh/joint_sets/{name}"
        missing = [ds for ds in JOINT_SET_DATASETS if ds not in group]
        for ds in missing:
            problems.append(f"missing {where}/{ds}")
        for attr in ["etype", "law"]:
            if attr not in group.attrs:
                problems.append(f"missing attribute '{attr}' of {where}")
        if missing:
            continue
        conn = group["connectivity"][...]
        if conn.size and nnode is not None and (conn.min() < 0 or conn.max() >= nnode):
            problems.append(f"{where}/connectivity outside 0..{nnode - 1}")
        xy = group["point_coordinates"]
        nel = conn.shape[0]
        if len(xy.shape) != 3 or xy.shape[0] != nel or xy.shape[2] != 2:
            problems.append(f"{where}/point_coordinates has shape {xy.shape}, expected "
                            f"({nel}, npoint, 2)")
            continue
        if group["point_tangents"].shape != xy.shape:
            problems.append(f"{where}/point_tangents has shape {group['point_tangents'].shape}"
                            f", not that of point_coordinates {xy.shape}")
        if group["element_ids"].shape != (nel,):
            problems.append(f"{where}/element_ids has shape {group['element_ids'].shape}, "
                            f"expected ({nel},)")
        shapes[name] = (nel, xy.shape[1])
    return shapes


def check_joint_fields(f, increment, shapes, problems):
    """Joint fields of one field increment against the joint sets of /mesh."""
    if not shapes:
        return
    base = f"increments/{increment}/joints"
    for name, (nel, npoint) in shapes.items():
        where = f"/{base}/{name}"
        if f"{base}/{name}" not in f:
            problems.append(f"missing {where}")
            continue
        group = f[f"{base}/{name}"]
        expected = {"relative_displacement": (nel, npoint, 2), "stress": (nel, npoint, 2),
                    "mode": (nel, npoint), "plastic_slip": (nel, npoint)}
        for ds in JOINT_FIELDS:
            if ds not in group:
                problems.append(f"missing {where}/{ds}")
            elif group[ds].shape != expected[ds]:
                problems.append(f"{where}/{ds} has shape {group[ds].shape}, expected "
                                f"{expected[ds]}")
        if "mode" in group and group["mode"].size:
            mode = group["mode"][...]
            if not np.all(np.isin(mode, [1, 2, 3])):
                problems.append(f"{where}/mode holds values other than 1 (stick), 2 (slip), "
                                f"3 (open)")
        if "state" in group and group["state"].shape[:2] != (nel, npoint):
            problems.append(f"{where}/state has shape {group['state'].shape}, expected "
                            f"({nel}, {npoint}, nstate)")


def phase_sets(f, increment):
    """(element sets, joint sets) active in the phase of field increment `increment` (the
    phase of /phases with the largest first_global_increment not after it), or (None, None)
    when the file lists no phase: every set."""
    if "phases" not in f:
        return None, None
    g = int(increment)
    best = None
    for group in f["phases"].values():
        first = int(group.attrs.get("first_global_increment", -1))
        if 1 <= first <= g and (best is None or first > best[0]):
            best = (first, group)
    if best is None:
        return None, None
    group = best[1]
    out = []
    for names, mask in (("element_sets", "active_element_sets"),
                        ("joint_sets", "active_joint_sets")):
        listed = [as_text(n) for n in group.attrs.get(names, [])]
        flags = group[mask][()] if mask in group else []
        out.append({n for n, m in zip(listed, flags) if m})
    return out[0], out[1]


def check_history(f, problems):
    """Equal lengths; returns the global increments whose row says fields were written."""
    if "history" not in f:
        return []
    h = f["history"]
    lengths = {}
    for name in HISTORY_1D:
        if name not in h:
            problems.append(f"missing /history/{name}")
        else:
            lengths[name] = h[name].shape[0]
    if "pattern_factors" not in h:
        problems.append("missing /history/pattern_factors")
    else:
        pf = h["pattern_factors"]
        lengths["pattern_factors"] = pf.shape[0]
        names = h.attrs.get("patterns")
        if names is None:
            problems.append("missing attribute 'patterns' of /history")
        elif len(names) != pf.shape[1]:
            problems.append(f"/history has {len(names)} pattern names for "
                            f"{pf.shape[1]} pattern_factors columns")
    n = min(lengths.values(), default=0)
    if len(set(lengths.values())) > 1:
        problems.append("history datasets differ in length: "
                        + ", ".join(f"{k}={v}" for k, v in lengths.items()))
        return []
    if "fields" in h and "global_increment" in h:
        fields = h["fields"][:n]
        glob = h["global_increment"][:n]
        return [int(g) for g, flag in zip(glob, fields) if flag == 1]
    return []


def check_increments(f, with_fields, problems):
    if "increments" not in f:
        return
    present = set(f["increments"].keys())
    expected = {f"{g:06d}" for g in with_fields}
    for name in sorted(expected - present):
        problems.append(f"history row of increment {name} has fields but no /increments/{name}")
    for name in sorted(present - expected):
        problems.append(f"/increments/{name} has no history row flagged with fields")
    shapes = joint_shapes(f, problems)
    for name in sorted(present):
        group = f["increments"][name]
        for ds in ["displacement", "displacement3"]:
            if ds not in group:
                problems.append(f"missing /increments/{name}/{ds}")
        esets, jsets = phase_sets(f, name)
        if esets is not None and "sets" in group:
            held = set(group["sets"].keys())
            for s in sorted(held - esets):
                problems.append(f"/increments/{name}/sets/{s}: fields of a set not active in "
                                f"the increment's phase")
            for s in sorted(esets - held):
                problems.append(f"/increments/{name}/sets: no fields of the active set {s}")
        if jsets is not None:
            held = set(group["joints"].keys()) if "joints" in group else set()
            for s in sorted(held - jsets):
                problems.append(f"/increments/{name}/joints/{s}: fields of a joint set not "
                                f"active in the increment's phase")
            check_joint_fields(f, name, {k: v for k, v in shapes.items() if k in jsets},
                               problems)
        else:
            check_joint_fields(f, name, shapes, problems)


def check_finite(f, problems):
    def visit(name, obj):
        for key, value in obj.attrs.items():
            arr = np.asarray(value)
            if arr.dtype.kind == "f" and not np.all(np.isfinite(arr)):
                problems.append(f"non-finite value in attribute '{key}' of /{name}")
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
            if not np.all(np.isfinite(obj[...])):
                problems.append(f"non-finite value (NaN/Inf) in /{name}")
    visit("", f)
    f.visititems(visit)


CHECKSUM_P = 67108859


def fletcher(words):
    """Fletcher's checksum of a sequence of 32-bit words as the program computes it
    (doc/results.md, Checksums): s1 = sum of the words, s2 = sum of the running s1, both
    modulo CHECKSUM_P, returned as s2 * 2^26 + s1. s2 = sum_j w_j (n - j) (0-based j)."""
    w = np.asarray(words, dtype=np.int64) % CHECKSUM_P
    n = w.size
    weights = (n - np.arange(n, dtype=np.int64)) % CHECKSUM_P
    s1 = s2 = 0
    for k in range(0, n, 4096):  # products < 2^52, sums of 4096 of them < 2^64
        s1 = (s1 + int(w[k:k + 4096].sum())) % CHECKSUM_P
        s2 = (s2 + int((w[k:k + 4096] * weights[k:k + 4096] % CHECKSUM_P).sum())) % CHECKSUM_P
    return float(s2 * 2**26 + s1)


def values_checksum(values):
    """Checksum of float64 values in file order: each value's low, then high 32-bit word."""
    return fletcher(np.ascontiguousarray(values, dtype="<f8").reshape(-1).view("<u4"))


def text_checksum(text):
    """Checksum of a text: one word per byte of its UTF-8 encoding."""
    return fletcher(np.frombuffer(text.encode("utf-8"), dtype=np.uint8))


def deck_identity(text):
    """The deck text without the paths of its '** ---- file: <path>' lines (what
    deck_text_checksum sums: the same files read from elsewhere are the same deck)."""
    mark = "** ---- file:"
    return "".join(mark + ("\n" if line.endswith("\n") else "") if line.startswith(mark)
                   else line for line in text.splitlines(keepends=True))


def check_checksums(f, problems):
    """Every dataset with a `checksum` attribute (the program's real datasets) and the root
    `deck_text_checksum` match their values (an independent computation of the program's
    checksum)."""
    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and "checksum" in obj.attrs:
            if values_checksum(obj[...]) != float(obj.attrs["checksum"]):
                problems.append(f"/{name}: values do not match their checksum")
    f.visititems(visit)
    if "deck_text_checksum" in f.attrs and "deck_text" in f.attrs:
        text = deck_identity(as_text(f.attrs["deck_text"]))
        if text_checksum(text) != float(f.attrs["deck_text_checksum"]):
            problems.append("deck_text does not match deck_text_checksum")


# datasets (by name) with a component axis, and the root attribute naming their unit
COMPONENT_DATASETS = {
    "coordinates": "length_unit", "gauss_coordinates": "length_unit",
    "point_coordinates": "length_unit", "point_tangents": None,
    "displacement": "length_unit", "displacement3": "length_unit",
    "reaction": "force_unit", "reaction3": "force_unit",
    "stress": "stress_unit", "stress_mean": "stress_unit", "strain": None,
    "relative_displacement": None, "pattern_factors": None}


def check_units(f, problems):
    """Every float dataset says its units; component axes are named."""
    root = {k: as_text(f.attrs[k]) for k in ("length_unit", "force_unit", "stress_unit")
            if k in f.attrs}

    def visit(name, obj):
        if not isinstance(obj, h5py.Dataset) or obj.dtype.kind != "f":
            return
        if name.startswith("restart/") or name.startswith("restart_next/"):
            return  # the driver's packed state, read back only by --restart
        leaf = name.rsplit("/", 1)[-1]
        units = obj.attrs.get("units")
        if units is None or not as_text(units):
            problems.append(f"/{name} has no 'units' attribute")
        unit_attr = COMPONENT_DATASETS.get(leaf)
        if unit_attr and unit_attr in root and units is not None \
                and as_text(units) != root[unit_attr]:
            problems.append(f"/{name} is in {as_text(units)!r}, not in the file's "
                            f"{unit_attr} {root[unit_attr]!r}")
        components = obj.attrs.get("components")
        if leaf in COMPONENT_DATASETS and components is None:
            problems.append(f"/{name} has no 'components' attribute")
        if components is not None and (not obj.shape or len(components) != obj.shape[-1]):
            problems.append(f"/{name} names {len(components)} components for shape "
                            f"{obj.shape}")
    f.visititems(visit)


def check_status(f, expect, problems):
    if "status" not in f.attrs or "complete" not in f.attrs:
        return
    status = as_text(f.attrs["status"])
    complete = int(f.attrs["complete"])
    if status not in STATUSES:
        problems.append(f"unknown status {status!r} (known: {', '.join(STATUSES)})")
    if complete not in (0, 1):
        problems.append(f"complete is {complete}, not 0 or 1")
    if (complete == 1) != (status == "completed"):
        problems.append(f"complete = {complete} contradicts status {status!r}")
    if expect is not None and status != expect:
        problems.append(f"status is {status!r}, expected {expect!r}")


def check_xdmf(h5_path, xmf_path, f, problems):
    """Every DataItem 'file.h5:/path' names a dataset of the file with those dimensions."""
    if not os.path.exists(xmf_path):
        problems.append(f"no XDMF file {xmf_path}")
        return 0
    try:
        tree = ET.parse(xmf_path)
    except ET.ParseError as err:
        problems.append(f"{xmf_path} is not valid XML: {err}")
        return 0
    root = tree.getroot()
    if root.tag != "Xdmf":
        problems.append(f"{xmf_path}: root element is <{root.tag}>, not <Xdmf>")
    h5_real = os.path.realpath(h5_path)
    items = [d for d in root.iter("DataItem") if d.get("Format", "XML") == "HDF"]
    # (the sidecar shows element and joint sets; a model of plates alone has none)
    if not items and not (len(f["mesh/sets"]) == 0 and "mesh/plates" in f):
        problems.append(f"{xmf_path} references no HDF5 dataset")
    for item in items:
        text = (item.text or "").strip()
        if ":" not in text:
            problems.append(f"DataItem {text!r} is not of the form file.h5:/path")
            continue
        fname, path = text.rsplit(":", 1)
        target = os.path.realpath(os.path.join(os.path.dirname(xmf_path) or ".", fname))
        if target != h5_real:
            problems.append(f"DataItem {text!r} points to {fname}, not to this results file")
            continue
        if path not in f or not isinstance(f[path], h5py.Dataset):
            problems.append(f"DataItem {text!r}: no dataset {path}")
            continue
        dims = tuple(int(x) for x in item.get("Dimensions", "").split())
        if dims != f[path].shape:
            problems.append(f"DataItem {text!r}: Dimensions {dims} but dataset shape "
                            f"{f[path].shape}")
    check_hyperslabs(root, problems)
    check_joint_grids(root, f, problems)
    check_structure_grids(root, f, problems)
    return len(items)


def check_hyperslabs(root, problems):
    """A HyperSlab item: start/stride/count rows inside its HDF item, count = Dimensions."""
    for slab in root.iter("DataItem"):
        if slab.get("ItemType") != "HyperSlab":
            continue
        kids = slab.findall("DataItem")
        if len(kids) != 2:
            problems.append("HyperSlab DataItem without its two DataItems")
            continue
        rows = np.array((kids[0].text or "").split(), dtype=int)
        shape = tuple(int(x) for x in kids[1].get("Dimensions", "").split())
        out = tuple(int(x) for x in slab.get("Dimensions", "").split())
        if rows.size != 3 * len(shape):
            problems.append(f"HyperSlab of {kids[1].text!r}: {rows.size} numbers for rank "
                            f"{len(shape)}")
            continue
        start, stride, count = rows.reshape(3, len(shape))
        last = start + stride * (count - 1)
        if tuple(count) != out or np.any(start < 0) or np.any(last >= np.array(shape)):
            problems.append(f"HyperSlab of {kids[1].text!r}: start {start}, stride {stride}, "
                            f"count {count} does not fit {shape} or Dimensions {out}")


def check_joint_grids(root, f, problems):
    """Each spatial collection holds a grid 'joints_<set>' per joint set of the file; in a
    staged run, a grid per element set and joint set active in the increment's phase and
    none of the others."""
    jall = list(f["mesh/joint_sets"]) if "mesh/joint_sets" in f else []
    eall = list(f["mesh/sets"]) if "mesh/sets" in f else []
    for grid in root.iter("Grid"):
        if grid.get("CollectionType") != "Spatial":
            continue
        names = {g.get("Name") for g in grid.findall("Grid")}
        esets, jsets = (None, None)
        if (grid.get("Name") or "").isdigit():
            esets, jsets = phase_sets(f, grid.get("Name"))
        wanted = {f"joints_{n}" for n in (jall if jsets is None else jsets)}
        for name in sorted(wanted - names):
            problems.append(f"XDMF increment {grid.get('Name')}: no grid {name}")
        if jsets is not None:
            for name in sorted({f"joints_{n}" for n in jall} - wanted & names):
                problems.append(f"XDMF increment {grid.get('Name')}: grid {name} of a joint "
                                f"set not active in its phase")
        if esets is not None:
            for name in sorted((set(eall) - esets) & names):
                problems.append(f"XDMF increment {grid.get('Name')}: grid {name} of an element "
                                f"set not active in its phase")
            for name in sorted(esets - names):
                problems.append(f"XDMF increment {grid.get('Name')}: no grid {name}")


def check_structure_grids(root, f, problems):
    """A grid 'plates_<set>' ('anchors_<set>') in an increment's collection exactly when the
    increment holds the set's fields (the set is active in its phase); every structure in the
    collection of the bare mesh."""
    kinds = {kind: list(f[f"mesh/{kind}"]) if f"mesh/{kind}" in f else []
             for kind in ("plates", "anchors")}
    for grid in root.iter("Grid"):
        if grid.get("CollectionType") != "Spatial":
            continue
        key = grid.get("Name") or ""
        names = {g.get("Name") for g in grid.findall("Grid")}
        for kind, sets in kinds.items():
            for n in sets:
                held = not key.isdigit() or f"increments/{key}/{kind}/{n}" in f
                if held and f"{kind}_{n}" not in names:
                    problems.append(f"XDMF increment {key}: no grid {kind}_{n}")
                if not held and f"{kind}_{n}" in names:
                    problems.append(f"XDMF increment {key}: grid {kind}_{n} of a set not "
                                    "active in its phase")


def check(h5_path, expect_status=None, xmf_path=None, xdmf=True):
    """Returns (problems, summary)."""
    problems = []
    try:
        f = h5py.File(h5_path, "r")
    except OSError as err:
        return [f"cannot open {h5_path} as HDF5: {err}"], ""
    with f:
        check_structure(f, problems)
        with_fields = check_history(f, problems)
        check_increments(f, with_fields, problems)
        check_finite(f, problems)
        check_checksums(f, problems)
        check_units(f, problems)
        check_status(f, expect_status, problems)
        nitems = 0
        if xdmf:
            if xmf_path is None:
                base, ext = os.path.splitext(h5_path)
                xmf_path = (base if ext in (".h5", ".hdf5") else h5_path) + ".xmf"
            nitems = check_xdmf(h5_path, xmf_path, f, problems)
        nrows = f["history/time"].shape[0] if "history/time" in f else 0
        njoint = len(f["mesh/joint_sets"]) if "mesh/joint_sets" in f else 0
        summary = (f"status {as_text(f.attrs.get('status', '?'))!r}, {nrows} history rows, "
                   f"{len(with_fields)} field increments, {njoint} joint sets, "
                   f"{nitems} XDMF data items")
    return problems, summary


def left_behind(target):
    """Lines describing what killed runs left beside `target`, and whether all is sound."""
    directory = os.path.dirname(target)
    name = os.path.basename(target)
    stem = name[:-3] if name.endswith(".h5") else name
    pattern = re.compile(rf"^\.({re.escape(name)}|{re.escape(stem)}\.xmf)\.(\d+)\.(\w+)$")
    runs = {}
    for entry in sorted(os.listdir(directory or ".")):
        m = pattern.match(entry)
        if m:
            runs.setdefault(int(m.group(2)), []).append(os.path.join(directory, entry))
    lines, sound = [], True
    for pid, files in sorted(runs.items()):
        h5 = os.path.join(directory, f".{name}.{pid}.tmp")
        xmf = os.path.join(directory, f".{stem}.xmf.{pid}.tmp")
        # a symbolic .tmp (file systems without hard links) needs the copy it names
        kept = (h5, xmf, os.path.join(directory, os.readlink(h5))) if os.path.islink(h5) \
            else (h5, xmf)
        others = [f for f in files if f not in kept]
        alive = os.path.exists(f"/proc/{pid}")
        note = " (a process with this id is running: the run may not be over)" if alive else ""
        if not os.path.exists(h5):
            lines.append(f"run {pid}{note}: stopped before its first increment was published, "
                         f"nothing to keep; delete {' '.join(files)}")
            continue
        problems, summary = check(h5, "running", xmf, os.path.exists(xmf))
        if problems:
            sound = False
            lines.append(f"run {pid}{note}: {h5} has {len(problems)} problem(s): "
                         + "; ".join(problems[:3]))
            continue
        sidecar = f" with its sidecar {xmf}" if os.path.exists(xmf) else ""
        lines.append(f"run {pid}{note}: keep {h5}{sidecar} ({summary}); rename it, or continue "
                     f"with pecplas DECK --restart {h5} -o NEW.h5"
                     + (f"; delete {' '.join(others)}" if others else ""))
    if not runs:
        lines.append(f"no temporary files of {target} in {directory or '.'}")
    return lines, sound


def main(argv=None):
    parser = argparse.ArgumentParser(description="Check a PECPLAS results file and its XDMF.")
    parser.add_argument("results", help="results file (.h5)")
    parser.add_argument("--left", action="store_true",
                        help="list what killed runs left beside RESULTS (the target) and "
                             "which file of each to keep")
    parser.add_argument("--expect-status", choices=STATUSES,
                        help="fail unless the status attribute has this value")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--xmf", help="XDMF file (default: the .h5 path with .xmf)")
    group.add_argument("--no-xdmf", action="store_true", help="do not check the XDMF file")
    args = parser.parse_args(argv)
    if args.left:
        lines, sound = left_behind(args.results)
        print("\n".join(lines))
        return 0 if sound else 1
    problems, summary = check(args.results, args.expect_status, args.xmf, not args.no_xdmf)
    if problems:
        print(f"FAIL {args.results}: {len(problems)} problem(s)")
        for p in problems:
            print(f"  - {p}")
        return 1
    print(f"OK {args.results}: {summary}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
