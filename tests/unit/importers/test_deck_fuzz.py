"""Decks that cannot crash the import: the decks of ``studies/lsdyna`` with one card's field replaced by a bad
value (blank, text, NaN, infinity, a number beyond a double, negative, zero, huge, a fraction in an integer
field, an unknown parameter, an id no part, set or curve has), a card cut short after a field, a card or a
keyword line deleted, or the mesh include missing, are either imported (and the scene written loads) or
refused with every problem naming the file and line, and the keyword (``SceneError``, exit 2): never a
traceback or a hang.  The suite runs a fixed sample (``SAMPLE`` mutations of the hand-written decks' cards
and a few of their mesh includes', the same every run);
``python scripts/import-fuzz.py`` runs every mutation of every card of the hand-written decks and a sample of
their mesh includes' cards, and its docstring gives what it found."""
import os
import pathlib
import random
import re
import shutil

import pytest

from shockfem.importers import import_model
from shockfem.importers.cards import Card, split_fields
from shockfem.scene import SceneError, load_scene
from shockfem.verify.lsdyna_cases import DECKS

STUDIES = pathlib.Path(__file__).parents[3] / "studies" / "lsdyna"
BAD_VALUES = ("", "abc", "nan", "inf", "-inf", "1e400", "-1", "-1e30", "0", "99999999", "1.5", "&nope")
# each keyword's field widths (``deck_model.py``'s readers): the first card's, then the others'
WIDTHS = {"NODE": ([8, 16, 16, 16, 8, 8], [8, 16, 16, 16, 8, 8]), "ELEMENT_SOLID": ([8], [8]),
          "DEFINE_CURVE": ([10], [20])}
# a problem names where it is: "file:line: *KEYWORD ..." (or "file: *KEYWORD" for a keyword without cards), or
# is one of the whole-deck problems (no solids; the units)
NAMED = re.compile(r"^[^\s:]+(:\d+)?: (\*[A-Z0-9_]+|no \*[A-Z_]+|a data line before)")
SAMPLE = 40


def _cards(path: pathlib.Path):
    """(line index, keyword, card number in it) of every data card of a deck file."""
    keyword, number = None, 0
    for i, text in enumerate(path.read_text().splitlines()):
        if text.startswith("$") or not text.strip():
            continue
        if text.startswith("*"):
            keyword, number = text[1:].split()[0].upper().rstrip("+-"), 0
            continue
        yield i, keyword, number
        number += 1


def _replace(text: str, keyword: str, card: int, k: int, value: str) -> str | None:
    """The card ``text`` with field ``k`` replaced by ``value`` (None if it has no such field)."""
    if "," in text:
        fields = text.split(",")
        if k >= len(fields):
            return None
        fields[k] = value
        return ",".join(fields)
    first, rest = WIDTHS.get(keyword, ([10], [10]))
    widths = first if card == 0 else rest
    texts = split_fields(Card(text, "", 0), widths)
    if k >= len(texts):
        return None
    w = len(texts[k])
    texts[k] = value.rjust(w)[-w:] if len(value) > w else value.rjust(w)
    return "".join(texts)


def _cut(text: str, keyword: str, card: int, k: int) -> str:
    """The card ``text`` cut after its first ``k`` fields."""
    if "," in text:
        return ",".join(text.split(",")[:k])
    first, rest = WIDTHS.get(keyword, ([10], [10]))
    return "".join(split_fields(Card(text, "", 0), first if card == 0 else rest)[:k])


def mesh_cards(name: str, count: int, seed: int = 7) -> set:
    """``count`` cards of deck ``name``'s mesh include drawn at random (line indices), with the first card
    of each of its keywords."""
    cards = list(_cards(STUDIES / f"{name}_mesh.k"))
    firsts = {i for i, _, card in cards if card == 0}
    return firsts | set(random.Random(seed).sample([i for i, _, _ in cards], count))


def mutations(name: str, mesh: set | None = None):
    """Every mutation of deck ``name``, as an edit: (file, label, line index, the line's new text, "" to delete
    it, or None for the whole file deleted); of its mesh include, the cards of the lines ``mesh`` only
    (None: all of them; an include has ten thousand cards).  Lazy."""
    for path in (STUDIES / f"{name}.k", STUDIES / f"{name}_mesh.k"):
        lines = path.read_text().splitlines()
        for i, keyword, card in _cards(path):
            if mesh is not None and path.name.endswith("_mesh.k") and i not in mesh:
                continue
            text = lines[i]
            where = f"{path.name}:{i + 1} *{keyword} card {card + 1}"
            count = len(text.split(",")) if "," in text else len(split_fields(Card(text, "", 0), [10]))
            for k in range(max(count, 1)):
                for value in BAD_VALUES:
                    new = _replace(text, keyword, card, k, value)
                    if new is not None and new != text:
                        yield path.name, f"{where} field {k + 1} = {value!r}", i, new
                yield path.name, f"{where} cut after field {k}", i, _cut(text, keyword, card, k)
            yield path.name, f"{where} deleted", i, ""
        for i, text in enumerate(lines):
            if text.startswith("*") and not text.startswith(("*KEYWORD", "*END")):
                yield path.name, f"{path.name}:{i + 1} {text.split()[0]} line deleted", i, ""
    yield f"{name}_mesh.k", f"{name}_mesh.k missing", None, None


def import_mutated(name: str, file: str, line: int | None, text: str | None, workdir: pathlib.Path) -> str:
    """Import deck ``name`` with line ``line`` of ``file`` replaced by ``text`` ("": deleted; ``line`` None: the
    file deleted) in ``workdir``: "imported", "refused by the scene check" (the deck read, its scene refused:
    not named by card), or "refused"; raises AssertionError for a problem that does not say where it is, and
    lets any other exception through."""
    if workdir.exists():
        shutil.rmtree(workdir)
    workdir.mkdir(parents=True)
    for f in (f"{name}.k", f"{name}_mesh.k"):
        shutil.copy(STUDIES / f, workdir / f)
    if line is None:
        os.remove(workdir / file)
    else:
        lines = (STUDIES / file).read_text().splitlines()
        lines[line:line + 1] = [text] if text else []
        (workdir / file).write_text("\n".join(lines) + "\n")
    try:
        done = import_model(str(workdir / f"{name}.k"), str(workdir / "out.toml"), DECKS[name]["units"])
    except SceneError as e:
        unnamed = [p for p in e.problems if not NAMED.match(p)]
        assert e.problems and not unnamed, unnamed
        return "refused"
    try:
        load_scene(done.scene)
    except SceneError:
        return "refused by the scene check"
    return "imported"


def _sample() -> list:
    """``SAMPLE`` mutations drawn from every deck's (a reservoir: the mutations are not all held at once)."""
    rng, kept, seen = random.Random(7), [], 0
    for name in DECKS:
        for m in mutations(name, mesh_cards(name, 5)):
            seen += 1
            if len(kept) < SAMPLE:
                kept.append((name, *m))
            elif (j := rng.randrange(seen)) < SAMPLE:
                kept[j] = (name, *m)
    return kept


CASES = _sample()


@pytest.mark.parametrize("name,file,label,line,text", CASES, ids=[c[2] for c in CASES])
def test_a_mutated_deck_is_imported_or_refused_by_line(name, file, label, line, text, tmp_path):
    outcome = import_mutated(name, file, line, text, tmp_path / "deck")
    assert outcome in ("imported", "refused"), (label, outcome)
