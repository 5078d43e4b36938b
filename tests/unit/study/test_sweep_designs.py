"""A sweep's factors and designs: levels as --vary reads them, the full factorial's order, pyDOE3's
fractional factorials mapped onto the two levels, a table of cases; bad input named (SceneError)."""
import pytest

from shockfem.scene.checker import SceneError
from shockfem.study.sweep import cases_from_table, design_cases, parse_vary


def test_levels_with_a_unit_or_as_toml():
    assert parse_vary('bodies.striker.velocity=[5, 10, 20] m/s') == (
        "bodies.striker.velocity", ['"5 m/s"', '"10 m/s"', '"20 m/s"'])
    assert parse_vary('contact.0.friction=[0.1, 0.25]') == ("contact.0.friction", ["0.1", "0.25"])
    assert parse_vary('bodies.a.material=["steel", "aluminium"]') == ("bodies.a.material", ['"steel"', '"aluminium"'])
    for bad in ("bodies.a.velocity", "=[1]", "x=5 m/s", "x=[]", 'x=["a"] m/s'):
        with pytest.raises(SceneError):
            parse_vary(bad)


def test_full_factorial_first_factor_slowest():
    cases = design_cases("s.toml", [("a", ["1", "2"]), ("b", ['"x"', '"y"', '"z"'])], fixed=("scene.end_time=1",))
    assert [c.name for c in cases] == [f"case_{k}" for k in range(6)]
    assert [c.factors for c in cases[:4]] == [{"a": "1", "b": "x"}, {"a": "1", "b": "y"}, {"a": "1", "b": "z"},
                                              {"a": "2", "b": "x"}]
    assert cases[1].overrides == ("scene.end_time=1", "a=1", 'b="y"')


def test_fractional_factorials():
    factors = [(n, ["0", "1"]) for n in "abcd"]
    # D = ABC: half of the 16 runs, every factor balanced, D's coded level the product of A's, B's and C's
    half = design_cases("s.toml", factors, "fractional", generators="a b c abc")
    assert len(half) == 8
    coded = [[2 * int(c.factors[n]) - 1 for n in "abcd"] for c in half]
    assert all(sum(r[j] for r in coded) == 0 for j in range(4))
    assert all(r[3] == r[0] * r[1] * r[2] for r in coded)
    assert len({tuple(r) for r in coded}) == 8
    assert len(design_cases("s.toml", factors, "fractional", resolution=3)) == 8
    with pytest.raises(SceneError, match="two levels"):
        design_cases("s.toml", [("a", ["0", "1", "2"]), ("b", ["0", "1"])], "fractional")
    with pytest.raises(SceneError, match="columns"):
        design_cases("s.toml", factors, "fractional", generators="a b c")


def test_a_table_of_cases(tmp_path):
    table = tmp_path / "cases.csv"
    table.write_text("case,bodies.striker.velocity,scene.safety_factor\nslow,5 m/s,0.5\n,10 m/s,\n")
    slow, other = cases_from_table("s.toml", str(table))
    assert slow.name == "slow" and slow.overrides == ('bodies.striker.velocity="5 m/s"', "scene.safety_factor=0.5")
    assert other.name == "case_1" and other.factors == {"bodies.striker.velocity": "10 m/s"}
