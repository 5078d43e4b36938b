"""(d), the closed-breech gas drive, at the premise's 12 lb article (its spec diameter, the reference ogive's length): the
numbers docs/machine.md's "(d) at 12 lb" quotes, without the premise study's fixture.

    PYTHONPATH=. python scripts/gas-drive-12lb.py
"""
from shockfem.machine import gas_drive as D
from shockfem.machine.fixture import article_length
from shockfem.machine.limits import broken
from shockfem.machine.spec import read_spec
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
print(D.verdict_words([d], *[type("R", (), {"fixture_problems": ["x"], "gun_feasible": True, "feasible": True})()] * 2))
