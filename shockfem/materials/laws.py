"""The registry of material laws: which law a parameter row follows, and the dispatch to it.

A law is a compiled function of one material point over one step in the rotated frame

    law(row, curve, point, sigma, d, dt) -> (sigma_np1, plastic work density [J/m^3])

with ``row`` the material's parameter row (``params[m]``, columns ``layout.py``), ``curve`` its
curve (hardening, crush), ``point`` the point's state (``state[c, p]``, updated in place), ``sigma`` the stress
at t_n already turned with the material (``objective.py``) and ``d`` the strain rate of the step.  A
law that needs no curve or state (elastic) takes ``(row, sigma, d, dt)``; a law of the total
deformation (rubber) takes ``(row, point, d, w, dt)``, w the step's spin, and makes its stress from
the deformation gradient it carries.  The laws are called
functions, compiled once: ``law_update``, the dispatch, is compiled into the element kernels
(``update.py`` says why).  ``update.update_stress`` is the one caller the element
kernels see; it rotates, applies the slotted ring's hoop constraint and calls ``law_update``.

How to add a law: ``docs/theory.md``, "Adding a material law".
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from numba import njit

from .elastic import elastic_update
from .foam import foam_update, pack_foam
from .j2 import j2_update, pack_j2
from .layout import ELASTIC, FOAM, J2, P_LAW, RUBBER
from .rubber import pack_rubber, rubber_update


@dataclass(frozen=True)
class Law:
    """A registered law: its id in ``P_LAW``, what it is, and how its own constants are written into
    a parameter row (``pack(row, curve, constants)``; None when it needs only the elastic columns)."""
    id: int
    summary: str
    pack: Callable | None = None


# ``model.materials.parameter_table`` writes the columns every law shares and calls the law's ``pack``
LAWS = {
    "elastic": Law(ELASTIC, "linear isotropic elasticity, Hooke's law in the objective frame (elastic.py)"),
    "j2": Law(J2, "J2 plasticity, radial return: bilinear or tabulated hardening, mixed isotropic/kinematic, "
                  "Cowper-Symonds rate factor (j2.py)", pack_j2),
    "foam": Law(FOAM, "crushable foam, principal stresses capped at a crush stress of the volumetric strain, "
                      "tension cutoff, Cowper-Symonds rate factor (foam.py, MAT_063-like)", pack_foam),
    "rubber": Law(RUBBER, "nearly incompressible Mooney-Rivlin (Neo-Hookean) hyperelasticity of the point's "
                          "deformation gradient (rubber.py, MAT_027-like)", pack_rubber),
}


@njit(cache=True, fastmath=True, inline="always")
def law_update(params, curves, m, state, c, p, s, d, w, dt):
    """The law of row ``m`` over one step in the rotated frame (see the module docstring)."""
    law = params[m, P_LAW]
    if law == J2:
        return j2_update(params[m], curves[m], state[c, p], s, d, dt)
    if law == FOAM:
        return foam_update(params[m], curves[m], state[c, p], s, d, dt)
    if law == RUBBER:
        return rubber_update(params[m], state[c, p], d, w, dt)
    return elastic_update(params[m], s, d, dt)
