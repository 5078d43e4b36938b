"""Materials library: ``library = "mild_steel"`` in a scene's material fills in the fields below,
and any field the scene gives overrides the library's.

Values are typical, for design studies; use certified data for a real part.  Sources:

* [Jones] N. Jones, *Structural Impact*, Cambridge University Press 1989, Cowper-Symonds
  constants D, q of the rate factor 1 + (rate/D)^(1/q) (shockfem/references quote them; check the book);
* [JC] G. R. Johnson, W. H. Cook, "A constitutive model and data for metals subjected to large
  strains, high strain rates and high temperatures", 7th Int. Symp. Ballistics, The Hague 1983:
  sigma = A + B eps_p^n, tabulated here at strains 0 ... 1 as a hardening curve (MAT_024-like);
* [WG] M. L. Wilkins, M. W. Guinan, "Impact of cylinders on a rigid boundary", J. Appl. Phys.
  44 (1973) 1200: the Taylor-bar copper of the numerical benchmark (bilinear, rate independent);
* [ASTM] minimum specified yield and tensile strengths of the named grade; the tangent modulus
  is the straight line from yield to the tensile strength at the minimum elongation;
* [GA] L. J. Gibson, M. F. Ashby, *Cellular Solids*, 2nd ed., Cambridge University Press 1997,
  open-cell scaling of a foam of relative density phi from its solid: modulus E_s phi^2, plastic
  collapse (plateau) stress 0.3 sigma_ys phi^(3/2), densification strain 1 - 1.4 phi.  A foam's
  crush curve here is that plateau to the densification strain and a steep rise after it (the
  rise's shape is assumed: use a tested curve for a real programmer).
"""
from __future__ import annotations

from ..units import to_si


def _foam(phi: float, rho_solid: float, E_solid: float, yield_solid: float, hardening: float) -> dict:
    """A crushable foam of relative density ``phi`` scaled from its solid [GA]: plateau from volumetric
    strain 0 to the densification strain (rising by ``hardening`` over it), then a rise to 40 times
    the plateau stress by the strain halfway from densification to 1; the modulus E_s phi^2 is kept at
    least the rise's slope (``scene/materials.py`` requires it)."""
    plateau = 0.3 * yield_solid * phi ** 1.5
    e_d = 1.0 - 1.4 * phi
    e_top = 0.5 * (1.0 + e_d)
    top = 40.0 * plateau
    E = max(E_solid * phi ** 2, (top - plateau * hardening) / (e_top - e_d))
    return {"density": f"{phi * rho_solid:.4g} kg/m^3", "youngs_modulus": f"{E / 1e6:.4g} MPa", "poisson_ratio": 0.0,
            "crush_curve": [[0.0, f"{plateau / 1e6:.4g} MPa"], [round(e_d, 3), f"{plateau * hardening / 1e6:.4g} MPa"],
                            [round(e_top, 3), f"{top / 1e6:.4g} MPa"]],
            "tension_cutoff": f"{0.1 * plateau / 1e6:.3g} MPa"}


def _power_law_curve(A: float, B: float, n: float) -> list[list[float]]:
    """Johnson-Cook's quasi-static hardening A + B eps^n [MPa] as [plastic strain, "stress"] points."""
    strains = (0.0, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0)
    return [[e, f"{A + B * e ** n:.1f} MPa"] for e in strains]


