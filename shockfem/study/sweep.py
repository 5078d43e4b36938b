"""A user's sweep: factors of a scene and the levels each takes -> the cases of a design (``batch.Case``).

``--vary bodies.striker.velocity="[5, 10, 20] m/s"``: a factor is a scene path (as ``--set`` takes it)
and a list of levels, a unit after the list applying to each (``"[5, 10] m/s"``), or a TOML list
(``["5 m/s", "10 m/s"]``, ``[0.1, 0.2]``).  Designs:

* ``full``: every combination (the full factorial), the first factor changing slowest;
* ``fractional``: a two-level fractional factorial from pyDOE3 (every factor with two levels, the first
  taken as -1 and the second as +1): ``generators`` as pyDOE3's ``fracfact`` writes them ("a b c abc":
  D = ABC), or the smallest design of a ``resolution`` (``fracfact_by_res``; resolution III by default:
  main effects clear of each other, aliased with two-factor interactions);
* a table of cases (``cases_from_table``): one column per scene path, one row per case.
"""
from __future__ import annotations

import csv
import itertools
import re
import tomllib

from ..scene.checker import SceneError
from .batch import Case

DESIGNS = ("full", "fractional")


def parse_vary(text: str) -> tuple[str, list[str]]:
    """``path=levels`` -> (path, each level as ``--set`` will take it: TOML text)."""
    path, sep, value = text.partition("=")
    path, value = path.strip(), value.strip()
    if not sep or not path or not value:
        raise SceneError([f"--vary {text!r}: write it as PATH=LEVELS, e.g. bodies.striker.velocity=\"[5, 10] m/s\""])
    match = re.fullmatch(r"\[(.*)\]\s*([^\]\[]*)", value, re.S)
    if not match:
        raise SceneError([f"--vary {path}: the levels must be a list, e.g. \"[5, 10, 20] m/s\", got {value!r}"])
    items, unit = match.group(1), match.group(2).strip()
    try:
        levels = tomllib.loads(f"x = [{items}]")["x"]
    except tomllib.TOMLDecodeError:
        levels = [i.strip() for i in items.split(",") if i.strip()]
    if not levels:
        raise SceneError([f"--vary {path}: no levels in {value!r}"])
    if unit:
        if any(not isinstance(v, (int, float)) or isinstance(v, bool) for v in levels):
            raise SceneError([f"--vary {path}: a unit after the list ({unit!r}) needs numbers in it, got {value!r}"])
        return path, [f'"{v} {unit}"' for v in levels]
    return path, [_toml_value(v) for v in levels]


def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    return '"' + str(v).replace('"', '\\"') + '"'


def _shown(level: str) -> str:
    """A level as the table shows it (its TOML quotes dropped)."""
    return level[1:-1] if level.startswith('"') and level.endswith('"') else level


def design_cases(scene: str, factors: list[tuple[str, list[str]]], design: str = "full", generators: str = "",
                 resolution: int = 3, fixed: tuple[str, ...] = ()) -> list[Case]:
    """The cases of ``design`` over ``factors`` ((path, levels) pairs), each with the ``fixed`` overrides
    before its own."""
    if design not in DESIGNS:
        raise SceneError([f"--design: one of {', '.join(DESIGNS)}, got {design!r}"])
    if not factors:
        raise SceneError(["--vary: a sweep needs at least one factor (PATH=LEVELS)"])
    if design == "full":
        combos = list(itertools.product(*[range(len(levels)) for _, levels in factors]))
    else:
        if any(len(levels) != 2 for _, levels in factors):
            raise SceneError(["--design fractional: every factor takes two levels, got "
                              + ", ".join(f"{p}: {len(l)}" for p, l in factors)])
        import pyDOE3
        try:
            coded = (pyDOE3.fracfact(generators) if generators
                     else pyDOE3.fracfact_by_res(len(factors), resolution))
        except ValueError as exc:
            raise SceneError([f"--design fractional: no design for {len(factors)} factors "
                              f"({'generators ' + repr(generators) if generators else f'resolution {resolution}'}): {exc}"])
        if coded.shape[1] != len(factors):
            raise SceneError([f"--generators {generators!r}: {coded.shape[1]} columns for {len(factors)} factors"])
        combos = [tuple(int(c > 0) for c in run) for run in coded]
    width = len(str(len(combos) - 1))
    cases = []
    for k, combo in enumerate(combos):
        chosen = [(path, levels[i]) for (path, levels), i in zip(factors, combo)]
        cases.append(Case(f"case_{k:0{width}d}", scene, tuple(fixed) + tuple(f"{p}={v}" for p, v in chosen),
                          {p: _shown(v) for p, v in chosen}))
    return cases


def cases_from_table(scene: str, path: str, fixed: tuple[str, ...] = ()) -> list[Case]:
    """The cases of a CSV table: a header of scene paths, a row per case of levels as ``--vary`` takes
    one level ("10 m/s", 0.2); a column ``case`` names the cases (default case_<row>)."""
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    if not rows:
        raise SceneError([f"--cases {path}: no rows"])
    width = len(str(len(rows) - 1))
    cases = []
    for k, row in enumerate(rows):
        name = (row.pop("case", "") or "").strip() or f"case_{k:0{width}d}"
        levels = {p.strip(): parse_vary(f"{p}=[{v}]")[1][0] for p, v in row.items() if p and v not in (None, "")}
        cases.append(Case(name, scene, tuple(fixed) + tuple(f"{p}={v}" for p, v in levels.items()),
                          {p: _shown(v) for p, v in levels.items()}))
    return cases
