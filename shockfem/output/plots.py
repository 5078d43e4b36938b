"""PNG plots of a run's histories (read from the run directory's history.csv)."""
from __future__ import annotations

import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .history import ENERGY_COLUMNS, read_history_csv  # noqa: E402


def _save(fig, path: str) -> str:
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_histories(run_dir: str, body_names) -> list[str]:
    h = read_history_csv(os.path.join(run_dir, "history.csv"))
    t = h["time"] * 1e3
    written = []
    fig, ax = plt.subplots(figsize=(7, 4))
    for k in ENERGY_COLUMNS:
        ax.plot(t, h[f"energy.{k}"], label=k)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("energy [J]")
    ax.legend()
    ax.grid(alpha=0.3)
    ax.set_title("Energy balance")
    written.append(_save(fig, os.path.join(run_dir, "energy.png")))
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for name in body_names:
        for key, ax, scale in ((f"{name}.v_", axes[0], 1.0), (f"{name}.a_", axes[1], 1 / 9.80665)):
            for col in h:
                if col.startswith(key):
                    ax.plot(t, h[col] * scale, label=col)
    axes[0].set_ylabel("mean velocity [m/s]")
    axes[1].set_ylabel("mean acceleration [g]")
    axes[1].set_xlabel("time [ms]")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Rigid-body motion of each body (mass-weighted means)")
    written.append(_save(fig, os.path.join(run_dir, "bodies.png")))
    return written
