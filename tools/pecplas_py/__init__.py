"""pecplas_py: the Python tools of PECPLAS/PECJOIN, one package (doc/tools.md).

Shared modules:
    exe          where the project's executables are (one way for every script and test)
    deck         writing keyword decks (doc/deck.md)
    results      reading results files (doc/results.md)
    figures      saving matplotlib figures atomically
    doc_blocks   the generated blocks of the documentation

Scripts, by role (run as `python3 -m pecplas_py.<role>.<script>` with tools/ on PYTHONPATH,
which make, tools/*.sh, CTest and pytest.ini set):
    decks/     deck generators (input/, test/data/)
    scenes/    scenes S1-S6: plots, readers and the blocks of doc/validation.md
    docs/      generators of the numbers quoted in doc/validation.md and doc/theory.md
    plots/     figures of any results file (make run) or pecplas-path run
    bench/     make bench
    peers/     the same problems for CalculiX and OpenSees
    checks/    result checker, deck fuzzer, MPI check
    programs/  pecplas-sweep (installed by make install; stand-alone, standard library + h5py)
"""
import os
import sys
from pathlib import Path

#: the repository root (tools/pecplas_py/__init__.py is two folders below it)
ROOT = Path(__file__).resolve().parents[2]

# The scripts a script starts (`python3 -m pecplas_py...`) find the package as it did.
_tools = str(ROOT / "tools")
if _tools not in os.environ.get("PYTHONPATH", "").split(os.pathsep):
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (_tools, os.environ.get("PYTHONPATH"))
                                               if p)


def script_cmd(name):
    """Command prefix (a list) that runs the script `pecplas_py.<name>`, e.g.
    script_cmd("decks.make_s2_decks") + ["--out", DIR]."""
    return [sys.executable, "-m", f"pecplas_py.{name}"]
