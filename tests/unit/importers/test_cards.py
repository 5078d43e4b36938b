"""The card reader: fixed, free and long format, parameters, includes, Fortran numbers, and errors that
name the keyword, card and line."""
import pytest

from shockfem.importers.cards import Card, DeckError, parse_number, read_deck, split_fields


def _deck(tmp_path, text, name="deck.k"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


@pytest.mark.parametrize("text, value", [("7.85e-9", 7.85e-9), ("7.85-9", 7.85e-9), ("1.d3", 1000.0),
                                         ("-2.5+3", -2500.0), (" 42 ", 42.0), ("abc", None), ("1.2.3", None)])
def test_fortran_numbers(text, value):
    assert parse_number(text) == value


def test_fixed_free_and_long_fields():
    fixed = Card("       1             0.5            -2.0", "x.k", 1)
    assert [t.strip() for t in split_fields(fixed, [8, 16, 16])] == ["1", "0.5", "-2.0"]
    free = Card("1, 0.5,-2.0", "x.k", 1)
    assert split_fields(free, [8, 16, 16]) == ["1", "0.5", "-2.0"]
    long = Card(f"{1:>20}{0.5:>20}{-2.0:>20}", "x.k", 1, long=True)
    assert [t.strip() for t in split_fields(long, [8, 16, 16])] == ["1", "0.5", "-2.0"]


def test_parameters_include_comments_and_long_flags(tmp_path):
    (tmp_path / "sub").mkdir()
    _deck(tmp_path / "sub", "*NODE -\n       2             1.0\n", "nodes.k")
    path = _deck(tmp_path, "*KEYWORD LONG=Y\n$ comment\n*PARAMETER -\n" + f"{'R x':<10}{2.5:>10}{'I n':<10}{3:>10}\n"
                           "*NODE\n" + f"{1:>20}{'&x':>20}{'-&x':>20}\n" + "*INCLUDE\nsub/nodes.k\n"
                           "*SECTION_SOLID -\n&n,1\n*END\n")
    title, keywords = read_deck(path)
    names = [k.name for k in keywords]
    assert names == ["NODE", "NODE", "SECTION_SOLID"]
    assert keywords[0].fields(0, [8, 16, 16], "iff") == [1, 2.5, -2.5]        # long (the deck's LONG=Y)
    assert keywords[1].fields(0, [8, 16], "if") == [2, 1.0]                   # "-": standard in the include
    assert keywords[1].cards[0].line == 2 and keywords[1].path.endswith("nodes.k")
    assert keywords[2].fields(0, [10], "ii") == [3, 1]                        # an integer parameter


def test_errors_name_keyword_card_and_line(tmp_path):
    path = _deck(tmp_path, "*KEYWORD\n*MAT_ELASTIC\n$ MID RO\n         1      &rho\n*NODE\n  x\n")
    _, keywords = read_deck(path)
    with pytest.raises(DeckError) as e:
        keywords[0].fields(0, [10], "iff")
    assert e.value.problems == ["deck.k:4: *MAT_ELASTIC card 1: field 2: no *PARAMETER named 'rho' in the deck"]
    with pytest.raises(DeckError) as e:
        keywords[1].fields(0, [8], "i")
    assert "deck.k:6: *NODE card 1: field 1: 'x' is not a number" in e.value.problems
    with pytest.raises(DeckError) as e:
        keywords[1].fields(1, [8], "i", required=1)
    assert "deck.k:5: *NODE: card 2 is missing" in e.value.problems[0]


def test_missing_include_and_data_before_keyword(tmp_path):
    path = _deck(tmp_path, "1, 2\n*KEYWORD\n*INCLUDE\nnone.k\n")
    with pytest.raises(DeckError) as e:
        read_deck(path)
    assert e.value.problems[0] == "deck.k:1: a data line before any keyword"
    assert "cannot read" in e.value.problems[1] and "none.k" in e.value.problems[1]


def test_include_cycle(tmp_path):
    path = _deck(tmp_path, "*KEYWORD\n*INCLUDE\ndeck.k\n")
    with pytest.raises(DeckError, match="includes itself"):
        read_deck(path)
