"""The orifice's jet as a load on the part it meets: what one shot sends through the orifice (mass,
momentum and energy relative to the piston) and the pressure it puts on a receiver, against that
receiver's own limit.

The receiver (``RECEIVER_STEEL``): a flat plate of the fixture's steel normal to the jet and riding with
the piston, the part that stands over the orifice in these designs (the orifice is in the piston the
article stands on: the article's base, or a catcher plate between it and the piston).  A coherent jet
stopped by it presses at its stagnation pressure (Bernoulli in the piston's frame):

    p_s = rho u_j^2 / 2,     u_j = mdot / (rho Cc a)        (the jet's speed from the orifice law)

which is the orifice's upstream pressure over 1 - (Cc n)^2 (``fluid.orifice``): at least the liquid's
pressure at the piston's face.  The receiver holds the jet while p_s stays below its initial yield
stress (the steel's, ``scene.library.initial_yield_stress``): above it, every shot yields the receiver
where the jet strikes it.  Per shot (integrated over the column run's samples, the face's pressure at
each, the pin's area at its stroke):

    mass = int mdot dt,    momentum = int mdot u_j dt  (the receiver's impulse),
    energy = int mdot u_j^2 / 2 dt                     (the jet's kinetic energy, heat in the receiver)

What it leaves out (an upper bound on the pressure, not a jet model): the jet's spreading and breakup
over its flight to the receiver, the transient of its front's first impact (a liquid's impact pressure
rho c u_j is higher than p_s, for microseconds), the cavitating jet's vapour, the receiver's own
motion relative to the piston, and a receiver that stands so close over the orifice that no free jet
forms (then the orifice's law itself does not hold).  The jet's speed is the orifice law's, capped at
the liquid's sound speed as the column caps it.
"""
from __future__ import annotations

import numpy as np

from ..fluid import orifice
from ..fluid.column import density, sound_speed
from ..scene.library import initial_yield_stress
from .dashpot_design import CARRIER_STEEL
from .lumped_dashpot import LumpedDashpot

RECEIVER_STEEL = CARRIER_STEEL


def jet_load(d: LumpedDashpot, run, liquid, receiver: str = RECEIVER_STEEL) -> dict:
    """The jet of a dashpot ``d`` (its lumped form: bore, pin, law) on its column ``run`` (a
    ``column_dashpot.ColumnRun``) filled with ``liquid`` (a ``fluid.column.ColumnLiquid``), on a
    receiver of the library metal ``receiver``: mass [kg], momentum [N s] and energy [J] per shot
    relative to the piston, the largest jet speed [m/s] and stagnation pressure [Pa], the receiver's
    initial yield [Pa] and whether it ``holds`` (the stagnation pressure below it)."""
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    area = np.interp(run.stroke, pin[:, 0], pin[:, 1])
    law, params, A = d.orifice_law().code(), liquid.params(), d.piston_area
    mdot, u_jet = np.zeros(len(run.t)), np.zeros(len(run.t))
    for k, (p, a) in enumerate(zip(run.pressure, area)):
        if p <= 0.0 or a <= 0.0:
            continue
        rho = density(p, params)
        mdot[k] = orifice.mass_flow(p, rho, sound_speed(rho, params), a, A, law)
        u_jet[k] = mdot[k] / (rho * orifice.jet_coefficient(min(a / A, 1.0), law) * a)
    rho_jet = np.array([density(max(p, 0.0), params) for p in run.pressure])
    stagnation = 0.5 * rho_jet * u_jet ** 2
    limit = initial_yield_stress(receiver)
    peak = float(np.max(stagnation, initial=0.0))
    return {"receiver": receiver, "mass": float(np.trapz(mdot, run.t)),
            "momentum": float(np.trapz(mdot * u_jet, run.t)),
            "energy": float(np.trapz(0.5 * mdot * u_jet ** 2, run.t)),
            "peak_jet_speed": float(np.max(u_jet, initial=0.0)), "peak_stagnation_pressure": peak,
            "receiver_yield": limit, "holds": bool(peak <= limit)}
