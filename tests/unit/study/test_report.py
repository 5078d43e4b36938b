"""A study report writes its tables twice: formatted in report.md, unformatted in results.json."""
import json
import math

from shockfem.study.report import Report


def test_tables_and_values_land_in_results_json(tmp_path):
    rep = Report(str(tmp_path), "T")
    rep.table("t", ["case", "gain", "wall [s]"], [["a", 1.23456, 0.5], ["b", math.nan, 2.0]],
              ["{}", "{:.2f}", "{:.1f}"])
    assert rep.value("best", 1.23456) == 1.23456
    results = json.loads((tmp_path / "results.json").read_text())
    assert results["tables"]["t"] == {"columns": ["case", "gain", "wall [s]"],
                                      "rows": [["a", 1.23456, 0.5], ["b", None, 2.0]]}   # full precision; NaN -> null
    assert results["values"] == {"best": 1.23456} and results["title"] == "T"
    assert "| a | 1.23 | 0.5 |" in (tmp_path / "report.md").read_text()
