"""A shot's run directory: summary.json (shot, model, ASME sizing), history.csv, launcher.png."""
from __future__ import annotations

import csv
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .vessel import barrel_weight, tank_weight  # noqa: E402

G0 = 9.80665


def sizing(gun, options: dict) -> dict:
    """ASME wall thicknesses and weights of barrel and tank at the reservoir pressure (the
    highest either sees), with the hoop-stress margin at that pressure."""
    P = gun.reservoir_pressure
    barrel, w_barrel = barrel_weight(P, gun.bore, gun.length, options["barrel_material"], options["joint_efficiency"])
    shell, t_head, w_tank = tank_weight(P, gun.reservoir_volume, options["tank_diameter"], options["tank_material"],
                                        options["joint_efficiency"])
    return {"design_pressure": P,
            "barrel": {"material": options["barrel_material"], "thickness": barrel.thickness, "rule": barrel.rule,
                       "hoop_stress": barrel.hoop_stress, "margin": barrel.margin, "weight": w_barrel},
            "tank": {"material": options["tank_material"], "diameter": options["tank_diameter"],
                     "shell_thickness": shell.thickness, "head_thickness": t_head, "rule": shell.rule,
                     "hoop_stress": shell.hoop_stress, "margin": shell.margin, "weight": w_tank},
            "total_weight": w_barrel + w_tank}


def write_shot(out_dir: str, shot, size: dict) -> str:
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "summary.json"), "w") as fh:
        json.dump({**shot.summary(), "sizing": size}, fh, indent=2, default=float)
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
    fig.tight_layout()
    path = os.path.join(out_dir, "launcher.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
