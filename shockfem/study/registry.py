"""The registry of studies: name -> where its ``run_study(size, out_dir)`` lives and what it answers.

``shockfem study NAME`` takes its choices and their help from here, and runs the study through
``run``; each study's module is imported only when it runs (some import the whole solver).  A new
study is one module with a ``run_study`` and one entry below (``docs/theory.md``, "Adding a study").
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass

# the sizes every study runs at: smoke (coarse and short, what the tests run) and default (its answer)
SIZES = ("smoke", "default")


@dataclass(frozen=True)
class Study:
    module: str          # the module (below ``shockfem``) whose ``run_study(size, out_dir)`` runs it
    question: str        # what the study answers, in a line


STUDIES = {
    "penetration": Study("study.penetration", "the white paper's task 1: the environment to reproduce, a 12 lb "
                                              "article's deceleration in concrete (Forrestal's law)"),
    "fixture": Study("study.fixture", "task 2: from a striking mass to the pulse on the unit under test, "
                                      "through each programmer concept"),
    "amplifier": Study("study.amplifier", "task 3: the velocity amplifier's masses, restitution and gain, "
                                          "rigid to finite elements"),
    "launcher": Study("study.launcher", "task 4: the gas gun that launches the first mass, and its trade curves"),
    "system": Study("study.system", "task 5: the whole machine for 10 to 100 lb payloads, and the coupled check"),
    "premise": Study("study.premise", "the white paper's premise at 12 lb: the amplifier against one gun firing "
                                      "the striker, the closed form's boundary, the map, the white paper's claims"),
}


def run(name: str, size: str, out_dir: str) -> str:
    """Run the study ``name`` at ``size`` into ``out_dir``; returns the path of its report."""
    module = importlib.import_module(f"shockfem.{STUDIES[name].module}")
    return module.run_study(size, out_dir)
