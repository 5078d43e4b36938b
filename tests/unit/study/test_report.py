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


def test_run_pictures_show_what_the_run_drew(tmp_path):
    """A run's two pictures go into the report where it drew them; where it drew one or none (the
    suite's SHOCKFEM_PICTURES=0) the report says which are missing instead of linking to nothing."""
    rep = Report(str(tmp_path), "T")
    (tmp_path / "full").mkdir()
    for name in ("peak_stress.png", "final_shape.png"):
        (tmp_path / "full" / name).write_bytes(b"png")
    (tmp_path / "half").mkdir()
    (tmp_path / "half" / "final_shape.png").write_bytes(b"png")
    rep.run_pictures("full", "The design,", "the r-z half-section")
    rep.run_pictures("half", "The other run,")
    rep.run_pictures("none", "The third run,")
    text = (tmp_path / "report.md").read_text()
    assert "![The design, at the field frame of its highest von Mises stress: deformed at true scale" in text
    assert "](full/peak_stress.png)" in text and "](full/final_shape.png)" in text
    assert "](half/final_shape.png)" in text and "](half/peak_stress.png)" not in text
    assert "No peak_stress.png of the other run in `half/`" in text
    assert "No peak_stress.png or final_shape.png of the third run in `none/`" in text
    assert "](none/" not in text and "No " not in text.split("The other run,")[0]


def test_a_readings_nested_numpy_values_are_written_as_json(tmp_path):
    """A reading may be a dict of a design's numbers as numpy computed them (a housing's verdict a numpy
    bool inside a nested dict): results.json holds them as plain JSON, NaN as null."""
    import json
    import numpy as np
    from shockfem.study.report import Report
    rep = Report(str(tmp_path), "t")
    rep.value("fixture", {"wall": {"holds": np.bool_(True), "ratio": np.float64(3.5), "nan": np.float64("nan")},
                          "masses": [np.float64(1.5), (np.int64(2), np.bool_(False))]})
    with open(tmp_path / "results.json") as fh:
        got = json.load(fh)["values"]["fixture"]
    assert got == {"wall": {"holds": True, "ratio": 3.5, "nan": None}, "masses": [1.5, [2, False]]}
