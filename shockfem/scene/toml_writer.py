"""A minimal TOML writer for the scenes shockfem generates (tables, arrays of tables,
strings, numbers (numpy's too), booleans and flat lists) - enough to hand a scene to the CLI."""
from __future__ import annotations

import numpy as np


def _value(v) -> str:
    if isinstance(v, (np.generic, np.ndarray)):      # numbers a study computed with numpy
        v = v.tolist()
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(float(v)) if isinstance(v, float) else str(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {v!r} as TOML")


def _table(prefix: str, d: dict, lines: list):
    scalars = {k: v for k, v in d.items() if not isinstance(v, dict)
               and not (isinstance(v, list) and v and isinstance(v[0], dict))}
    for k, v in scalars.items():
        lines.append(f"{k} = {_value(v)}")
    for k, v in d.items():
        if isinstance(v, dict):
            lines.append(f"\n[{prefix}{k}]")
            _table(f"{prefix}{k}.", v, lines)
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            for item in v:
                lines.append(f"\n[[{prefix}{k}]]")
                _table(f"{prefix}{k}.", item, lines)


def dumps(d: dict) -> str:
    lines: list[str] = []
    _table("", d, lines)
    return "\n".join(lines).lstrip() + "\n"
