"""What a machine is designed for: the test article, the pulse, and the designer's choices and limits.

Every field is SI inside; ``read_spec`` takes the user's strings with units ("12 lb", "10000 gee",
"5 ms", "325 ft/s", "5000 psi") and checks them all at once, every problem named with its fix (the
scene checker's ``SceneError``: exit 2 on the command line).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from ..amplifier.gain import ARCHITECTURES
from ..launcher.gas import GASES
from ..programmer.dashpot_design import STRIKER_RATIO, PulseSpec
from ..programmer.shapes import SHAPES
from ..scene.checker import Checker
from ..scene.library import LIBRARY
from ..units import FT, IN, LB, PSI

# the dashpot's design pressure, the payload's force m A_g over the piston (the peak runs some 15% above
# it): the housing's wall needs steel of about 2 F / (S - p) in section, so a lower pressure makes a
# lighter striker at the price of a wider bore and a heavier piston and oil column
OIL_PRESSURE = 120e6
# the fixture study's article: a solid ogive of 60 mm calibre at 12 lb; other masses scale it
# geometrically (its calibre as the cube root of the mass) unless a diameter is given
REFERENCE_ARTICLE = {"mass": 12 * LB, "diameter": 0.060, "library": "steel_4340", "crh": 3.0,
                     "meplat_over_radius": 0.2}


@dataclass(frozen=True)
class MachineSpec:
    article_mass: float                       # the unit under test [kg]
    pulse: PulseSpec                          # what it must feel
    article_diameter: float = 0.0             # [m]; 0: the reference article scaled to the mass
    architecture: str = "launched-chain"      # amplifier (``amplifier.gain.ARCHITECTURES``)
    masses: int = 5                           # amplifier masses, the striker (fixture housing) last
    launch_speed: float = 325 * FT            # of the first mass (or the stack) [m/s]
    material: str = "high_strength_steel"     # amplifier masses, housing, frame (scene library)
    gas: str = "air"                          # the launcher's (``launcher.gas.GASES``)
    max_pressure: float = 5000 * PSI          # launcher reservoir [Pa]
    max_barrel_length: float = 20 * FT        # [m]
    max_bore: float = 36 * IN                 # [m]
    striker_ratio: float = STRIKER_RATIO      # striker (housing and oil) over payload, at least
    safety_factor: float = 1.5                # allowable = yield / safety factor (structural parts)
    catch_deceleration: float = 0.0           # the payload's catcher [m/s^2]; 0: half the pulse's peak
    oil_pressure: float = OIL_PRESSURE        # the map's design oil pressure (``fixture.bore_radius``) and the
                                              #   most the stops' hydraulic buffers work at [Pa]
    pad_resolution: str = "smoke"             # the pads' finite-element runs (``pads.RESOLUTIONS``): the
                                              #   design runs each interface at every iteration; "estimate":
                                              #   none, each material's estimate (a study's quickest size)

    @property
    def diameter(self) -> float:
        """The article's diameter [m]: as given, or the reference article scaled to its mass."""
        if self.article_diameter:
            return self.article_diameter
        return REFERENCE_ARTICLE["diameter"] * (self.article_mass / REFERENCE_ARTICLE["mass"]) ** (1 / 3)

    @property
    def catch(self) -> float:
        return self.catch_deceleration or 0.5 * self.pulse.peak

    def with_article(self, mass: float) -> "MachineSpec":
        """The same machine for another article mass (diameter scaled unless given)."""
        return dataclasses.replace(self, article_mass=mass)


# option name -> (field, dimension or None for a plain number, default as the user writes it)
OPTIONS = {
    "article": ("article_mass", "mass", None),
    "article_diameter": ("article_diameter", "length", "0 mm"),
    "peak": ("peak", "acceleration", "10000 gee"),
    "duration": ("duration", "time", "5 ms"),
    "launch": ("launch_speed", "velocity", "325 ft/s"),
    "max_pressure": ("max_pressure", "pressure", "5000 psi"),
    "max_barrel_length": ("max_barrel_length", "length", "20 ft"),
    "max_bore": ("max_bore", "length", "36 in"),
    "catch_deceleration": ("catch_deceleration", "acceleration", "0 gee"),
    "oil_pressure": ("oil_pressure", "pressure", "120 MPa"),
}


def read_spec(options: dict) -> MachineSpec:
    """A ``MachineSpec`` from the user's options (strings with units, numbers, choices); every problem
    at once as ``SceneError``."""
    ck = Checker()
    known = set(OPTIONS) | {"shape", "architecture", "masses", "material", "gas", "striker_ratio", "safety_factor"}
    for k in options:
        if k not in known:
            ck.fail(f"--{k.replace('_', '-')}", f"unknown option (known: {', '.join(sorted(known))})")
    si = {}
    for name, (field, dimension, default) in OPTIONS.items():
        value = options.get(name)
        value = default if value is None else value
        flag = f"--{name.replace('_', '-')}"
        zero_ok = default is not None and default.startswith("0 ")
        si[field] = ck.quantity({flag: value}, flag, "", dimension, None, positive=not zero_ok,
                                nonnegative=zero_ok)
    shape = ck.choice({"--shape": options.get("shape", "rectangle")}, "--shape", "", SHAPES)
    arch = ck.choice({"--architecture": options.get("architecture", "launched-chain")}, "--architecture", "",
                     ARCHITECTURES)
    material = ck.choice({"--material": options.get("material", "high_strength_steel")}, "--material", "",
                         tuple(k for k, v in LIBRARY.items() if "yield_stress" in v or "hardening_curve" in v))
    gas = ck.choice({"--gas": options.get("gas", "air")}, "--gas", "", tuple(GASES))
    masses = options.get("masses", 5)
    if not (isinstance(masses, int) and not isinstance(masses, bool) and 2 <= masses <= 12):
        ck.fail("--masses", f"the amplifier's masses, the striker last: a whole number from 2 to 12, got {masses!r}")
        masses = 5
    ratio = ck.number({"--striker-ratio": options.get("striker_ratio", STRIKER_RATIO)}, "--striker-ratio", "",
                      STRIKER_RATIO, 1.0, 1000.0, "striker over payload mass")
    sf = ck.number({"--safety-factor": options.get("safety_factor", 1.5)}, "--safety-factor", "", 1.5, 1.0, 10.0,
                   "yield over allowable stress")
    ck.done()
    if si["catch_deceleration"] and si["catch_deceleration"] > si["peak"]:
        raise_for = f"must not exceed the pulse's peak ({si['peak']:.4g} m/s^2): the catcher would be the harsher test"
        ck.fail("--catch-deceleration", f"{raise_for}, got {options.get('catch_deceleration')}")
        ck.done()
    return MachineSpec(si["article_mass"], PulseSpec(shape, si["peak"], si["duration"]), si["article_diameter"],
                       arch, masses, si["launch_speed"], material, gas, si["max_pressure"], si["max_barrel_length"],
                       si["max_bore"], ratio, sf, si["catch_deceleration"], si["oil_pressure"])
