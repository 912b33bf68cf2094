"""Results-file safety of the `pecplas` executable (doc/results.md, "Safety"): results never
overwrite an input, a run writes a temporary file renamed onto the target only when it ends,
a write failure ends with exit 3 and one line on stderr, SIGTERM ends with status
'interrupted' and exit 4, and kill -9 at any moment leaves readable, consistent files
(restartable) and the previous result untouched.

Run from the project root: python3 -m pytest test/python/test_results_safety.py
(uses $PECPLAS_BIN, else the executable of `fpm run`).
"""

import hashlib
import os
import random
import re
import shutil
import signal
import subprocess
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

from pecplas_exe import exe_path

ROOT = Path(__file__).resolve().parents[2]
from pecplas_py.checks import check_results

OEDOMETER = ROOT / "test" / "data" / "cli" / "oedometer.inp"
INCLUDES = ROOT / "test" / "data" / "decks"
S6 = ROOT / "input" / "s6" / "s6_modjoin.inp"


@pytest.fixture(scope="module")
def exe():
    """The pecplas executable itself (kill must reach it, not an `fpm run` wrapper)."""
    return exe_path("pecplas")


def digest(path):
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def run(exe, *args, env=None, cwd=None):
    full = dict(os.environ, **(env or {}))
    return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, env=full,
                          cwd=cwd, timeout=120)


def temporaries(directory):
    return sorted(p for p in Path(directory).iterdir() if p.name.endswith(".tmp"))


def check_file(h5, xmf, status):
    """pecplas_py.checks.check_results (in this process): structure, history rows against field
    groups, every XDMF reference a dataset of the file with its shape, no NaN."""
    problems, _ = check_results.check(str(h5), status, str(xmf))
    assert not problems, f"{h5}: {problems}"


@pytest.fixture(scope="module")
def s6_deck(tmp_path_factory):
    """The S6 MODJOIN deck (135 increments) with fields every 10th increment: a run of
    a few tenths of a second with many commit points, and files quick to check."""
    deck = tmp_path_factory.mktemp("deck") / "s6.inp"
    text = S6.read_text()
    assert "*OUTPUT, EVERY=1\n" in text
    deck.write_text(text.replace("*OUTPUT, EVERY=1\n", "*OUTPUT, EVERY=10\n"))
    return deck


def test_output_never_overwrites_an_input(exe, tmp_path):
    # the deck itself, an *INCLUDE file (also under another spelling), and a deck whose
    # .xmf sidecar would be the input
    shutil.copytree(INCLUDES / "inc", tmp_path / "inc")
    deck = tmp_path / "main.inp"
    shutil.copy(INCLUDES / "good_t6_main.inp", deck)
    inputs = {p: digest(p) for p in tmp_path.rglob("*.inp")}
    for target in ["main.inp", "inc/t6_nodes.inp", "./inc/../inc/t6_material.inp"]:
        r = run(exe, "main.inp", "-o", target, "--quiet", cwd=tmp_path)
        assert r.returncode == 2, r.stderr
        line = r.stderr.strip()
        assert "\n" not in line and "would overwrite the input file" in line, line
        assert Path(target).name in line and "choose another name with -o" in line, line
    (tmp_path / "side.xmf").write_text("not results\n")
    shutil.copy(deck, tmp_path / "side.inp")
    text = (tmp_path / "side.inp").read_text().replace(
        "*TITLE", "*INCLUDE, FILE=side.xmf\n*TITLE", 1)
    (tmp_path / "side.inp").write_text(text)
    # side.xmf holds no keyword line: including it adds nothing, but it is an input
    r = run(exe, "side.inp", "-o", "side.h5", "--quiet", cwd=tmp_path)
    assert r.returncode == 2 and "side.xmf" in r.stderr, r.stderr
    assert {p: digest(p) for p in tmp_path.rglob("*.inp") if p.name != "side.inp"} == inputs
    assert (tmp_path / "side.xmf").read_text() == "not results\n"
    assert not list(tmp_path.glob("*.h5")) and not temporaries(tmp_path)


