"""The one input checker: every scene table (plain scenes, chains, launchers) and the commands'
options are read through ``Checker``, which collects *every* problem as ``field: problem, got X``
and raises them together as a ``SceneError`` (the command line exits with status 2).
"""
from __future__ import annotations

from ..units import SI_UNITS, UnitError, to_si

# the largest magnitude a scene's quantity may have, by dimension [SI]: far beyond any shock machine, so a
# value past it is a slip (1e308 m/s, a modulus in Pa read as GPa twice), refused before it overflows a
# formula or sets a time step that never ends (a lumped stand-in may be dense: 106,200 kg/m^3 makes a plug
# weigh 12 lb in the gallery; a strain rate has no limit: Cowper-Symonds D = 1e40 /s is how a rate effect is
# switched off)
MAGNITUDE_LIMITS = {"length": 1e4, "mass": 1e9, "time": 1e3, "velocity": 1e5, "angular_velocity": 1e7,
                    "acceleration": 1e12, "force": 1e13, "pressure": 1e15, "density": 1e8, "frequency": 1e10,
                    "strain_rate": None, "energy": 1e15, "stiffness": 1e16, "damping": 1e13, "slowness": 1e3,
                    "area": 1e8, "volume": 1e12, "temperature": 1e5, "angle": 1e4, "dimensionless": 1e12}


def _checked_si(value, dimension: str) -> float:
    """``to_si``, and a magnitude within ``MAGNITUDE_LIMITS`` (else a ``UnitError`` saying so)."""
    v = to_si(value, dimension)
    limit = MAGNITUDE_LIMITS.get(dimension)
    if limit is not None and abs(v) > limit:
        shown = value if isinstance(value, str) else repr(value)
        raise UnitError(f"must be at most {limit:g} {SI_UNITS.get(dimension, '')} in size (far beyond a shock "
                        f"machine: a slip?), got {shown}")
    return v