LIBRARY: dict[str, dict] = {
    "mild_steel": {
        "source": "ASTM A36 (yield 250 MPa, tensile 400 MPa at 20%); Cowper-Symonds D = 40.4 /s, q = 5 [Jones]",
        "density": "7850 kg/m^3", "youngs_modulus": "210 GPa", "poisson_ratio": 0.3,
        "yield_stress": "250 MPa", "tangent_modulus": "0.75 GPa",
        "cowper_symonds_D": "40.4 /s", "cowper_symonds_q": 5.0,
    },
    "high_strength_steel": {
        "source": "ASTM A514 (yield 690 MPa, tensile 760 MPa at 18%); high-tensile steel D = 3200 /s, q = 5 [Jones]",
        "density": "7850 kg/m^3", "youngs_modulus": "210 GPa", "poisson_ratio": 0.3,
        "yield_stress": "690 MPa", "tangent_modulus": "0.39 GPa",
        "cowper_symonds_D": "3200 /s", "cowper_symonds_q": 5.0,
    },
    "steel_4340": {
        "source": "4340 steel Rc 30, A = 792 MPa, B = 510 MPa, n = 0.26 [JC]; rate constants of high-tensile "
                  "steel D = 3200 /s, q = 5 [Jones] (none published for 4340 there)",
        "density": "7830 kg/m^3", "youngs_modulus": "200 GPa", "poisson_ratio": 0.29,
        "hardening_curve": _power_law_curve(792.0, 510.0, 0.26),
        "cowper_symonds_D": "3200 /s", "cowper_symonds_q": 5.0,
    },
    "stainless_304": {
        "source": "ASTM A240 type 304 (yield 205 MPa, tensile 515 MPa at 40%); D = 100 /s, q = 10 [Jones]",
        "density": "8000 kg/m^3", "youngs_modulus": "193 GPa", "poisson_ratio": 0.29,
        "yield_stress": "205 MPa", "tangent_modulus": "0.78 GPa",
        "cowper_symonds_D": "100 /s", "cowper_symonds_q": 10.0,
    },
    "aluminium_6061_t6": {
        "source": "ASTM B209 6061-T6 (yield 240 MPa, tensile 290 MPa at 10%); D = 6500 /s, q = 4 [Jones]",
        "density": "2700 kg/m^3", "youngs_modulus": "68.9 GPa", "poisson_ratio": 0.33,
        "yield_stress": "240 MPa", "tangent_modulus": "0.50 GPa",
        "cowper_symonds_D": "6500 /s", "cowper_symonds_q": 4.0,
    },
    "copper": {
        "source": "Taylor-bar copper of the Wilkins-Guinan benchmark [WG]: yield 400 MPa, tangent 100 MPa, "
                  "rate independent (no Cowper-Symonds constants for copper in [Jones]; add your own)",
        "density": "8930 kg/m^3", "youngs_modulus": "117 GPa", "poisson_ratio": 0.35,
        "yield_stress": "400 MPa", "tangent_modulus": "100 MPa",
    },
    "copper_ofhc": {
        "source": "OFHC copper, A = 90 MPa, B = 292 MPa, n = 0.31 [JC]; rate independent here",
        "density": "8960 kg/m^3", "youngs_modulus": "124 GPa", "poisson_ratio": 0.34,
        "hardening_curve": _power_law_curve(90.0, 292.0, 0.31),
    },
    "titanium_50a": {
        "source": "commercially pure titanium 50A (ASTM grade 2 class; yield 345 MPa typical, tensile 450 MPa at 20%); "
                  "D = 120 /s, q = 9 [Jones]",
        "density": "4510 kg/m^3", "youngs_modulus": "105 GPa", "poisson_ratio": 0.34,
        "yield_stress": "345 MPa", "tangent_modulus": "0.53 GPa",
        "cowper_symonds_D": "120 /s", "cowper_symonds_q": 9.0,
    },
    "aluminium_foam": {
        "source": "open-cell aluminium foam of relative density 0.1 scaled from its solid [GA] (density 2700 kg/m^3, "
                  "E 69 GPa, cell-wall yield 150 MPa assumed): plateau 1.42 MPa rising 20% to densification at 0.86 "
                  "volumetric strain, then to 57 MPa at 0.93; modulus E_s phi^2 = 690 MPa raised to 789 MPa, the "
                  "slope of that rise; tension cutoff 10% of the plateau; rate independent",
        **_foam(0.1, 2700.0, 69e9, 150e6, 1.2),
    },
    "polyurethane_foam": {
        "source": "rigid polyurethane foam of relative density 0.2 (240 kg/m^3, about 15 lb/ft^3) scaled from its "
                  "solid [GA] (density 1200 kg/m^3, E 1.6 GPa, yield 127 MPa assumed, rigid polymer values): plateau "
                  "3.41 MPa rising 10% to densification at 0.72 volumetric strain, then to 136 MPa at 0.86; modulus "
                  "E_s phi^2 = 64 MPa raised to 947 MPa, the slope of that rise; tension cutoff 10% of the plateau; "
                  "rate independent (the open-cell scaling, without the closed cells' face and gas terms)",
        **_foam(0.2, 1200.0, 1.6e9, 127e6, 1.1),
    },
}


def property_si(name: str, key: str, dimension: str) -> float:
    """A library material's property in SI (``key`` e.g. "density", dimension e.g. "density")."""
    return to_si(LIBRARY[name][key], dimension)


def initial_yield_stress(name: str) -> float:
    """The initial yield stress of a library metal [Pa]: its hardening curve's first point, or its yield."""
    m = LIBRARY[name]
    return to_si(m["hardening_curve"][0][1] if "hardening_curve" in m else m["yield_stress"], "pressure")
