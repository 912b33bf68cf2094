"""Deck variants for the work-precision study (bench/work_precision.py): small, checked
edits of the decks that decks/make_s2_decks.py and decks/make_s6_decks.py generate, so that the
study always runs the generators' current scenes (their fixes included) and changes only what
it varies: solver method, increments, the load steps, output frequency, and Q4 -> Q8 with
GOODMAN6 / 6-node thin-layer joints.

Every edit raises ValueError when the keyword it edits is missing (a generator changed its
deck layout), rather than silently running the unedited deck.
"""
import re


def _sub(pattern, repl, text, what, count=0):
    new, n = re.subn(pattern, repl, text, count=count, flags=re.MULTILINE | re.IGNORECASE)
    if n == 0:
        raise ValueError(f"deck edit '{what}': no match for {pattern!r}")
    return new


def set_solver(text, method, max_iterations=None):
    """*SOLVER METHOD= (and MAX_ITERATIONS= when given)."""
    text = _sub(r"^(\*SOLVER\b.*?METHOD=)\w+", rf"\g<1>{method}", text, "solver method")
    if max_iterations is not None:
        text = _sub(r"^(\*SOLVER\b.*?MAX_ITERATIONS=)\d+", rf"\g<1>{max_iterations}", text,
                    "max iterations")
    return text


def _blocks(text):
    """Lines grouped as [keyword line, data lines...] (comments and the preamble kept as
    their own groups)."""
    groups = []
    for line in text.splitlines():
        if line.startswith("*") and not line.startswith("**") or not groups:
            groups.append([line])
        else:
            groups[-1].append(line)
    return groups


def _join(groups):
    return "\n".join(line for g in groups for line in g) + "\n"


def _set_targets(group, factor):
    """A *STEP group with every pattern's target factor (last number of each data line) set."""
    return [group[0]] + [re.sub(r",\s*[-+0-9.eE]+\s*$", f", {factor:.12g}", d)
                         if d.strip() and not d.startswith("**") else d for d in group[1:]]


def first_step_only(text, factor=None, increments=None):
    """Keep only the first *STEP (the loading); optionally set its target pattern factor
    (every pattern on its data lines) and its INCREMENTS."""
    groups, out, nstep = _blocks(text), [], 0
    for g in groups:
        if re.match(r"\*STEP\b", g[0], re.IGNORECASE):
            nstep += 1
            if nstep > 1:
                continue
            if increments is not None:
                g[0] = _sub(r"INCREMENTS=\d+", f"INCREMENTS={increments}", g[0], "increments")
            if factor is not None:
                g = _set_targets(g, factor)
        out.append(g)
    if nstep == 0:
        raise ValueError("deck edit 'first step': no *STEP")
    return _join(out)


def scale_steps(text, inc_factor, last_target=None, last_increments=None):
    """Every *STEP's INCREMENTS times inc_factor (at least 1); optionally the last step's
    target factor (every pattern on its data lines) and its increments before scaling.
    Used for the imposed-uplift MODJOIN decks of S6, whose load steps are not a force."""
    groups, steps = _blocks(text), []
    for i, g in enumerate(groups):
        if re.match(r"\*STEP\b", g[0], re.IGNORECASE):
            steps.append(i)
    if not steps:
        raise ValueError("deck edit 'scale steps': no *STEP")
    for i in steps:
        g = groups[i]
        m = re.search(r"INCREMENTS=(\d+)", g[0], re.IGNORECASE)
        if m is None:
            raise ValueError("deck edit 'scale steps': a *STEP without INCREMENTS=")
        n = int(m.group(1))
        if i == steps[-1] and last_increments is not None:
            n = last_increments
        g[0] = g[0][:m.start(1)] + str(max(1, round(n * inc_factor))) + g[0][m.end(1):]
        if i == steps[-1] and last_target is not None:
            groups[i] = _set_targets(g, last_target)
    return _join(groups)


def set_output_every(text, every):
    """Fields only every `every` increments (and at each step's end)."""
    return _sub(r"^(\*OUTPUT\b.*?EVERY=)\d+", rf"\g<1>{every}", text, "output every")


def to_q8(text):
    """Q4 -> Q8 (straight mid-side nodes), GOODMAN4 -> GOODMAN6 and 4-node THIN_LAYER -> 6-node
    joints, 2-node -> 3-node *EDGES, and every node set gains the mid-side nodes of the edges
    whose two ends it holds (right for straight boundary lines, which is what the scenes'
    sets are). Spring joints (node doublets) are not converted: a spring deck stays Q4."""
    groups = _blocks(text)
    xy, maxid = {}, 0
    for g in groups:
        if re.match(r"\*NODES\b", g[0], re.IGNORECASE):
            for d in g[1:]:
                if d.strip() and not d.startswith("**"):
                    k, x, y = d.split(",")[:3]
                    xy[int(k)] = (float(x), float(y))
    maxid = max(xy)
    mids, new_nodes = {}, []

    def mid(a, b):
        nonlocal maxid
        key = (min(a, b), max(a, b))
        if key not in mids:
            maxid += 1
            mids[key] = maxid
            (xa, ya), (xb, yb) = xy[a], xy[b]
            new_nodes.append(f"{maxid}, {0.5 * (xa + xb):.12g}, {0.5 * (ya + yb):.12g}")
        return mids[key]

    def ints(d):
        return [int(v) for v in d.split(",")]

    for g in groups:
        head = g[0].upper()
        if head.startswith("*ELEMENTS") and "TYPE=Q4" in head:
            g[0] = re.sub("TYPE=Q4", "TYPE=Q8", g[0], flags=re.IGNORECASE)
            for i, d in enumerate(g[1:], 1):
                if d.strip() and not d.startswith("**"):
                    e, *c = ints(d)
                    m = [mid(c[k], c[(k + 1) % 4]) for k in range(4)]
                    g[i] = ", ".join(map(str, [e, *c, *m]))
    for g in groups:
        head = g[0].upper()
        if head.startswith("*JOINTS") and ("TYPE=GOODMAN4" in head or "TYPE=THIN_LAYER" in head):
            g[0] = re.sub("TYPE=GOODMAN4", "TYPE=GOODMAN6", g[0], flags=re.IGNORECASE)
            for i, d in enumerate(g[1:], 1):
                if d.strip() and not d.startswith("**"):
                    j, a1, a2, b2, b1 = ints(d)
                    g[i] = ", ".join(map(str, [j, a1, a2, b2, b1, mid(a1, a2), mid(b2, b1)]))
        elif head.startswith("*EDGES"):
            for i, d in enumerate(g[1:], 1):
                if d.strip() and not d.startswith("**"):
                    a, b = ints(d)
                    g[i] = f"{a}, {b}, {mid(a, b)}"
    for g in groups:
        if g[0].upper().startswith("*NSET"):
            data = [d for d in g[1:] if d.strip() and not d.startswith("**")]
            members = {int(v) for d in data for v in d.split(",") if v.strip()}
            extra = [m for (a, b), m in mids.items() if a in members and b in members]
            if extra:
                g.append(", ".join(map(str, extra)))
    for g in groups:
        if re.match(r"\*NODES\b", g[0], re.IGNORECASE):
            g.extend(new_nodes)
            break
    return _join(groups)


def count_dofs(text):
    """2 x the number of nodes of a deck (plane strain / axisymmetric)."""
    n, on = 0, False
    for line in text.splitlines():
        if line.startswith("*") and not line.startswith("**"):
            on = bool(re.match(r"\*NODES\b", line, re.IGNORECASE))
        elif on and line.strip() and not line.startswith("**"):
            n += 1
    return 2 * n
