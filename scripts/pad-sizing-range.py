"""The closed-form sizing of an elastomer pad against its own finite-element run: each interface's pad sized
by the bare closed form (peak factor 1: rigid bodies on a Neo-Hookean disc, quasi-static) and run, and the
run's peak contact stress over the closed form's (``pads.run_peak_factor``); docs/machine.md, "Pads", and
``pads.PEAK_FACTOR_RANGE`` quote it.

    python scripts/pad-sizing-range.py [--resolution smoke] OUT

The interfaces: compact steel cylinders (length = diameter) of M_A on M_B kg closing at SPEED m/s, high-strength
steel at 1.5 on yield, every polyurethane of the library.
"""
import argparse
import math

from shockfem.amplifier.gain import cylinder_size
from shockfem.errors import UnstableRun
from shockfem.machine.pads import Interface, RunCache, run_peak_factor
from shockfem.scene.library import initial_yield_stress

STEEL, RHO = "high_strength_steel", 7850.0
# (M_A, M_B, SPEED): the test chain's first interface (8 on 4 kg at 3 m/s), its speed halved and doubled,
# equal masses, a mass ratio of 4, bodies ten times heavier, and faster (12, 24 m/s: pads as wide as the
# face and longer than a quarter of it)
CASES = [(8.0, 4.0, 3.0), (8.0, 4.0, 1.5), (8.0, 4.0, 6.0), (4.0, 4.0, 3.0), (8.0, 2.0, 3.0), (80.0, 40.0, 3.0),
         (8.0, 4.0, 12.0), (8.0, 4.0, 24.0)]

p = argparse.ArgumentParser()
p.add_argument("--resolution", default="smoke")
p.add_argument("--materials", default="pu_90a,pu_95a,pu_60d")
p.add_argument("out")
args = p.parse_args()
cache = RunCache(args.out)
factors = []
for m_a, m_b, v in CASES:
    a, b = cylinder_size(m_a, RHO, 1.0), cylinder_size(m_b, RHO, 1.0)
    iface = Interface("a_b", m_a, a["diameter"], a["length"], m_b, b["diameter"], b["length"], v, STEEL,
                      initial_yield_stress(STEEL) / 1.5)
    for name in args.materials.split(","):
        try:
            m, pad = cache.measure(iface, name, args.resolution, peak_factor=1.0)
        except UnstableRun as err:
            print(f"{m_a:g} on {m_b:g} kg at {v:g} m/s, {name}: the run went unstable ({str(err)[:60]}...)")
            continue
        if not m.ran:
            print(f"{m_a:g} on {m_b:g} kg at {v:g} m/s, {name}: {m.note}")
            continue
        f = run_peak_factor(iface.rounded(), pad, m)
        factors.append(f)
        strain = pad.travel / pad.thickness
        print(f"{m_a:g} on {m_b:g} kg at {v:g} m/s, {name}: pad {pad.diameter * 1e3:.3g} x {pad.thickness * 1e3:.3g} mm "
              f"(height {pad.thickness / pad.diameter:.3g} of its diameter) at strain {strain:.3f}; run's peak over the closed form's {f:.4f}, e = {m.restitution:.4f} "
              f"({m.elements} cells, {m.wall_time_s:.3g} s)")
print(f"peak factor over {len(factors)} runs: {min(factors):.4f} to {max(factors):.4f}, "
      f"mean {sum(factors) / len(factors):.4f}")
