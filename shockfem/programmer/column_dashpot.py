"""The fluid dashpot as two rigid masses on a compressible liquid column: the lumped dashpot's bodies
(``lumped_dashpot.py``) with the liquid of ``fluid/column.py`` (its mass, waves, cavitation, the jet)
instead of a control volume at one pressure.

The striker (the housing, less the liquid, which the column now carries) closes at V on the payload
(piston and article, at rest); the column runs from the bore's floor to the piston, moving with the
housing at first:

    (M - m_l + m_c) x_s'' = -p_floor A + F(t),     m x_p'' = p_piston A - J,     a = a(s), s = L0 - (x_p - x_s)

integrated by symplectic Euler on the column's own step (its Courant limit).  F(t) and m_c are an optional
push on the striker from outside the dashpot (``StrikerPush``: a gun's gas on its base while the base is
still in the bore) and the mass it carries with it until a release time (a sabot on its base, stripped as
the base leaves the muzzle; it leaves at the striker's speed, so the striker's speed is continuous there);
none by default.  The run's energy balance
(``energy_balance``, in its summary): the kinetic energy in (the striker's, its liquid's with it) is the
bodies' kinetic energy, the column's stored energy (its liquid's kinetic and compression energy), what
the jet carries out of the column (``fluid.column``'s energy out) and takes off the piston by its reaction
(the work of J on the payload), the push's work and the carried mass's kinetic energy at its release, and
the column's dissipation D (its fronts; >= 0), to the residual, the
coupling's own error (first order in the step).  Beside it, the column's compression energy when the
bodies first reach a common speed (the liquid spring's, at restitution 0 none would be left) and the
bodies' kinetic energy of rebound at the end, 1/2 mu (v_p - v_s)^2 (what of it the spring gave back).
Left out: everything elastic in the bodies (the finite-element run has that), and what the column leaves out (its
docstring: friction on the bore, liquid returning through the orifice).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..amplifier.interfaces import reduced_mass
from ..fluid.column import OUT_ENERGY, ColumnLiquid, LiquidColumn
from .lumped_dashpot import LumpedDashpot

CELLS = 200                     # the column's cells (``verify liquid_column`` shows the pulse converged)


@dataclass(frozen=True)
class ColumnRun:
    t: np.ndarray                       # [s]
    acceleration: np.ndarray            # the payload's [m/s^2]
    pressure: np.ndarray                # at the piston's face [Pa]
    floor_pressure: np.ndarray          # at the bore's floor [Pa]
    stroke: np.ndarray                  # [m]
    payload_speed: np.ndarray           # [m/s]
    striker_speed: np.ndarray           # [m/s]
    cavity: np.ndarray                  # the column's void [m^3]
    summary: dict                       # the column's accounts at the end (``LiquidColumn.summary``) and the
                                        # dashpot's energy balance (``energy_balance``)
    steps: int


@dataclass(frozen=True)
class StrikerPush:
    """A force on the striker from outside the dashpot, from first contact: ``force`` [N] at ``time`` [s]
    (interpolated, zero outside them), and a ``carried`` mass [kg] moving with the striker until
    ``release`` [s]."""
    time: np.ndarray
    force: np.ndarray
    carried: float = 0.0
    release: float = 0.0

    def at(self, t: float) -> float:
        return float(np.interp(t, self.time, self.force, left=0.0, right=0.0))

    def mass(self, t: float) -> float:
        return self.carried if t < self.release else 0.0


def column_liquid(d: LumpedDashpot) -> ColumnLiquid:
    """The column's liquid with the lumped dashpot's density, modulus and Tait exponent."""
    return ColumnLiquid(density=d.density, bulk_modulus=d.bulk_modulus, tait_exponent=d.tait_exponent)


def simulate_column(d: LumpedDashpot, end_time: float, samples: int = 4000, cells: int = CELLS,
                    liquid: ColumnLiquid | None = None, push: StrikerPush | None = None) -> ColumnRun:
    """The dashpot ``d`` from first contact to ``end_time`` with its liquid as a column of ``cells``
    finite volumes, sampled at ``samples`` even times (the state of the step that reaches each); ``push``
    a force on the striker and the mass it carries (none by default; without one the step skips it: the
    design searches run the column hundreds of times)."""
    liquid = liquid or column_liquid(d)
    L0, A = d.column, d.piston_area
    column = LiquidColumn(liquid, 0.0, L0, A, cells, d.orifice_law(), d.initial_pressure, d.speed)
    housing = d.striker_mass - column.mass()
    if housing <= 0.0:
        raise ValueError(f"column dashpot: the striker's {d.striker_mass:.4g} kg must outweigh its liquid's "
                         f"{column.mass():.4g} kg")
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    t_out = np.linspace(0.0, end_time, samples)
    rows = np.zeros((samples, 7))
    v_s, v_p, t, k, steps = d.speed, 0.0, 0.0, 0, 0
    force_p = d.initial_pressure * A
    carried_at = push.mass if push is not None else lambda _: 0.0
    energy_in, jet_work = 0.5 * (housing + carried_at(0.0)) * d.speed ** 2 + column.energy(), 0.0
    push_work = carried_out = 0.0
    spring = None                # the column's compression energy when the bodies first reach a common speed
    while k < samples:
        stroke = L0 - column.length()
        if t >= t_out[k]:
            rows[k] = (force_p / d.payload_mass, column.piston_pressure, column.floor_pressure, stroke, v_p, v_s,
                       column.void())
            k += 1
            continue
        if column.length() <= 1e-3 * L0:
            raise RuntimeError(f"column dashpot: the piston reached the floor at t = {t:.6g} s")
        dt = min(column.stable_step(v_s, v_p), t_out[k] - t) if t_out[k] > t else column.stable_step(v_s, v_p)
        area = float(np.interp(stroke, pin[:, 0], pin[:, 1]))
        force_f, force_p = column.step(v_s, v_p, area, dt)
        jet_work += dt * column.jet_force * v_p
        if push is None:
            v_s += dt * force_f / housing
        else:
            pushed, carried = push.at(t), push.mass(t)
            push_work += dt * pushed * v_s
            v_s += dt * (force_f + pushed) / (housing + carried)
            if carried and push.mass(t + dt) == 0.0:
                carried_out = 0.5 * carried * v_s ** 2
        v_p += dt * force_p / d.payload_mass
        if spring is None and v_p >= v_s:
            spring = column.energy() - column.kinetic_energy()
        t += dt
        steps += 1
    r = rows.T
    balance = energy_balance(column, energy_in, 0.5 * (housing + carried_at(t)) * v_s ** 2,
                             0.5 * d.payload_mass * v_p ** 2, jet_work, push_work, carried_out)
    summary = {**column.summary(), **balance,
               "compression energy at the common speed [J]": float("nan") if spring is None else spring,
               "rebound's kinetic energy [J]": 0.5 * reduced_mass(housing, d.payload_mass) * max(v_p - v_s, 0.0) ** 2}
    return ColumnRun(t_out, r[0], r[1], r[2], r[3], r[4], r[5], r[6], summary, steps)


def energy_balance(column: LiquidColumn, energy_in: float, housing: float, payload: float, jet_work: float,
                   push_work: float = 0.0, carried_out: float = 0.0) -> dict:
    """The dashpot's energy balance at the end of a run [J]: ``energy_in`` (the striker's kinetic energy
    and its column's at contact) and a push's work on the striker, ``push_work``, against the housing's and
    the payload's kinetic energy, the carried mass's at its release (``carried_out``), the column's stored
    energy, the jet's (its energy out of the column and ``jet_work``, its reaction's work taken off the
    piston) and the column's dissipation; the residual what they leave (the coupling's error).  The push's
    two terms are in the balance only where a push ran."""
    stored, jet = column.energy(), column.accounts[OUT_ENERGY] + jet_work
    dissipated = column.dissipated()
    pushed = ({"push's work on the striker [J]": push_work, "carried mass's kinetic energy at its release [J]":
               carried_out} if push_work or carried_out else {})
    return {"kinetic energy in [J]": energy_in, **pushed, "housing's kinetic energy [J]": housing,
            "payload's kinetic energy [J]": payload, "column's stored energy [J]": stored,
            "jet's energy out [J]": jet, "jet reaction's work on the piston [J]": jet_work,
            "energy balance residual [J]": energy_in + push_work - carried_out - housing - payload - stored - jet
            - dissipated}
