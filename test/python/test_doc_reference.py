"""The reference pages agree with the program and with each other:
- doc/deck.md documents every keyword, parameter, material and interface-law key and type the
  deck reader accepts, and every parameter written in a keyword's signature is accepted
  (pecplas_py.docs.deck_reference: the reader is asked by one-line decks, each an input error
  of a few milliseconds);
- every relative link, anchor and image of README.md, doc/*.md and doc/bench/*.md resolves
  (pecplas_py.docs.links; pure Python).
"""
import pytest
from pecplas_exe import exe_path

from pecplas_py.docs import deck_reference, links


@pytest.fixture(scope="module")
def vocab():
    return deck_reference.reader_vocabulary(exe_path("pecplas"))


def test_deck_reference_covers_the_reader(vocab):
    # the probes themselves worked: the reader lists keywords, parameters and keys
    assert len(vocab["keywords"]) >= 30 and "*STEP" in vocab["keywords"]
    assert "INCREMENTS" in vocab["params"]["*STEP"]
    assert "E" in vocab["material_keys"]["ELASTIC"]
    problems = deck_reference.check(vocab)
    assert not problems, "doc/deck.md and the deck reader disagree:\n" + "\n".join(problems)


def test_deck_reference_finds_a_bad_example(vocab, tmp_path):
    """The checker is not vacuous: an unknown parameter in a signature and in a deck example
    are reported."""
    page = tmp_path / "p.md"
    page.write_text("`*OUTPUT, EVERY=2, OFTEN=YES`\n\n```\n*SOLVER, METHOD=NEWTON, FOO=1\n```\n")
    found = [p for p in deck_reference.check(vocab, pages=[page]) if p.startswith("p.md")]
    assert len(found) == 2 and "OFTEN" in found[0] and "FOO" in found[1], found


def test_doc_links_resolve():
    problems = links.broken()
    assert not problems, "broken links in the docs:\n" + "\n".join(problems)


def test_link_checker_finds_a_broken_anchor(tmp_path):
    """The checker is not vacuous: a dead anchor and a missing image are reported."""
    page = tmp_path / "p.md"
    page.write_text("# Title\n\n[ok](#title) [bad](#nowhere) ![img](missing.png)\n"
                    "```\n[not a link](#nowhere)\n```\n")
    found = links.broken([page])
    assert len(found) == 2, found
    assert "#nowhere" in found[0] and "missing.png" in found[1]
