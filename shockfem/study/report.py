"""A study report: ``report.md`` with tables and figures, and ``results.json`` with every number of
the report's tables and of its readings, both written as the study goes.

``results.json``: ``{"title", "tables": {name: {"columns": [...], "rows": [[...], ...]}}, "values":
{name: number or text}}``; the columns carry their units as the report's headers do ("wall [s]").
Tests and later studies read it instead of parsing the Markdown.
"""
from __future__ import annotations

import json
import math
import os
import time

from ..output.figures import save


def _plain(value):
    """A JSON value for a table cell or a reading (NaN becomes null), through the dicts, lists and tuples
    a reading may nest its numbers in."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if hasattr(value, "item") and getattr(value, "size", 1) == 1:      # numpy scalars
        return _plain(value.item())
    if hasattr(value, "tolist"):                                        # numpy arrays
        return _plain(value.tolist())
    return value


class Report:
    def __init__(self, out_dir: str, title: str):
        self.out_dir = out_dir
        os.makedirs(out_dir, exist_ok=True)
        self.lines = [f"# {title}", ""]
        self.results = {"title": title, "tables": {}, "values": {}}

    def value(self, name: str, value):
        """Record a number a reading states (``results.json``'s ``values``); returns it."""
        self.results["values"][name] = _plain(value)
        self.write()
        return value

    def text(self, *paragraphs: str):
        for p in paragraphs:
            self.lines += [p, ""]
        self.write()

    def lead(self, *paragraphs: str):
        """Paragraphs at the top of the report, under its title: a study's answer, written once the sections
        below have computed its numbers."""
        at = 2
        for p in paragraphs:
            self.lines[at:at] = [p, ""]
            at += 2
        self.write()

    def heading(self, title: str, level: int = 2):
        self.lines += [f"{'#' * level} {title}", ""]

    def table(self, name: str, header: list[str], rows: list[list], formats: list[str] | None = None):
        """A table in the report, and its unformatted rows under ``name`` in ``results.json``."""
        self.results["tables"][name] = {"columns": list(header), "rows": [[_plain(c) for c in row] for row in rows]}
        formats = formats or ["{}"] * len(header)
        self.lines.append("| " + " | ".join(header) + " |")
        self.lines.append("|" + "---|" * len(header))
        for row in rows:
            cells = [f.format(c) if not isinstance(c, str) else c for f, c in zip(formats, row)]
            self.lines.append("| " + " | ".join(cells) + " |")
        self.lines.append("")
        self.write()

    def figure(self, filename: str, caption: str, fig=None):
        """Reference the PNG ``filename`` in the report; with a matplotlib ``fig``, save it there first."""
        if fig is not None:
            save(fig, self.path(filename))
        self.lines += [f"![{caption}]({filename})", "", f"*{caption}*", ""]
        self.write()

    def run_pictures(self, run: str, subject: str, shown: str = ""):
        """The deformed shape of the run in ``run`` (a directory beside the report) at its field frame of
        highest von Mises stress and at its end (the run's ``peak_stress.png`` and ``final_shape.png``), captioned
        with ``subject`` ("The five-mass design, axisymmetric (10 mm),") and ``shown`` (what the picture
        shows or leaves out); a sentence instead where the run drew none (``SHOCKFEM_PICTURES=0``, or a
        run that stopped early)."""
        pictures = (("peak_stress.png", "at the field frame of its highest von Mises stress"),
                    ("final_shape.png", "at the end of its run"))
        drawn = [(name, when) for name, when in pictures if os.path.exists(self.path(f"{run}/{name}"))]
        for name, when in drawn:
            self.figure(f"{run}/{name}", f"{subject} {when}: deformed at true scale, coloured by von Mises stress"
                        + (f"; {shown}" if shown else ""))
        missing = [name for name, when in pictures if (name, when) not in drawn]
        self.text((f"No {' or '.join(missing)} of {subject[:1].lower() + subject[1:].rstrip(',')} in `{run}/` (runs draw them unless "
                   "`SHOCKFEM_PICTURES=0`; a run that stopped early draws none). " if missing else "")
                  + f"Its fields over time: `{run}/fields.xdmf` "
                  "and `final_shape.xdmf`, which ParaView opens with its default reader (`docs/outputs.md`).")

    def finish(self, started: float, echo=print) -> str:
        """Close a study: its wall time since ``started`` (``time.perf_counter()``) in the report and in
        ``results.json`` (``wall_time_s``); echo and return the report's path."""
        wall = time.perf_counter() - started
        self.value("wall_time_s", wall)
        self.text(f"Study wall time {wall:.0f} s.")
        path = self.path("report.md")
        echo(f"report: {path}")
        return path

    def path(self, name: str) -> str:
        return os.path.join(self.out_dir, name)

    def write(self):
        with open(os.path.join(self.out_dir, "report.md"), "w") as fh:
            fh.write("\n".join(self.lines) + "\n")
        with open(os.path.join(self.out_dir, "results.json"), "w") as fh:
            json.dump(self.results, fh, indent=1)


def run_sections(out_dir: str, title: str, intro: str, sections, ctx, echo=print) -> str:
    """A study of ``sections`` ((title, function(report, ctx)), in order) into ``out_dir``: its report
    opened with ``intro``, each section echoed as it starts, the wall time at the end; returns the
    report's path."""
    started = time.perf_counter()
    rep = Report(out_dir, title)
    rep.text(intro)
    for k, (name, section) in enumerate(sections, 1):
        echo(f"{k}/{len(sections)} {name}")
        section(rep, ctx)
    return rep.finish(started, echo)

