"""What a finished run warns of (such as 34% hourglass energy in a 500 m/s steel impact):
``runner.run_warnings`` on made-up summaries, each threshold just crossed and just not."""
from shockfem.runner import run_warnings


def _summary(hourglass=0.0, internal=10.0, penetration=0.0, overlap=0.0, facet=1e-3, body_internal=20.0):
    """A run of 1000 J whose body "plate" has ``hourglass`` times its internal energy in hourglass work."""
    return {"energy": {"hourglass_to_internal": 0.0, "initial_total": 1000.0, "kinetic": 500.0,
                       "internal": internal, "external_work": 0.0},
            "bodies": {"plate": {"hourglass_to_internal": hourglass, "internal_energy": body_internal,
                                 "hourglass_energy": hourglass * body_internal},
                       "striker": {"hourglass_to_internal": 0.0, "internal_energy": 5.0, "hourglass_energy": 0.0}},
            "contacts": {"impact": {"max_penetration": penetration, "smallest_facet": facet,
                                    "initial_overlap": {"nodes": 0, "deepest": overlap}}}}


def test_a_clean_run_has_no_warning():
    assert run_warnings(_summary(hourglass=0.09, internal=-0.09, penetration=1.9e-4)) == []


def test_each_warning_names_its_number_and_its_fix():
    (w,) = run_warnings(_summary(hourglass=0.34))
    assert "body plate" in w and "34% of its internal energy" in w and 'integration = "full"' in w
    # the same share in a body whose hourglass work is under 0.1% of the run's energy (1000 J) shapes nothing
    assert run_warnings(_summary(hourglass=0.34, body_internal=2.0)) == []
    assert len(run_warnings(_summary(hourglass=0.34, body_internal=3.0))) == 1
    (w,) = run_warnings(_summary(internal=-0.2))
    assert "internal energy ends negative (-0.2 J" in w and "safety_factor" in w
    (w,) = run_warnings(_summary(penetration=3e-4))
    assert "contact impact" in w and "30% of its smallest facet" in w and "penalty_scale" in w
    # an interference fit starts overlapped: only what goes beyond that counts
    assert run_warnings(_summary(penetration=3e-4, overlap=2e-4)) == []


def test_a_liquid_outside_its_models_range_is_warned_of():
    """A column whose orifice opened to the whole bore (a / A = 1 against the law's 0.56)."""
    checks = [{"name": "orifice area ratio a / A", "value": 1.0, "limit": 0.5625, "holds": False},
              {"name": "piston Mach number |w_P - w_F| / c", "value": 0.41, "limit": 0.5, "holds": True}]
    summary = {**_summary(), "cavities": {"oil": {"model": "1D compressible liquid column; ...", "validity": checks}}}
    (w,) = run_warnings(summary)
    assert "cavity oil: orifice area ratio a / A reached 1" in w and "0.562" in w and "liquid column" in w