class SceneError(Exception):
    """All problems found in a scene, each ``path: message``."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        super().__init__("\n".join(problems))


def _article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


class Checker:
    """Collects problems while reading fields; every getter returns a usable default, so that one
    pass finds every problem.  ``path`` is the table's own (``bodies[1]``, ``launcher``; "" for
    top-level names such as a command's ``--article``); a field is named ``path.key``."""

    def __init__(self):
        self.problems: list[str] = []

    def fail(self, path: str, message: str):
        self.problems.append(f"{path}: {message}")

    def done(self):
        """Raise every problem found so far as one ``SceneError``."""
        if self.problems:
            raise SceneError(self.problems)

    @staticmethod
    def field(path: str, key: str) -> str:
        return f"{path}.{key}" if path else key

    def table(self, d: dict, key: str, path: str, required=True) -> dict:
        v = d.get(key)
        if v is None:
            if required:
                self.fail(path, "missing section")
            return {}
        if not isinstance(v, dict):
            self.fail(path, f"must be a table, got {v!r}")
            return {}
        return v

    def unknown(self, d: dict, allowed, path: str):
        for k in d:
            if k not in allowed:
                self.fail(self.field(path, k), f"unknown field (allowed: {', '.join(sorted(allowed))})")

    def quantity(self, d: dict, key: str, path: str, dimension: str, default=None,
                 positive=False, nonnegative=False, upper=None) -> float:
        """``d[key]`` with its units, in SI (``default`` where absent; required when None)."""
        at = self.field(path, key)
        if key not in d:
            if default is None:
                what = dimension.replace('_', ' ')
                self.fail(at, f"missing ({_article(what)} {what})")
                return 1.0
            return default
        raw = d[key]
        try:
            v = _checked_si(raw, dimension)
        except UnitError as e:
            self.fail(at, str(e))
            return default if default is not None else 1.0
        shown = raw if isinstance(raw, str) else repr(raw)
        if positive and not v > 0:
            self.fail(at, f"must be > 0, got {shown}")
        if nonnegative and v < 0:
            self.fail(at, f"must be >= 0, got {shown}")
        if upper is not None and v >= upper:
            self.fail(at, f"must be < {upper}, got {shown}")
        return v

    def quantities(self, d: dict, path: str, fields: dict, optional=()) -> dict:
        """Every field of ``fields`` (name: (dimension, default or None if required, must be > 0))
        read with ``quantity``; a field in ``optional`` may be absent even without a default."""
        out = {}
        for key, (dimension, default, positive) in fields.items():
            if key not in d and default is None and key in optional:
                out[key] = None
                continue
            out[key] = self.quantity(d, key, path, dimension, default, positive=positive,
                                     nonnegative=not positive)
        return out

    def number(self, d: dict, key: str, path: str, default: float, low: float, high: float,
               what: str = "a number", high_open: bool = False, low_open: bool = False) -> float:
        """A plain number (no units) in [low, high] (either end open when asked)."""
        v = d.get(key, default)
        ok = (isinstance(v, (int, float)) and not isinstance(v, bool)
              and (low < v if low_open else low <= v) and (v < high if high_open else v <= high))
        if not ok:
            interval = f"{'(' if low_open else '['}{low:g}, {high:g}{')' if high_open else ']'}"
            self.fail(self.field(path, key), f"must be {what} in {interval}, got {v!r}")
            return default
        return float(v)

    def choice(self, d: dict, key: str, path: str, choices, default=None) -> str:
        v = d.get(key, default)
        choices = tuple(choices)
        if v is None:
            self.fail(self.field(path, key), f"missing (one of: {', '.join(choices)})")
            return choices[0]
        if v not in choices:
            self.fail(self.field(path, key), f"must be one of {', '.join(choices)}, got {v!r}")
            return default if default is not None else choices[0]
        return v

    def entries(self, raw: dict, key: str, path: str | None = None, fields: tuple[str, ...] = ()):
        """(path, table) of every entry of the list ``raw[key]`` (``[[key]]`` at the top level);
        a non-list or a non-table entry is a problem.  ``fields``: the table's fields, named in
        the messages (``path`` is the list's own, default ``key``)."""
        path = path or key
        items = raw.get(key, [])
        if not isinstance(items, list):
            self.fail(path, f"must be a list of {{{', '.join(fields)}}} tables" if fields else
                      f"must be a list of [[{key}]] entries")
            return
        for i, item in enumerate(items):
            item_path = f"{path}[{i}]"
            if not isinstance(item, dict):
                self.fail(item_path, "must be a table {" + ", ".join(f"{f} = ..." for f in fields) + "}"
                          if fields else "must be a table")
                continue
            yield item_path, item

    def pairs(self, d: dict, key: str, path: str, names: tuple[str, str], dimensions: tuple[str, str],
              minimum: int = 1) -> list[tuple[float, float]]:
        """A table of ``[x, y]`` pairs with units (a history, a force curve), x increasing."""
        raw = d.get(key)
        what = f"[{names[0]}, {names[1]}]"
        if not isinstance(raw, list) or len(raw) < minimum:
            at_least = f"at least {minimum} " if minimum > 1 else ""
            self.fail(f"{path}.{key}", f"must be a list of {at_least}{what} pairs")
            return []
        out = []
        for j, pair in enumerate(raw):
            if not isinstance(pair, list) or len(pair) != 2:
                article = "an" if names[0][0] in "aeiou" else "a"
                self.fail(f"{path}.{key}[{j}]", f"must be {article} {what} pair")
                continue
            try:
                out.append((_checked_si(pair[0], dimensions[0]), _checked_si(pair[1], dimensions[1])))
            except UnitError as e:
                self.fail(f"{path}.{key}[{j}]", str(e))
        if any(x1 <= x0 for (x0, _), (x1, _) in zip(out, out[1:])):
            self.fail(f"{path}.{key}", f"{names[0]}s must increase")
        return out

    def vector(self, d: dict, key: str, path: str, dimension: str, n: int, default) -> tuple:
        if key not in d:
            return tuple(default)
        raw = d[key]
        if not isinstance(raw, list):
            # A single value means "along the z axis" (the axis of axisymmetry).
            try:
                vz = _checked_si(raw, dimension)
            except UnitError as e:
                self.fail(f"{path}.{key}", str(e))
                return tuple(default)
            return tuple([0.0] * (n - 1) + [vz])
        if len(raw) != n:
            self.fail(f"{path}.{key}", f"needs {n} components for this kinematics, got {len(raw)}")
            return tuple(default)
        out = []
        for i, item in enumerate(raw):
            try:
                out.append(_checked_si(item, dimension))
            except UnitError as e:
                self.fail(f"{path}.{key}[{i}]", str(e))
                out.append(0.0)
        return tuple(out)