def test_write_failure_keeps_earlier_increments_and_old_result(exe, tmp_path):
    out = tmp_path / "oed.h5"
    assert run(exe, OEDOMETER, "-o", out, "--quiet").returncode == 0
    old = digest(out), digest(tmp_path / "oed.xmf")
    r = run(exe, OEDOMETER, "-o", out, env={"PECPLAS_TEST_FAIL_WRITE": "3"})
    assert r.returncode == 3, r.stderr
    lines = r.stderr.strip().splitlines()
    # one line, ours: the HDF5 library's own error stack is off
    assert len(lines) == 1 and lines[0].startswith("pecplas: error: cannot write results"), lines
    assert "HDF5-DIAG" not in r.stderr and "PECPLAS_TEST_FAIL_WRITE=3" in lines[0]
    # the old result is untouched; the run's increments 1-2 are in its temporary file
    assert (digest(out), digest(tmp_path / "oed.xmf")) == old
    h5, xmf = temporaries(tmp_path)
    assert h5.name.startswith(".oed.h5.") and xmf.name.startswith(".oed.xmf.")
    assert h5.name in lines[0]
    with h5py.File(h5, "r") as f:
        assert f.attrs["status"] == "running" and f.attrs["complete"] == 0
        assert list(f["history/global_increment"][()]) == [1, 2]
    check_file(h5, xmf, "running")


