"""Every pad material of the library at one amplifier interface: its sized pad, its broken limits, and (with
--run) its finite-element restitution (``machine/pads.py``); docs/machine.md, "Pads", quotes the 12 lb
machine's first interface of the 2% design.

    python scripts/pad-interface.py [--run] [--resolution smoke] [--materials A,B] OUT M_A D_A L_A M_B D_B L_B SPEED

masses [kg], diameters and lengths [m], closing speed [m/s]; the bodies high-strength steel at 1.5 on yield.
The 2% design's first interface: 4772.5 0.914 0.926 1599.6 0.638 0.638 99.06
"""
import argparse

from shockfem.machine.pad_materials import PAD_MATERIALS
from shockfem.machine.pads import Interface, RunCache, estimated_restitution, size_pad
from shockfem.scene.library import initial_yield_stress

p = argparse.ArgumentParser()
p.add_argument("--run", action="store_true")
p.add_argument("--resolution", default="smoke")
p.add_argument("--materials", default=",".join(PAD_MATERIALS), help="comma-separated (default: all)")
p.add_argument("out")
p.add_argument("numbers", nargs=7, type=float)
args = p.parse_args()
steel = "high_strength_steel"
iface = Interface("a_b", *args.numbers, steel, initial_yield_stress(steel) / 1.5)
cache = RunCache(args.out)
print(f"M* {iface.m_star:.4g} kg, {iface.energy / 1e6:.4g} MJ at {iface.speed:.4g} m/s on a "
      f"{iface.face_diameter:.3g} m face")
for name in args.materials.split(","):
    pad = size_pad(iface.rounded(), name, estimated_restitution(name))
    line = (f"{name:18s} d {pad.diameter:.3g} m, t {pad.thickness:.3g} m, {pad.mass:.4g} kg, crown {pad.crown:.3g} m; "
            f"broken: " + (", ".join(f"{lim.quantity} {lim.ratio:.3g}x" for lim in pad.limits if not lim.holds)
                           or "none"))
    if args.run:
        m, _ = cache.measure(iface, name, args.resolution)
        line += (f"; e = {m.restitution:.4f} ({m.elements} cells, {m.steps} steps, {m.wall_time_s:.3g} s)"
                 if m.ran else f"; {m.note}")
    print(line)
