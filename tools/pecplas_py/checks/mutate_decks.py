#!/usr/bin/env python3
"""Mutation testing of the deck reader and the run: random mutations of the decks under
input/ (lines deleted, duplicated or swapped, numbers swapped or replaced by huge, negative,
NaN or garbage values, truncated files, random keyword lines, a byte order mark; for a deck
with *MESH, half of the time its Gmsh file is mutated instead), each run
by the release `pecplas` with a timeout, and the outcome classified:

  completed (exit 0) | input error (exit 2) | stopped (exit 3)
  crash (any other exit code, or a signal) | hang (timeout)
  no line (exit 2 whose message names no file:line; a whole-deck error such as "no *STEP"
           names the deck with line 0 and is counted apart as "whole deck")
  file left (exit 2 with a results file written)

Usage: checks/mutate_decks.py [-n 10000] [--exe build/.../pecplas] [--timeout 20]
       [--seed 1] [--keep DIR] [--jobs 1] [--json FILE] [--sources DECK ...]
Only source decks whose unmutated run takes less than --max-source-seconds are used (also
among those given with --sources), so that the run stays short and a timeout is a hang. Failing cases are copied to --keep (default
build/mutate_decks) with their stderr, to reproduce them. Exit 1 when any crash, hang, no
line or file left was seen."""
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


def mutate(text, rng):
    lines = text.splitlines()
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        lines = mutate_once(lines, rng)
    out = "\n".join(lines) + "\n"
    r = rng.random()
    if r < 0.03:
        out = "\ufeff" + out
    elif r < 0.08:
        out = out[: rng.randrange(len(out) + 1)]  # truncated anywhere, even mid-number
    return out


def run(exe, deck, out, timeout):
    t0 = time.monotonic()
    try:
        r = subprocess.run([exe, str(deck), "-o", str(out), "--quiet"], cwd=deck.parent,
                           capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return "hang", "", time.monotonic() - t0
    err = r.stderr
    if r.returncode == 0:
        kind = "completed"
    elif r.returncode == 3:
        kind = "stopped"
    elif r.returncode == 2:
        msg = next((s for s in err.splitlines() if "error:" in s), "")
        if out.exists():
            kind = "file left"
        elif WHERE.search(msg):
            kind = "input error"
        elif re.search(r"error: \S+\.inp: \[", msg):
            kind = "whole deck"
        else:
            kind = "no line"
    else:
        kind = "crash"
    return kind, err, time.monotonic() - t0


def sources(exe, max_seconds, timeout, decks=None):
    """The decks (default: those under input/) that pecplas runs (not pecplas-path decks) in
    under max_seconds, so that a mutated run over the timeout is a hang, not a slow deck."""
    found = []
    for deck in decks or sorted((ROOT / "input").rglob("*.inp")):
        text = deck.read_text(errors="replace")
        if "*PATH" in text.upper():
            continue
        with tempfile.TemporaryDirectory() as tmp:
            kind, _, t = run(exe, deck, Path(tmp) / "r.h5", min(timeout, max_seconds + 1))
        if kind in ("completed", "stopped", "input error", "whole deck") and t < max_seconds:
            found.append(deck)
    return found


def one_case(args, srcs, case):
    rng = random.Random(args.seed * 1000003 + case)
    src = rng.choice(srcs)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        # the source deck's siblings (includes, meshes) stay reachable by relative paths
        for sib in src.parent.iterdir():
            if sib != src:
                (tmp / sib.name).symlink_to(sib)
        deck = tmp / src.name
        text = src.read_text(errors="replace")
        mesh = MESH.search(text)
        if mesh and not (src.parent / mesh.group(1)).is_file():
            mesh = None  # a deck of a missing mesh (an error test): its text is mutated
        if mesh:
            # the mesh as an absolute path (it may sit above the deck's folder), or half of
            # the time a mutated copy of it under a new name
            msh = (src.parent / mesh.group(1)).resolve()
            name = str(msh)
            if rng.random() < 0.5:
                name = "mutated.msh"
                (tmp / name).write_text(mutate(msh.read_text(errors="replace"), rng),
                                        errors="replace")
            text = text[:mesh.start(1)] + name + text[mesh.end(1):]
            if name == str(msh):
                text = mutate(text, rng)
        else:
            text = mutate(text, rng)
        deck.write_text(text, errors="replace")
        kind, err, secs = run(args.exe, deck, tmp / "out" / "r.h5", args.timeout)
        if kind in ("crash", "hang", "no line", "file left"):
            keep = Path(args.keep) / f"{kind.replace(' ', '_')}_{case}"
            keep.mkdir(parents=True, exist_ok=True)
            shutil.copy(deck, keep / src.name)
            (keep / "source.txt").write_text(str(src.relative_to(ROOT)) + "\n")
            (keep / "stderr.txt").write_text(err)
    return kind, secs, str(src.relative_to(ROOT)), err.strip().splitlines()[-1:] if err else []


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("-n", type=int, default=10000, help="number of mutated decks")
    p.add_argument("--exe", help="pecplas executable (default: pecplas_py.exe: $PECPLAS_BIN, "
                   "else fpm's release build)")
    p.add_argument("--timeout", type=float, default=20.0, help="seconds per run (hang bound)")
    p.add_argument("--max-source-seconds", type=float, default=2.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--keep", default=str(ROOT / "build" / "mutate_decks"))
    p.add_argument("--json", help="write the counts to this file")
    p.add_argument("--sources", nargs="*", help="source decks (default: every pecplas deck "
                   "under input/); those that run in under --max-source-seconds are used")
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
    counts, slowest, examples = {}, 0.0, {}
    t0 = time.monotonic()
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for i, (kind, secs, src, last) in enumerate(
                pool.map(lambda c: one_case(args, srcs, c), range(args.n))):
            counts[kind] = counts.get(kind, 0) + 1
            slowest = max(slowest, secs)
            if kind not in examples:
                examples[kind] = f"{src}: {last[0] if last else ''}"[:300]
            if (i + 1) % 500 == 0:
                print(f"{i + 1}/{args.n} {counts} ({time.monotonic() - t0:.0f} s)",
                      flush=True)
    summary = {"decks": args.n, "sources": len(srcs), "counts": counts,
               "slowest_run_s": round(slowest, 2), "timeout_s": args.timeout,
               "wall_s": round(time.monotonic() - t0, 1), "examples": examples}
    print(json.dumps(summary, indent=1))
    if args.json:
        Path(args.json).write_text(json.dumps(summary, indent=1) + "\n")
    bad = sum(counts.get(k, 0) for k in ("crash", "hang", "no line", "file left"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
