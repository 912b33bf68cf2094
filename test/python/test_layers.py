"""The source tree is layered: each folder of src/ uses only folders below it, so no two
folders reach each other through `use` statements.

The folder of a Fortran file is the folder holding it (src/model/refine/x.f90 belongs to
src/model/refine, not to src/model); folder A depends on folder B when a file of A uses a
module (or extends a module by a submodule) defined in B. A *folder circle* is a strongly
connected component of two or more folders of that graph. The test fails on any circle and
prints, for each, the `use` lines from one of its folders into another, as FILE:LINE, the
pairs with the fewest lines first (the likeliest to point the wrong way; at most 5 a pair).
Pure Python, no build needed: the modules are found by their `module NAME` lines.
"""
import collections
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SOURCES = (".f90", ".F90", ".f", ".F")

MODULE = re.compile(r"^\s*module\s+(?!procedure\b|subroutine\b|function\b)(\w+)\s*(?:!.*)?$",
                    re.I)
SUBMODULE = re.compile(r"^\s*submodule\s*\(\s*(\w+)", re.I)
USE = re.compile(r"^\s*use\s*(?:,\s*(intrinsic|non_intrinsic)\s*)?(?:::)?\s*(\w+)", re.I)


def use_lines(src):
    """({module: folder}, [(folder, module, 'path:line: text')]) of every source under `src`."""
    defined, uses = {}, []
    for path in sorted(p for p in Path(src).rglob("*") if p.suffix in SOURCES):
        folder = path.parent.relative_to(src.parent).as_posix()
        where = path.relative_to(src.parent).as_posix()
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if m := MODULE.match(line):
                defined[m.group(1).lower()] = folder
            elif m := SUBMODULE.match(line):
                uses.append((folder, m.group(1).lower(), f"{where}:{number}: {line.strip()}"))
            elif (m := USE.match(line)) and (m.group(1) or "").lower() != "intrinsic":
                uses.append((folder, m.group(2).lower(), f"{where}:{number}: {line.strip()}"))
    return defined, uses


def folder_graph(src):
    """{folder: {used folder: [use lines]}} between different folders of `src`."""
    defined, uses = use_lines(src)
    edges = collections.defaultdict(lambda: collections.defaultdict(list))
    for folder, module, text in uses:
        target = defined.get(module)  # None: an intrinsic or external module (hdf5, omp_lib)
        if target is not None and target != folder:
            edges[folder][target].append(text)
    return edges


def circles(edges):
    """Strongly connected components of two or more folders (Tarjan's algorithm)."""
    nodes = sorted(set(edges) | {b for bs in edges.values() for b in bs})
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):  # recursion depth <= number of folders (a few dozen)
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(edges.get(v, {})):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in nodes:
        if v not in index:
            visit(v)
    return found


#: use lines shown per folder pair (a pair of many lines is seldom the one to cut)
SHOWN = 5


def describe(edges, comps):
    """The use lines closing each circle, the folder pairs with the fewest lines first."""
    out = []
    for comp in comps:
        out.append(f"folder circle of {len(comp)}: {', '.join(comp)}")
        pairs = [(a, b, edges[a][b]) for a in comp for b in comp if b in edges.get(a, {})]
        for a, b, lines in sorted(pairs, key=lambda p: (len(p[2]), p[0], p[1])):
            out.append(f"  {a} -> {b} ({len(lines)} use lines):")
            out.extend(f"    {line}" for line in lines[:SHOWN])
            if len(lines) > SHOWN:
                out.append(f"    ... and {len(lines) - SHOWN} more")
    return "\n".join(out)


def test_no_folder_circle():
    edges = folder_graph(ROOT / "src")
    assert len(edges) > 10, "src/ not found or its folders use no one another"
    comps = circles(edges)
    assert not comps, "\n" + describe(edges, comps)


def _tree(tmp_path, files):
    for name, text in files.items():
        path = tmp_path / "src" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return tmp_path / "src"


def test_a_circle_is_found_and_its_use_lines_printed(tmp_path):
    """The check can fail: base <- model <- solve, and base/b.f90 using solve closes a circle
    of the three (a folder and its subfolder are two folders: model/refine using model and
    model using model/refine is a circle too); intrinsic and unknown modules are no edges."""
    src = _tree(tmp_path, {
        "base/b.f90": "module p_base_b\n   use, intrinsic :: iso_fortran_env\n"
                      "   use hdf5, only: h5open_f\nend module p_base_b\n",
        "model/m.f90": "module p_model_m\n   use p_base_b, only: x\nend module p_model_m\n",
        "solve/s.f90": "module p_solve_s\n   use p_model_m\nend module p_solve_s\n",
        "model/refine/r.f90": "module p_model_refine_r\n   use p_model_m\nend module\n"})
    edges = folder_graph(src)
    assert circles(edges) == []
    (src / "base/b.f90").write_text("module p_base_b\n   use :: p_solve_s, only: y\n"
                                    "end module p_base_b\n")
    (src / "model/m2.f90").write_text("module p_model_m2\n   use p_model_refine_r\n"
                                      "end module p_model_m2\n")
    edges = folder_graph(src)
    comps = circles(edges)
    assert comps == [["src/base", "src/model", "src/model/refine", "src/solve"]], comps
    text = describe(edges, comps)
    assert "src/base/b.f90:2: use :: p_solve_s, only: y" in text, text
    assert "src/model/m2.f90:2: use p_model_refine_r" in text, text
