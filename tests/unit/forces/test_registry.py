"""The force sources' registry: every kind implements the whole protocol, and the run's summary takes
each kind's section from it (``forces/registry.py``, ``forces/source.py``)."""
import importlib

import pytest

from shockfem.forces import registry
from shockfem.forces.source import ForceSource

# where each kind's class lives: the registry builds them lazily, so the test names them itself
CLASSES = {"contact": ("shockfem.contact.pairs", "ContactPair"),
           "spring": ("shockfem.contact.springs", "DiscreteSpring"),
           "cavity": ("shockfem.fluid.cavity", "LiquidCavity"),
           "penetration": ("shockfem.target.penetration", "ConcreteTarget")}
# the kinds with more than one class (a [[cavity]] by its model)
MORE = {"cavity": [("shockfem.fluid.column_source", "ColumnSource")]}
# what a source must implement itself: the base's defaults of these raise or record nothing
OWN = ("rows", "apply", "energy", "columns", "history", "summary")


def test_the_registry_lists_every_kind_once_in_the_solvers_order():
    # the order is the force sum's: contact pairs, springs, cavities, the target (to the bit on verify)
    assert [k.kind for k in registry.SOURCES] == ["contact", "spring", "cavity", "penetration"]
    assert set(registry.KINDS) == set(CLASSES)
    assert len({k.summary_key for k in registry.SOURCES}) == len(registry.SOURCES)


@pytest.mark.parametrize("kind, module, name", [(k, *CLASSES[k]) for k in sorted(CLASSES)]
                         + [(k, *c) for k, classes in MORE.items() for c in classes])
def test_each_kind_implements_the_protocol(kind, module, name):
    cls = getattr(importlib.import_module(module), name)
    assert issubclass(cls, ForceSource) and cls.kind == kind
    missing = [method for method in OWN if getattr(cls, method) is getattr(ForceSource, method)]
    assert missing == [], f"{name} leaves {missing} to the base"


class _Fake(ForceSource):
    def __init__(self, kind, name):
        self.kind, self.name = kind, name

    def summary(self):
        return {"of": self.name}


def test_summaries_have_a_section_per_kind():
    sources = [_Fake("contact", "impact"), _Fake("contact", "floor"), _Fake("cavity", "oil")]
    out = registry.summaries(sources)
    assert out == {"contacts": {"impact": {"of": "impact"}, "floor": {"of": "floor"}}, "springs": {},
                   "cavities": {"oil": {"of": "oil"}}, "penetration": None}
    assert registry.summaries([_Fake("penetration", "penetration")])["penetration"] == {"of": "penetration"}


def test_build_makes_one_source_per_spec_in_the_registrys_order(monkeypatch):
    made = []
    kinds = tuple(registry.SourceKind(k.kind, lambda m, k=k: getattr(m, k.kind), lambda m, spec: made.append(spec)
                                      or spec, k.summary_key, k.single) for k in registry.SOURCES)
    monkeypatch.setattr(registry, "SOURCES", kinds)

    class Model:
        contact, spring, cavity, penetration = ["c1", "c2"], ["s1"], [], ["p"]
    assert registry.build(Model()) == ["c1", "c2", "s1", "p"] == made
