#!/usr/bin/env python3
"""Mutation testing (fuzzing) of the deck reader and the run: random mutations of the decks
under input/ and test/data (or of the mesh and include files they read), each run by the
release `pecplas` with a timeout, and the outcome classified (doc/tools.md, Fuzzing):

  completed (exit 0) | input error (exit 2, "file:line: [KEYWORD] ...") | stopped (exit 3)
  whole deck (exit 2 about the whole deck, such as "no *STEP": the deck named, no line)
  crash (another exit code, a signal, or a runtime error / backtrace on stderr)
  hang (timeout)
  no line (exit 2 whose message names no file:line) | no keyword (no [KEYWORD])
  file left (exit 2 with anything written to the output folder)
  silent (a value doc/deck.md refuses, put in by the mutation, run to exit 0 or 3 without
          an error or a warning)

Mutations: mutate_once (lines deleted, duplicated, swapped, cut short; numbers replaced by
garbage or extreme values; random keyword lines) and mutate_targeted (stray comma, tab,
non-ASCII bytes, misspelt keyword or name, dropped parameter, empty data line, undefined or
repeated node, same coordinates, refused material values, ...); then sometimes a byte order
mark, a truncated file, CRLF or CR-only line ends.

Usage: checks/mutate_decks.py [-n 10000] [--exe build/.../pecplas] [--timeout 20]
       [--seed 1] [--first 0] [--keep DIR] [--jobs 1] [--json FILE] [--messages FILE]
       [--sources DECK ...]
Only source decks whose unmutated run takes less than --max-source-seconds are used (also
among those given with --sources), so that the run stays short and a timeout is a hang.
Failing cases are copied to --keep (default build/mutate_decks) with their stderr and
mutations, to reproduce them. Exit 1 when any defect (crash, hang, no line, no keyword,
file left, silent) was seen."""
import argparse
import json
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from pecplas_py import ROOT
from pecplas_py.exe import ExeError, exe_path

GARBAGE = ["abc", "1e999", "-1e999", "nan", "NaN", "inf", "-inf", "0", "-0", "1e-320",
           "1e308", "-1e308", "2147483648", "-2147483649", "99999999999999999999", "*", ",",
           "", "-7", "3.5.1", "1d400", "0x10", "1e8", "100000000", "-1", "0.5236"]
KEYWORDS = ["*NODES", "*ELEMENTS, TYPE=Q4, SET=x", "*NSET, NAME=g, GENERATE", "*STEP",
            "*STEP, INCREMENTS=1000015", "*LOAD, NAME=p, TYPE=FORCE", "*BOUNDARY",
            "*MATERIAL, NAME=m", "*SECTION, SET=x, MATERIAL=m", "*INCLUDE, FILE=nowhere.inp",
            "*MESH, FILE=nowhere.msh", "*JOINTS, TYPE=GOODMAN4, SET=j, LAW=l", "*END STEP",
            "*INITIAL_STRESS, TYPE=GEOSTATIC", "*SOLVER, MAX_ITERATIONS=100000000",
            "*OUTPUT, EVERY=0", "*FOO", "*", "**", "*EDGES, NAME=e", "*INTERFACE_LAW"]
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?")
WHERE = re.compile(r"\S+:\d+: ")
MESH = re.compile(r"^\*MESH\s*,\s*FILE\s*=\s*(\S+)", re.I | re.M)


def mutate_once(lines, rng):
    if not lines:
        return [rng.choice(KEYWORDS)]
    kind = rng.randrange(9)
    i = rng.randrange(len(lines))
    if kind == 0:
        del lines[i]
    elif kind == 1:
        lines.insert(i, lines[rng.randrange(len(lines))])
    elif kind == 2:
        j = rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind in (3, 4):
        nums = list(NUMBER.finditer(lines[i]))
        if nums:
            m = rng.choice(nums)
            lines[i] = lines[i][:m.start()] + rng.choice(GARBAGE) + lines[i][m.end():]
        else:
            fields = lines[i].split(",")
            fields[rng.randrange(len(fields))] = rng.choice(GARBAGE)
            lines[i] = ",".join(fields)
    elif kind == 5:
        nums = list(NUMBER.finditer(lines[i]))
        if len(nums) >= 2:
            a, b = rng.sample(nums, 2)
            if a.start() > b.start():
                a, b = b, a
            s = lines[i]
            lines[i] = s[:a.start()] + b.group() + s[a.end():b.start()] + a.group() + s[b.end():]
    elif kind == 6:
        del lines[rng.randrange(1, len(lines) + 1):]
    elif kind == 7:
        lines.insert(i, rng.choice(KEYWORDS))
    else:
        text = lines[i]
        lines[i] = text[: rng.randrange(len(text) + 1)]  # a line cut short
    return lines


