"""Writing keyword decks (doc/deck.md): the one writer of the deck generators and benchmarks.

    from pecplas_py.deck import Deck
    d = Deck()
    d.comment("S1 shear box")
    d.title("S1 shear box").units("kN, m, kPa").analysis("PLANE_STRAIN")
    d.nodes({1: (0.0, -0.5), 2: (1.0, -0.5)})               # or [(id, x, y), ...]
    d.elements("Q8", "lower", [(1, 1, 2, 3, 4, 5, 6, 7, 8)])
    d.material("soft", E=1e5, NU=0.3).section("lower", "soft")
    d.interface_law("iface", "MOHR_COULOMB", KN=5e6, KT=1000, C=1, PHI=0, PSI=0)
    d.joints("GOODMAN6", "joint", "iface", [(3, 4, 3, 10, 9, 7, 13)])
    d.nset("bottom", [1, 5, 2]).boundary("bottom, XY")
    d.load("shear", "FORCE", (9, 1, 0.1667)).step("shear", 30, "shear, 1.5")
    d.solver(METHOD="NEWTON").output(EVERY=1)
    d.write("s1.inp")                                          # or d.text()

Every method appends lines in the order called and returns the deck, so calls chain. Numbers
are written by `num` (integers as they are, floats with the deck's format, `g` unless given,
e.g. Deck(fmt=".12g")); text is written as given, so a caller that wants an exact spelling
("E = 1e5") passes it as text. `keyword("NAME", KEY=value, ...)` and `data(...)` write any
keyword or data line; `line(...)` writes lines as they are.
"""
from pathlib import Path


def num(value, fmt="g"):
    """A value as the deck writes it: text as given, integers in full, floats by `fmt`."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "YES" if value else "NO"
    if isinstance(value, int):
        return str(value)
    return format(value, fmt)


class Deck:
    """A keyword deck under construction (see the module docstring)."""

    def __init__(self, fmt="g"):
        self.lines = []
        self.fmt = fmt

    # ---- generic lines
    def line(self, *lines):
        """Lines as they are."""
        self.lines.extend(lines)
        return self

    def comment(self, *texts):
        """`** text` per text (`**` alone for an empty one)."""
        self.lines.extend(f"** {t}" if t else "**" for t in texts)
        return self

    def num(self, value, fmt=None):
        return num(value, fmt or self.fmt)

    def keyword(self, name, **params):
        """`*NAME, KEY=value, ...` (parameters in the order given; None leaves one out)."""
        parts = [f"*{name}"] + [f"{k}={self.num(v)}" for k, v in params.items() if v is not None]
        self.lines.append(", ".join(parts))
        return self

    def data(self, *values, fmt=None):
        """One data line: the values joined by `, `."""
        self.lines.append(", ".join(self.num(v, fmt) for v in values))
        return self

    def rows(self, rows, fmt=None, per_line=None):
        """Data lines: one per row (a sequence of values), or, for a flat list of values,
        `per_line` values per line (all on one line when per_line is None)."""
        rows = list(rows)
        if rows and not isinstance(rows[0], (tuple, list)):
            step = per_line or max(len(rows), 1)
            rows = [rows[k:k + step] for k in range(0, len(rows), step)]
        for r in rows:
            self.data(*r, fmt=fmt)
        return self

    def props(self, *text, **values):
        """A property line `KEY = value, ...` (materials, laws), after any text given."""
        self.lines.append(", ".join(list(text) + [f"{k} = {self.num(v)}"
                                                  for k, v in values.items()]))
        return self

    # ---- the keywords of doc/deck.md
    def title(self, text):
        return self.keyword("TITLE").line(text)

    def units(self, text="kN, m, kPa"):
        return self.keyword("UNITS").line(text)

    def analysis(self, type, **params):
        return self.keyword("ANALYSIS", TYPE=type, **params)

    def nodes(self, nodes, fmt=None):
        """*NODES from {id: (x, y)}, [(id, x, y), ...] or [(id, (x, y)), ...]."""
        self.keyword("NODES")
        items = nodes.items() if isinstance(nodes, dict) else (
            (n[0], n[1] if len(n) == 2 else n[1:]) for n in nodes)
        for nid, (x, y) in items:
            self.data(nid, x, y, fmt=fmt)
        return self

    def elements(self, type, set, elements, **params):
        """*ELEMENTS, TYPE=, SET= with rows (id, n1, n2, ...)."""
        return self.keyword("ELEMENTS", TYPE=type, SET=set, **params).rows(elements)

    def material(self, name, *lines, type=None, **props):
        """*MATERIAL, NAME= [, TYPE=] then the given lines, or one line of `props`."""
        self.keyword("MATERIAL", NAME=name, TYPE=type).line(*lines)
        return self.props(**props) if props else self

    def section(self, set, material):
        return self.keyword("SECTION", SET=set, MATERIAL=material)

    def interface_law(self, name, type, *lines, **props):
        """*INTERFACE_LAW, NAME=, TYPE= then the given lines, or one line of `props`."""
        self.keyword("INTERFACE_LAW", NAME=name, TYPE=type).line(*lines)
        return self.props(**props) if props else self

    def joints(self, type, set, law, joints, **params):
        """*JOINTS, TYPE=, SET=, LAW= [, INTEGRATION=, ...] with rows (id, n1, n2, ...)."""
        return self.keyword("JOINTS", TYPE=type, SET=set, LAW=law, **params).rows(joints)

    def nset(self, name, ids, per_line=None):
        """*NSET, NAME= with the node ids (on one line, or `per_line` per line)."""
        return self.keyword("NSET", NAME=name).rows(ids, per_line=per_line)

    def edges(self, name, edges):
        """*EDGES, NAME= with rows (end, end[, mid])."""
        return self.keyword("EDGES", NAME=name).rows(edges)

    def boundary(self, *rows):
        """*BOUNDARY with rows: text ("bottom, XY") or tuples ("top", "Y")."""
        self.keyword("BOUNDARY")
        for r in rows:
            self.line(r) if isinstance(r, str) else self.data(*r)
        return self

    def initial_stress(self, type, *rows):
        self.keyword("INITIAL_STRESS", TYPE=type)
        for r in rows:
            self.line(r) if isinstance(r, str) else self.data(*r)
        return self

    def load(self, name, type, *rows):
        """*LOAD, NAME=, TYPE= with rows: text or tuples."""
        self.keyword("LOAD", NAME=name, TYPE=type)
        for r in rows:
            self.line(r) if isinstance(r, str) else self.data(*r)
        return self

    def step(self, name, increments, *rows, end=False, **params):
        """*STEP, NAME=, INCREMENTS= [, ...] with its pattern rows ("head, 1" or ("head", 1));
        `end` closes it with *END STEP."""
        self.keyword("STEP", NAME=name, INCREMENTS=increments, **params)
        for r in rows:
            self.line(r) if isinstance(r, str) else self.data(*r)
        return self.keyword("END STEP") if end else self

    def solver(self, **params):
        return self.keyword("SOLVER", **params)

    def output(self, **params):
        return self.keyword("OUTPUT", **params)

    # ---- the result
    def text(self):
        """The deck: its lines, each ended by a newline."""
        return "\n".join(self.lines) + "\n"

    def write(self, path):
        """Writes the deck to `path`; returns the path."""
        path = Path(path)
        path.write_text(self.text())
        return path

    def __str__(self):
        return self.text()
