"""A shot's run directory: summary.json (shot, model, ASME sizing), history.csv, launcher.png;
a design's: design.json and, with trade curves, trade.csv and trade.png."""
from __future__ import annotations

import csv
import json
import math
import os

from ..output.figures import pyplot, save
from ..output.rundir import write_json_atomic

from .vessel import barrel_weight, tank_weight
from ..units import FT, G0, IN, LB, PSI



def sizing(gun, options) -> dict:
    """ASME wall thicknesses and weights of barrel and tank (``options``: a ``design.Sizing``)
    at the reservoir pressure (the highest either sees), with the hoop-stress margin there."""
    P = gun.reservoir_pressure
    E = options.joint_efficiency
    barrel, w_barrel = barrel_weight(P, gun.bore, gun.length, options.barrel_material, E)
    diameter = options.tank_diameter_of(gun.reservoir_volume)
    shell, t_head, w_tank = tank_weight(P, gun.reservoir_volume, diameter, options.tank_material, E)
    return {"design_pressure": P,
            "barrel": {"material": options.barrel_material, "thickness": barrel.thickness, "rule": barrel.rule,
                       "hoop_stress": barrel.hoop_stress, "margin": barrel.margin, "weight": w_barrel},
            "tank": {"material": options.tank_material, "diameter": diameter,
                     "shell_thickness": shell.thickness, "head_thickness": t_head, "rule": shell.rule,
                     "hoop_stress": shell.hoop_stress, "margin": shell.margin, "weight": w_tank},
            "total_weight": w_barrel + w_tank}


