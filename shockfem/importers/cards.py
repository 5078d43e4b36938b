"""The LS-DYNA keyword file's card format: keywords, cards and their fields, with every line's origin.

A deck is a list of keywords (``*NODE``, ``*MAT_ELASTIC``, ...), each followed by its data cards. A card
is one line of fields: fixed width (8, 10, 16 or 20 characters, as the keyword's layout says), or free
format (fields separated by commas, in the same order), or long format (every field 20 characters wide:
``*KEYWORD LONG=Y`` for the whole deck, ``*NODE +`` for one keyword, ``*NODE -`` back to standard).
``$`` starts a comment line. ``*INCLUDE`` reads another file (a path relative to the including file) in
place; ``*PARAMETER`` defines names that a field reads as ``&name`` (``-&name`` negated).

Every card keeps its file and line, and every field error names the keyword, the card's number within
it and the line, so that a bad deck is reported where an engineer would fix it.

A reader of our own rather than a keyword library from PyPI: ``docs/import.md`` gives the comparison
(the candidates read long format or ``*PARAMETER`` references silently wrong, or bring in a solver
client's dependencies).
"""
from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass, field

# how wide a field is in long format, whatever its standard width (LS-DYNA's LONG=Y)
LONG_WIDTH = 20
# the largest integer field: LS-DYNA's ids are 32-bit signed integers (its double-precision builds' 64-bit ids
# go beyond, but no deck here needs them; numpy's int64 arrays of ids would overflow past 2^63)
MAX_ID = 2 ** 31 - 1