def test_sigterm_ends_as_interrupted_with_exit_4(exe, s6_deck, tmp_path):
    out = tmp_path / "s6.h5"
    proc = subprocess.Popen([exe, str(s6_deck), "-o", str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    # progress lines are flushed one by one: wait for the 10th increment
    for line in proc.stdout:
        if re.match(r"\s*step\s+1\s+\S+\s+inc\s+10\b", line):
            break
    proc.send_signal(signal.SIGTERM)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode == 4, stderr
    assert "interrupted" in stderr and "SIGTERM" in stderr, stderr
    with h5py.File(out, "r") as f:
        assert f.attrs["status"] == "interrupted" and f.attrs["complete"] == 0
        n = len(f["history/step"])
        assert 10 <= n < 135, n  # stopped between increments, before the last (135)
    check_file(out, tmp_path / "s6.xmf", "interrupted")
    assert not temporaries(tmp_path)


def test_rerun_while_old_file_is_open(exe, tmp_path):
    out = tmp_path / "oed.h5"
    assert run(exe, OEDOMETER, "-o", out, "--quiet").returncode == 0
    with h5py.File(out, "r") as old:
        rows = len(old["history/step"])
        r = run(exe, OEDOMETER, "-o", out, "--quiet")
        assert r.returncode == 0, r.stderr
        # the reader still sees the whole old file; the target is the new, complete one
        assert len(old["history/step"]) == rows and old["increments/000006/displacement"].shape
    check_file(out, tmp_path / "oed.xmf", "completed")


def last_displacement(path):
    with h5py.File(path, "r") as f:
        last = sorted(f["increments"])[-1]
        return f["increments"][last]["displacement"][()], len(f["history/step"])


def restart_to_end(exe, deck, source, target, rows):
    """Restarts `deck` from the results file `source` into `target` (removed after):
    the last displacement, after checking the restart wrote the `rows` missing increments."""
    r = run(exe, deck, "-o", target, "--quiet", "--restart", source)
    assert r.returncode == 0, r.stderr
    u, n = last_displacement(target)
    assert n == rows, (n, rows)
    target.unlink()
    target.with_suffix(".xmf").unlink()
    return u


def check_left_by_kill(directory, stem):
    """What a killed run left beside the target: its results `.STEM.h5.<pid>.tmp` open and
    are consistent (status running, whole history rows, one increment group per row with
    fields); its sidecar `.STEM.xmf.<pid>.tmp`, when there is one, parses and names only
    datasets of that file; it is there as soon as the file holds an increment. Returns the
    results file (None: killed before its first publication) and its history length."""
    h5s = sorted(p for p in Path(directory).iterdir()
                 if p.name.startswith(f".{stem}.h5.") and p.name.endswith(".tmp"))
    xmfs = sorted(p for p in Path(directory).iterdir()
                  if p.name.startswith(f".{stem}.xmf.") and p.name.endswith(".tmp"))
    assert len(h5s) <= 1 and len(xmfs) <= 1, (h5s, xmfs)
    if not h5s:
        assert not xmfs, "a sidecar without its results file"
        return None, 0
    h5 = h5s[0]
    with h5py.File(h5, "r") as f:
        rows = len(f["history/step"])
    sidecar = Path(directory) / h5.name.replace(f".{stem}.h5.", f".{stem}.xmf.")
    if sidecar.exists():
        check_file(h5, sidecar, "running")
    else:
        assert rows == 0, f"{h5.name}: {rows} increments but no sidecar"
        problems, _ = check_results.check(str(h5), "running", xdmf=False)
        assert not problems, problems
    return h5, rows


def test_kill9_at_random_moments(exe, s6_deck, tmp_path):
    """20 runs killed with SIGKILL at random moments (seeded): the previous result stays
    byte for byte unless the run ended first; the running results left, `.NAME.h5.<pid>.tmp`
    and its sidecar, open and are consistent every time (the published copy of the two the
    run writes is never written, doc/results.md); the first killed run that left some but
    not all increments is restarted from that file: it ends as the same run stopped cleanly
    after those increments and restarted does."""
    out = tmp_path / "s6.h5"
    xmf = tmp_path / "s6.xmf"
    t0 = time.monotonic()
    assert run(exe, s6_deck, "-o", out, "--quiet").returncode == 0
    duration = time.monotonic() - t0
    u_full, total = last_displacement(out)
    rng = random.Random(20240611)
    outcomes = {"killed": 0, "finished": 0, "left rows": []}
    restarted = None
    for _ in range(20):
        old = digest(out), digest(xmf)
        proc = subprocess.Popen([exe, str(s6_deck), "-o", str(out), "--quiet"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(rng.uniform(0.0, 1.1*duration))
        proc.kill()
        code = proc.wait()
        if code == 0:
            outcomes["finished"] += 1
            check_file(out, xmf, "completed")
        else:
            outcomes["killed"] += 1
            assert code == -signal.SIGKILL
            if digest(out) == old[0]:
                # the old result, byte for byte (the .xmf is renamed after the .h5)
                assert digest(xmf) == old[1]
            else:
                # killed after the .h5 rename: the new file is a whole, completed result
                check_file(out, xmf, "completed")
        h5, rows = check_left_by_kill(tmp_path, "s6")
        outcomes["left rows"].append(rows)
        if restarted is None and h5 is not None and 0 < rows < total:
            restarted = rows
            # the checker names the file to keep (doc/results.md, "After kill -9")
            lines, sound = check_results.left_behind(str(out))
            assert sound and len(lines) == 1 and f"keep {h5} with its sidecar" in lines[0], lines
            u_killed = restart_to_end(exe, s6_deck, h5, tmp_path / "restarted.h5", total - rows)
            # the same run stopped cleanly after as many increments (its restart data then
            # exact, EXACT_RESTART=ON_STOP: doc/results.md) restarts to the uninterrupted
            # run's end to the last bit
            part = tmp_path / "part.h5"
            r = run(exe, s6_deck, "-o", part, "--quiet", "--stop-after-increments", rows)
            assert r.returncode == 4, r.stderr
            u_clean = restart_to_end(exe, s6_deck, part, tmp_path / "restarted.h5", total - rows)
            assert np.array_equal(u_clean, u_full)
            # the killed run left the state only: its restart equals a clean stop's whose data
            # are the state only too (EXACT_RESTART=NO), to the last bit ...
            state_deck = tmp_path / "s6_state.inp"
            state_deck.write_text(s6_deck.read_text().replace(
                "*OUTPUT, EVERY=10\n", "*OUTPUT, EVERY=10, EXACT_RESTART=NO\n"))
            part = tmp_path / "part_state.h5"
            r = run(exe, state_deck, "-o", part, "--quiet", "--stop-after-increments", rows)
            assert r.returncode == 4, r.stderr
            u_state = restart_to_end(exe, state_deck, part, tmp_path / "restarted.h5",
                                     total - rows)
            assert np.array_equal(u_killed, u_state)
            # ... and is near the uninterrupted run: its first Newton iteration uses the
            # stiffness factorised at set-up, so the later increments meet the residual
            # tolerance at other points (2.6e-7 measured, killed after 81 increments)
            assert np.abs(u_killed - u_full).max() <= 1e-5 * np.abs(u_full).max()
        for p in tmp_path.iterdir():
            if p.name.startswith(".") or p.name.startswith("part"):
                p.unlink()
    print(f"kill -9: {outcomes}; restarted after {restarted} of {total} increments")
    assert outcomes["killed"] >= 10, outcomes
    assert restarted is not None, outcomes


def datasets(path):
    """Every dataset of an HDF5 file, by path, as NumPy arrays."""
    found = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: found.__setitem__(name, obj[()])
                     if isinstance(obj, h5py.Dataset) else None)
    return found


def test_kernel_copy_and_its_fallback_give_the_same_file(exe, tmp_path):
    """The second copy of a new file is a kernel copy of the first (doc/results.md,
    Safety); with the copy refused (PECPLAS_TEST_NO_KERNEL_COPY=1) HDF5 writes it again.
    Both runs end alike, and their files hold the same datasets bit for bit (the oedometer's
    mesh, fields, history except the CPU times) and pass the checker."""
    files = {}
    for name, env in (("copied", {}), ("written", {"PECPLAS_TEST_NO_KERNEL_COPY": "1"})):
        out = tmp_path / f"{name}.h5"
        r = run(exe, OEDOMETER, "-o", out, "--quiet", env=env)
        assert r.returncode == 0 and not r.stderr, r.stderr
        assert not temporaries(tmp_path), "a finished run leaves no temporary file"
        check_file(out, tmp_path / f"{name}.xmf", "completed")
        files[name] = datasets(out)
    copied, written = files["copied"], files["written"]
    assert sorted(copied) == sorted(written) and any(k.startswith("mesh/") for k in copied)
    for key in copied:
        if key != "history/cpu_time":
            assert np.array_equal(copied[key], written[key]), key


def test_checksum_definition():
    # Fletcher's sums by hand: words 1, 2, 3 give s1 = 6, s2 = 1 + 3 + 6 = 10
    assert check_results.fletcher([1, 2, 3]) == 10 * 2**26 + 6
    # modulo P: a word of P counts as 0
    assert check_results.fletcher([check_results.CHECKSUM_P, 5]) == 5 * 2**26 + 5
    # a value is its low then its high 32-bit word: 1.0 = 0x3FF00000_00000000
    assert check_results.values_checksum([1.0]) == check_results.fletcher([0, 0x3FF00000])
    # a text is one word per UTF-8 byte ('é' is two)
    assert check_results.text_checksum("é") == check_results.fletcher([0xC3, 0xA9])
    # many words (more than one 4096 block): the closed form against a plain loop
    rng = np.random.default_rng(1)
    w = rng.integers(0, 2**32, size=10000, dtype=np.int64)
    s1 = s2 = 0
    for x in w:
        s1 = (s1 + int(x)) % check_results.CHECKSUM_P
        s2 = (s2 + s1) % check_results.CHECKSUM_P
    assert check_results.fletcher(w) == s2 * 2**26 + s1


def test_failure_to_write_the_end_of_run_warning_keeps_the_increments(exe, tmp_path):
    """A unit square of E = 1 kPa pulled by 10 kN in 3 increments moves ~9 m: the small-strain
    warning is found at the end of the run and written into the file then. When that write
    fails (the hook's 4th write, after the 3 increments), the run ends as a write failure:
    exit 3 and one error line naming the .tmp file, which keeps the 3 increments with status
    'running'; the target is not created. (It exited 1, an internal error, with the file left
    unfinished.)"""
    deck = tmp_path / "soft.inp"
    deck.write_text("*UNITS\nkN, m, kPa\n*NODES\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n"
                    "*ELEMENTS, TYPE=Q4, SET=block\n1, 1, 2, 3, 4\n"
                    "*MATERIAL, NAME=soft\nE = 1, NU = 0.3\n*SECTION, SET=block, MATERIAL=soft\n"
                    "*NSET, NAME=base\n1, 2\n*NSET, NAME=top\n3, 4\n*BOUNDARY\nbase, XY\n"
                    "*LOAD, NAME=pull, TYPE=FORCE\ntop, Y, 5\n*STEP, NAME=pull, INCREMENTS=3\n"
                    "pull, 1\n")
    out = tmp_path / "soft.h5"
    r = run(exe, deck, "-o", out, "--quiet", env={"PECPLAS_TEST_FAIL_WRITE": "4"})
    assert r.returncode == 3, r.stderr
    errors = [s for s in r.stderr.splitlines() if s.startswith("pecplas: error:")]
    assert len(errors) == 1 and "cannot write results" in errors[0], r.stderr
    assert "small-strain theory no longer holds" in r.stderr
    assert not out.exists()
    h5, xmf = temporaries(tmp_path)
    assert h5.name in errors[0]
    with h5py.File(h5, "r") as f:
        assert f.attrs["status"] == "running" and f.attrs["complete"] == 0
        assert list(f["history/global_increment"][()]) == [1, 2, 3]
    check_file(h5, xmf, "running")
