"""checks/compare_results.py, the check that a change leaves the results of input/ as they were,
on small files written here: equal files compare as 0; a number moved by 1e-10 of its
dataset's largest entry, a changed integer, string or exit code, a dataset or CSV row more or
less are each reported; time stamps, timings and checksum attributes are not compared."""
import json
from pathlib import Path

import h5py
import numpy as np

from pecplas_py.checks import compare_results as cr

ROOT = Path(__file__).resolve().parents[2]


def write_h5(path, u=(1.0, 2.0, -4.0), mode=(1, 2), status="completed", cpu=0.5, extra=False,
             created="2024-01-01"):
    with h5py.File(path, "w") as f:
        f.attrs["status"] = status
        f.attrs["created"] = created
        f.attrs["thickness"] = 1.0
        d = f.create_dataset("increments/000001/displacement", data=np.array(u))
        d.attrs["checksum"] = float(hash(tuple(u)) % 1000)
        f.create_dataset("increments/000001/joints/j/mode", data=np.array(mode, dtype=np.int32))
        f.create_dataset("history/cpu_time", data=np.array([cpu]))
        if extra:
            f.create_dataset("history/extra", data=np.zeros(2))


def compare(tmp_path, old_kw=None, new_kw=None):
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    write_h5(a, **(old_kw or {}))
    write_h5(b, **(new_kw or {}))
    w = cr.Worst()
    cr.compare_h5(a, b, w)
    return w


def test_equal_files_and_what_is_not_compared(tmp_path):
    w = compare(tmp_path, {}, {"cpu": 9.0, "created": "2025-02-02"})
    assert w.value == 0.0 and not w.problems, (w.value, w.problems)


def test_each_kind_of_difference_is_reported(tmp_path):
    w = compare(tmp_path, {}, {"u": (1.0, 2.0, -4.0 * (1 + 1e-10))})
    assert abs(w.value / 1e-10 - 1) < 1e-3 and "displacement" in w.where, (w.value, w.where)
    assert compare(tmp_path, {}, {"mode": (1, 3)}).problems
    assert "status" in compare(tmp_path, {}, {"status": "diverged"}).problems[0]
    assert "only in new" in compare(tmp_path, {}, {"extra": True}).problems[0]


def test_csv_columns(tmp_path):
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    a.write_text("step,tau,mode\n0, 1.0,stick\n1, 2.0,slip\n")
    b.write_text("step,tau,mode\n0, 1.0,stick\n1, 2.000000002,slip\n")
    w = cr.Worst()
    cr.compare_csv(a, b, w)
    assert abs(w.value - 1e-9) < 1e-12 and "tau" in w.where and not w.problems
    b.write_text("step,tau,mode\n0, 1.0,stick\n1, 2.0,open\n")
    w = cr.Worst()
    cr.compare_csv(a, b, w)
    assert w.problems and "mode" in w.problems[0]
    b.write_text("step,tau,mode\n0, 1.0,stick\n")
    w = cr.Worst()
    cr.compare_csv(a, b, w)
    assert w.problems


def test_exit_codes_and_missing_files(tmp_path, capsys):
    for side, code in (("old", 0), ("new", 3)):
        d = tmp_path / side
        (d / "s1").mkdir(parents=True)
        write_h5(d / "s1/x.h5")
        (d / cr.MANIFEST).write_text(json.dumps({"files": {"s1/x.h5": code, "s1/y.h5": 0}}))
    failed = cr.compare_dirs(tmp_path / "old", tmp_path / "new", 1e-12,
                             [("s1/x", "pecplas", None), ("s1/y", "pecplas", None)])
    out = capsys.readouterr().out
    assert failed == 1 and "exit code" in out, out
    assert "every deck" not in out and "1 of 2 decks differ" in out, out


def test_deck_comments_are_no_results(tmp_path):
    """Two decks that differ in a `**` comment line only (a generator's path) compare equal;
    a changed keyword line is reported from the first differing character."""
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    for path, text in ((a, "** by tools/x.py\n*STEP, INCREMENTS=20\n"),
                       (b, "** by tools/pecplas_py/decks/x.py\n*STEP, INCREMENTS=20\n")):
        write_h5(path)
        with h5py.File(path, "a") as f:
            f.attrs["deck_text"] = text
    w = cr.Worst()
    cr.compare_h5(a, b, w)
    assert not w.problems, w.problems
    with h5py.File(b, "a") as f:
        f.attrs["deck_text"] = "*STEP, INCREMENTS=30\n"
    w = cr.Worst()
    cr.compare_h5(a, b, w)
    assert w.problems and "'30'" in w.problems[0], w.problems
