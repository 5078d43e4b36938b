"""The ``[outputs]`` table: which cell fields are written and how often, the history's interval, and the
stress sections along slender bodies."""
from __future__ import annotations

from .checker import Checker
from .specs import FIELDS, Outputs, SectionCuts

OUTPUT_FIELDS = ("fields", "field_interval", "history_interval", "sections")


def read_outputs(ck: Checker, raw: dict, bodies, end_time: float) -> Outputs:
    """``[outputs]``: by default every field, ten frames over the run, a history row every step."""
    o = ck.table(raw, "outputs", "outputs", required=False)
    ck.unknown(o, OUTPUT_FIELDS, "outputs")
    fields = o.get("fields", list(FIELDS))
    if not isinstance(fields, list) or any(f not in FIELDS for f in fields):
        ck.fail("outputs.fields", f"must be a list drawn from {', '.join(FIELDS)}, got {fields!r}")
        fields = list(FIELDS)
    fi = ck.quantity(o, "field_interval", "outputs", "time", default=end_time / 10, positive=True)
    hi = ck.quantity(o, "history_interval", "outputs", "time", default=0.0, nonnegative=True)
    return Outputs(fields=tuple(fields), field_interval=fi, history_interval=hi,
                   sections=_section_cuts(ck, o, bodies))


def _section_cuts(ck: Checker, o: dict, bodies) -> tuple[SectionCuts, ...]:
    """``outputs.sections = [{body = "bar", count = 21}]``: stress along slender deformable bodies."""
    deformable = [b.name for b in bodies if not b.rigid]
    cuts = []
    for path, c in ck.entries(o, "sections", "outputs.sections", ("body", "count")):
        ck.unknown(c, ("body", "count"), path)
        body = c.get("body")
        if body not in deformable:
            ck.fail(f"{path}.body", f"must name a deformable body (a rigid one has no stress; deformable: "
                                    f"{', '.join(deformable) or 'none'}), got {body!r}")
        count = c.get("count", 21)
        if not isinstance(count, int) or isinstance(count, bool) or not 2 <= count <= 1000:
            ck.fail(f"{path}.count", f"must be a whole number of cuts in [2, 1000], got {count!r}")
            count = 21
        if any(cut.body == body for cut in cuts):
            ck.fail(f"{path}.body", f"{body!r} already has its sections: one entry per body")
        cuts.append(SectionCuts(str(body), count))
    return tuple(cuts)
