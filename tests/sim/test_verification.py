"""The verification cases with the tolerances they state: coarse size, except the axisymmetric rod
contact cases, which run at their default size (1 to 4 s each): the penalty's compliance scales
with the element size, and at coarse size the rod-on-rod contact lasts 2.3% longer than 2L/c0
(tolerance 2%), the unequal rods rebound with e 3.3% above L1/L2 (tolerance 3%), and the struck
rod's fitted pulse lasts 3.1% longer (tolerance 3%); the Taylor bar in one-point quads (16 s),
whose radius converges from below (-3.1% at coarse size, -1.3% at the default; tolerance 1.5%); and
the rubber pad (3 s), whose energy balance is 0.82% at coarse size and 0.43% at the default
(tolerance 1%); and the yawed nose (4 s), whose faceted tetrahedra at coarse size put the lateral force
2.8% above the exact surface's (0.4% at the default; tolerance 1.5%)."""
import pytest

from shockfem.verify import CASES, run_cases

DEFAULT_SIZE = {"rod_on_rod", "rod_on_wall", "unequal_rods", "rod_impact_metrics", "taylor_bar", "rubber_pad",
                "penetration_yaw"}


@pytest.mark.parametrize("name", list(CASES))
def test_case_passes(name, tmp_path):
    size = "default" if name in DEFAULT_SIZE else "coarse"
    checks = run_cases([name], size, str(tmp_path), echo=lambda *a: None)
    failed = [c for c in checks if not c["passed"]]
    assert checks and not failed, failed
