"""The command that runs the `pecplas` executable for the Python tests: $PECPLAS_BIN (set by
`make test` and CTest to the CMake release build) when it exists, else `fpm run` (builds the
debug executable first)."""
import os
from pathlib import Path


def pecplas_cmd():
    """Command prefix (a list) to which the deck and options are appended."""
    exe = os.environ.get("PECPLAS_BIN")
    if exe and Path(exe).exists():
        return [exe]
    return ["fpm", "run", "--target", "pecplas", "--"]


def program_cmd(name):
    """Command prefix of another program of the project (e.g. "pecplas-path"): the one next
    to $PECPLAS_BIN when it exists, else `fpm run`."""
    exe = os.environ.get("PECPLAS_BIN")
    if exe and (Path(exe).parent / name).exists():
        return [str(Path(exe).parent / name)]
    return ["fpm", "run", "--target", name, "--"]
