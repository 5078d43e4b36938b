"""Quantities with units in scene files: ``"12 lb"``, ``"1600 ft/s"``, ``"2000 psi"``, ``"5 ms"``.

Everything inside shockfem is SI (m, kg, s, N, Pa, J); bare numbers in a scene are SI.
"""
from __future__ import annotations

import functools
import math
import sys

# Dimensions a scene field may ask for, as pint dimensionality strings.
DIMENSIONS = {
    "length": "[length]",
    "mass": "[mass]",
    "time": "[time]",
    "velocity": "[length] / [time]",
    "angular_velocity": "1 / [time]",
    "acceleration": "[length] / [time] ** 2",
    "force": "[mass] * [length] / [time] ** 2",
    "pressure": "[mass] / [length] / [time] ** 2",
    "density": "[mass] / [length] ** 3",
    "frequency": "1 / [time]",
    "strain_rate": "1 / [time]",
    "energy": "[mass] * [length] ** 2 / [time] ** 2",
    "stiffness": "[mass] / [time] ** 2",
    "damping": "[mass] / [time]",
    "slowness": "[time] / [length]",
    "area": "[length] ** 2",
    "volume": "[length] ** 3",
    "temperature": "[temperature]",
    "specific_heat": "[length] ** 2 / [time] ** 2 / [temperature]",
    "angle": "",
    "dimensionless": "",
}

# SI unit each dimension is converted to.
SI_UNITS = {
    "length": "m", "mass": "kg", "time": "s", "velocity": "m/s", "angular_velocity": "rad/s",
    "acceleration": "m/s**2", "force": "N", "pressure": "Pa", "density": "kg/m**3",
    "frequency": "Hz", "strain_rate": "1/s", "energy": "J", "stiffness": "N/m", "damping": "N*s/m", "slowness": "s/m",
    "area": "m**2", "volume": "m**3", "temperature": "K", "specific_heat": "J/(kg*K)", "angle": "rad",
    "dimensionless": "",
}


# The factors shockfem's own reports divide by (inputs go through pint, which agrees with these):
G0 = 9.80665              # standard gravity [m/s^2]: accelerations are also reported in g
LB = 0.45359237           # pound (avoirdupois) [kg]
FT = 0.3048               # foot [m]
IN = 0.0254               # inch [m]
PSI = LB * G0 / IN ** 2   # pound-force per square inch [Pa] (6894.757...)


class UnitError(ValueError):
    """A value whose unit cannot be read or has the wrong dimension."""


def _pint():
    """pint, imported when the first string with a unit is read (a scene of bare SI numbers never needs it:
    0.2 s of a run's start).  pint imports dask when it is installed (``shockfem[batch]``), for quantities
    that hold dask arrays, which shockfem never makes: 0.1 s more.  dask is hidden from pint's import
    (``sys.modules`` entry ``None``: "not installed") unless something loaded it already, and shown again
    at once, so that anything importing dask later gets it."""
    if "pint" in sys.modules:
        return sys.modules["pint"]
    hide = "dask" not in sys.modules
    if hide:
        sys.modules["dask"] = None
    try:
        import pint
    finally:
        if hide and "dask" in sys.modules and sys.modules["dask"] is None:
            del sys.modules["dask"]
    return pint


@functools.lru_cache(maxsize=1)
def registry():
    """pint's unit registry with shockfem's names for a standard gravity (``gee``, ``gn``)."""
    pint = _pint()
    try:
        # pint's parsed definitions kept in the user's cache directory: building the registry from its
        # text takes 0.29 s of every run's start, from the cache 0.07 s
        ureg = pint.UnitRegistry(cache_folder=":auto:")
    except Exception:              # no writable cache directory (a read-only home): build it from the text
        ureg = pint.UnitRegistry()
    # "g" is gram in pint; shock engineers write accelerations in standard gravities as "gn"
    # or "g0" (pint's own name is "g_n"); we accept "gee" too so that "10000 gee" is unambiguous.
    # Outputs write the unit as "g" ("11,344 g"): a standard gravity, never a gram.
    ureg.define(f"gee = {G0} m/s**2")
    ureg.define(f"gn = {G0} m/s**2")
    return ureg


def _a(dimension: str) -> str:
    """'a velocity', 'an acceleration'."""
    words = dimension.replace("_", " ")
    return f"{'an' if words[0] in 'aeiou' else 'a'} {words}"


def to_si(value, dimension: str) -> float:
    """Convert a scene value (number or string with unit) to an SI float.

    Parameters
    ----------
    value : int, float or str
        Bare numbers are taken as SI; strings are parsed by pint ("12 lb", "5 ms").
    dimension : str
        A key of ``DIMENSIONS``.

    Raises
    ------
    UnitError
        With a message that says what was expected, e.g. "expected a velocity
        (like '12 m/s' or '1600 ft/s'), got '3 kg'".
    """
    if isinstance(value, bool):
        raise UnitError(f"expected {_a(dimension)}, got {value!r}")
    v = _parse(value, dimension)
    if not math.isfinite(v):              # "nan m", "1e400 m", float("inf"): no input value
        words = "number" if dimension == "dimensionless" else dimension.replace("_", " ")
        raise UnitError(f"expected a finite {words}, got {value!r}")
    return v


def _parse(value, dimension: str) -> float:
    """The SI value of a bare number or a string with a unit (``to_si``)."""
    if isinstance(value, (int, float)):
        return float(value)
    if not isinstance(value, str):
        raise UnitError(f"expected a number or a string with a unit, got {value!r}")
    ureg = registry()
    try:
        q = ureg.Quantity(value.strip())
    except Exception:
        raise UnitError(f"cannot read {value!r} as a quantity (write e.g. '{_example(dimension)}')") from None
    if not isinstance(q, _pint().Quantity):
        return float(q)
    want = ureg.Quantity(1, SI_UNITS[dimension] or "dimensionless")
    if q.dimensionality != want.dimensionality:
        raise UnitError(f"expected {_a(dimension)} (like '{_example(dimension)}'), "
                        f"got {value!r}")
    return float(q.to(want.units).magnitude)


def _example(dimension: str) -> str:
    return {"length": "25 mm", "mass": "12 lb", "time": "5 ms", "velocity": "1600 ft/s",
            "pressure": "2000 psi", "density": "7850 kg/m^3", "frequency": "5 kHz",
            "force": "10 kN", "acceleration": "10000 gee", "energy": "1 kJ",
            "angular_velocity": "100 rad/s", "angle": "7 deg", "area": "20 mm^2", "stiffness": "1e6 N/m", "damping": "100 N*s/m",
            "volume": "20 ft**3", "temperature": "293 K",
            "dimensionless": "0.3"}.get(dimension, "1")


def format_si(value: float, dimension: str) -> str:
    """'3.000e-03 m' style text for messages."""
    unit = SI_UNITS[dimension]
    return f"{value:.4g} {unit}".strip()
