#!/usr/bin/env python3
"""Collects the benchmark fragments doc/bench/*.md (written by tools/pecplas_py/bench/*.py through
bench_common.write_fragment) into doc/bench/README.md, in a fixed order (stability, scaling,
scaling_elastic, amg, work_precision, advice, peer, peer_footing, peer_opensees, then the others
alphabetically), under a header with the commit, machine and date (bench_common.provenance)
and, if given, the wall time of the whole suite.

    python3 -m pecplas_py.bench.summary [--wall SECONDS] [--dir doc/bench] [--keep-header]
"""
import argparse
from pathlib import Path

from pecplas_py.bench.common import BENCH_DIR, provenance

ORDER = ("stability", "scaling", "scaling_elastic", "amg", "work_precision", "advice", "peer",
         "peer_footing", "peer_opensees")
OUTPUT = "README.md"


def ordered_fragments(directory):
    """Fragment paths: the known sections in ORDER, then any others by name."""
    found = {p.stem: p for p in Path(directory).glob("*.md") if p.name != OUTPUT}
    first = [found[n] for n in ORDER if n in found]
    rest = [found[n] for n in sorted(found) if n not in ORDER]
    return first + rest


def header(prov, wall=None):
    lines = ["# Benchmarks", "",
             "Written by `tools/pecplas_py/bench/summary.py` from the fragments of the "
             "`tools/pecplas_py/bench/*.py` "
             "scripts; every number below was measured in the run that wrote it (CSV files "
             "next to this one carry commit and machine on every row).", "",
             f"- commit: `{prov['commit']}`", f"- machine: {prov['machine']}",
             f"- date: {prov['date']}"]
    if wall is not None:
        lines.append(f"- wall time of the benchmark suite: {wall:.0f} s ({wall / 60:.1f} min)")
    return "\n".join(lines) + "\n"


def kept_header(text):
    """(provenance, wall) read back from a README written by `header`."""
    import re
    prov = {}
    for key in ("commit", "machine", "date"):
        m = re.search(rf"^- {key}: (.*)$", text, re.M)
        prov[key] = m.group(1).strip("`") if m else "unknown"
    m = re.search(r"^- wall time of the benchmark suite: (\d+) s", text, re.M)
    return prov, float(m.group(1)) if m else None


def section_runs(directory):
    """Per fragment with a CSV of the same name: (name, commits, first date, last date) of
    the rows of that CSV (bench_common.write_csv adds commit, machine and date to every
    row), so a section rerun alone after the whole suite says which run wrote it."""
    import csv
    out = []
    for p in ordered_fragments(directory):
        c = p.with_suffix(".csv")
        if not c.exists():
            continue
        with open(c) as f:
            rows = list(csv.DictReader(f))
        commits = sorted({r.get("commit") or "unknown" for r in rows})
        dates = sorted(r["date"] for r in rows if r.get("date"))
        if rows and dates:
            out.append((p.stem, commits, dates[0], dates[-1]))
    return out


def sections_text(directory):
    lines = ["", "Commit and date of the run that wrote each section's data (a section rerun "
             "alone after the whole suite has its own):", ""]
    for name, commits, first, last in section_runs(directory):
        when = first if first[:13] == last[:13] else f"{first} – {last}"
        lines.append(f"- {name}: commit {', '.join(f'`{c}`' for c in commits)}, {when}")
    return "\n".join(lines) + "\n" if len(lines) > 3 else ""


def summary(directory, wall=None, prov=None):
    """Text of the README: header, the run of each section, then each fragment (separated
    by blank lines)."""
    parts = [header(prov or provenance(), wall) + sections_text(directory)]
    for p in ordered_fragments(directory):
        parts.append(p.read_text().rstrip() + "\n")
    return "\n".join(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--wall", type=float, default=None, help="total bench wall time [s]")
    ap.add_argument("--dir", default=str(BENCH_DIR))
    ap.add_argument("--keep-header", action="store_true",
                    help="keep the commit, machine, date and wall time of the README's header "
                         "(one fragment rewritten by its script alone; it states its own)")
    a = ap.parse_args()
    out = Path(a.dir) / OUTPUT
    prov, wall = None, a.wall
    if a.keep_header and out.exists():
        prov, kept_wall = kept_header(out.read_text())
        wall = wall if wall is not None else kept_wall
    out.write_text(summary(a.dir, wall, prov))
    print(out)


if __name__ == "__main__":
    main()
