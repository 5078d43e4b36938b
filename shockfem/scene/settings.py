"""The ``[scene]`` table: the run's own settings (name, kinematics and element, end time and step
safety, energy limit, hourglass control, gravity, bulk viscosity, checkpoints, mass scaling), as the
keyword arguments of ``Scene`` they become."""
from __future__ import annotations

from .checker import Checker
from .specs import ELEMENTS, HOURGLASS_FORMS, INTEGRATIONS, KINEMATICS

SCENE_FIELDS = ("name", "kinematics", "element", "end_time", "safety_factor", "thickness", "energy_error_limit",
                "integration", "hourglass", "hourglass_coefficient", "gravity", "bulk_viscosity_quadratic",
                "bulk_viscosity_linear", "curve_elements", "checkpoint_interval", "mass_scaling_step",
                "mass_scaling_limit", "max_time_step", "preload")


def read_settings(ck: Checker, raw: dict) -> dict:
    """``[scene]``, checked, as ``Scene``'s keyword arguments."""
    s = ck.table(raw, "scene", "scene")
    ck.unknown(s, SCENE_FIELDS, "scene")
    name = s.get("name", "scene")
    if not isinstance(name, str) or not name.strip() or name.strip(".") == "" or any(c in name for c in "/\\"):
        # the name is the run directory's default (results/<name>): it must name one directory
        ck.fail("scene.name", f"must be a name for the run's directory (letters, digits, - and _; no slash), "
                              f"got {name!r}")
        name = "scene"
    kin = ck.choice(s, "kinematics", "scene", KINEMATICS)
    gdim = 3 if kin == "3d" else 2
    element = ck.choice(s, "element", "scene", ELEMENTS[kin], default=ELEMENTS[kin][0])
    end_time = ck.quantity(s, "end_time", "scene", "time", positive=True)
    sf = ck.quantity(s, "safety_factor", "scene", "dimensionless", default=0.9, positive=True)
    if sf > 1.0:
        ck.fail("scene.safety_factor", f"must be <= 1 (explicit stability), got {sf}")
    thickness = ck.quantity(s, "thickness", "scene", "length", default=1.0, positive=True)
    elimit = ck.quantity(s, "energy_error_limit", "scene", "dimensionless", default=0.05, positive=True)
    # simulated time between checkpoints (``output/checkpoint.py``); 0: only when a signal stops the run
    checkpoint = ck.quantity(s, "checkpoint_interval", "scene", "time", default=end_time / 10,
                             nonnegative=True)
    # mass scaling (``model/mass_scaling.py``): the smallest step the run takes (safety factor included),
    # and the largest share of a body's mass it may add before the run is refused
    ms_step = ck.quantity(s, "mass_scaling_step", "scene", "time", default=0.0, nonnegative=True)
    ms_limit = ck.quantity(s, "mass_scaling_limit", "scene", "dimensionless", default=0.05, positive=True)
    # an upper bound of the step for accuracy (0: the stable step and the lumped oscillators' bound only)
    max_dt = ck.quantity(s, "max_time_step", "scene", "time", default=0.0, nonnegative=True)
    curve = s.get("curve_elements", 24)
    if not isinstance(curve, int) or isinstance(curve, bool) or not 6 <= curve <= 360:
        ck.fail("scene.curve_elements", f"must be a whole number of elements round a circle in [6, 360], got {curve!r}")
        curve = 24
    integration = ck.choice(s, "integration", "scene", INTEGRATIONS, default="reduced")
    hourglass = ck.choice(s, "hourglass", "scene", HOURGLASS_FORMS, default="stiffness")
    hg_coef = ck.quantity(s, "hourglass_coefficient", "scene", "dimensionless", default=0.05,
                          nonnegative=True, upper=1.0)
    gravity = ck.vector(s, "gravity", "scene", "acceleration", gdim, [0.0] * gdim)
    bulk_viscosity = (ck.quantity(s, "bulk_viscosity_quadratic", "scene", "dimensionless", default=1.5,
                                  nonnegative=True),
                      ck.quantity(s, "bulk_viscosity_linear", "scene", "dimensionless", default=0.06,
                                  nonnegative=True))
    if kin == "axisymmetric" and gravity[0] != 0.0:
        ck.fail("scene.gravity", "axisymmetric gravity acts along the axis: the r component must be 0")
    return dict(name=name, kinematics=kin, element=element, end_time=end_time, safety_factor=sf,
                thickness=thickness, energy_error_limit=elimit, integration=integration, hourglass=hourglass,
                hourglass_coefficient=hg_coef, gravity=gravity if any(gravity) else (),
                bulk_viscosity=bulk_viscosity, curve_elements=curve, checkpoint_interval=checkpoint,
                mass_scaling_step=ms_step, mass_scaling_limit=ms_limit, max_time_step=max_dt)
