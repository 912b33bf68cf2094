"""Reading a results file of pecplas (layout: doc/results.md).

    from pecplas_py.results import Results
    with Results("output/default.h5") as r:
        r.status, r.complete, r.attr("title")
        for key in r.keys:                           # "000001", ... (written increments)
            u = r.field(key, "displacement")         # (nnode, 2)
            s = r.field(key, "joints/shaft/stress")  # (nel, npoint, 2)
        r.history("iterations"), r.pattern_factors(), r.field_rows()
        r.limit()                                    # None, or {"factors", "global_increment"}
        r.phases()          # staged runs: [{"index", "name", "changes", "active_element_sets", ...}]
        r.phase_of(key)     # the phase (step) of a written increment

Text attributes come back as `str` (h5py gives bytes for some of them); arrays as NumPy
arrays. `r.file` is the open h5py.File for what this module does not cover. Scripts that check
the file's structure itself (checks/check_results.py) walk it with h5py directly.
"""
import h5py
import numpy as np


def flat_items(group, skip=()):
    """Every dataset value and attribute under the h5py `group`, flattened: path -> value,
    attributes as path@name (the group's own as @name), those named in `skip` left out."""
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out[name] = obj[()]
        for a, v in obj.attrs.items():
            if a not in skip:
                out[name + "@" + a] = v
    group.visititems(visit)
    for a, v in group.attrs.items():
        if a not in skip:
            out["@" + a] = v
    return out


def text(value):
    """An attribute as str when it is text (bytes, NumPy bytes or str), a list of str when it
    is a list of texts (e.g. `warnings`, `patterns`), else unchanged."""
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode()
    if isinstance(value, np.str_):
        return str(value)
    if isinstance(value, np.ndarray) and value.dtype.kind in "OSU":
        return [text(v) for v in value.tolist()]
    return value


