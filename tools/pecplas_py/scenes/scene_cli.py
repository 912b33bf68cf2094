"""The command line shared by the scene scripts (scenes/plot_s*.py): one optional directory,
`--help` from the script's docstring, and a clear error when the directory does not exist."""
import argparse
from pathlib import Path


def scene_dir(doc, default, what="directory holding the scene's results"):
    """Parses `[DIR]` (default `default`) and returns it as a Path; exits 2 when missing."""
    parser = argparse.ArgumentParser(description=doc,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir", nargs="?", default=default, help=f"{what} (default {default})")
    args = parser.parse_args()
    d = Path(args.dir)
    if not d.is_dir():
        parser.error(f"no directory {d} (run the scene's make target first, see doc/validation.md)")
    return d
