"""Where the project's executables are: the one way every script and test finds them.

A target is `pecplas`, `pecplas-path`, `pecplas-identify`, `pecplas-sensitivity` or the
suite driver `pecplas_tests`. In order:

1. a directory given by the caller (a script's `--bin DIR`): `DIR/target`;
2. `$PECPLAS_BIN`, the `pecplas` executable of a build: the target next to it. With
   `$PECPLAS_STAMP` (written by tools/test_all.sh after the CMake build of `make test`: the
   SHA-256 of each executable it built) the binary must match the stamp; without it, it must
   be newer than every source file under src/ and app/. No script or test ever runs a binary
   left over from an earlier build;
3. fpm's release build (`make build`, `make run`): `fpm run --profile release --target T --`
   (`fpm test --profile release --` for the suite driver), which builds the current sources
   first;
4. without fpm on the PATH, the CMake build of the Makefile (`$CMAKE_DIR`, default
   build/cmake), when newer than the sources.

`exe_cmd` gives a command prefix (arguments are appended), `exe_path` a path (for tools
that time the program or send it signals: fpm is then asked where its build is, building it
if needed). A binary that cannot be used raises ExeError, whose message says what to do.

pecplas-sweep (pecplas_py/programs/pecplas_sweep.py) is installed as one file without this
package and finds `pecplas` its own way: --pecplas, $PECPLAS_BIN, next to itself, the PATH.
"""
import functools
import hashlib
import os
import shutil
import subprocess
from pathlib import Path

from pecplas_py import ROOT

SUITE_DRIVER = "pecplas_tests"


class ExeError(RuntimeError):
    """No usable executable (missing, stale, or not the one this `make test` built)."""


def _sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_stamp(stamp):
    """{executable name: sha256} from the stamp written by tools/test_all.sh."""
    table = {}
    for line in Path(stamp).read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            digest, name = line.split(maxsplit=1)
            table[Path(name).name] = digest
    return table


def newest_source():
    """Modification time of the newest Fortran or C source under src/ and app/."""
    newest = 0.0
    for top in ("src", "app"):
        for p in (ROOT / top).rglob("*"):
            if p.suffix in (".f90", ".c", ".h"):
                newest = max(newest, p.stat().st_mtime)
    return newest


def _check_fresh(exe, what):
    if exe.stat().st_mtime < newest_source():
        raise ExeError(f"{exe} is older than the sources under src/ or app/: rebuild it "
                       f"(cmake --build, make build) or unset {what}")


@functools.lru_cache(maxsize=None)
def _from_pecplas_bin(target, bin_env, stamp):
    exe = Path(bin_env).parent / target
    if not exe.exists():
        raise ExeError(f"{exe} does not exist (PECPLAS_BIN={bin_env}): build it first "
                       "(`make test` builds it with CMake)")
    if stamp:
        if not Path(stamp).exists():
            raise ExeError(f"no build stamp {stamp}: the CMake build of this `make test` did "
                           f"not succeed, so {exe} may be left over from an earlier build")
        digest = read_stamp(stamp).get(target)
        if digest is None or digest != _sha256(exe):
            raise ExeError(f"{exe} is not the binary the CMake build of this `make test` "
                           f"produced (stamp {stamp})")
    else:
        _check_fresh(exe, "PECPLAS_BIN to let fpm build")
    return exe


def _fpm():
    return os.environ.get("FPM", "fpm")


def _cmake_build(target):
    exe = ROOT / os.environ.get("CMAKE_DIR", "build/cmake") / target
    if not exe.exists():
        raise ExeError(f"no {target}: neither PECPLAS_BIN is set nor fpm on the PATH, and "
                       f"{exe} does not exist (make build, or set PECPLAS_BIN)")
    _check_fresh(exe, "CMAKE_DIR")
    return exe


def built_exe(target="pecplas", bin_dir=None):
    """Path of an already built, checked executable (steps 1, 2 and 4 above), or None when
    fpm is to build and run it (step 3)."""
    if bin_dir:
        exe = Path(bin_dir) / target
        if not exe.exists():
            raise ExeError(f"{exe} does not exist (--bin {bin_dir})")
        return exe
    bin_env = os.environ.get("PECPLAS_BIN")
    if bin_env:
        return _from_pecplas_bin(target, bin_env, os.environ.get("PECPLAS_STAMP") or None)
    if shutil.which(_fpm()):
        return None
    return _cmake_build(target)


def exe_cmd(target="pecplas", bin_dir=None):
    """Command prefix (a list) that runs the executable `target`; arguments are appended."""
    exe = built_exe(target, bin_dir)
    if exe is not None:
        return [str(exe)]
    if target == SUITE_DRIVER:
        return [_fpm(), "test", "--profile", "release", "--"]
    return [_fpm(), "run", "--profile", "release", "--target", target, "--"]


def exe_path(target="pecplas", bin_dir=None):
    """Path (a string) of the executable `target`: the checked build, else fpm's release build
    (built first when the sources changed)."""
    exe = built_exe(target, bin_dir)
    if exe is not None:
        return str(exe)
    if target == SUITE_DRIVER:
        raise ExeError("the suite driver's path is known only from a build directory (--bin, "
                       "PECPLAS_BIN); through fpm, run it with exe_cmd")
    r = subprocess.run([_fpm(), "run", "--profile", "release", "--target", target,
                        "--runner", "echo"], cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        raise ExeError(f"fpm could not build {target}:\n{r.stderr}")
    path = Path(r.stdout.split()[-1])
    return str(path if path.is_absolute() else ROOT / path)  # whatever the caller's cwd


def runs_through_fpm(cmd):
    """True when a command prefix of exe_cmd goes through fpm (a signal sent to it would reach
    fpm, not the program)."""
    return Path(cmd[0]).name == Path(_fpm()).name
