#!/usr/bin/env python3
"""Cross-checks doc/deck.md against what the deck reader accepts.

The reader is asked, not parsed: for every keyword a one-line deck with an unknown parameter
makes `pecplas` answer with the parameters that keyword knows ("known parameters: ..."), an
unknown keyword with the keyword list, an unknown material or law type with the type list, an
unknown data key of each material and interface-law type with that type's keys. Each answer
is an input error at the first line (exit 2, no results file), a few milliseconds per probe.

Checked:
- every keyword the reader knows is a row of the keyword table of doc/deck.md, and every row
  is a keyword the reader knows;
- every parameter a keyword accepts is written (in backticks) in its section of doc/deck.md;
- every parameter written in a keyword's signature (a backticked `*KEYWORD, A=... [, B=...]`)
  or on a keyword line of a deck example (a fenced code block) anywhere in README.md and
  doc/*.md is accepted by that keyword;
- every data key of every material type is in the section *MATERIAL* (the water keys in
  *GROUNDWATER*), of every interface-law type in *INTERFACE_LAW*; every type name the reader
  lists (materials, laws, elements, loads, joints, anchors) is in its section.

    python3 -m pecplas_py.docs.deck_reference [--exe PECPLAS]   # exit 1 and the list when not
"""
import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from pecplas_py import ROOT

DECK_MD = ROOT / "doc" / "deck.md"
TOKEN = re.compile(r"\b[A-Z][A-Z0-9_]*\b")
# keywords of the point driver's decks (pecplas-path, doc/path.md), not of pecplas's reader
OTHER_PROGRAMS = ("*PATH",)


def _answer(exe, text, workdir):
    """First line of pecplas's answer to the deck `text` (an input error is expected)."""
    deck = Path(workdir) / "probe.inp"
    deck.write_text(text)
    r = subprocess.run([str(exe), str(deck), "--quiet", "-o", str(Path(workdir) / "p.h5")],
                       capture_output=True, text=True, timeout=30)
    if r.returncode != 2:
        raise RuntimeError(f"probe {text!r}: exit {r.returncode}, expected 2\n{r.stdout}"
                           f"{r.stderr}")
    return (r.stderr or r.stdout).strip().splitlines()[0]


def _after(line, marker):
    """The blank-separated words after `marker` in `line`."""
    if marker not in line:
        raise RuntimeError(f"no '{marker}' in the reader's answer: {line}")
    words = line.split(marker, 1)[1].split("(", 1)[0].split(";", 1)[0]
    return [w for w in words.split() if w != "(none)"]


def reader_vocabulary(exe):
    """What the reader accepts: {'keywords': [...], 'params': {kw: [...]},
    'material_keys': {type: [...]}, 'water_keys': [...], 'law_keys': {type: [...]},
    'types': {kw: [...]}}. The water data keys of *MATERIAL are read by the water, not by the
    soil model: its answer lists them after the soil model's ("; water parameters: ...")."""
    with tempfile.TemporaryDirectory() as tmp:
        ask = lambda text: _answer(exe, text, tmp)  # noqa: E731
        keywords = ["*" + k for k in " ".join(_after(ask("*ZZQ\n"), "known keywords:"))
                    .replace("*END STEP", "*END_STEP").lstrip("*").split(" *")]
        keywords = [k.replace("*END_STEP", "*END STEP") for k in keywords]
        params = {kw: _after(ask(f"{kw}, ZZQ=1\n"), "known parameters:") for kw in keywords}
        types = {
            "*MATERIAL": _after(ask("*MATERIAL, NAME=m, TYPE=ZZQ\n"), "known types:"),
            "*INTERFACE_LAW": _after(ask("*INTERFACE_LAW, NAME=m, TYPE=ZZQ\n"),
                                     "known types:"),
            "*ELEMENTS": _after(ask("*ELEMENTS, TYPE=ZZQ, SET=a\n"), "known types:"),
            "*LOAD": _after(ask("*LOAD, NAME=a, TYPE=ZZQ\n"), "known types:"),
            "*JOINTS": _after(ask("*JOINTS, TYPE=ZZQ, SET=a, LAW=b\n"), "known types:"),
            "*ANCHOR": _after(ask("*ANCHOR, NAME=a, TYPE=ZZQ, EA=1\n1\n"), "known types:"),
            "*INITIAL_STRESS": _after(ask("*INITIAL_STRESS, TYPE=ZZQ\n"), "known types:"),
            "*ANALYSIS": _after(ask("*ANALYSIS, TYPE=ZZQ\n"), "known types:"),
        }
        material_keys = {t: _after(ask(f"*MATERIAL, NAME=m, TYPE={t}\nZZQ=1\n"),
                                   "known parameters:") for t in types["*MATERIAL"]}
        water_keys = _after(ask("*MATERIAL, NAME=m\nZZQ=1\n"), "water parameters:")
        law_keys = {t: _after(ask(f"*INTERFACE_LAW, NAME=m, TYPE={t}\nZZQ=1\n"),
                              "known parameters:") for t in types["*INTERFACE_LAW"]}
    return {"keywords": keywords, "params": params, "types": types,
            "material_keys": material_keys, "water_keys": water_keys, "law_keys": law_keys}


def _sections(text):
    """{anchor: section text} of the '### ' sections of a page (GitHub anchors)."""
    out, name, lines = {}, None, []
    for line in text.splitlines():
        if line.startswith("#"):
            if name:
                out[name] = "\n".join(lines)
            name = line.lstrip("#").strip().lower().replace(" ", "-") \
                if line.startswith("### ") else None
            lines = []
        elif name:
            lines.append(line)
    if name:
        out[name] = "\n".join(lines)
    return out


