"""The orifice law of ``fluid/orifice.py``: Idelchik's contraction, its inverse, the jet's reaction and the
designer's inverse, each against a closed form worked by hand."""
import math

import pytest

from shockfem.fluid import orifice
from shockfem.fluid.orifice import AREA_RATIO, FIXED_CD, OrificeLaw

RHO, A = 870.0, 3.2e-3          # the study's oil; a 32 mm bore


def test_idelchiks_contraction_at_its_ends():
    # Idelchik's thin orifice: Cc = 1 / (1 + 0.707 sqrt(1 - n)): 1 / 1.707 = 0.5858 for a small orifice,
    # 1 / 1.5 at n = 0.5 (0.707 sqrt(0.5) = 0.49992), 1 with no plate
    assert orifice.contraction(0.0) == pytest.approx(1.0 / 1.707, rel=1e-12)
    assert orifice.contraction(0.5) == pytest.approx(1.0 / (1.0 + 0.707 * math.sqrt(0.5)), rel=1e-12)
    assert orifice.contraction(1.0) == 1.0


def test_the_fixed_law_is_the_studys_first_one():
    # mdot = Cd a rho sqrt(2 p / rho), with no approach whatever the passage
    p, a = 100e6, 1e-3
    expected = 0.7 * a * RHO * math.sqrt(2.0 * p / RHO)
    assert orifice.mass_flow(p, RHO, 1300.0, a, 1.01 * a, FIXED_CD.code()) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("n", [0.05, 0.3, 0.56, 0.9])
def test_pressure_for_flow_inverts_mass_flow(n):
    law = AREA_RATIO.code()
    p = 50e6
    mdot = orifice.mass_flow(p, RHO, 1e9, n * A, A, law)
    assert orifice.pressure_for_flow(mdot / RHO, RHO, n * A, A, law) == pytest.approx(p, rel=1e-12)


@pytest.mark.parametrize("n", [0.1, 0.4, 0.8])
def test_the_force_with_the_jet_is_borda_carnots(n):
    """p A - mdot (u_j - u1) = rho A (u_j - u1)^2 / 2 once p is Bernoulli's with the approach (the module
    docstring's algebra): a wrong sign or velocity in the jet's reaction breaks it."""
    law = AREA_RATIO.code()
    v = 200.0
    u_jet = v / (orifice.contraction(n) * n)
    assert orifice.piston_force(n * A, v, RHO, A, law) == pytest.approx(RHO * A * (u_jet - v) ** 2 / 2, rel=1e-12)


def test_the_approach_lowers_the_pressure_of_a_wide_orifice():
    # at n = 0.9 with Cd 0.7: a factor 1 - 0.63^2 = 0.603 on the fixed law's pressure
    with_approach, without = OrificeLaw(0.7, True, False).code(), OrificeLaw(0.7, False, False).code()
    Q, a = 0.1, 0.9 * A
    ratio = orifice.pressure_for_flow(Q, RHO, a, A, with_approach) / orifice.pressure_for_flow(Q, RHO, a, A, without)
    assert ratio == pytest.approx(1.0 - 0.63 ** 2, rel=1e-12)


def test_area_for_force_inverts_the_force_and_stops_at_the_largest_area():
    law = AREA_RATIO.code()
    v, largest = 300.0, orifice.VALID_AREA_RATIO * A
    force = orifice.piston_force(0.2 * A, v, RHO, A, law)
    assert orifice.area_for_force(force, v, RHO, A, largest, law) == pytest.approx(0.2 * A, rel=1e-9)
    # a force below what the largest area throttles: the largest area
    least = orifice.piston_force(largest, v, RHO, A, law)
    assert orifice.area_for_force(0.5 * least, v, RHO, A, largest, law) == largest


@pytest.mark.parametrize("beta", [0.3, 0.5, 0.7])
def test_the_law_is_iso_5167s_orifice_within_three_percent(beta):
    """ISO 5167-2's Reader-Harris/Gallagher coefficient, corner tappings, Re_D -> infinity, D >= 71.12 mm:
    C = 0.5961 + 0.0261 beta^2 - 0.216 beta^8.  Measured: -0.5%, +1.0%, +2.7% (``verify orifice_law``)."""
    rhg = 0.5961 + 0.0261 * beta ** 2 - 0.216 * beta ** 8
    assert orifice.iso_discharge_coefficient(beta ** 2) == pytest.approx(rhg, rel=0.03)


def test_the_fixed_law_cuts_the_closed_form_metering_pin():
    """Under the fixed-Cd law the designer's inverse is fixtures.md's closed form
    a = (A^1.5 / Cd) sqrt(rho / (2F)) v (``programmer.concepts.metering_pin_area`` at stroke 0, speed v):
    the bisection's 1e-12 of the bore."""
    from shockfem.programmer.concepts import metering_pin_area
    F, v = 5e5, 400.0
    closed = metering_pin_area(0.0, A, F, 1.0, v, RHO, 0.7)
    assert orifice.area_for_force(F, v, RHO, A, A, FIXED_CD.code()) == pytest.approx(closed, rel=1e-10)


