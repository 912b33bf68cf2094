"""Warnings channel and errors with deck lines, through the `pecplas` command.

- test/data/trust/warn_all.inp runs to completion (exit 0) with one warning of each deck-time
  kind; each is printed on stderr as "file:line: warning: ..." and stored in the results
  file's root attribute `warnings` (a list of strings, doc/results.md).
- --strict turns the first warning into an input error: exit 2, no results file.
- errors found after reading (a concave element, a singular stiffness) name the deck line of
  the element or node."""
import subprocess
from pathlib import Path

import h5py
import pytest
from pecplas_exe import pecplas_cmd

from pecplas_py.results import Results

ROOT = Path(__file__).resolve().parents[2]
TRUST = ROOT / "test" / "data" / "trust"

# line of warn_all.inp each warning must name, and a phrase of its text
WARNINGS = [(24, "PHI = 0.5236"), (25, "material 'spare' is used by no *SECTION"),
            (30, "node set 'lonely' is used by no"), (38, "load pattern 'forgotten'"),
            (42, "step 'again' changes no load factor"), (45, "geostatic y_surface"),
            (17, "element 2 of set 'thin' is distorted")]


def run(deck, *options, out=None):
    args = [*pecplas_cmd(), str(deck), "--quiet", *options]
    if out is not None:
        args += ["-o", str(out)]
    return subprocess.run(args, cwd=ROOT, capture_output=True, text=True, timeout=120)


def test_warnings_printed_and_stored(tmp_path):
    out = tmp_path / "w.h5"
    r = run(TRUST / "warn_all.inp", out=out)
    assert r.returncode == 0, r.stderr  # a warning never changes the exit code
    lines = [s for s in r.stderr.splitlines() if ": warning: " in s]
    assert len(lines) == len(WARNINGS), r.stderr
    with Results(out) as r:
        stored = r.attr("warnings")
        assert r.status == "completed"
    assert stored == lines  # the file holds exactly what was printed
    for line, phrase in WARNINGS:
        hits = [s for s in lines if s.startswith(f"{TRUST / 'warn_all.inp'}:{line}: warning: ")
                or f"warn_all.inp:{line}: warning: " in s]
        assert any(phrase in s for s in hits), (line, phrase, lines)


def test_no_warning_stores_empty_list(tmp_path):
    out = tmp_path / "b.h5"
    r = run(TRUST / "good_bom.inp", out=out)
    assert r.returncode == 0, r.stderr
    assert ": warning: " not in r.stderr
    with Results(out) as r:
        assert len(r.attr("warnings")) == 0


@pytest.mark.parametrize("deck, line, phrase", [
    ("warn_all.inp", 24, "PHI = 0.5236"),
    ("warn_duplicate_joint.inp", 24, "and 7 more warning(s)"),
])
def test_strict_turns_warnings_into_errors(tmp_path, deck, line, phrase):
    out = tmp_path / "s.h5"
    r = run(TRUST / deck, "--strict", out=out)
    assert r.returncode == 2, r.stderr
    assert f"{deck}:{line}: warning treated as an error (--strict)" in r.stderr, r.stderr
    assert phrase in r.stderr
    assert not out.exists()  # no results file for an input error


def test_duplicate_joint_warning_names_both_lines(tmp_path):
    r = run(TRUST / "warn_duplicate_joint.inp", out=tmp_path / "d.h5")
    assert "warn_duplicate_joint.inp:51: warning: joint 20 of set 'j2' is on the same " \
           "nodes as joint 10 of set 'j1' (" in r.stderr, r.stderr
    assert "warn_duplicate_joint.inp:49)" in r.stderr


@pytest.mark.parametrize("deck, where, phrase", [
    (TRUST / "bad_not_convex.inp", "bad_not_convex.inp:13: [*ELEMENTS]", "not convex at node 7"),
    (TRUST / "bad_q8_midside.inp", "bad_q8_midside.inp:13: [*ELEMENTS]",
     "element 1 of set soil: massif element inverted"),
    (TRUST / "bad_joint_overlap.inp", "bad_joint_overlap.inp:27: [*JOINTS]",
     "overlaps joint 10 of set 'j1'"),
    # node 4 is the first free node of the mechanism; line 8 of the deck defines it
    (ROOT / "test" / "data" / "cli" / "floating.inp", "floating.inp:8: [*NODES]",
     "the stiffness matrix is singular: node 4"),
])
def test_errors_after_reading_name_the_line(tmp_path, deck, where, phrase):
    out = tmp_path / "e.h5"
    r = run(deck, out=out)
    assert r.returncode == 2, r.stderr
    assert where in r.stderr and phrase in r.stderr, r.stderr
    assert not out.exists()


# ---- pecplas-path: bounded runs, progress, and a status on every file ----
from pecplas_exe import program_cmd  # noqa: E402


def run_path(deck, out, *options):
    return subprocess.run([*program_cmd("pecplas-path"), str(deck), "-o", str(out), *options],
                          cwd=ROOT, capture_output=True, text=True, timeout=120)