def _table_keywords(text):
    """{keyword: anchor} from the keyword table of doc/deck.md."""
    table = {}
    for row in text.splitlines():
        if not row.startswith("| ["):
            continue
        first = row.split("|")[1]
        for kw, anchor in re.findall(r"\[`(\*[A-Z_ ]+)`\]\(#([a-z_-]+)\)", first):
            table[kw] = anchor
        for kw in re.findall(r"`(\*[A-Z_ ]+)`(?!\])", first):  # `*END STEP` without a link
            table.setdefault(kw, None)
    return table


def _backticked(text):
    return set(TOKEN.findall(" ".join(re.findall(r"`([^`]*)`", text))))


def _signatures(text):
    """(keyword, [parameters]) of every backticked `*KEYWORD, ...` span of a page."""
    for span in re.findall(r"`(\*[A-Z_]+(?: STEP)?(?:,| \[)[^`]*)`", text, flags=re.S):
        kw = re.match(r"\*[A-Z_]+(?: STEP)?", span).group(0)
        names = re.findall(r"\b([A-Z][A-Z0-9_]*)=", span)
        names += re.findall(r"\[, ([A-Z][A-Z0-9_]*)\]", span)
        yield kw, sorted(set(names))


def _code_keyword_lines(text):
    """(keyword, [parameters]) of every keyword line `*KEYWORD, A=.., B` inside the fenced code
    blocks of a page (the deck examples)."""
    fenced = False
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        m = re.match(r"\s*(\*[A-Za-z_]+(?: [Ss][Tt][Ee][Pp])?)\s*(,.*)?$", line) if fenced else None
        if m and not line.lstrip().startswith("**"):
            fields = (m.group(2) or "").split("!")[0].split(",")[1:]
            names = [f.split("=")[0].strip().upper() for f in fields if f.strip()]
            yield m.group(1).upper(), sorted({n for n in names if TOKEN.fullmatch(n)})


def check(vocab, deck_md=DECK_MD, pages=None):
    """List of problems (empty when the docs and the reader agree)."""
    text = deck_md.read_text()
    sections = _sections(text)
    table = _table_keywords(text)
    problems = []
    for kw in vocab["keywords"]:
        if kw not in table:
            problems.append(f"{deck_md.name}: keyword {kw} is accepted but not in the keyword "
                            "table")
    for kw in table:
        if kw not in vocab["keywords"]:
            problems.append(f"{deck_md.name}: keyword {kw} of the table is unknown to the "
                            "reader")
    anchor_of = dict(table)
    anchor_of["*END STEP"] = anchor_of.get("*END STEP") or "step"
    for kw, params in vocab["params"].items():
        section = sections.get(anchor_of.get(kw) or "", "")
        words = _backticked(section)
        for p in params:
            if p not in words:
                problems.append(f"{deck_md.name}: {kw} accepts {p}, not written in its "
                                f"section #{anchor_of.get(kw)}")
    pages = pages or [ROOT / "README.md", *sorted((ROOT / "doc").glob("*.md"))]
    for page in pages:
        text = page.read_text()
        for kw, names in [*_signatures(text), *_code_keyword_lines(text)]:
            if kw not in vocab["params"]:
                if kw not in vocab["keywords"] and kw not in OTHER_PROGRAMS:
                    problems.append(f"{page.name}: `{kw}` is no keyword of the reader")
                continue
            for p in names:
                if p not in vocab["params"][kw]:
                    problems.append(f"{page.name}: `{kw}, {p}=` is written but {kw} does not "
                                    f"accept {p}")
    sec = lambda name: _backticked(sections.get(name, ""))  # noqa: E731
    for t, keys in vocab["material_keys"].items():
        for k in keys:
            if k not in sec("material"):
                problems.append(f"{deck_md.name}: *MATERIAL TYPE={t} key {k} not in #material")
    for k in vocab["water_keys"]:
        if k not in sec("groundwater"):
            problems.append(f"{deck_md.name}: *MATERIAL water key {k} not in #groundwater")
    law_words = sec("interface_law")
    for t, keys in vocab["law_keys"].items():
        for k in keys:
            if k not in law_words:
                problems.append(f"{deck_md.name}: *INTERFACE_LAW TYPE={t} key {k} not in "
                                "#interface_law")
    for kw, names in vocab["types"].items():
        anchors = {"*LOAD": ["load", "plate"]}.get(kw, [anchor_of.get(kw)])
        words = set().union(*(sec(a) for a in anchors))
        for n in names:
            if n not in words:
                problems.append(f"{deck_md.name}: {kw} TYPE={n} not in #{anchors[0]}")
    return problems


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--exe", help="the pecplas executable (default: the project's, "
                    "pecplas_py.exe)")
    args = ap.parse_args(argv)
    if args.exe:
        exe = args.exe
    else:
        from pecplas_py.exe import exe_path
        exe = exe_path("pecplas")
    vocab = reader_vocabulary(exe)
    problems = check(vocab)
    n = sum(len(v) for v in vocab["params"].values())
    print(f"{len(vocab['keywords'])} keywords, {n} keyword parameters, "
          f"{sum(len(v) for v in vocab['material_keys'].values())} material keys, "
          f"{len(vocab['water_keys'])} water keys, "
          f"{sum(len(v) for v in vocab['law_keys'].values())} law keys checked")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