def test_idelchiks_thick_edged_orifice_by_hand():
    """Idelchik 4-12's tau = (2.4 - l) 10^-phi, phi = 0.25 + 0.535 l^8 / (0.05 + l^8) (as the Modelica Standard
    Library's Fluid.Dissipation writes it): 2.4 x 10^-0.25 = 1.3496 at l / d_h = 0; 1.4 x 10^-(0.25 + 0.535 / 1.05)
    = 0.2436 at 1; at 0.5, 1.9 x 10^-(0.25 + 0.535 / (0.05 x 256 + 1)) = 0.9772; 0 reattached.  Into a large space the
    coefficient over the thin one's is sqrt((0.5 + 1.3496 + 1) / (0.5 + 1 + 0.02 x 2.4)) = 1.3568 at 2.4."""
    assert orifice.thick_edge_excess(0.0) == pytest.approx(2.4 * 10 ** -0.25, rel=1e-12)
    assert orifice.thick_edge_excess(1.0) == pytest.approx(1.4 * 10 ** -(0.25 + 0.535 / 1.05), rel=1e-12)
    assert orifice.thick_edge_excess(0.5) == pytest.approx(1.9 * 10 ** -(0.25 + 0.535 / (0.05 * 256 + 1)), rel=1e-12)
    assert orifice.thick_edge_excess(3.0) == 0.0
    assert orifice.thick_discharge_ratio(0.0) == 1.0
    assert orifice.thick_discharge_ratio(2.4) == pytest.approx(math.sqrt((1.5 + 2.4 * 10 ** -0.25) / 1.548), rel=1e-12)


def test_nurick_cavitation_chokes_a_thick_orifice_to_the_thin_laws_coefficient():
    """K = (p1 - p_v) / (p1 - p2): at 287 MPa into the atmosphere (p_v one atmosphere below it) 287.1 / 287;
    a reattached land chokes there at sqrt(K) (within 2e-4 of the thin law), and not at 0.05 MPa (K = 3,
    sqrt 1.73 above its 1.36); a thin plate never chokes."""
    k = orifice.cavitation_number(287e6, -1e5)
    assert k == pytest.approx(287.1 / 287.0, rel=1e-12)
    assert orifice.coefficient_ratio(2.4, k) == pytest.approx(math.sqrt(k), rel=1e-12)
    assert orifice.cavitates(2.4, k) and not orifice.cavitates(0.0, k)
    k_low = orifice.cavitation_number(0.05e6, -1e5)
    assert k_low == pytest.approx(3.0, rel=1e-12)
    assert orifice.coefficient_ratio(2.4, k_low) == orifice.thick_discharge_ratio(2.4)
    assert math.isinf(orifice.cavitation_number(0.0, -1e5))


def test_lichtarowiczs_viscous_shift_and_the_annulus_length_scale():
    """1 / Cd = 1 / Cd_inf + 20 (1 + 2.25 l / d) / Re: at Re = 1000, a thin plate at Cd 0.6 keeps
    1 / 1.012 of its coefficient; the ideal jet's Re at 2 MPa in water through 1 mm: 1e-3 sqrt(4000) 1e6 =
    63246; a pin of 6 mm in a hole of 10 mm radius leaves a gap of hydraulic diameter 8 mm."""
    assert orifice.viscous_coefficient_ratio(1000.0, 0.0, 0.6) == pytest.approx(1 / 1.012, rel=1e-12)
    assert orifice.viscous_coefficient_ratio(1000.0, 2.0, 0.6) == pytest.approx(1 / (1 + 0.012 * 5.5), rel=1e-12)
    assert orifice.jet_reynolds(2e6, 1000.0, 1e-3, 1e-3) == pytest.approx(1e-3 * math.sqrt(4000.0) * 1e6, rel=1e-12)
    hole = math.pi * 0.01 ** 2
    assert orifice.annulus_hydraulic_diameter(hole - math.pi * 0.006 ** 2, hole) == pytest.approx(0.008, rel=1e-9)
    assert orifice.annulus_hydraulic_diameter(hole, hole) == pytest.approx(0.02, rel=1e-12)


def test_the_largest_opening_is_the_designs_and_beyond_the_checked_data_it_is_extrapolation():
    """``valid_area_ratio`` of a law with the approach is its own largest_ratio (0.5625 by default, the
    data the law is checked on); 0.8 is extrapolated, 0.5625 is not."""
    assert orifice.valid_area_ratio(AREA_RATIO) == orifice.VALID_AREA_RATIO == 0.5625
    assert orifice.valid_area_ratio(OrificeLaw(largest_ratio=0.8)) == 0.8
    assert orifice.extrapolated(0.8) and not orifice.extrapolated(0.5625)