class DeckError(Exception):
    """Problems of a deck, each naming the file, line, keyword and card."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        super().__init__("\n".join(problems))


@dataclass(frozen=True)
class Card:
    """One data line of a keyword, where it came from, and whether it is in long format."""
    text: str
    path: str
    line: int                       # 1-based line number in ``path``
    long: bool = False

    def where(self) -> str:
        return f"{os.path.basename(self.path)}:{self.line}"


@dataclass
class Keyword:
    """A keyword (its name without the ``*``, upper case, e.g. ``MAT_ELASTIC``) and its data cards."""
    name: str
    path: str
    line: int
    cards: list[Card] = field(default_factory=list)
    long_flag: str = ""             # "+": this keyword's cards in long format, "-": standard, "": the deck's
    parameters: dict = field(default_factory=dict, repr=False)     # the deck's *PARAMETER values

    def where(self) -> str:
        return f"{os.path.basename(self.path)}:{self.line}"

    def error(self, card: int | None, message: str) -> str:
        """A problem naming the keyword, the card (1-based, None: the keyword itself) and its line."""
        if card is None or card >= len(self.cards):
            return f"{self.where()}: *{self.name}: {message}"
        c = self.cards[card]
        return f"{c.where()}: *{self.name} card {card + 1}: {message}"

    def fields(self, card: int, widths: list[int], kinds: str, required: int = 0) -> list:
        """The fields of card ``card`` (0-based) as numbers: ``kinds`` one letter per field, ``i``
        integer, ``f`` real, ``s`` text; blank fields are None.  ``required``: how many leading fields
        must be given (a card cut short, or missing, is an error naming it)."""
        if card >= len(self.cards):
            if required:
                raise DeckError([self.error(None, f"card {card + 1} is missing (the deck ends or the next "
                                                  f"keyword starts first)")])
            return [None] * len(kinds)
        c = self.cards[card]
        texts = split_fields(c, widths)
        values = []
        for k, (kind, text) in enumerate(zip(kinds, texts + [""] * (len(kinds) - len(texts)))):
            values.append(self._value(card, k, kind, text))
        missing = [k + 1 for k in range(required) if values[k] is None]
        if missing:
            raise DeckError([self.error(card, f"field {missing[0]} is blank, the card is cut short "
                                              f"(it needs at least {required} fields)")])
        return values

    def _value(self, card: int, k: int, kind: str, text: str):
        text = text.strip()
        if not text:
            return None
        if kind == "s":
            return text
        sign = 1
        body = text
        if body.startswith("-&") or body.startswith("&"):
            sign = -1 if body[0] == "-" else 1
            name = body.lstrip("-&").strip().lower()
            if name not in self.parameters:
                raise DeckError([self.error(card, f"field {k + 1}: no *PARAMETER named {name!r} in the deck")])
            value = self.parameters[name]
            if isinstance(value, str):
                raise DeckError([self.error(card, f"field {k + 1}: parameter {name!r} is text ({value!r}), "
                                                  "a number is needed here")])
            value = sign * value
        else:
            value = parse_number(body)
            if value is None:
                raise DeckError([self.error(card, f"field {k + 1}: {text!r} is not a number")])
        if not math.isfinite(value):
            # NaN, infinity or beyond a double (1e400): no field of a deck means it, and it would reach the
            # scene (or an integer conversion) unseen
            raise DeckError([self.error(card, f"field {k + 1}: {text!r} is not a finite number")])
        if kind == "i":
            if value != int(value):
                raise DeckError([self.error(card, f"field {k + 1}: {text!r} must be a whole number")])
            if abs(value) > MAX_ID:
                raise DeckError([self.error(card, f"field {k + 1}: {text!r} is beyond the largest id or count "
                                                  f"a deck holds ({MAX_ID})")])
            return int(value)
        return float(value)


def parse_number(text: str) -> float | None:
    """A Fortran-style number: ``7.85e-9``, ``7.85-9`` (exponent without its E), ``1.d3``."""
    t = text.strip().lower().replace("d", "e")
    try:
        return float(t)
    except ValueError:
        pass
    m = re.fullmatch(r"([+-]?(?:\d+\.?\d*|\.\d+))([+-]\d+)", t)
    return float(f"{m.group(1)}e{m.group(2)}") if m else None


def split_fields(card: Card, widths: list[int]) -> list[str]:
    """The texts of a card's fields: comma separated (free format) or fixed width (long format: every
    field ``LONG_WIDTH`` wide); the last width repeats for as many fields as the line holds."""
    text = card.text.rstrip("\n")
    if "," in text:
        return [t.strip() for t in text.split(",")]
    out, pos, k = [], 0, 0
    while pos < len(text):
        w = LONG_WIDTH if card.long else widths[min(k, len(widths) - 1)]
        out.append(text[pos:pos + w])
        pos += w
        k += 1
    return out


def read_deck(path: str) -> tuple[str, list[Keyword]]:
    """The title and keywords of the deck ``path`` with its includes in place.

    Raises ``DeckError`` listing every problem of the format (a missing include, a bad parameter)."""
    reader = _Reader()
    reader.read(os.path.abspath(path), [])
    if reader.problems:
        raise DeckError(reader.problems)
    for kw in reader.keywords:
        kw.parameters = reader.parameters
    return reader.title, reader.keywords


class _Reader:
    """Reads files line by line into keywords, following includes and parameters as they come."""

    def __init__(self):
        self.keywords: list[Keyword] = []
        self.parameters: dict = {}
        self.problems: list[str] = []
        self.title = ""
        self.long = False                       # *KEYWORD LONG=Y

    def read(self, path: str, stack: list[str]):
        if path in stack:
            self.problems.append(f"{os.path.basename(stack[-1])}: *INCLUDE {path} includes itself (a cycle)")
            return
        try:
            with open(path, encoding="utf-8", errors="replace") as fh:
                lines = fh.read().splitlines()
        except OSError as e:
            where = f"{os.path.basename(stack[-1])}: *INCLUDE" if stack else "deck"
            self.problems.append(f"{where}: cannot read {path} ({e.strerror})")
            return
        current: Keyword | None = None
        for number, text in enumerate(lines, start=1):
            if text.startswith("$") or not text.strip():
                continue
            if text.startswith("*"):
                if current is not None:
                    self._close(current, stack + [path])
                current = self._open(text, path, number)
                continue
            if current is None:
                self.problems.append(f"{os.path.basename(path)}:{number}: a data line before any keyword")
                continue
            current.cards.append(Card(text, path, number, current_long(current, self.long)))
        if current is not None:
            self._close(current, stack + [path])

    def _open(self, text: str, path: str, number: int) -> Keyword:
        head = text[1:].strip()
        name, _, rest = head.partition(" ")
        name = name.upper()
        flag = head[-1] if head[-1] in "+-" else ""
        kw = Keyword(name.rstrip("+-"), path, number, long_flag=flag)
        if kw.name == "KEYWORD":
            option = rest.upper().replace(" ", "")
            if "LONG=Y" in option:
                self.long = True
            elif "LONG=S" in option:
                self.problems.append(f"{os.path.basename(path)}:{number}: *KEYWORD LONG=S (long real fields, "
                                     "standard integer fields) is not read; write LONG=Y or standard format")
        return kw

    def _close(self, kw: Keyword, stack: list[str]):
        if kw.name == "INCLUDE":
            for card in kw.cards:
                target = card.text.strip()
                base = os.path.dirname(card.path)
                self.read(os.path.normpath(os.path.join(base, target)), stack)
            return
        if kw.name in ("PARAMETER", "PARAMETER_LOCAL"):
            self._parameters(kw)
            return
        if kw.name == "TITLE":
            self.title = kw.cards[0].text.strip() if kw.cards else ""
            return
        if kw.name in ("KEYWORD", "END"):
            return
        self.keywords.append(kw)

    def _parameters(self, kw: Keyword):
        """``*PARAMETER`` cards: up to four (name, value) pairs of 10 characters each; a name's first
        letter gives its type (R real, I integer, C text)."""
        for c, card in enumerate(kw.cards):
            texts = split_fields(card, [10])
            for k in range(0, len(texts) - 1, 2):
                head, value = texts[k].strip(), texts[k + 1].strip()
                if not head:
                    continue
                kind, _, name = head.partition(" ")
                kind, name = kind.upper(), name.strip().lower()
                if kind not in ("R", "I", "C") or not name:
                    self.problems.append(kw.error(c, f"{head!r}: a parameter is its type (R, I or C), a space "
                                                     "and its name"))
                    continue
                if kind == "C":
                    self.parameters[name] = value
                    continue
                number = parse_number(value)
                if number is None or not math.isfinite(number):
                    self.problems.append(kw.error(c, f"parameter {name!r}: {value!r} is not a finite number"))
                    continue
                if kind == "I" and (number != int(number) or abs(number) > MAX_ID):
                    self.problems.append(kw.error(c, f"parameter {name!r}: {value!r} is not a whole number "
                                                     f"(type I) up to {MAX_ID}"))
                    continue
                self.parameters[name] = int(number) if kind == "I" else number


def current_long(kw: Keyword, deck_long: bool) -> bool:
    """Whether a keyword's cards are in long format: its own ``+`` / ``-``, else the deck's LONG=Y."""
    return True if kw.long_flag == "+" else False if kw.long_flag == "-" else deck_long
