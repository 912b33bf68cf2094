"""Which executables the Python tests run, and a guard against stale ones.

- Under `make test` (tools/test_all.sh): $PECPLAS_BIN is the CMake release `pecplas` and
  $PECPLAS_STAMP a file that tools/test_all.sh writes only after the CMake build of this same
  `make test` succeeded, holding the SHA-256 of every executable it built. A missing stamp or a
  binary that differs from it fails the test: no test runs a binary left over from an earlier
  build.
- Under CTest: $PECPLAS_BIN alone (set by CMakeLists.txt to the target of the same build tree);
  the binary must then be newer than every source file under src/ and app/.
- Otherwise (pytest by hand): `fpm run`, which builds the current sources first.
"""
import functools
import hashlib
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _read_stamp(stamp):
    """{executable name: sha256} from the stamp written by tools/test_all.sh."""
    table = {}
    for line in Path(stamp).read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            digest, name = line.split(maxsplit=1)
            table[Path(name).name] = digest
    return table


def _newest_source():
    newest = 0.0
    for top in ("src", "app"):
        for p in (ROOT / top).rglob("*"):
            if p.suffix in (".f90", ".c", ".h"):
                newest = max(newest, p.stat().st_mtime)
    return newest


@functools.lru_cache(maxsize=None)
def _checked_binary(target):
    """Path of the built executable `target` next to $PECPLAS_BIN, checked for freshness;
    None when $PECPLAS_BIN is not set (then fpm builds and runs)."""
    bin_env = os.environ.get("PECPLAS_BIN")
    if not bin_env:
        return None
    exe = Path(bin_env).parent / target
    if not exe.exists():
        pytest.fail(f"{exe} does not exist (PECPLAS_BIN={bin_env}): build it first "
                    "(`make test` builds it with CMake)", pytrace=False)
    stamp = os.environ.get("PECPLAS_STAMP")
    if stamp:
        if not Path(stamp).exists():
            pytest.fail(f"no build stamp {stamp}: the CMake build of this `make test` did not "
                        f"succeed, so {exe} may be left over from an earlier build",
                        pytrace=False)
        digest = _read_stamp(stamp).get(target)
        if digest is None or digest != _sha256(exe):
            pytest.fail(f"{exe} is not the binary the CMake build of this `make test` "
                        f"produced (stamp {stamp})", pytrace=False)
    elif exe.stat().st_mtime < _newest_source():
        pytest.fail(f"{exe} is older than the sources under src/ or app/: rebuild it "
                    "(cmake --build) or unset PECPLAS_BIN to let fpm build", pytrace=False)
    return exe


def exe_cmd(target):
    """Command prefix (a list) that runs the project executable `target` (pecplas,
    pecplas-path, ...); arguments are appended."""
    exe = _checked_binary(target)
    if exe is not None:
        return [str(exe)]
    return ["fpm", "run", "--profile", "release", "--target", target, "--"]


def pecplas_cmd():
    """Command prefix (a list) to which the deck and options of `pecplas` are appended."""
    return exe_cmd("pecplas")


def exe_path(target="pecplas"):
    """Path of the executable `target` for tools that take one (not a command prefix): the
    checked binary of this make test, else fpm's release build (built if needed)."""
    cmd = exe_cmd(target)
    if cmd[0] != "fpm":
        return cmd[0]
    r = subprocess.run(["fpm", "run", "--profile", "release", "--target", target, "--runner",
                        "echo"], cwd=Path(__file__).resolve().parents[2], capture_output=True,
                       text=True, check=True)
    return r.stdout.split()[-1]


def program_cmd(name):
    """Command prefix of another program of the project (e.g. "pecplas-path")."""
    return exe_cmd(name)
