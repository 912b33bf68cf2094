"""The command lines of the four programs, as a user meets them (one layer, src/cmd/args.f90):

- the usage that --help prints is the one the docs quote (README.md, doc/path.md,
  doc/identify.md), so the docs cannot drift from the programs;
- every usage error is one line on stderr, "<program>: error: <text>. usage: ...", exit 2,
  nothing on stdout; the same mistake gets the same words from every program;
- --help and --version (where the program has one) exit 0 and write to stdout only."""
import re
import subprocess
from pathlib import Path

import pytest
from pecplas_exe import program_cmd

ROOT = Path(__file__).resolve().parents[2]
PROGRAMS = ["pecplas", "pecplas-path", "pecplas-identify", "pecplas-sensitivity"]


def run(program, *args):
    return subprocess.run([*program_cmd(program), *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=120)


def words(text):
    return " ".join(text.split())


def help_usage(program):
    """The usage forms of `program --help`: one string per form, line breaks undone."""
    r = run(program, "--help")
    assert r.returncode == 0 and r.stderr == "", r.stderr
    block = r.stdout.split("\n\n")[0]
    forms = re.split(r"\n\s*or: ", block.removeprefix("usage: "))
    return [words(f) for f in forms]


def doc_usage(path, program):
    """The indented usage block of `program` in the doc `path`, line breaks undone."""
    lines = (ROOT / path).read_text().splitlines()
    start = next(i for i, s in enumerate(lines) if s.startswith("    " + program + " "))
    block = [lines[start]]
    for s in lines[start + 1:]:
        if not s.startswith("     "):
            break
        block.append(s)
    return words(" ".join(block))


@pytest.mark.parametrize("program, doc", [("pecplas-path", "doc/path.md"),
                                          ("pecplas-identify", "doc/identify.md"),
                                          ("pecplas-sensitivity", "doc/identify.md")])
def test_docs_quote_the_usage(program, doc):
    assert help_usage(program) == [doc_usage(doc, program)]


def test_readme_quotes_the_usage():
    forms = help_usage("pecplas")
    readme = (ROOT / "README.md").read_text()
    assert forms[0] == "pecplas DECK [-o FILE.h5] [--quiet] [--restart OLD.h5] [--strict]"
    assert "\n" + forms[0] + "\n" in readme
    assert len(forms) == 3 and forms[1].startswith("pecplas --advise DECK") and \
        forms[2].startswith("pecplas DECK --target-error")


# the same mistakes, for each program (a deck or curve word so that only the mistake is wrong)
MISTAKES = [
    (["--bogus"], "unknown option --bogus"),
    (["-o"], "option -o needs a value ("),
]


@pytest.mark.parametrize("program", PROGRAMS)
@pytest.mark.parametrize("args, text", MISTAKES)
def test_usage_errors_read_alike(program, args, text):
    r = run(program, "x.inp", *args)
    lines = r.stderr.splitlines()
    assert r.returncode == 2 and r.stdout == "" and len(lines) == 1, r.stderr
    assert lines[0].startswith(f"{program}: error: {text}"), lines[0]
    assert f". usage: {program} " in lines[0], lines[0]


@pytest.mark.parametrize("program, args, text", [
    ("pecplas", ["x.inp", "--max-dofs", "0"], "option --max-dofs: expected an integer > 0, "
                                               "got '0'"),
    ("pecplas-path", ["x.inp", "--max-seconds", "-1"], "option --max-seconds: expected a "
                                                        "number > 0, got '-1'"),
    ("pecplas-identify", ["x.csv", "--secant", "a"], "option --secant: expected a number, "
                                                      "got 'a'"),
    ("pecplas-identify", ["x.csv", "--version", "cubic"], "option --version: expected "
                                                           "initial or improved, got 'cubic'"),
    ("pecplas-sensitivity", ["--steps", "many"], "option --steps: expected an integer > 0, "
                                                 "got 'many'"),
    ("pecplas-sensitivity", ["--table", "IV"], "option --table: expected III.3 or III.4, "
                                               "got 'IV'"),
    ("pecplas", [], "no deck given"),
    ("pecplas-path", ["a.inp", "b.inp"], "only one deck may be given"),
    ("pecplas-identify", ["-q"], "no test curve given"),
    ("pecplas-sensitivity", ["a.inp", "b.inp"], "only one deck may be given"),
])
def test_bad_values_and_words(program, args, text):
    r = run(program, *args)
    assert r.returncode == 2 and r.stdout == "", r.stderr
    assert r.stderr.startswith(f"{program}: error: {text}. usage: {program} "), r.stderr


@pytest.mark.parametrize("program", PROGRAMS)
def test_help_and_version(program):
    r = run(program, "--help")
    assert r.returncode == 0 and r.stderr == "" and r.stdout.startswith("usage: " + program)
    assert "  -h, --help" in r.stdout
    v = run(program, "--version")
    if program == "pecplas-identify":
        # its --version is the MODJOIN version it identifies: a value is missing
        assert v.returncode == 2 and "option --version needs a value" in v.stderr
    else:
        assert v.returncode == 0 and v.stderr == "" and v.stdout.strip()
