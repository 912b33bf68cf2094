#!/usr/bin/env python3
"""Lists the loops of the program that gfortran vectorises as a chain of conditional
reductions, a kind of loop that gfortran 12.2 at -O3 (Debian 12's compiler) can compile
wrongly (doc/build.md, "A compiler defect at -O3").

Such a loop assigns the same scalar under two or more conditions, e.g.

    do i = 1, n
       if (a(i) == -1) k = 0
       if (a(i) > 0) k = a(i)
    end do

The vectoriser turns it into a chain of 'condition reductions'; with gfortran 12.2 at -O3 the
chain can lose the last match (for a = [2, 0, 0, 0] it returns 1 from n = 4 on: -O2 returns 2).

The check configures a Release build of the library in a scratch folder with
-fdump-tree-vect-details, builds it (about 5 minutes of CPU on one core) and reads the
vectoriser's notes: a loop is listed when it was vectorised and one of its reduction paths goes
through two or more if-converted statements (`_ifc__`). It exits 1 when any is listed.

    python3 -m pecplas_py.checks.cond_reductions [--build DIR] [--keep] [--no-build]

--build DIR: the scratch folder (default: a temporary one); --no-build reads the notes of an
earlier --keep run in DIR.
"""

from __future__ import annotations

import argparse
import collections
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

NOTE = re.compile(r"(\S+\.f90:\d+):\d+: (\w+):\s+(.*)")


def chained_loops(dumps: list[pathlib.Path]) -> dict[str, int]:
    """Loop locations (file:line) vectorised with a reduction path through two or more
    if-converted statements, with the largest such count."""
    chained: dict[str, int] = collections.defaultdict(int)
    vectorised: set[str] = set()
    for dump in dumps:
        for line in dump.read_text(errors="replace").splitlines():
            match = NOTE.match(line)
            if not match:
                continue
            loc, kind, message = match.groups()
            if message.startswith("reduction path:"):
                chained[loc] = max(chained[loc], message.count("_ifc__"))
            elif kind == "optimized" and "loop vectorized" in message:
                vectorised.add(loc)
    return {loc: n for loc, n in chained.items() if n >= 2 and loc in vectorised}


def build(root: pathlib.Path, folder: pathlib.Path) -> None:
    """Configures and builds the library with the vectoriser's notes written."""
    subprocess.run(["cmake", "-S", str(root), "-B", str(folder), "-DCMAKE_BUILD_TYPE=Release",
                    "-DCMAKE_Fortran_FLAGS=-fdump-tree-vect-details"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", str(folder), "--target", "pecplas_lib", "-j1"],
                   check=True, stdout=subprocess.DEVNULL)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=pathlib.Path)
    parser.add_argument("--keep", action="store_true")
    parser.add_argument("--no-build", action="store_true")
    args = parser.parse_args(argv)
    root = pathlib.Path(__file__).resolve().parents[3]
    folder = args.build or pathlib.Path(tempfile.mkdtemp(prefix="pecplas_vect_"))
    try:
        if not args.no_build:
            build(root, folder)
        dumps = sorted(folder.rglob("*.vect"))
        if not dumps:
            print(f"cond_reductions: no vectoriser notes (*.vect) under {folder}", file=sys.stderr)
            return 2
        loops = chained_loops(dumps)
        for loc, count in sorted(loops.items()):
            print(f"{loc}: vectorised with {count} conditional assignments chained")
        print(f"cond_reductions: {len(dumps)} files read, {len(loops)} loop(s) listed")
        return 1 if loops else 0
    finally:
        if args.build is None and not args.keep:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
