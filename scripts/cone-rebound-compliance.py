"""Where the split cone's apparent restitution departs from fixtures.md's lumped ring: the plug of
``shockfem verify cone_rebound`` (7 deg, friction 0.1) dropped with each of the two series
compliances the lumped model leaves out switched on or off (an elastic plug; a ring free to
compress axially).  Usage: python scripts/cone-rebound-compliance.py [coarse|default|fine]"""
import math
import sys
import tempfile

from shockfem.verify.scenes import STEEL, solve
from shockfem.verify.split_cone_cases import REBOUND, _cone_scene

size = sys.argv[1] if len(sys.argv) > 1 else "default"
alpha, mu = math.radians(7.0), 0.1
lumped = math.sqrt(math.tan(alpha - math.atan(mu)) / math.tan(alpha + math.atan(mu)))
print(f"lumped ring (fixtures.md): e = {lumped:.4f}")
print(f"{'plug':8s} {'ring':16s} {'e':>7s} {'vs lumped':>10s} {'balance':>9s}")
with tempfile.TemporaryDirectory() as workdir:
    for rigid in (True, False):
        for held in (True, False):
            raw = _cone_scene("cone_rebound", alpha, mu, size, workdir, REBOUND["end_time"],
                              {**STEEL, "density": REBOUND["plug_density"]}, plug_rigid=rigid, ring_held=held)
            raw["bodies"][1]["velocity"] = -REBOUND["speed"]
            solver, wall = solve(raw, cache_dir=workdir)
            e = solver.body_means()[0][1, 1] / REBOUND["speed"]
            print(f"{'rigid' if rigid else 'elastic':8s} {'held axially' if held else 'free axially':16s} "
                  f"{e:7.4f} {e / lumped - 1:+10.2%} {solver.energy.balance_error:9.2e}")