def test_path_time_limit_stops_with_status(tmp_path):
    # eps_t = 1e4 mm in 0.001 mm substeps would run for hours: stopped after 1 s, exit 3,
    # the rows done are kept and the file says it is not complete
    out = tmp_path / "huge"
    r = run_path(TRUST / "path_huge_target.inp", out, "--max-seconds", "1")
    assert r.returncode == 3, r.stderr
    assert "time limit of 1.000 s reached" in r.stderr
    with h5py.File(out.with_suffix(".h5")) as f:
        assert f.attrs["status"] == "stopped" and f.attrs["complete"] == 0
        assert "time limit" in f.attrs["status_message"]
        assert 1 <= len(f["step"]) < 801  # fewer rows than the 800 increments asked


def test_path_completed_status(tmp_path):
    out = tmp_path / "short"
    r = run_path(TRUST / "path_short.inp", out, "--quiet")
    assert r.returncode == 0, r.stderr
    with h5py.File(out.with_suffix(".h5")) as f:
        assert f.attrs["status"] == "completed" and f.attrs["complete"] == 1
        assert len(f["step"]) == 21  # 20 increments and the initial state


def test_path_increment_cap(tmp_path):
    out = tmp_path / "big"
    r = run_path(TRUST / "path_bad_steps.inp", out)
    assert r.returncode == 2
    assert "path_bad_steps.inp:6: [*PATH] STEPS x targets must be <= 1000000" in r.stderr
    assert not out.with_suffix(".h5").exists()


def test_path_output_that_cannot_be_created_is_an_input_error(tmp_path):
    # the directory of BASE is a regular file: exit 2 before the path runs, as pecplas does
    # with a results file it cannot create (it was exit 1, an internal error, after the run)
    (tmp_path / "afile").write_text("")
    out = tmp_path / "afile" / "x"
    r = run_path(TRUST / "path_short.inp", out, "--quiet")
    assert r.returncode == 2, r.stderr
    assert "cannot write results: cannot create " + str(out) + ".csv" in r.stderr, r.stderr
    assert not out.with_suffix(".h5").exists() and len(r.stderr) < 500
    # a name of 100 000 characters (too long for the system): the same error, its name cut
    # in the message ('...(n characters)') instead of printed whole
    out = tmp_path / ("o" * 100000)
    r = run_path(TRUST / "path_short.inp", out, "--quiet")
    assert r.returncode == 2, r.stderr[:500]
    assert "cannot create " in r.stderr and "characters)" in r.stderr and len(r.stderr) < 500


def test_identify_and_sensitivity_output_that_cannot_be_written_is_an_input_error(tmp_path):
    # -o inside a regular file: exit 2 with the file named (it was exit 1, internal error)
    (tmp_path / "afile").write_text("")
    bad = tmp_path / "afile" / "x.csv"
    r = run_path(ROOT / "input/paths/cnl_modjoin.inp", tmp_path / "cnl", "--quiet")
    assert r.returncode == 0, r.stderr
    for cmd in ([*program_cmd("pecplas-identify"), str(tmp_path / "cnl.csv")],
                [*program_cmd("pecplas-sensitivity")]):
        r = subprocess.run([*cmd, "-o", str(bad), "--quiet"], cwd=ROOT, capture_output=True,
                           text=True, timeout=120)
        assert r.returncode == 2, (cmd, r.stderr)
        assert "cannot write " + str(bad) in r.stderr, r.stderr


def test_katona_interpenetrated_doublet_names_its_line(tmp_path):
    # reproducer found by checks/mutate_decks.py: spring 552 of input/s2/s2_katona.inp joined
    # to node 7 instead of 71, a doublet whose face-2 node lies behind face 1
    src = ROOT / "input" / "s2" / "s2_katona.inp"
    lines = src.read_text().splitlines()
    assert lines[185] == "552, 20, 71"
    lines[185] = "552, 20, 7"
    for sib in src.parent.iterdir():
        if sib.name != src.name:
            (tmp_path / sib.name).symlink_to(sib)
    deck = tmp_path / src.name
    deck.write_text("\n".join(lines) + "\n")
    r = run(deck, out=tmp_path / "k.h5")
    assert r.returncode == 2, r.stderr
    assert "s2_katona.inp:186: [*JOINTS] Katona doublet (nodes 20, 7) of joint set below " \
           "starts interpenetrated" in r.stderr, r.stderr


