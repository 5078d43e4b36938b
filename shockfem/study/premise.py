"""The white paper's premise on its own: the 12 lb machine designed (``shockfem design-machine --article
"12 lb"``), then the system study's premise sections on it: the amplifier against a direct striker, a
flying target and a closed-breech gas drive with the closed form's boundary and the verdict, the map of where each arrangement wins, and
the white paper side by side (``study/system_premise.py``), the answer boxed at the report's top.
``shockfem study premise`` runs it; the
smoke size runs no pad (their restitutions the materials' estimates), one start per gun and a 4-point map;
the default runs the pads at the spec's meshes and the system study's 27-point map."""
from __future__ import annotations

import dataclasses
import time

from ..machine.design import design_machine
from ..machine.output import write_machine
from ..machine.spec import read_spec
from .report import Report
from . import system_premise as sections
from .system import SIZES as SYSTEM_SIZES

# the default's sabot scan at three starts and five bores: on the representative 12 lb striker of
# ``verify premise_boundary`` (498.8 kg at 412.2 m/s, the full-bore valve) it takes 6.4 s (3.1 s of CPU) on
# the shared 2-core machine
SIZES = {"smoke": {**SYSTEM_SIZES["smoke"], "pads": "estimate", "best_chain": True},
         "default": {**SYSTEM_SIZES["default"], "pads": None, "sabot_starts": 3, "sabot_bores": 5, "best_chain": True}}


def run_study(size: str = "default", out_dir: str = "results/premise", echo=print) -> str:
    t0 = time.perf_counter()
    cfg = SIZES[size]
    rep = Report(out_dir, "The white paper's premise: velocity amplification against one gun, 12 lb")
    spec = read_spec({"article": "12 lb"})
    if cfg["pads"]:
        spec = dataclasses.replace(spec, pad_resolution=cfg["pads"])
    echo("1/3 the 12 lb machine")
    m = design_machine(spec, f"{out_dir}/12lb", echo=echo, starts=cfg["starts"],
                       evaluations=cfg["fixture_evaluations"])
    ran = sum(st.measured for st in m.amplifier.stages)
    rep.text(f"`shockfem study premise --size {size}`; every number below was computed by this run. The machine is "
             f"`shockfem design-machine --article \"12 lb\"` (pads meshed at '{spec.pad_resolution}': {ran} of its "
             f"{len(m.amplifier.stages)} pads run, the others at their material's estimate), in `12lb/`.")
    write_machine(m, f"{out_dir}/12lb")
    rep.text(f"The machine: {'FEASIBLE' if m.feasible else 'NOT FEASIBLE'}; " + "; ".join(m.binding) + ".")
    echo("2/3 the premise and its map")
    *_, target = sections.premise(rep, m, cfg, echo, answer_at_top=True)
    sections.premise_map(rep, m, target, cfg, out_dir, echo)
    echo("3/3 the white paper side by side")
    sections.white_paper(rep, m)
    return rep.finish(t0, echo)
