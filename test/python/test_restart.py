"""Restart (doc/results.md, "Restart"): a run stopped in the middle of a step
(--stop-after-increments N, the test hook standing for a wall-time kill) and continued with
--restart equals the uninterrupted run; a results file of another deck is refused."""
import fcntl
import re
import shutil
import subprocess
import time
from pathlib import Path

import h5py
import numpy as np
import pytest

from footing_decks import deck
from pecplas_exe import pecplas_cmd

ROOT = Path(__file__).resolve().parents[2]


def run(args, cwd):
    # a restart that loops on its own (it did, resumed inside a limit probe) must not hang
    return subprocess.run(pecplas_cmd() + [str(a) for a in args] + ["--quiet"], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def last_fields(path):
    with h5py.File(path) as f:
        k = sorted(f["increments"])[-1]
        g = f["increments"][k]
        joints = {n: g["joints"][n]["stress"][:] for n in g.get("joints", {})}
        rows = list(zip(f["history/step"][:], f["history/increment"][:],
                        f["history/global_increment"][:]))
        return g["displacement"][:], joints, rows, f.attrs["status"]


# The uninterrupted run of each deck of the repository, run once per test process and shared
# by every test here that compares a run of that deck with it: those tests assert equality to
# the last bit with it, which holds only if the run is deterministic, so one run serves them
# all (it was run 15 times for 7 decks).
_UNINTERRUPTED = {}


def uninterrupted(deck, tmp_path):
    """tmp_path/full.h5, the results of the uninterrupted run of `deck`, with its exit code,
    stderr and seconds taken. A deck of the repository is run once, into the tmp_path of the
    first test asking, and linked into later ones; another deck (a variant written into
    tmp_path) is run each time."""
    d = Path(deck).resolve()
    full = tmp_path / "full.h5"
    key = (d, d.stat().st_mtime_ns)
    shared = ROOT in d.parents and tmp_path.resolve() not in d.parents
    if shared and key in _UNINTERRUPTED:
        path, code, err, seconds = _UNINTERRUPTED[key]
        full.symlink_to(path)
        return full, code, err, seconds
    t0 = time.monotonic()
    r = run([d, "-o", full], d.parent)
    result = (full, r.returncode, r.stderr, time.monotonic() - t0)
    if shared:
        _UNINTERRUPTED[key] = result
    return result


def interrupted_and_restarted(tmp_path, deck, n):
    """(full run, restarted run) results of `deck` stopped after n increments."""
    d = ROOT / deck
    part, rest = tmp_path / "part.h5", tmp_path / "rest.h5"
    full, code, err, _ = uninterrupted(d, tmp_path)
    assert code in (0, 3), err
    r = run([d, "-o", part, "--stop-after-increments", n], d.parent)
    assert r.returncode == 4, r.stderr  # interrupted
    with h5py.File(part) as f:
        assert f.attrs["status"] == "interrupted" and len(f["history/step"]) == n
    r = run([d, "-o", rest, "--restart", part], d.parent)
    assert r.returncode in (0, 3), r.stderr
    return last_fields(full), last_fields(part), last_fields(rest)


@pytest.mark.parametrize("deck,n", [
    # MODJOIN cyclic penalty joint, full Newton: stopped 10 increments into the first reversal
    ("test/data/modjoin/fe_cyclic.inp", 30),
    # the same, stopped where the last factorisation is a slipping joint's tangent: restarted
    # from the set-up stiffness instead (before the restart data carried that matrix) the
    # iterations took another path and the run ended 3.4e-7 of the largest displacement away
    ("test/data/modjoin/fe_cyclic.inp", 73),
    # Tresca footing, full Newton, plastic tangents (2e-7 away without the matrix)
    ("test/data/plasticity/footing_t6.inp", 13),
    # Katona contact (S1 box opening and closing): stopped in the middle of the opening step
    ("test/data/katona/s1_open_close.inp", 18),
    # Katona, friction limit: stopped after increment cuts (the halved size is resumed)
    ("test/data/katona/pad_slip.inp", 6)])
def test_restart_equals_uninterrupted(tmp_path, deck, n):
    """Final displacements and joint stresses equal the uninterrupted run's to the last bit
    (the same arithmetic from the same state, on the same machine and thread setting); the
    restarted history continues the interrupted one row for row."""
    (ua, ja, rows_a, st_a), (_, _, rows_b, _), (uc, jc, rows_c, st_c) = \
        interrupted_and_restarted(tmp_path, deck, n)
    assert st_a == st_c
    assert np.array_equal(uc, ua)
    assert ja.keys() == jc.keys()
    for name in ja:
        assert np.array_equal(jc[name], ja[name]), name
    assert rows_b + rows_c == rows_a


def test_restart_from_another_deck_is_refused(tmp_path):
    """A results file of another deck: exit 2, a message saying so, no results file."""
    a = ROOT / "test/data/katona/s1_open_close.inp"
    b = ROOT / "test/data/katona/pad_slip.inp"
    r = run([a, "-o", tmp_path / "a.h5", "--stop-after-increments", 3], a.parent)
    assert r.returncode == 4
    r = run([b, "-o", tmp_path / "b.h5", "--restart", tmp_path / "a.h5"], b.parent)
    assert r.returncode == 2
    assert "written by another deck" in r.stderr and "a.h5" in r.stderr
    assert not (tmp_path / "b.h5").exists()
    r = run([a, "-o", tmp_path / "a.h5", "--restart", tmp_path / "a.h5"], a.parent)
    assert r.returncode == 2 and "another file" in r.stderr


def test_sigterm_then_restart_equals_uninterrupted(tmp_path):
    """A real SIGTERM (what Slurm sends before its kill) in the middle of the MODJOIN cyclic
    run: exit 4, status 'interrupted'; the run restarted from that file ends where the
    uninterrupted run ends (displacements and joint stresses to the last bit). The signal is
    sent when the run prints its first increment of step 2 (of 5, 181 increments); the pipe
    it prints into holds one page (4096 bytes, about 30 progress lines), so the run is then
    at most that far ahead, well inside its steps, on any machine and load."""
    import signal
    d = ROOT / "test/data/modjoin/fe_cyclic.inp"
    part, rest = tmp_path / "part.h5", tmp_path / "rest.h5"
    if pecplas_cmd()[0] == "fpm":
        pytest.skip("the signal must reach pecplas itself, not `fpm run` (set PECPLAS_BIN)")
    full, code, err, _ = uninterrupted(d, tmp_path)
    assert code == 0, err
    with h5py.File(full) as f:
        total = len(f["history/step"])
    proc = subprocess.Popen(pecplas_cmd() + [str(d), "-o", str(part)], cwd=d.parent,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # the run's output blocks once a page is unread (it starts with a header of 5 lines)
    fcntl.fcntl(proc.stdout.fileno(), fcntl.F_SETPIPE_SZ, 4096)
    for line in proc.stdout:
        if re.match(r"\s*step\s+2\s", line):
            break
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 4, err
    with h5py.File(part) as f:
        assert f.attrs["status"] == "interrupted"
        done = len(f["history/step"])
    assert 0 < done < total
    r = run([d, "-o", rest, "--restart", part], d.parent)
    assert r.returncode == 0, r.stderr
    ua, ja, _, _ = last_fields(full)
    uc, jc, _, _ = last_fields(rest)
    print(f"SIGTERM after {done} of {total} increments; restarted to the end")
    assert np.array_equal(uc, ua)
    for name in ja:
        assert np.array_equal(jc[name], ja[name]), name



CYCLIC = ROOT / "test/data/modjoin/fe_cyclic.inp"
FOOTING = ROOT / "test/data/plasticity/footing_t6.inp"


def variant(tmp_path, deck, old, new):
    """`deck` copied into tmp_path with its *INCLUDE files, `old` -> `new` in its text."""
    text = deck.read_text()
    assert old in text
    for inc in deck.parent.glob("*.inc"):
        shutil.copy(inc, tmp_path / inc.name)
    out = tmp_path / deck.name
    out.write_text(text.replace(old, new))
    return out


def restart_links(path, set_name):
    """{restart item: the field of the last increment it is a hard link to, or None} for
    u and the stress, strain and history of the first element set (`set_name`), and
    whether the last increment has fields. An item not linked must be a flat copy."""
    items = {"u": "displacement", "stress_1": f"sets/{set_name}/stress",
             "strain_1": f"sets/{set_name}/strain", "hist_1": f"sets/{set_name}/state"}
    with h5py.File(path) as f:
        fields = bool(f["history/fields"][-1])
        group = f["increments"].get(f"{int(f['history/global_increment'][-1]):06d}")
        out = {}
        for name, field in items.items():
            item = f["restart"][name]
            target = group.get(field) if group is not None else None
            out[name] = field if target is not None and target.id == item.id else None
            if out[name] is None:
                assert item.ndim == 1, (name, item.shape)
        return out, fields


@pytest.mark.parametrize("every,linked", [
    # fields every increment: u, stresses and strains of the restart data are links to the
    # fields of increment 31 (the massif is elastic: no history)
    (1, {"u", "stress_1", "strain_1"}),
    # fields every 2nd increment of a step; increment 31 is the 11th of step 2: none, so
    # the restart data are copies
    (2, set())])
def test_restart_from_linked_or_copied_data(tmp_path, every, linked):
    """The MODJOIN cyclic run stopped after 31 increments and restarted equals the
    uninterrupted run to the last bit (final displacements and joint stresses: the same
    arithmetic from the same state), whether its restart data are
    links to the fields of the last increment or copies of their own."""
    deck = variant(tmp_path, CYCLIC, "*OUTPUT, EVERY=1\n", f"*OUTPUT, EVERY={every}\n")
    (ua, ja, rows_a, st_a), (_, _, rows_b, _), (uc, jc, rows_c, st_c) = \
        interrupted_and_restarted(tmp_path, deck, 31)
    links, fields = restart_links(tmp_path / "part.h5", "lower")
    assert fields == (every == 1)
    assert {n for n, t in links.items() if t} == linked, links
    assert st_a == st_c == "completed"
    assert np.array_equal(uc, ua)
    for name in ja:
        assert np.array_equal(jc[name], ja[name]), name
    assert rows_b + rows_c == rows_a


def test_plastic_restart_links_copies_and_values_agree(tmp_path):
    """The Tresca footing (Mohr-Coulomb, 6 history values per Gauss point, plastic from the
    first increments) stopped after 13 of its increments, its restart data links (fields
    every increment, the history included), copies (fields every 2nd increment) or values
    of fields not written (no stresses or strains in the fields): the three restarts end
    with the displacements of the uninterrupted run to the last bit (the same state and the
    same last factorised tangent restored, the same arithmetic)."""
    ends = {}
    for output, expect in [("*OUTPUT, EVERY=1", {"u", "stress_1", "strain_1", "hist_1"}),
                           ("*OUTPUT, EVERY=2", set()),
                           ("*OUTPUT, STRESSES=NO, STRAINS=NO", {"u"})]:
        d = tmp_path / str(len(ends))
        d.mkdir()
        deck = variant(d, FOOTING, "*OUTPUT, STRESSES=NO, STRAINS=NO\n", output + "\n")
        deck.write_text(deck.read_text().replace("INCREMENTS=100\n", "INCREMENTS=20\n"))
        (ua, _, _, _), _, (uc, _, _, st) = interrupted_and_restarted(d, deck, 13)
        links, _ = restart_links(d / "part.h5", "soil")
        assert {n for n, t in links.items() if t} == expect, (output, links)
        assert st == "completed"
        ends[output] = uc
    for output, uc in ends.items():
        assert np.array_equal(uc, ua), output


def test_restart_of_a_fallback_run_carries_its_tangent(tmp_path):
    """The Tresca footing under modified Newton: from its 12th increment on, the increments
    converge only by the full-Newton fallback, which keeps its own factorisation of the
    tangent and starts each increment with it. Stopped after 40 increments, the restart data
    hold that matrix (`tangent_operator`, not the run's own stiffness, which is still the
    set-up one) and the restarted run ends on the uninterrupted run's displacements to the
    last bit (without it: 4.9e-7 of their largest)."""
    deck = variant(tmp_path, FOOTING, "METHOD=NEWTON, TOLERANCE", "METHOD=MODIFIED_NEWTON, TOLERANCE")
    (ua, _, _, st_a), _, (uc, _, _, st_c) = interrupted_and_restarted(tmp_path, deck, 40)
    with h5py.File(tmp_path / "full.h5") as f:
        assert (f["history/method"][:] == 3).sum() > 50  # the fallback does the run's work
    with h5py.File(tmp_path / "part.h5") as f:
        r = f["restart"]
        assert list(r["operators"][:2]) == [0.0, 1.0]
        assert "tangent_operator" in r and "operator" not in r
    assert st_a == st_c == "completed"
    assert np.array_equal(uc, ua)


def test_restart_without_the_matrix(tmp_path):
    """*OUTPUT, EXACT_RESTART=NO: the restart data hold the state only (no factorised
    matrix); the restarted run solves its first iteration with the set-up stiffness and still
    completes, within 1e-5 of the uninterrupted run's largest displacement (a different first
    iteration, the same equilibrium to the Newton tolerance 1e-9; 3.4e-7 measured). Data of
    that kind (like those written before the matrix was carried) are read as they are; a
    matrix of the wrong size is refused with exit 2 and no results file."""
    deck = variant(tmp_path, CYCLIC, "*OUTPUT, EVERY=1\n", "*OUTPUT, EVERY=1, EXACT_RESTART=NO\n")
    (ua, _, _, _), _, (uc, _, _, st) = interrupted_and_restarted(tmp_path, deck, 73)
    with h5py.File(tmp_path / "part.h5") as f:
        assert "operator" not in f["restart"] and "tangent_operator" not in f["restart"]
        assert list(f["restart/operators"][:]) == [0.0, 0.0, 0.0, 0.0]
    assert st == "completed"
    assert np.abs(uc - ua).max() <= 1e-5 * np.abs(ua).max()
    # the default deck's data with a matrix cut short
    part = tmp_path / "cut.h5"
    r = run([CYCLIC, "-o", part, "--stop-after-increments", 73], CYCLIC.parent)
    assert r.returncode == 4, r.stderr
    with h5py.File(part, "r+") as f:
        v = f["restart/operator"][:]
        del f["restart/operator"]
        f["restart/operator"] = v[:-1]
    out = tmp_path / "refused.h5"
    r = run([CYCLIC, "-o", out, "--restart", part], CYCLIC.parent)
    assert r.returncode == 2, r.stderr
    assert "does not fit" in r.stderr and "operator" in r.stderr
    assert not out.exists()


def test_linked_restart_data_add_little(tmp_path):
    """A file of one increment with fields: what /restart adds to the fields alone (HDF5
    storage of the datasets of /increments and /restart, each object once) stays below
    20 %. Reason: u, stresses, strains and histories are links; what remains is the
    converged internal forces (2 values per node against 10 per node in displacement,
    displacement3, reaction and reaction3) and a few scalars. As copies the same items
    would add over half (checked on the same file, each link counted as a copy). The
    factorised matrix of an exact restart (doc/results.md) is not a field: this file is
    written with EXACT_RESTART=NO."""
    deck = variant(tmp_path, FOOTING, "*OUTPUT, STRESSES=NO, STRAINS=NO\n",
                   "*OUTPUT, EXACT_RESTART=NO\n")
    out = tmp_path / "one.h5"
    r = run([deck, "-o", out, "--stop-after-increments", 1], deck.parent)
    assert r.returncode == 4, r.stderr

    def storage(group):
        sizes = {}

        def visit(_, obj):
            if isinstance(obj, h5py.Dataset):
                sizes[h5py.h5o.get_info(obj.id).addr] = obj.id.get_storage_size()
        group.visititems(visit)
        return sizes

    with h5py.File(out) as f:
        fields = storage(f["increments"])
        restart = storage(f["restart"])
    alone = sum(fields.values())
    linked = sum(v for a, v in restart.items() if a not in fields)
    copied = sum(restart.values())
    print(f"fields {alone} B; /restart adds {linked} B linked, would add {copied} B copied")
    assert (alone + linked) / alone < 1.2
    assert (alone + copied) / alone > 1.5


def test_restart_items_leave_no_lost_space(tmp_path):
    """With fields every 3rd increment, restart items turn from datasets into links to the
    fields and back every few increments; the file space of a dataset deleted then would be
    lost at the next commit (HDF5 keeps no free space across a close). The bytes of the file
    not in any dataset (metadata, and lost space), per increment with fields, stay within
    1.5 times those of the run with fields every 2nd increment, where the items of each
    restart group never change kind (measured: 1.1 times with spare datasets, 5 times when
    deleting them)."""
    def overhead(every):
        d = tmp_path / str(every)
        d.mkdir()
        deck = variant(d, FOOTING, "*OUTPUT, STRESSES=NO, STRAINS=NO\n",
                       f"*OUTPUT, EVERY={every}\n")
        deck.write_text(deck.read_text().replace("INCREMENTS=100\n", "INCREMENTS=60\n"))
        out = d / "run.h5"
        r = run([deck, "-o", out], d)
        assert r.returncode == 0, r.stderr
        sizes = {}
        with h5py.File(out) as f:
            def visit(_, obj):
                if isinstance(obj, h5py.Dataset):
                    sizes[h5py.h5o.get_info(obj.id).addr] = obj.id.get_storage_size()
            f.visititems(visit)
            groups = len(f["increments"])
        return (out.stat().st_size - sum(sizes.values())) / groups
    two, three = overhead(2), overhead(3)
    print(f"bytes outside datasets per field increment: every 2: {two:.0f}, every 3: {three:.0f}")
    assert three <= 1.5 * two


def limit_of(path):
    with h5py.File(path) as f:
        g = f["limit"]
        return (g.attrs["kind"], int(g.attrs["global_increment"]), float(g.attrs["fraction"]),
                g["pattern_factors"][:].tolist())


@pytest.mark.parametrize("n", [
    # before the peak (increment 86 of 149): the path's length and direction are carried
    # (a first length computed anew from the restored tangent factorisation: 0.7 % off)
    20,
    # 14 increments beyond the peak: the peak found before the stop must still be reported
    # (without the carried state the restarted run reported a limit at increment 101,
    # fraction 0.563, for the true 86, 0.577)
    100])
def test_restart_inside_an_arc_length_step(tmp_path, n):
    """MODJOIN CNL shear under force control with CONTROL=ARC_LENGTH (peak and softening),
    stopped after n increments and restarted: the same final displacements to the last
    bit, the same status 'limit load' and the same limit (increment, fraction, load
    factors, exactly: the path's peak is part of the carried state)."""
    d = ROOT / "test/data/modjoin/fe_cnl_force_arc.inp"
    (ua, _, rows_a, st_a), (_, _, rows_b, _), (uc, _, rows_c, st_c) = \
        interrupted_and_restarted(tmp_path, d, n)
    assert st_a == st_c == "limit load"
    assert rows_b + rows_c == rows_a
    assert limit_of(tmp_path / "rest.h5") == limit_of(tmp_path / "full.h5")
    assert np.array_equal(uc, ua)


def test_restart_inside_a_limit_probe(tmp_path):
    """A rigid footing on Tresca soil pushed by a force beyond its bearing capacity, load
    control: the step cannot be converged at any cut after 23 increments and the arc-length
    probe takes over (doc/theory.md §4). Stopped after 24 increments, inside the probe, and
    restarted: the probe goes on (it looped for ever on zero-size load increments before the
    probe's state was carried) and the run ends as the uninterrupted one, status 'limit
    load' with the same limit and final displacements to the last bit."""
    text = deck(nf=2, stiff_footing=True, drive="pressure", pressure=70.0, increments=20,
                solver="*SOLVER, METHOD=NEWTON, MAX_ITERATIONS=30, MAX_CUTS=8")
    d = tmp_path / "force.inp"
    d.write_text(text)
    (ua, _, rows_a, st_a), _, (uc, _, rows_c, st_c) = interrupted_and_restarted(tmp_path, d, 24)
    with h5py.File(tmp_path / "full.h5") as f:
        control = f["history/control"][:]
    assert control[:23].sum() == 0 and control[23] == 1  # increment 24 is the probe's first
    assert st_a == st_c == "limit load"
    assert limit_of(tmp_path / "rest.h5") == limit_of(tmp_path / "full.h5")
    assert np.array_equal(uc, ua)


@pytest.mark.parametrize("deck,every", [
    ("test/data/katona/s1_open_close.inp", 2),   # Katona opening and closing, 35 increments
    ("test/data/katona/pad_slip.inp", 2),        # Katona friction limit (cuts, limit load)
    ("input/s2/s2_katona.inp", 3),               # S2 pile, Katona shaft
    ("test/data/modjoin/fe_cyclic.inp", 9),      # MODJOIN cyclic, full Newton
    ("test/data/modjoin/fe_cnl_force_arc.inp", 8),   # arc-length through a peak
    ("test/data/modjoin/fe_cnl_arc_then_load.inp", 1)])  # arc-length landing, then load
def test_restart_anywhere(tmp_path, deck, every):
    """Stopped after every `every`-th increment and restarted, each run stops after exactly
    that increment and the restarted one ends as the uninterrupted one: the same status, the same limit when there is one, the same final
    displacements to the last bit (the restart data carry all the run's arithmetic depends
    on, wherever it stops)."""
    d = ROOT / deck
    full, code, err, _ = uninterrupted(d, tmp_path)
    assert code in (0, 3), err
    ua, _, _, st_a = last_fields(full)
    total = len(h5py.File(full)["history/step"])
    bad = []
    for n in range(1, total, every):
        part, rest = tmp_path / f"p{n}.h5", tmp_path / f"r{n}.h5"
        r = run([d, "-o", part, "--stop-after-increments", n], d.parent)
        assert r.returncode == 4, (n, r.stderr)
        r = run([d, "-o", rest, "--restart", part], d.parent)
        assert r.returncode in (0, 3), (n, r.stderr)
        uc, _, rows, st_c = last_fields(rest)
        # stopped after exactly n increments (also one that lands on a step's target)
        assert len(rows) == total - n, (n, len(rows))
        err = np.abs(uc - ua).max() / np.abs(ua).max()
        same_limit = st_a != "limit load" or limit_of(rest) == limit_of(full)
        if st_c != st_a or err != 0.0 or not same_limit:
            bad.append((n, st_c, err, same_limit))
        part.unlink()
        rest.unlink()
    assert not bad, f"restarts that differ from the uninterrupted run (of {total}): {bad}"


def test_exact_restart_modes(tmp_path):
    """*OUTPUT, EXACT_RESTART= (doc/results.md). ON_STOP, the default: the factorised matrix
    is written only with the increment after which the run stops (--stop-after-increments,
    a signal), so a run that is not stopped writes none (its cost per increment is saved).
    ALWAYS: written with every increment, so that even a run killed outright (SIGKILL, no
    chance to write anything more) restarts from its `.tmp` file to the uninterrupted run's
    final displacements to the last bit."""
    import signal
    d = ROOT / "test/data/modjoin/fe_cyclic.inp"
    full, code, err, _ = uninterrupted(d, tmp_path)
    assert code == 0, err
    with h5py.File(full) as f:
        assert "operator" not in f["restart"] and f["restart/operators"][3] == 0.0
    deck = variant(tmp_path, CYCLIC, "*OUTPUT, EVERY=1\n", "*OUTPUT, EVERY=1, EXACT_RESTART=ALWAYS\n")
    ua, _, _, _ = last_fields(full)
    every = tmp_path / "always.h5"
    assert run([deck, "-o", every], tmp_path).returncode == 0
    with h5py.File(every) as f:
        assert "operator" in f["restart"] and f["restart/operators"][3] == 1.0
    if pecplas_cmd()[0] == "fpm":
        pytest.skip("the signal must reach pecplas itself, not `fpm run` (set PECPLAS_BIN)")
    killed = tmp_path / "killed.h5"
    # killed when it prints its first increment of step 2 (of 5): its output pipe holds one
    # page (about 30 progress lines), so it is then that far ahead at most, on any load
    proc = subprocess.Popen(pecplas_cmd() + [str(deck), "-o", str(killed)], cwd=tmp_path,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    fcntl.fcntl(proc.stdout.fileno(), fcntl.F_SETPIPE_SZ, 4096)
    for line in proc.stdout:
        if re.match(r"\s*step\s+2\s", line):
            break
    proc.send_signal(signal.SIGKILL)
    proc.communicate(timeout=60)
    left = sorted(tmp_path.glob(".killed.h5.*.tmp"))
    assert proc.returncode == -signal.SIGKILL and len(left) == 1, (proc.returncode, left)
    rest = tmp_path / "rest.h5"
    r = run([deck, "-o", rest, "--restart", left[0]], tmp_path)
    assert r.returncode == 0, r.stderr
    uc, _, _, _ = last_fields(rest)
    with h5py.File(left[0]) as f:
        print(f"SIGKILL after {len(f['history/step'])} increments; restarted to the end")
    assert np.array_equal(uc, ua)


@pytest.mark.parametrize("damaged,item", [
    # restart data of test/data/cli/oedometer.inp stopped after 2 increments, a byte of the
    # dataspace of /restart/u changed (found by corrupting the file at random): 2.4e9 values
    # announced; the run read and copied them for minutes (a hang)
    ("oedometer_u_extent.h5", "/restart/u"),
    # /restart/position announced with 1.1e12 values: the allocation failed, exit 1 with a
    # runtime backtrace
    ("oedometer_position_extent.h5", "/restart/position"),
])
def test_restart_from_a_damaged_extent_is_an_input_error(tmp_path, damaged, item):
    d = ROOT / "test" / "data" / "cli" / "oedometer.inp"
    src = ROOT / "test" / "data" / "restart_damaged" / damaged
    out = tmp_path / "out.h5"
    r = subprocess.run(pecplas_cmd() + [str(d), "-o", str(out), "--quiet", "--restart",
                                        str(src)], cwd=tmp_path, capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 2, r.stderr[-2000:]
    assert f"dataset {item} is damaged" in r.stderr and "more than the file holds" in r.stderr
    assert not out.exists() and not list(tmp_path.glob(".out.h5*"))


OEDOMETER = ROOT / "test" / "data" / "cli" / "oedometer.inp"


def run_oedometer(*args):
    # the deck named as in the files of test/data/restart_damaged, from its folder (the deck
    # text recorded in a results file starts with the deck's path as given)
    return subprocess.run(pecplas_cmd() + [OEDOMETER.name, "--quiet"] + [str(a) for a in args],
                          cwd=OEDOMETER.parent, capture_output=True, text=True, timeout=60)


def restart_oedometer(tmp_path, source):
    out = tmp_path / "out.h5"
    return run_oedometer("-o", out, "--restart", source), out


@pytest.mark.parametrize("item", ["fint_conv", "u"])
def test_restart_refuses_a_value_changed_by_one_ulp(tmp_path, item):
    # every real dataset keeps the checksum of its values: one value of the restart data
    # moved by one unit in the last place (an item of its own, fint_conv, and one that is a
    # link to the increment's displacement field, u) is a damaged file, exit 2, no results.
    # Without the checksum the run restarted from the changed value and completed (exit 0).
    part = tmp_path / "part.h5"
    r = run_oedometer("-o", part, "--stop-after-increments", 2)
    assert r.returncode == 4, r.stderr
    with h5py.File(part, "r+") as f:
        d = f["restart"][item]
        a = d[()]
        flat = a.reshape(-1)
        k = int(np.argmax(np.abs(flat)))
        flat[k] = np.nextafter(flat[k], np.inf)
        d[...] = flat.reshape(a.shape)
    r, out = restart_oedometer(tmp_path, part)
    assert r.returncode == 2, r.stderr
    assert (f"dataset /restart/{item} is damaged: its values do not match their checksum"
            in r.stderr)
    assert not out.exists()


def test_restart_from_a_file_that_crashes_the_hdf5_library(tmp_path):
    # a randomly damaged restart file on which HDF5 1.10 (Debian 12) crashes inside H5Fopen
    # (a segmentation fault, exit -11 before): an input error with a message, no results
    r, out = restart_oedometer(tmp_path, ROOT / "test" / "data" / "restart_damaged" /
                               "oedometer_crashes_hdf5.h5")
    assert r.returncode == 2, (r.returncode, r.stderr[-2000:])
    assert "cannot restart from" in r.stderr and "damaged" in r.stderr
    assert not out.exists()


def test_restart_from_a_file_written_before_checksums(tmp_path):
    # restart data written by an earlier version (no checksums, the deck identified by its
    # text): read as before, the run ends where the uninterrupted one does
    r, out = restart_oedometer(tmp_path, ROOT / "test" / "data" / "restart_damaged" /
                               "oedometer_before_checksums.h5")
    assert r.returncode == 0, r.stderr
    full = tmp_path / "full.h5"
    r = run_oedometer("-o", full)
    assert r.returncode == 0, r.stderr
    u1, u2 = last_fields(out)[0], last_fields(full)[0]
    # not to the last bit: the fixture's state was computed by another build (4.7e-16 of the
    # largest displacement measured with three OpenBLAS kernels). The deck is linear elastic,
    # so the increments after the restart correct any error of the state they start from
    # (u = u_s + K^-1 (F - K u_s)): what remains is the rounding of those residuals and solves,
    # a small multiple of cond(K) eps for a backward-stable Cholesky solve (Higham, Accuracy
    # and Stability of Numerical Algorithms, 2nd ed., thm 10.4); 16 cond(K) eps covers both
    # runs, two increments each.
    bound = 16 * oedometer_condition() * np.finfo(float).eps
    assert np.max(np.abs(u1 - u2)) <= bound * np.max(np.abs(u2))


def oedometer_condition():
    # condition number of the oedometer's stiffness on its two free dofs (u_y of nodes 3 and
    # 4: sides on rollers, base fixed): the unit-square Q4 of the deck, plane strain,
    # E = 1e4, nu = 0.3, 2x2 Gauss points
    e, nu = 1.0e4, 0.3
    c = e / ((1 + nu) * (1 - 2 * nu))
    d = c * np.array([[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])
    xy = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    k = np.zeros((8, 8))
    g = 1 / np.sqrt(3)
    for xi in (-g, g):
        for eta in (-g, g):
            dn = 0.25 * np.array([[-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)],
                                  [-(1 - xi), -(1 + xi), 1 + xi, 1 - xi]])
            jac = dn @ xy
            dx = np.linalg.solve(jac, dn)
            b = np.zeros((3, 8))
            b[0, 0::2] = dx[0]
            b[1, 1::2] = dx[1]
            b[2, 0::2] = dx[1]
            b[2, 1::2] = dx[0]
            k += b.T @ d @ b * np.linalg.det(jac)
    free = [5, 7]
    return np.linalg.cond(k[np.ix_(free, free)])


def test_restart_from_a_file_with_the_whole_operator(tmp_path):
    # restart data of a CHOLMOD run written when the stiffness was stored whole (commit
    # a28947a: 912 values in /restart/operator): the run now stores the upper triangle (480)
    # and takes it from the whole matrix; refused before ("has 912 values where this deck
    # needs 480"). The restarted run repeats the uninterrupted one's arithmetic. (The deck is
    # loaded by forces: that version's data do not carry the point tangents that the first
    # iteration of an imposed-displacement increment now uses.)
    d = ROOT / "test" / "data" / "restart_earlier" / "footing_q8.inp"
    old = d.parent / "footing_q8_whole_operator.h5"
    with h5py.File(old) as f:
        assert f["restart/operator"].shape == (912,) and f["restart/operators"][0] == 1.0
    rest, full = tmp_path / "rest.h5", tmp_path / "full.h5"
    r = run([d.name, "-o", rest, "--restart", old], d.parent)
    assert r.returncode == 0, r.stderr
    r = run([d.name, "-o", full], d.parent)
    assert r.returncode == 0, r.stderr
    u1, _, rows1, _ = last_fields(rest)
    u2, _, rows2, _ = last_fields(full)
    assert rows1 == rows2[4:]
    assert np.max(np.abs(u1 - u2)) <= 1e-12 * np.max(np.abs(u2))
    with h5py.File(rest) as a, h5py.File(full) as b:
        assert list(a["history/iterations"][:]) == list(b["history/iterations"][4:])


def test_restart_with_the_deck_named_by_another_path(tmp_path):
    # the deck text holds the path of each file read; a restart compares the text without
    # those paths: the deck given by its absolute path, from another directory, is the same
    # deck (refused as another deck before), while an edited copy is still refused
    part = tmp_path / "part.h5"
    r = run_oedometer("-o", part, "--stop-after-increments", 2)
    assert r.returncode == 4, r.stderr
    out = tmp_path / "out.h5"
    r = subprocess.run(pecplas_cmd() + [str(OEDOMETER), "-o", str(out), "--quiet",
                                        "--restart", str(part)],
                       cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    edited = tmp_path / "oedometer.inp"
    edited.write_text(OEDOMETER.read_text().replace("*TITLE\n", "*TITLE\n** edited\n"))
    r = subprocess.run(pecplas_cmd() + [edited.name, "-o", str(tmp_path / "e.h5"),
                                        "--quiet", "--restart", str(part)],
                       cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "written by another deck" in r.stderr, r.stderr


def test_deck_longer_than_the_stack_runs_stops_and_restarts(tmp_path):
    """A deck text of 12 MB (a keyword mesh of about 1e6 nodes is 40 MB) is identified for
    the results file and for a restart: the identity was built in a stack buffer of the
    text's length, and every deck over the 8 MB stack crashed with a segfault when the
    results file was created. Here the oedometer with 12 MB of comment lines."""
    src = (ROOT / "test/data/cli/oedometer.inp").read_text()
    pad = "".join(f"** padding {i:07d}: the deck text of a large keyword mesh is this long, "
                  f"and longer\n" for i in range(150000))
    d = tmp_path / "big.inp"
    d.write_text(src + pad)
    assert d.stat().st_size > 12e6
    full, part, rest = tmp_path / "full.h5", tmp_path / "part.h5", tmp_path / "rest.h5"
    r = run([d, "-o", full], ROOT)
    assert r.returncode == 0, r.stderr
    r = run([d, "-o", part, "--stop-after-increments", 3], ROOT)
    assert r.returncode == 4, r.stderr
    r = run([d, "-o", rest, "--restart", part], ROOT)
    assert r.returncode == 0, r.stderr
    u_full, _, rows_full, status = last_fields(full)
    u_rest, _, rows_rest, status_rest = last_fields(rest)
    assert status == status_rest == "completed"
    assert rows_rest == rows_full[3:]  # the restarted file holds the increments after 3
    # linear elastic oedometer: the restarted run repeats the uninterrupted one to roundoff
    assert np.array_equal(u_rest, u_full)
