import pytest

from shockfem.units import UnitError, to_si


@pytest.mark.parametrize("text, dim, si", [
    ("12 lb", "mass", 12 * 0.45359237),
    ("1600 ft/s", "velocity", 1600 * 0.3048),
    ("2000 psi", "pressure", 2000 * 6894.757293168),
    ("5 ms", "time", 5e-3),
    ("10000 gee", "acceleration", 98066.5),
    ("10000 gn", "acceleration", 98066.5),          # the standard gravity's usual symbols (9.80665 m/s^2)
    ("10000 g0", "acceleration", 98066.5),
    ("7850 kg/m^3", "density", 7850.0),
])
def test_to_si(text, dim, si):
    assert to_si(text, dim) == pytest.approx(si, rel=1e-9)


def test_bare_numbers_are_si():
    assert to_si(3, "length") == 3.0


def test_wrong_dimension_names_expected_dimension():
    with pytest.raises(UnitError, match="expected a velocity"):
        to_si("3 kg", "velocity")


def test_unreadable():
    with pytest.raises(UnitError, match="cannot read"):
        to_si("fast", "velocity")


def test_report_factors_agree_with_the_input_units():
    """The factors reports divide by (units.G0, LB, FT, IN, PSI) are pint's conversions of the same
    units, to round-off: a value read as "2000 psi" prints back as 2000 psi."""
    from shockfem import units
    for text, dimension, factor in (("1 gee", "acceleration", units.G0), ("1 lb", "mass", units.LB),
                                    ("1 ft", "length", units.FT), ("1 in", "length", units.IN),
                                    ("1 psi", "pressure", units.PSI)):
        assert to_si(text, dimension) == pytest.approx(factor, rel=1e-14), text


@pytest.mark.parametrize("value", ["nan m", "inf m", "1e400 m", float("nan"), float("inf"), -float("inf")])
def test_nan_and_infinity_are_refused(value):
    """Every scene field goes through to_si, so a NaN or an infinity is refused with its field named."""
    with pytest.raises(UnitError, match="expected a finite length"):
        to_si(value, "length")


def test_pint_is_imported_with_the_first_unit_and_dask_stays_loadable():
    """``units._pint``: a scene of bare SI numbers does not import pint (0.2 s of a run's start); the first
    string with a unit does, without importing dask (0.1 s, ``shockfem[batch]``), and dask imports normally
    afterwards when it is installed.  In a fresh interpreter: this test process may hold pint already."""
    import subprocess
    import sys
    code = (
        "import sys\n"
        "from shockfem.scene import resolve\n"
        "from shockfem.verify.contact_cases import two_rods_scene\n"
        "resolve(two_rods_scene(0.0025, 'axisymmetric'))\n"
        "print('pint' in sys.modules)\n"
        "from shockfem.units import to_si\n"
        "print(to_si('12 lb', 'mass'), 'pint' in sys.modules, 'dask' in sys.modules)\n"
        "import importlib.util\n"
        "if importlib.util.find_spec('dask') is not None:\n"
        "    import dask.array\n"
        "print('dask' in sys.modules or importlib.util.find_spec('dask') is None)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert out[0] == "False" and out[2:] == ["True", "False", "True"], out
    assert float(out[1]) == pytest.approx(12 * 0.45359237, rel=1e-12)
