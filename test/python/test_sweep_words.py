"""pecplas-sweep's quantities take the deck's dof words (doc/deck.md, "Dofs"; doc/sweep.md):
x, r, 1 name the first component, y, z, 2 the second, in either letter case; anything else is
refused with the accepted forms."""
import pytest

from pecplas_py.programs.pecplas_sweep import InputError, parse_quantity


@pytest.mark.parametrize("word, component", [("x", 0), ("R", 0), ("1", 0), ("y", 1), ("Z", 1),
                                             ("2", 1)])
def test_component_words(word, component):
    assert parse_quantity(f"q=reaction:base:{word}")["dir"] == component
    assert parse_quantity(f"u=max:disp:0,1.5:{word}")["dir"] == component


@pytest.mark.parametrize("word", ["xy", "3", "w", ""])
def test_bad_words(word):
    with pytest.raises(InputError, match="r, z, 1, 2 too"):
        parse_quantity(f"q=reaction:base:{word}")
