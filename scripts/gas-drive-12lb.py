"""(d), the closed-breech gas drive, at the premise's 12 lb article (its spec diameter, the reference ogive's length): the
numbers docs/machine.md's "(d) at 12 lb" quotes, without the premise study's fixture.

    PYTHONPATH=. python scripts/gas-drive-12lb.py
"""
import numpy as np

from shockfem.machine import gas_drive as D
from shockfem.machine.fixture import article_length
from shockfem.machine.limits import broken
from shockfem.machine.spec import read_spec
from shockfem.metrics import shapes
from shockfem.units import G0, LB

spec = read_spec({"article": "12 lb"})
ARTICLE_LENGTH = article_length(spec)   # [m] the premise's article, as its fixture has it
for d in D.gas_drives(spec, type("Article", (), {"article_mass": 12 * LB, "article_diameter": spec.diameter,
                                                 "article_length": ARTICLE_LENGTH})):
    print(f"== {d.gas}: feasible {d.feasible}, in band {d.in_band}")
    for n in d.notes:
        print("  ", n)
    if d.moving:
        print(f"   frame {d.frame_mass:,.0f} kg; ports {d.port_band}; arrest {d.arrest.kind} {d.arrest.force:.4g} N over {d.arrest.stroke:.4g} m")
        for lim in d.limits:
            print(f"   limit {lim.component} {lim.quantity}: {lim.value:.4g} of {lim.limit:.4g} {lim.unit}")
        print("   broken:", [lim.describe() for lim in broken(d.limits)])
        # the band's placing against an unplaced one: a 1 ms opening at the lower end, the ideal held at t = 0
        slow = D.end_pulse(d, spec, d.pulse.ports, rise=1e-3)
        rest = np.linspace(-1e-3, 0.0, 200, endpoint=False)
        unplaced = shapes.band_check(np.concatenate([rest, slow.time]),
                                     np.concatenate([np.zeros_like(rest), slow.acceleration]),
                                     shapes.specified(spec.pulse.checked_shape, spec.pulse.peak, spec.pulse.duration))
        placed = spec.pulse.band(slow.time, slow.acceleration)[1]
        print(f"   1 ms opening, lower end: separation {slow.separation_time * 1e3:.4g} ms, worst excess "
              f"{placed.worst_excess:.3g} placed, {unplaced.worst_excess:.3g} with the ideal at t = 0")
print(D.verdict_words([d], *[type("R", (), {"fixture_problems": ["x"], "gun_feasible": True, "feasible": True})()] * 2))