NAME_PARAM = re.compile(r"\b(NAME|SET|MATERIAL|LAW|SIDE|EDGES|FACES|PATTERN|NSET|ELSET)"
                        r"\s*=\s*([^,\s]+)", re.I)
PARAM = re.compile(r",\s*[A-Za-z_]+\s*=\s*[^,]*")
# values a deck must refuse (doc/deck.md): key = value on a data line -> nonsense replacements
NONSENSE = {"E": ["-1e4", "0"], "NU": ["0.5", "0.7", "-1.5"], "KN": ["-1e5"],
            "KS": ["-1e5"], "EA": ["-1e6", "0"], "EI": ["-1e3"],
            "THICKNESS": ["-0.1", "0"], "PHI": ["-5", "95"], "C": ["-10"],
            "GAMMA": ["-18"], "K0": ["-0.5"], "SPACING": ["-1", "0"], "LENGTH": ["-1", "0"]}
KEYVAL = re.compile(r"\b(" + "|".join(NONSENSE) + r")\s*=\s*"
                    r"([-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?)", re.I)
NONASCII = ["\u00e9", "\u00a0", "\u2013", "\udce9", "\udcff", "\ufeff", "\u00b5"]


def _is_keyword(line):
    s = line.lstrip()
    return s.startswith("*") and not s.startswith("**")


def _block_of(lines, i):
    """The keyword line (upper case) above line i, or ''."""
    for j in range(i, -1, -1):
        if _is_keyword(lines[j]):
            return lines[j].strip().upper()
    return ""


def _data_lines(lines, keyword=None):
    out = []
    for i, s in enumerate(lines):
        if not s.strip() or _is_keyword(s) or s.lstrip().startswith(("**", "#", "$")):
            continue
        if keyword is None or _block_of(lines, i).startswith(keyword):
            out.append(i)
    return out


