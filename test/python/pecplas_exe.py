"""Which executables the Python tests run: pecplas_py.exe (the one way every tool finds them,
see its docstring), with a failure of the test, not an exception, when the binary cannot be
used.

- Under `make test` (tools/test_all.sh): $PECPLAS_BIN is the CMake release `pecplas` and
  $PECPLAS_STAMP a file that tools/test_all.sh writes only after the CMake build of this same
  `make test` succeeded, holding the SHA-256 of every executable it built. A missing stamp or a
  binary that differs from it fails the test: no test runs a binary left over from an earlier
  build.
- Under CTest: $PECPLAS_BIN alone (set by CMakeLists.txt to the target of the same build tree);
  the binary must then be newer than every source file under src/ and app/.
- Otherwise (pytest by hand): `fpm run`, which builds the current sources first.
"""
import pytest

from pecplas_py import exe


def _checked(fn, *args):
    try:
        return fn(*args)
    except exe.ExeError as e:
        pytest.fail(str(e), pytrace=False)


def exe_cmd(target):
    """Command prefix (a list) that runs the project executable `target` (pecplas,
    pecplas-path, ...); arguments are appended."""
    return _checked(exe.exe_cmd, target)


def pecplas_cmd():
    """Command prefix (a list) to which the deck and options of `pecplas` are appended."""
    return exe_cmd("pecplas")


def exe_path(target="pecplas"):
    """Path of the executable `target` for tools that take one (not a command prefix): the
    checked binary of this make test, else fpm's release build (built if needed)."""
    return _checked(exe.exe_path, target)


def program_cmd(name):
    """Command prefix of another program of the project (e.g. "pecplas-path")."""
    return exe_cmd(name)
