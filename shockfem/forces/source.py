"""The force source: what the time loop asks of anything that pushes the bodies besides their elements.

Contact pairs, discrete springs, liquid cavities and a penetrated target are force sources.  Each is
built from its spec in the model (``registry.SOURCES``) and the solver treats all of them alike: every
step, after the elements' forces at t_{n+1},

    limit = source.apply(x, u, v, dt, t, f_con)     its forces at t_{n+1} added into f_con (v is v_{n+1/2});
                                                     the step limit of its stiffness [s] (inf: none)

so that the step combines with the elements' as omega^2 <= omega_elements^2 + omega_source^2 (Gershgorin).
The rest of the protocol is what the run reads of it:

    rows()            the local nodes whose f_con it can write (the rest stay zero all run)
    begin(x, v)       at t = 0: what it has to say of the starting state
    said(t)           what it has to say at t, once (a preload reached)
    account(dt, t, body_velocities)    after every step: its peaks, impulses, intervals
    energy()          the energy it has taken from the bodies so far, minus its work on them [J]
    columns(axes)     its history columns, (name, unit) each; ``history()`` their values at t
    summary()         what summary.json says of it at the end
    period, oscillator   the period [s] of the lumped oscillation it sets (inf: none), which bounds the step
                      for accuracy (``ExplicitSolver.accuracy_step``), and what oscillates, for the log

A source that holds nodes kinematically rather than by a force (a constraint wall) sets
``holds_motion`` and implements ``take_velocities`` and ``hold`` (``ExplicitSolver.advance``).  Its energy
and the others' are counted by the solver from the nodal forces (``energy.contact``); ``energy()`` is each
source's own share, for its summary and for the check that the shares add up.
"""
from __future__ import annotations

import math

import numpy as np


class ForceSource:
    """The base of every force source: the protocol (see the module docstring), with the defaults of a
    source that says nothing, records nothing and holds no node."""

    kind = ""              # the registry's name for this kind of source (``registry.SOURCES``)
    holds_motion = False   # holds nodes on a surface inside the velocity update (``take_velocities``, ``hold``)
    name = ""
    period = math.inf      # of the lumped oscillation the source sets [s] (inf: none)

    @property
    def oscillator(self) -> str:
        """What oscillates at ``period``, for the log."""
        return f"{self.kind} '{self.name}'"

    def rows(self) -> np.ndarray:
        """The local nodes whose row of ``f_con`` ``apply`` can write."""
        raise NotImplementedError

    def begin(self, x: np.ndarray, v: np.ndarray) -> list[str]:
        """At t = 0, on the starting positions and velocities: what the log should say.  Collective."""
        return []

    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        """Add the forces at t_{n+1} = ``t`` into ``f`` (x, u at t_{n+1}, v = v_{n+1/2} of the step ``dt``
        just taken; dt = 0 at the start); return the step limit of the source's stiffness [s] (inf if
        none).  Collective."""
        raise NotImplementedError

    def said(self, t: float) -> list[str]:
        """Messages due at ``t`` (each said once)."""
        return []

    def account(self, dt: float, t: float, body_velocities) -> None:
        """After the step ending at ``t``: running peaks and integrals.  ``body_velocities()`` gives the
        bodies' mean velocities (collective: call it on every rank or on none)."""

    def take_velocities(self, v: np.ndarray) -> None:
        """A source that ``holds_motion``: the velocities before the step's update."""

    def hold(self, x: np.ndarray, v: np.ndarray, dt: float, dt_avg: float, t_end: float) -> float:
        """A source that ``holds_motion``: put its nodes on its surface (``v`` changed in place); returns
        its work on the bodies over the step [J]."""
        return 0.0

    def energy(self) -> float:
        """The energy taken up from the bodies so far (minus the source's work on them) [J]."""
        raise NotImplementedError

    def columns(self, axes: str | tuple) -> list[tuple[str, str]]:
        """The history's columns of this source, (name, unit) each; ``axes`` names the components."""
        return []

    def history(self) -> list[float]:
        """The values of ``columns`` at the current time."""
        return []

    def summary(self) -> dict:
        raise NotImplementedError
