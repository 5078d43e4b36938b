"""The registry of verification cases: name -> function(size, workdir) -> list of checks.

``shockfem verify`` runs them by name; each lives in the module of its topic and imports only the
shared helpers of ``checks.py`` and ``scenes.py``, never this registry.
"""
from __future__ import annotations

from .foundation_cases import (axisymmetric_vs_3d, bar_wave, bar_wave_tets, body_damping, energy_conservation,
                               free_flight, free_free_frequency, rayleigh_damping)
from .contact_cases import (contact_parallel, hertz_spheres, rod_on_constraint_wall, rod_on_rod, rod_on_rod_3d,
                            rod_on_wall, sliding_block, thick_rods, tunnel_slide, unequal_rods)
from .spring_cases import spring_oscillator
from .damping_cases import band_damping_modes, rayleigh_frequency_dependence
from .material_point import material_point
from .plasticity_cases import plastic_wave, taylor_bar, taylor_bar_3d, taylor_bar_full
from .metrics_cases import cfc_filter, pulse_shapes, rod_impact_metrics, srs_half_sine
from .modal_cases import circular_plate, modal_rod, nafems_fv12
from .amplifier_cases import amplifier_1d, amplifier_pads, amplifier_rigid
from .launcher_cases import launcher_design, launcher_model
from .machine_cases import direct_striker, machine_energy, machine_geometry
from .premise_cases import premise_boundary
from .gas_drive_cases import gas_drive
from .gas_column_cases import gas_column, gas_column_design
from .gas_spring_cases import gas_spring
from .pad_cases import pad_1d, pad_bars, pad_johnson, pad_mesh, pad_rigid
from .slotted_cases import slotted_ring
from .programmer_cases import crushable_pad, programmer_sizing, rubber_pad
from .split_cone_cases import cone_friction, cone_push, cone_rebound, shrink_fit
from .preload_cases import preload_stage
from .dashpot_cases import dashpot_designer, fluid_dashpot
from .column_cases import liquid_column, orifice_law, orifice_reynolds
from .column_fe_cases import column_fe
from .orientation_cases import oriented_body
from .penetration_cases import (forrestal, penetration_rigid, penetration_spin, penetration_wave,
                                penetration_yaw)
from .section_cases import section_stress
from .mass_scaling_cases import mass_scaling
from .lsdyna_cases import lsdyna_decks
from .rigid_drive_cases import rigid_drive_free, rigid_punch
from .hard_cases import HARD


CASES = {
    "free_flight": free_flight,
    "bar_wave": bar_wave,
    "bar_wave_tets": bar_wave_tets,
    "free_free_frequency": free_free_frequency,
    "energy_conservation": energy_conservation,
    "axisymmetric_vs_3d": axisymmetric_vs_3d,
    "rayleigh_damping": rayleigh_damping,
    "body_damping": body_damping,
    "band_damping_modes": band_damping_modes,
    "rayleigh_frequency_dependence": rayleigh_frequency_dependence,
    "rod_on_rod": rod_on_rod,
    "rod_on_wall": rod_on_wall,
    "rod_on_constraint_wall": rod_on_constraint_wall,
    "rigid_punch": rigid_punch,
    "rigid_drive_free": rigid_drive_free,
    "unequal_rods": unequal_rods,
    "thick_rods": thick_rods,
    "hertz_spheres": hertz_spheres,
    "rod_on_rod_3d": rod_on_rod_3d,
    "contact_parallel": contact_parallel,
    "mass_scaling": mass_scaling,
    "spring_oscillator": spring_oscillator,
    "sliding_block": sliding_block,
    "tunnel_slide": tunnel_slide,
    "material_point": material_point,
    "plastic_wave": plastic_wave,
    "taylor_bar": taylor_bar,
    "taylor_bar_full": taylor_bar_full,
    "slotted_ring": slotted_ring,
    "oriented_body": oriented_body,
    "crushable_pad": crushable_pad,
    "rubber_pad": rubber_pad,
    "shrink_fit": shrink_fit,
    "preload_stage": preload_stage,
    "cone_friction": cone_friction,
    "cone_push": cone_push,
    "cone_rebound": cone_rebound,
    "fluid_dashpot": fluid_dashpot,
    "dashpot_designer": dashpot_designer,
    "orifice_law": orifice_law,
    "orifice_reynolds": orifice_reynolds,
    "liquid_column": liquid_column,
    "column_fe": column_fe,
    "forrestal": forrestal,
    "penetration_rigid": penetration_rigid,
    "penetration_wave": penetration_wave,
    "penetration_spin": penetration_spin,
    "penetration_yaw": penetration_yaw,
    "section_stress": section_stress,
    "programmer_sizing": programmer_sizing,
    "taylor_bar_3d": taylor_bar_3d,
    "cfc_filter": cfc_filter,
    "srs_half_sine": srs_half_sine,
    "pulse_shapes": pulse_shapes,
    "rod_impact_metrics": rod_impact_metrics,
    "modal_rod": modal_rod,
    "nafems_fv12": nafems_fv12,
    "circular_plate": circular_plate,
    "amplifier_rigid": amplifier_rigid,
    "amplifier_1d": amplifier_1d,
    "amplifier_pads": amplifier_pads,
    "launcher_model": launcher_model,
    "launcher_design": launcher_design,
    "machine_geometry": machine_geometry,
    "machine_energy": machine_energy,
    "direct_striker": direct_striker,
    "premise_boundary": premise_boundary,
    "gas_drive": gas_drive,
    "gas_column": gas_column,
    "gas_column_design": gas_column_design,
    "gas_spring": gas_spring,
    "pad_bars": pad_bars,
    "pad_rigid": pad_rigid,
    "pad_johnson": pad_johnson,
    "pad_mesh": pad_mesh,
    "pad_1d": pad_1d,
    "lsdyna_decks": lsdyna_decks,
    **HARD,
}

# names that stand for several cases: ``shockfem verify hard``
GROUPS = {"hard": list(HARD)}