def mutate_targeted(lines, rng):
    """One mutation aimed at a rule of the deck (or mesh) format: (lines, tag, nonsense) where
    nonsense says that the mutant holds a value doc/deck.md refuses (it must not run silently).
    Returns tag None when the chosen mutation finds nothing to act on."""
    kind = rng.choice(["stray comma", "tab", "nonascii", "misspell keyword", "misspell name",
                       "drop parameter", "empty data line", "undefined node", "repeated node",
                       "same coordinates", "nonsense value", "nonsense value", "negative number",
                       "blank keyword value", "lowercase", "number as text"])
    if not lines:
        return lines, None, False
    i = rng.randrange(len(lines))
    if kind == "stray comma":
        s = lines[i]
        k = rng.randrange(len(s) + 1)
        lines[i] = s[:k] + rng.choice([",", ",,", ", ,"]) + s[k:]
    elif kind == "tab":
        s = lines[i]
        k = rng.randrange(len(s) + 1)
        lines[i] = s[:k] + "\t" + s[k:] if rng.random() < 0.5 else s.replace(" ", "\t")
    elif kind == "nonascii":
        s = lines[i]
        k = rng.randrange(len(s) + 1)
        lines[i] = s[:k] + rng.choice(NONASCII) + s[k:]
    elif kind == "misspell keyword":
        kws = [j for j, s in enumerate(lines) if _is_keyword(s)]
        if not kws:
            return lines, None, False
        i = rng.choice(kws)
        s = lines[i]
        name_end = len(s.split(",")[0])
        if name_end < 3:
            return lines, None, False
        k = rng.randrange(2, name_end)
        lines[i] = s[:k] + rng.choice("AEIXZ_") + s[k + 1:]
    elif kind == "misspell name":
        hits = [(j, m) for j, s in enumerate(lines) if _is_keyword(s)
                for m in NAME_PARAM.finditer(s)]
        if not hits:
            return lines, None, False
        j, m = rng.choice(hits)
        lines[j] = lines[j][:m.start(2)] + m.group(2) + "x" + lines[j][m.end(2):]
    elif kind == "drop parameter":
        hits = [(j, m) for j, s in enumerate(lines) if _is_keyword(s) for m in PARAM.finditer(s)]
        if not hits:
            return lines, None, False
        j, m = rng.choice(hits)
        lines[j] = lines[j][:m.start()] + lines[j][m.end():]
    elif kind == "blank keyword value":
        hits = [(j, m) for j, s in enumerate(lines) if _is_keyword(s) for m in PARAM.finditer(s)]
        if not hits:
            return lines, None, False
        j, m = rng.choice(hits)
        key = m.group().split("=")[0]
        lines[j] = lines[j][:m.start()] + key + rng.choice(["=", "= ", "=,"]) + lines[j][m.end():]
    elif kind == "empty data line":
        data = _data_lines(lines)
        if not data:
            return lines, None, False
        lines[rng.choice(data)] = rng.choice(["", ",", " , ", "\t", ",,,"])
    elif kind in ("undefined node", "repeated node"):
        data = _data_lines(lines, "*ELEMENTS") or _data_lines(lines, "*JOINTS") or \
            [j for j, s in enumerate(lines) if len(s.split()) >= 6 and
             all(t.lstrip("-").isdigit() for t in s.split())]   # a Gmsh element line
        if not data:
            return lines, None, False
        i = rng.choice(data)
        sep = "," if "," in lines[i] else None
        f = lines[i].split(sep)
        if len(f) < 3:
            return lines, None, False
        k = rng.randrange(1, len(f))
        if kind == "undefined node":
            f[k] = " 987654"
        else:
            other = rng.choice([q for q in range(1, len(f)) if q != k])
            f[k] = f[other]
        lines[i] = ("," if sep else " ").join(f)
    elif kind == "same coordinates":
        data = _data_lines(lines, "*NODES")
        if len(data) < 2:
            return lines, None, False
        a, b = rng.sample(data, 2)
        fa, fb = lines[a].split(","), lines[b].split(",")
        lines[a] = ",".join(fa[:1] + fb[1:])
    elif kind == "nonsense value":
        hits = [(j, m) for j, s in enumerate(lines) if not s.lstrip().startswith(("**", "#"))
                and not _block_of(lines, j).startswith(("*TITLE", "*UNITS"))
                for m in KEYVAL.finditer(s)]
        if not hits:
            return lines, None, False
        j, m = rng.choice(hits)
        key = m.group(1).upper()
        lines[j] = lines[j][:m.start(2)] + rng.choice(NONSENSE[key]) + lines[j][m.end(2):]
        return lines, f"nonsense {key}", True
    elif kind == "negative number":
        nums = list(NUMBER.finditer(lines[i]))
        if not nums:
            return lines, None, False
        m = rng.choice(nums)
        lines[i] = lines[i][:m.start()] + "-" + m.group().lstrip("+-") + lines[i][m.end():]
    elif kind == "number as text":
        nums = list(NUMBER.finditer(lines[i]))
        if not nums:
            return lines, None, False
        m = rng.choice(nums)
        text = rng.choice(["one", "1,0", "1 0", "1e", "e5", "--1", "+-2", "1..0", "NaN",
                           "Infinity", "1e300"])
        lines[i] = lines[i][:m.start()] + text + lines[i][m.end():]
    elif kind == "lowercase":
        lines[i] = lines[i].lower()
    return lines, kind, False


def mutate(text, rng):
    """A mutated copy of `text`: (text, tags, nonsense): tags name the mutations done,
    nonsense says that a value the deck must refuse was put in (mutate_targeted)."""
    lines = text.splitlines()
    tags, nonsense = [], False
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        if rng.random() < 0.5:
            lines = mutate_once(lines, rng)
            tags.append("random")
        else:
            lines, tag, bad = mutate_targeted(lines, rng)
            nonsense = nonsense or bad
            if tag:
                tags.append(tag)
    out = "\n".join(lines) + "\n"
    r = rng.random()
    if r < 0.03:
        out = "\ufeff" + out
        tags.append("byte order mark")
    elif r < 0.08:
        out = out[: rng.randrange(len(out) + 1)]  # truncated anywhere, even mid-number
        tags.append("truncated")
    elif r < 0.14:
        out = out.replace("\n", "\r\n")
        tags.append("CRLF")
    elif r < 0.16:
        out = out.replace("\n", "\r")
        tags.append("CR only")
    return out, tags, nonsense


CRASH = re.compile(r"Fortran runtime error|Backtrace|Segmentation fault|Program received "
                   r"signal|SIGSEGV|SIGFPE|SIGBUS|SIGABRT|At line \d+ of file|ERROR STOP|"
                   r"double free|malloc\(\)|HDF5-DIAG|Aborted", re.I)
