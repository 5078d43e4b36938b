"""The penetration study (the white paper's task 1): ``shockfem study penetration``.

The environment the shock tester must reproduce, from Forrestal's concrete-penetration law applied on
the nose of the fixture study's 12 lb article (``target/``, ``docs/penetration.md``):

1. The white paper's shot: 1600 ft/s into 5 ksi concrete and 10 ksi, axisymmetric, against Forrestal's
   closed form: depth, the deceleration and its duration, peak stresses and the axial stress along the
   body against its inertia relief; the pulse against the shock tester's 10,000 g / 5 ms; the cased
   article with its payload (the same 12 lb) at 5 ksi, and the pulse its payload sees.
2. The white paper's screening design: a 2^(4-1) fractional factorial (D = ABC) on yaw, concrete
   strength, spin and velocity, plus a centre point, each run in 3D with the tunnel and the friction
   torque: the tail's flexural deflection, the bending stress along the body, the peak deceleration and
   the depth, their effects, aliases, Lenth's test and the regression; the sensitivity of bending to spin;
   at default size the fold-over half (D = -ABC), which with the first is the full 2^4 and separates the
   aliased interactions.
3. Dynamic stress amplification: half-sine force pulses on the nose, the peak stress over the
   quasi-static stress against the pulse's duration over the article's first periods (``modal``): axial
   (axisymmetric, the nose-shank section, against the first axial period) and lateral (3D, the largest
   bending along the body against its inertia relief, against the first bending period), each beside its
   first mode alone (the shock spectrum).

Sizes: ``smoke`` (coarse meshes, the events cut short: for tests), ``default``.
"""
from __future__ import annotations


from ..report import run_sections
from .common import SIZES, Context
from .amplification import amplification
from .experiments import screening
from .white_paper import white_paper_shot

SECTIONS = (("the white paper's shot", white_paper_shot), ("screening design", screening),
            ("dynamic stress amplification", amplification))


def run_study(size: str = "default", out_dir: str = "results/penetration", echo=print) -> str:
    """Run the study's sections in order into ``out_dir``; returns the report's path."""
    return run_sections(out_dir, "Penetration study (white paper task 1)",
                        f"`shockfem study penetration --size {size}`; every number below was computed by this "
                        "run. The model and its verification: `docs/penetration.md`.",
                        SECTIONS, Context(SIZES[size], out_dir, echo), echo)