def write_shot(out_dir: str, shot, size: dict) -> str:
    plt = pyplot()
    os.makedirs(out_dir, exist_ok=True)
    write_json_atomic(os.path.join(out_dir, "summary.json"), {**shot.summary(), "sizing": size})
    h = shot.history
    cols = [("time", "s"), ("x", "m"), ("v", "m/s"), ("acceleration", "m/s^2"), ("p_reservoir", "Pa"),
            ("p_barrel", "Pa"), ("p_base", "Pa")]
    with open(os.path.join(out_dir, "history.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow([f"{c} [{u}]" for c, u in cols])
        w.writerows(zip(*[h[c] for c, _ in cols]))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    t = h["time"] * 1e3
    axes[0].plot(t, h["p_reservoir"] / 1e6, label="reservoir")
    axes[0].plot(t, h["p_barrel"] / 1e6, label="barrel (mean)")
    axes[0].plot(t, h["p_base"] / 1e6, "--", label="projectile base")
    axes[0].set_ylabel("pressure [MPa]")
    axes[1].plot(t, h["v"], label="velocity [m/s]")
    ax2 = axes[1].twinx()
    ax2.plot(t, h["acceleration"] / G0, color="C3", lw=0.8)
    ax2.set_ylabel("acceleration [g]", color="C3")
    axes[1].set_ylabel("velocity [m/s]")
    for ax in axes:
        ax.set_xlabel("time [ms]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"muzzle {shot.muzzle_velocity:.4g} m/s; {shot.model}", fontsize=7)
    return save(fig, os.path.join(out_dir, "launcher.png"))


def shot_lines(name: str, shot, size: dict) -> list[str]:
    """The console summary of a shot and its sizing."""
    b, t = size["barrel"], size["tank"]
    return [f"{name}: {shot.model}",
            f"  muzzle velocity {shot.muzzle_velocity:.5g} m/s ({shot.muzzle_velocity / FT:.5g} ft/s)"
            f"{'' if shot.left_barrel else ' -- ' + shot.note}; {shot.time_in_barrel * 1e3:.4g} ms in the barrel",
            f"  peak acceleration {shot.peak_acceleration / G0:.4g} g, peak base pressure "
            f"{shot.peak_base_pressure / 1e6:.4g} MPa, efficiency {shot.efficiency:.1%} of the gas energy, "
            f"energy balance {shot.energy_balance_error:.1e}",
            f"  barrel {b['material']}: wall {b['thickness'] * 1e3:.3g} mm ({b['rule']}), {b['weight']:.4g} kg; "
            f"tank {t['material']} {t['diameter'] * 1e3:.4g} mm: shell {t['shell_thickness'] * 1e3:.3g} mm, heads "
            f"{t['head_thickness'] * 1e3:.3g} mm, {t['weight']:.4g} kg; hoop margin "
            f"{min(b['margin'], t['margin']):+.1%} at {size['design_pressure'] / 1e6:.4g} MPa"]


def design_lines(design) -> list[str]:
    g = design.gun
    head = ("lightest launcher" if design.feasible else "NO FEASIBLE LAUNCHER; the closest") + \
        f" for {g.projectile_mass:.5g} kg ({g.projectile_mass / LB:.5g} lb) at {design.required_velocity:.5g} m/s " \
        f"({design.required_velocity / FT:.5g} ft/s):"
    lines = [head,
             f"  bore {g.bore * 1e3:.4g} mm ({g.bore / IN:.4g} in), barrel {g.length:.4g} m ({g.length / FT:.4g} ft), "
             f"{g.reservoir_pressure / 1e6:.4g} MPa ({g.reservoir_pressure / PSI:.5g} psi), tank "
             f"{g.reservoir_volume:.4g} m^3 ({g.reservoir_volume / FT ** 3:.4g} ft^3)",
             f"  weight {design.weight:.5g} kg ({design.weight / LB:.5g} lb): barrel {design.barrel_weight:.4g} kg, "
             f"tank {design.tank_weight:.4g} kg; muzzle {design.muzzle_velocity:.5g} m/s, peak acceleration "
             f"{design.peak_acceleration / G0:.4g} g, efficiency {design.efficiency:.1%}",
             f"  {design.evaluations} shots in {design.wall_time_s:.3g} s"]
    if design.note:
        lines.append("  " + design.note)
    if not design.binding:
        lines.append("  binding: only the muzzle velocity (every variable is inside its limits)")
    for b in design.binding:
        saved = b.get("weight_saved_by_relaxing_10%")
        unit = {"bore": "m", "length": "m", "reservoir_pressure": "Pa", "reservoir_volume": "m^3"}[b["variable"]]
        lines.append(f"  binding: {b['limit']} = {b['value']:.4g} {unit}" +
                     (f"; relaxing it by 10% saves {saved:.4g} kg" if saved is not None else ""))
    return lines


def write_design(out_dir: str, design, trades: dict | None = None) -> list[str]:
    """design.json; with ``trades`` (``weight_vs_pressure``: designs, ``length_vs_bore``: rows of
    ``design.length_against_bore``), trade.csv and trade.png."""
    plt = pyplot()
    os.makedirs(out_dir, exist_ok=True)
    trades = trades or {}
    pressure = trades.get("weight_vs_pressure", [])
    bore = trades.get("length_vs_bore", [])
    written = [os.path.join(out_dir, "design.json")]
    with open(written[0], "w") as fh:
        json.dump({"design": design.summary(), "weight_vs_pressure": [d.summary() for d in pressure],
                   "length_vs_bore": bore}, fh, indent=2, default=float)
    if not trades:
        return written
    with open(os.path.join(out_dir, "trade.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["curve", "bore [m]", "length [m]", "pressure [Pa]", "volume [m^3]", "weight [kg]",
                    "simple-wave barrel [m]", "feasible"])
        for d in pressure:
            g = d.gun
            w.writerow(["weight_vs_pressure", g.bore, g.length, g.reservoir_pressure, g.reservoir_volume, d.weight,
                        "", d.feasible])
        g = design.gun
        for r in bore:
            w.writerow(["length_vs_bore", r["bore"], r["length"], g.reservoir_pressure, g.reservoir_volume,
                        r["weight"], r["simple_wave"], math.isfinite(r["length"])])
    written.append(os.path.join(out_dir, "trade.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    ok = [d for d in pressure if d.feasible]
    axes[0].plot([d.gun.reservoir_pressure / PSI for d in ok], [d.weight / LB for d in ok], "o-")
    axes[0].plot([g.reservoir_pressure / PSI], [design.weight / LB], "r*", ms=12, label="lightest")
    axes[0].set_xlabel("reservoir pressure [psi]")
    axes[0].set_ylabel("lightest launcher at that pressure [lb]")
    axes[0].legend(fontsize=8)
    b = [r["bore"] / IN for r in bore]
    axes[1].plot(b, [r["length"] / FT for r in bore], "o-", label=f"the design's tank ({g.reservoir_volume:.3g} m^3)")
    axes[1].plot(b, [r["simple_wave"] / FT for r in bore], "s--", label="infinite chamber of the bore (simple wave)")
    axes[1].set_xlabel("bore [in]")
    axes[1].set_ylabel(f"barrel length for {design.required_velocity / FT:.4g} ft/s [ft]")
    axes[1].set_yscale("log")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    fig.suptitle(f"{g.projectile_mass / LB:.5g} lb at {design.required_velocity / FT:.4g} ft/s, "
                 f"{g.reservoir_pressure / PSI:.4g} psi", fontsize=9)
    written.append(save(fig, os.path.join(out_dir, "trade.png")))
    return written
