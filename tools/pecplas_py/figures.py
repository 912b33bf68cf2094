"""Writes a matplotlib figure the way pecplas writes its results: to a temporary name in the
target's directory, renamed onto the target when whole, so that a plot that is interrupted
never leaves a cut PNG (doc/results.md, "Safety")."""
import os
from pathlib import Path


def save_figure(fig, path, **kwargs):
    """fig.savefig(path, **kwargs) through `.NAME.<pid>.tmp` and an atomic rename."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    fmt = kwargs.pop("format", None) or path.suffix.lstrip(".") or None
    try:
        fig.savefig(tmp, format=fmt, **kwargs)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