KEYED = re.compile(r"\S+:\d+: \[[^\]]+\] ")
BAD = ("crash", "hang", "no line", "no keyword", "file left", "silent")


def run(exe, deck, outdir, timeout, nonsense=False):
    """Runs `deck` into outdir/r.h5: (class, stderr, seconds); outdir must exist and be empty."""
    t0 = time.monotonic()
    out = outdir / "r.h5"
    try:
        r = subprocess.run([exe, str(deck), "-o", str(out), "--quiet"], cwd=deck.parent,
                           capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return "hang", "", time.monotonic() - t0
    err = r.stderr
    secs = time.monotonic() - t0
    if CRASH.search(err) or r.returncode not in (0, 2, 3):
        return "crash", err + f"\n[exit code {r.returncode}]", secs
    if r.returncode in (0, 3):
        if nonsense and "warning" not in err.lower():
            return "silent", err, secs
        return ("completed" if r.returncode == 0 else "stopped"), err, secs
    msg = next((s for s in err.splitlines() if "error:" in s), "")
    left = sorted(q.name for q in outdir.iterdir()) if outdir.is_dir() else []
    if left:
        return "file left", err + f"\n[left in the output folder: {left}]", secs
    if KEYED.search(msg) or (WHERE.search(msg) and "before the first keyword" in msg):
        return "input error", err, secs  # (a data line above every keyword has none)
    if WHERE.search(msg):
        return "no keyword", err, secs
    if re.search(r"error: \S+: \[", msg):
        return "whole deck", err, secs
    return "no line", err, secs


FILE_REF = re.compile(r"^(\*(?:MESH|INCLUDE)\b.*?FILE\s*=\s*)([^,\s]+)", re.I | re.M)


def default_sources():
    """The decks of input/ and test/data that pecplas reads (not *PATH decks, not the sweep
    templates)."""
    found = []
    for top in ("input", "test/data"):
        for deck in sorted((ROOT / top).rglob("*.inp")):
            rel = deck.relative_to(ROOT).parts
            if "sweeps" in rel:
                continue
            if re.search(r"^\*PATH\b", deck.read_text(errors="replace"), flags=re.M | re.I):
                continue
            found.append(deck)
    return found


def sources(exe, max_seconds, timeout, decks=None):
    """The decks that run in under max_seconds, so that a mutated run over the timeout is a
    hang, not a slow deck: those given (an error test among them too), else those of
    default_sources() that run (completed or stopped: mutants of a deck refused already
    mostly meet the same error)."""
    found = []
    for deck in decks or default_sources():
        text = deck.read_text(errors="replace")
        if "*PATH" in text.upper():
            continue
        with tempfile.TemporaryDirectory() as tmp:
            (Path(tmp) / "out").mkdir()
            kind, _, t = run(exe, deck, Path(tmp) / "out", min(timeout, max_seconds + 1))
        if t < max_seconds and kind in (("completed", "stopped", "silent") if not decks else
                                        ("completed", "stopped", "input error", "whole deck",
                                         "no keyword", "silent")):
            found.append(deck)
    return found


def one_case(args, srcs, case):
    """Mutates one source deck (or a mesh or include file it reads) and runs it."""
    rng = random.Random(args.seed * 1000003 + case)
    src = rng.choice(srcs)
    with_files = [q for q in srcs if FILE_REF.search(q.read_text(errors="replace"))]
    if with_files and rng.random() < 0.3:  # meshes and includes: a third of the cases
        src = rng.choice(with_files)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        # the source deck's siblings stay reachable by relative paths; files named by *MESH
        # and *INCLUDE are made absolute (they may sit above the deck's folder)
        for sib in src.parent.iterdir():
            if sib != src:
                (tmp / sib.name).symlink_to(sib)
        deck = tmp / src.name
        text = src.read_text(errors="replace")
        refs = [m for m in FILE_REF.finditer(text) if (src.parent / m.group(2)).is_file()]
        target = rng.choice(refs) if refs and rng.random() < 0.5 else None
        pieces, pos = [], 0
        for m in refs:
            path = (src.parent / m.group(2)).resolve()
            name = str(path)
            if m is target:
                name = "mutated_" + path.name
                mtext, tags, nonsense = mutate(path.read_text(errors="replace"), rng)
                (tmp / name).write_text(mtext, errors="surrogateescape", newline="")
                tags = [f"{path.name}: {t}" for t in tags]
            pieces += [text[pos:m.start(2)], name]
            pos = m.end(2)
        text = "".join(pieces) + text[pos:]
        if target is None:
            text, tags, nonsense = mutate(text, rng)
        deck.write_text(text, errors="surrogateescape", newline="")
        outdir = tmp / "out"
        outdir.mkdir()
        kind, err, secs = run(args.exe, deck, outdir, args.timeout, nonsense)
        if kind in BAD:
            keep = Path(args.keep) / f"{kind.replace(' ', '_')}_{case}"
            keep.mkdir(parents=True, exist_ok=True)
            shutil.copy(deck, keep / src.name)
            for q in tmp.glob("mutated_*"):
                shutil.copy(q, keep / q.name)
            (keep / "source.txt").write_text(f"{src.relative_to(ROOT)}\nseed {args.seed} "
                                             f"case {case}\nmutations: {tags}\n")
            (keep / "stderr.txt").write_text(err)
    last = [s for s in err.strip().splitlines() if s.strip()][-1:] if err else []
    return kind, secs, str(src.relative_to(ROOT)), last, tags, err


def template(line):
    """An error message with its numbers and quoted names blanked, to count distinct ones."""
    line = re.sub(r"^.*?error: \S+?(:\d+)?: ", "", line)
    line = re.sub(r"'[^']*'", "'_'", line)
    return NUMBER.sub("#", line)[:160]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("-n", type=int, default=10000, help="number of mutated decks")
    p.add_argument("--exe", help="pecplas executable (default: pecplas_py.exe: $PECPLAS_BIN, "
                   "else fpm's release build)")
    p.add_argument("--timeout", type=float, default=20.0, help="seconds per run (hang bound)")
    p.add_argument("--max-source-seconds", type=float, default=2.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--first", type=int, default=0, help="number of the first case")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--keep", default=str(ROOT / "build" / "mutate_decks"))
    p.add_argument("--json", help="write the counts to this file")
    p.add_argument("--messages", help="write every distinct input-error message (numbers and "
                   "quoted names blanked) with its count to this file, to read them")
    p.add_argument("--sources", nargs="*", help="source decks (default: every pecplas deck "
                   "under input/ and test/data); those that run in under "
                   "--max-source-seconds are used")
    args = p.parse_args()
    if not args.exe:
        try:
            args.exe = exe_path("pecplas")
        except ExeError as e:
            sys.exit(f"no pecplas executable: {e}")
    args.exe = str(Path(args.exe).resolve())
    srcs = sources(args.exe, args.max_source_seconds, args.timeout,
                   [Path(q).resolve() for q in args.sources or []])
    if not srcs:
        sys.exit(f"mutate_decks: no source deck runs in under {args.max_source_seconds:g} s")
    print(f"{len(srcs)} source decks, {args.n} mutations, timeout {args.timeout:g} s",
          flush=True)
    counts, slowest, examples, messages = {}, 0.0, {}, {}
    t0 = time.monotonic()
    cases = range(args.first, args.first + args.n)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for i, (kind, secs, src, last, tags, err) in enumerate(
                pool.map(lambda c: one_case(args, srcs, c), cases)):
            counts[kind] = counts.get(kind, 0) + 1
            slowest = max(slowest, secs)
            if kind in BAD:
                print(f"{kind}: case {cases[i]} {src} {tags}: {last[0] if last else ''}"[:400],
                      flush=True)
            if kind not in examples:
                examples[kind] = f"{src}: {last[0] if last else ''}"[:300]
            if kind in ("input error", "whole deck", "no keyword", "no line"):
                msg = next((s for s in err.splitlines() if "error:" in s), "")
                t = template(msg)
                messages[t] = messages.get(t, 0) + 1
            if (i + 1) % 500 == 0:
                print(f"{i + 1}/{args.n} {counts} ({time.monotonic() - t0:.0f} s)",
                      flush=True)
    summary = {"decks": args.n, "sources": len(srcs), "counts": counts,
               "slowest_run_s": round(slowest, 2), "timeout_s": args.timeout,
               "wall_s": round(time.monotonic() - t0, 1), "examples": examples}
    print(json.dumps(summary, indent=1))
    if args.json:
        Path(args.json).write_text(json.dumps(summary, indent=1) + "\n")
    if args.messages:
        Path(args.messages).write_text("".join(
            f"{n:6d}  {t}\n" for t, n in sorted(messages.items(), key=lambda x: -x[1])))
    bad = sum(counts.get(k, 0) for k in BAD)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
