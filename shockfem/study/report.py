"""A study report: ``report.md`` with tables and figures, written as the study goes."""
from __future__ import annotations

import os

from ..output.figures import save


class Report:
    def __init__(self, out_dir: str, title: str):
        self.out_dir = out_dir
        os.makedirs(out_dir, exist_ok=True)
        self.lines = [f"# {title}", ""]

    def text(self, *paragraphs: str):
        for p in paragraphs:
            self.lines += [p, ""]
        self.write()

    def heading(self, title: str):
        self.lines += [f"## {title}", ""]

    def table(self, header: list[str], rows: list[list], formats: list[str] | None = None):
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

    def path(self, name: str) -> str:
        return os.path.join(self.out_dir, name)

    def write(self):
        with open(os.path.join(self.out_dir, "report.md"), "w") as fh:
            fh.write("\n".join(self.lines) + "\n")
