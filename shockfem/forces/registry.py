"""Every kind of force source, in the order the solver applies them.

Each entry names where the model keeps its specs, how a source is built from one, and the key of
summary.json under which its summaries go.  The solver builds its sources here (``build``), the history
takes its columns from them and the run's summary its sections (``summaries``): a new kind of source is
one new module and one entry below (``docs/theory.md``, "Adding a force source").

The order is the solver's: the sources add into the same force array, and a sum taken in another order
differs in its last bits.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from ..model import Model
from .source import ForceSource


@dataclass(frozen=True)
class SourceKind:
    """One kind of force source."""
    kind: str                                  # its name (``ForceSource.kind``)
    specs: Callable[[Model], list]             # the model's specs of this kind
    build: Callable[[Model, object], ForceSource]
    summary_key: str                           # its section of summary.json
    single: bool = False                       # at most one per scene: its section is one summary, or None


def _contact_pair(model, spec):
    from ..contact.pairs import ContactPair
    return ContactPair(model, spec)


def _spring(model, spec):
    from ..contact.springs import DiscreteSpring
    return DiscreteSpring(model, spec)


def _cavity(model, spec):
    """A [[cavity]] by its model: the control volume (``fluid/cavity.py``) or the liquid column
    (``fluid/column_source.py``); both are the kind "cavity", summarised under "cavities"."""
    if spec.model == "column":
        from ..fluid.column_source import ColumnSource
        return ColumnSource(model, spec)
    from ..fluid.cavity import LiquidCavity
    return LiquidCavity(model, spec)


def _target(model, spec):
    # imported only for a scene with a target: it and target.concrete's ufunc take 0.28 s to import
    # (python -X importtime), which no other scene needs
    from ..target.penetration import ConcreteTarget
    return ConcreteTarget(model, spec)


SOURCES = (
    SourceKind("contact", lambda m: m.contacts, _contact_pair, "contacts"),
    SourceKind("spring", lambda m: m.springs, _spring, "springs"),
    SourceKind("cavity", lambda m: m.cavities, _cavity, "cavities"),
    SourceKind("penetration", lambda m: [m.penetration] if m.penetration else [], _target, "penetration",
               single=True),
)
KINDS = {k.kind: k for k in SOURCES}


def build(model: Model) -> list[ForceSource]:
    """The model's force sources, kind by kind in ``SOURCES``' order, each kind in its specs' order."""
    return [kind.build(model, spec) for kind in SOURCES for spec in kind.specs(model)]


def summaries(sources: list[ForceSource]) -> dict:
    """summary.json's sections of the sources: ``{summary_key: {name: summary}}``, or for a kind that is
    ``single``, ``{summary_key: summary or None}``."""
    out = {}
    for kind in SOURCES:
        of_kind = [s for s in sources if s.kind == kind.kind]
        if kind.single:
            out[kind.summary_key] = of_kind[0].summary() if of_kind else None
        else:
            out[kind.summary_key] = {s.name: s.summary() for s in of_kind}
    return out
