"""Why ``shockfem verify lsdyna_decks``' scenes end with a negative energy at coarse size
(docs/theory.md, "Energies that go negative"):

* the two rods (3D, 12.5 mm cells, undamped contact): the contact energy at separation with the meshes as
  built (the striker's face nodes on the target's), with the striker turned about its axis (no node on
  another's), and with every facet given the same penalty stiffness (their mean);
* the Taylor bar (3D, 1.6 mm cells): the stored energy of the nodal account (internal work less the
  elements' plastic, hourglass and bulk-viscosity work) against the elements' own stress work less their
  plastic work, at safety factors 0.9 and 0.45.

    python scripts/negative-energies.py
"""
import numpy as np

import shockfem.contact.pairs as pairs
from shockfem.verify.contact_cases import two_rods_scene
from shockfem.verify.plasticity_cases import taylor_scene
from shockfem.verify.scenes import solve

WORK = "/tmp/shockfem-negative-energies"


def rods(turn_deg=0.0, uniform=False):
    raw = two_rods_scene(0.0125, kinematics="3d")
    raw["contact"][0]["damping"] = 0.0
    if turn_deg:
        raw["bodies"][0]["orientation"] = {"axis": [0, 0, 1], "angle": f"{turn_deg} deg"}
    built = pairs.facet_stiffness
    if uniform:
        pairs.facet_stiffness = lambda s, scale, bulk=None: np.full(len(s.area), built(s, scale, bulk).mean())
    try:
        solver, _ = solve(raw, cache_dir=WORK)
    finally:
        pairs.facet_stiffness = built
    e = solver.energy
    k = built(solver.contacts[0].surfaces()[1], 0.1)
    return e.contact, e.kinetic, e.initial, k.min(), k.max()


for label, kwargs in (("as meshed", {}), ("striker turned 7 deg", {"turn_deg": 7.0}),
                      ("one stiffness for every facet", {"uniform": True})):
    contact, kinetic, initial, k_lo, k_hi = rods(**kwargs)
    print(f"two rods, {label}: contact energy {contact:.4f} J, kinetic {kinetic:.4f} J of {initial:.4f} J "
          f"(target facets' penalty {k_lo:.3g} to {k_hi:.3g} N/m)")

for sf in (0.9, 0.45):
    raw = taylor_scene(0.0016, kinematics="3d")
    raw["scene"]["safety_factor"] = sf
    solver, _ = solve(raw, cache_dir=WORK)
    body = solver.body_energies()
    print(f"Taylor bar, safety factor {sf}: stored energy {solver.energy.internal:.4f} J (nodal account), "
          f"{body['internal'][0] - body['plastic'][0]:.4f} J (the elements' stress work less their plastic "
          f"work), plastic work {solver.energy.plastic:.2f} J")