def test_singular_on_split_node_names_the_joints_line(tmp_path):
    # reproducer found by pecplas_py.checks.mutate_decks: KN = 1e308 in test/data/joints/
    # gmsh_interface.inp; the free node is a duplicate made for the generated joints, so the
    # error names the *JOINTS line that made it
    src = ROOT / "test" / "data" / "joints" / "gmsh_interface.inp"
    lines = src.read_text().splitlines()
    assert lines[12] == "KN = 1e5, KT = 1e4"
    lines[12] = "KN = 1e308, KT = 1e4"
    (tmp_path / "interface.msh").symlink_to(src.parent / "interface.msh")
    deck = tmp_path / src.name
    deck.write_text("\n".join(lines) + "\n")
    r = run(deck, out=tmp_path / "j.h5")
    assert r.returncode == 2, r.stderr
    assert "gmsh_interface.inp:14: [*JOINTS] the stiffness matrix is singular" in r.stderr, \
        r.stderr


def test_huge_modjoin_increment_stops_fast(tmp_path):
    # reproducer found by pecplas_py.checks.mutate_decks (a hang beyond its 20 s bound): the pile of
    # input/s6/s6_modjoin_ag.inp pulled by a factor of -2147483649 asked MODJOIN for ~1e12
    # substeps per increment; such an increment is now refused and cut, and the run stops
    src = ROOT / "input" / "s6" / "s6_modjoin_ag.inp"
    lines = src.read_text().splitlines()
    k = lines.index("pull, 0.05")  # the second step's factor
    lines[k] = "pull, -2147483649"
    for sib in src.parent.iterdir():
        if sib.name != src.name:
            (tmp_path / sib.name).symlink_to(sib)
    deck = tmp_path / src.name
    deck.write_text("\n".join(lines) + "\n")
    r = run(deck, out=tmp_path / "s6.h5")  # the 120 s timeout of run() is the hang bound
    assert r.returncode == 3, r.stderr
    assert "did not converge" in r.stderr


def test_large_displacement_warning_joins_the_list(tmp_path):
    """A unit square of E = 1 kPa pulled by 10 kN moves ~10 m (7 times its diagonal): the run
    completes (exit 0) with the small-strain warning printed, in the status message and in
    the file's `warnings` list (found at the end of the run, after the deck's warnings)."""
    deck = tmp_path / "soft.inp"
    deck.write_text("*UNITS\nkN, m, kPa\n*NODES\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n"
                    "*ELEMENTS, TYPE=Q4, SET=block\n1, 1, 2, 3, 4\n"
                    "*MATERIAL, NAME=soft\nE = 1, NU = 0.3\n*SECTION, SET=block, MATERIAL=soft\n"
                    "*NSET, NAME=base\n1, 2\n*NSET, NAME=top\n3, 4\n*BOUNDARY\nbase, XY\n"
                    "*LOAD, NAME=pull, TYPE=FORCE\ntop, Y, 5\n*STEP, NAME=pull\npull, 1\n")
    out = tmp_path / "soft.h5"
    r = run(deck, out=out)
    assert r.returncode == 0, r.stderr
    assert "small-strain theory no longer holds" in r.stderr
    with Results(out) as res:
        stored = res.attr("warnings")
        message = res.attr("status_message")
    assert any("small-strain theory no longer holds" in s for s in stored), stored
    assert "small-strain theory no longer holds" in message


def test_unit_slips_warned(tmp_path):
    """Under *UNITS kN, m, kPa: the sand's E = 30 (typed in MPa) and GAMMA = 2000 (a density
    in kg/m3) each get a warning at their line naming the value, the range in the deck's units
    and the likely slip; the concrete's plausible values get none; the run completes and the
    file keeps what was printed. (doc/deck.md, UNITS, Plausibility)"""
    out = tmp_path / "u.h5"
    r = run(TRUST / "warn_units.inp", out=out)
    assert r.returncode == 0, r.stderr
    lines = [s for s in r.stderr.splitlines() if ": warning: " in s]
    assert len(lines) == 2, r.stderr
    assert "warn_units.inp:20: warning: [*MATERIAL] material 'sand': E = 30 kPa is softer " \
           "than any soil (peat 100-500 kPa" in lines[0]
    assert lines[0].endswith("typed in MPa? (30 MPa is 30000 kPa)")
    assert "warn_units.inp:21: warning: [*MATERIAL] material 'sand': GAMMA = 2000 kN/m3 is " \
           "heavier than any material" in lines[1]
    assert "a density in kg/m3" in lines[1]
    with Results(out) as f:
        assert list(f.attr("warnings")) == lines
        assert f.status == "completed"


def test_plausible_units_not_warned(tmp_path):
    """The same deck with the values in kPa and kN/m3: no warning. (Every deck of input/ and
    test/data/ was run once to see that none is warned: E from 5 MPa to 210 GPa, unit weights
    16-25 kN/m3, a factor 100 or more inside the bounds.)"""
    deck = tmp_path / "plausible.inp"
    deck.write_text((TRUST / "warn_units.inp").read_text()
                    .replace("E = 30, NU = 0.3", "E = 30000, NU = 0.3")
                    .replace("GAMMA = 2000", "GAMMA = 19.6"))
    r = run(deck, out=tmp_path / "p.h5")
    assert r.returncode == 0, r.stderr
    assert ": warning: " not in r.stderr, r.stderr