class Results:
    """An open results file (read only); use it in a `with` block or call close()."""

    def __init__(self, path):
        self.path = path
        self.file = h5py.File(path, "r")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        self.file.close()

    # ---- root attributes
    def attr(self, name, default=None):
        """Root attribute `name` (text decoded), `default` when absent."""
        return text(self.file.attrs[name]) if name in self.file.attrs else default

    @property
    def attrs(self):
        """Every root attribute, text decoded."""
        return {k: text(v) for k, v in self.file.attrs.items()}

    @property
    def status(self):
        """`completed`, `limit load`, `diverged`, `failed`, `interrupted` or `running`."""
        return self.attr("status")

    @property
    def complete(self):
        return bool(self.attr("complete", 0))

    @property
    def deck_text(self):
        return self.attr("deck_text", "")

    # ---- mesh
    @property
    def coordinates(self):
        return self.file["mesh/coordinates"][()]

    @property
    def node_ids(self):
        return self.file["mesh/node_ids"][()]

    def node_index(self, node_id):
        """0-based row of the node with user id `node_id`."""
        return int(np.nonzero(self.node_ids == node_id)[0][0])

    def node_set(self, name):
        """0-based node numbers of node set `name`."""
        return self.file[f"mesh/node_sets/{name}/nodes"][()]

    def element_set(self, name):
        """The group /mesh/sets/<name> (connectivity, element_ids, gauss_coordinates)."""
        return self.file[f"mesh/sets/{name}"]

    def joint_set(self, name):
        """The group /mesh/joint_sets/<name> (point_coordinates, tributary, ...)."""
        return self.file[f"mesh/joint_sets/{name}"]

    # ---- history: one row per converged increment
    def history(self, name=None):
        """The history column `name` (step, increment, iterations, ...), or all as a dict."""
        if name is None:
            return {k: v[()] for k, v in self.file["history"].items()}
        return self.file[f"history/{name}"][()]

    def pattern_factors(self, rows=None):
        """(nrow, npattern) load factors; only the rows `rows` when given."""
        pf = self.file["history/pattern_factors"][()]
        return pf if rows is None else pf[rows]

    @property
    def patterns(self):
        """The load pattern names (columns of pattern_factors)."""
        return [text(n) for n in self.file["history"].attrs.get("patterns", [])]

    def field_rows(self):
        """History rows whose fields were written (one per increment key, in order)."""
        return np.nonzero(self.file["history/fields"][()])[0]

    # ---- increments with fields
    @property
    def keys(self):
        """Keys of the written increments, in order."""
        return sorted(self.file["increments"].keys()) if "increments" in self.file else []

    def increment(self, key):
        """The group /increments/<key> (attributes step, increment, time, ...)."""
        return self.file[f"increments/{key}"]

    def step_of(self, key):
        return int(self.increment(key).attrs["step"])

    def keys_of(self, step):
        """Keys of the written increments of step `step`, in order."""
        return [k for k in self.keys if self.step_of(k) == step]

    def last_key(self, step=None):
        """The last written increment, of step `step` when given."""
        keys = self.keys if step is None else self.keys_of(step)
        return keys[-1]

    def field(self, key, name):
        """Dataset `name` of increment `key`: displacement, reaction, sets/<set>/stress,
        joints/<set>/stress, ..."""
        return self.file[f"increments/{key}/{name}"][()]

    def fields(self, name):
        """Dataset `name` of every written increment, stacked (nkeys, ...)."""
        return np.array([self.field(k, name) for k in self.keys])

    # ---- phases of a staged run (the step is the phase)
    def phases(self):
        """The phases listed in /phases, in order: dicts with index, name, changes (list of
        str), first_global_increment (-1: none written), first_history_row (1-based),
        element_sets / joint_sets (names), active_element_sets / active_joint_sets (lists of
        the names active in the phase). A run without phases: one entry per step of the
        history, every set active and no change listed."""
        esets = list(self.file["mesh/sets"].keys()) if "mesh/sets" in self.file else []
        jsets = list(self.file["mesh/joint_sets"].keys()) if "mesh/joint_sets" in self.file \
            else []
        if "phases" not in self.file:
            steps = self.history("step") if "history/step" in self.file else []
            glob = self.history("global_increment") if len(steps) else []
            out = []
            for index in sorted(set(int(s) for s in steps)):
                row = int(np.nonzero(steps == index)[0][0])
                out.append({"index": index, "name": "", "changes": [],
                            "first_global_increment": int(glob[row]),
                            "first_history_row": row + 1, "element_sets": esets,
                            "joint_sets": jsets, "active_element_sets": list(esets),
                            "active_joint_sets": list(jsets)})
            return out
        out = []
        for key in sorted(self.file["phases"].keys(), key=int):
            g = self.file["phases"][key]
            names_e = text(g.attrs.get("element_sets", np.array([], dtype=object)))
            names_j = text(g.attrs.get("joint_sets", np.array([], dtype=object)))
            mask_e = g["active_element_sets"][()] if "active_element_sets" in g else []
            mask_j = g["active_joint_sets"][()] if "active_joint_sets" in g else []
            out.append({"index": int(g.attrs["index"]), "name": text(g.attrs["name"]),
                        "changes": list(text(g.attrs.get("changes",
                                                         np.array([], dtype=object)))),
                        "first_global_increment": int(g.attrs["first_global_increment"]),
                        "first_history_row": int(g.attrs["first_history_row"]),
                        "element_sets": list(names_e), "joint_sets": list(names_j),
                        "active_element_sets": [n for n, m in zip(names_e, mask_e) if m],
                        "active_joint_sets": [n for n, m in zip(names_j, mask_j) if m]})
        return out

    def phase(self, index):
        """The phase (dict of phases()) of step `index`."""
        for p in self.phases():
            if p["index"] == index:
                return p
        raise KeyError(f"no phase {index} in {self.path}")

    def phase_of(self, key):
        """The phase index of written increment `key`: the phase of /phases whose first
        increment is the latest not after it (its step, as the driver writes them), else
        the increment's step."""
        if "phases" in self.file:
            g = int(self.increment(key).attrs["global_increment"])
            best = None
            for p in self.file["phases"].values():
                first = int(p.attrs["first_global_increment"])
                if 1 <= first <= g and (best is None or first > best[0]):
                    best = (first, int(p.attrs["index"]))
            if best is not None:
                return best[1]
        return self.step_of(key)

    def active_sets(self, key):
        """(element sets, joint sets) that hold fields in increment `key`: those active in
        its phase."""
        g = self.increment(key)
        return (sorted(g["sets"].keys()) if "sets" in g else [],
                sorted(g["joints"].keys()) if "joints" in g else [])

    def phase_ends(self):
        """{phase index: key of the last written increment of that phase}."""
        ends = {}
        for k in self.keys:
            ends[self.phase_of(k)] = k
        return ends

    # ---- limit load
    def limit(self):
        """None, or the limit load found: {'factors': pattern factors, 'global_increment'}."""
        if "limit" not in self.file:
            return None
        g = self.file["limit"]
        return {"factors": g["pattern_factors"][()],
                "global_increment": int(g.attrs["global_increment"])}
