"""PNG plots of a run's histories (read from the run directory's history.csv)."""
from __future__ import annotations

import os

from .figures import pyplot, save

from .history import ENERGY_COLUMNS
from .history_file import read_history_csv
from ..units import G0




def plot_histories(run_dir: str, body_names) -> list[str]:
    plt = pyplot()
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
    written.append(save(fig, os.path.join(run_dir, "energy.png")))
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for name in body_names:
        for key, ax, scale in ((f"{name}.v_", axes[0], 1.0), (f"{name}.a_", axes[1], 1 / G0)):
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
    written.append(save(fig, os.path.join(run_dir, "bodies.png")))
    return written




class ChannelPlots:
    """The pulse and shock-response-spectrum pictures of a run's channels (``pulse(...)``, ``srs(...)``, one PNG
    each), drawn on one figure of each kind that every channel draws on again.  A new matplotlib figure
    makes its axes, ticks and tick labels anew, and that is most of a picture's time: a run with six
    channels spent about 3 s of its end on twelve figures.  Use it as a context manager (it closes the two
    figures)."""

    def __init__(self):
        plt = pyplot()
        self._pulse = plt.subplots(figsize=(7, 4))
        self._srs = plt.subplots(figsize=(7, 4))
        _log_axes(self._srs[1])

    def __enter__(self) -> "ChannelPlots":
        return self

    def __exit__(self, *exc):
        plt = pyplot()
        plt.close(self._pulse[0])
        plt.close(self._srs[0])

    def pulse(self, path: str, name: str, arrays: dict, metrics: dict) -> str:
        """Acceleration pulse of a channel in g: without a filter and filtered, the ideal pulse and its
        tolerance band."""
        fig, ax = self._pulse
        _clear(ax)
        t = arrays["t"] * 1e3
        if metrics["filter"] == "none":      # shock.cfc = "none": one curve, said once
            ax.plot(t, arrays["a"] / G0, color="C0", lw=1.4, label='no filter (shock.cfc = "none")')
        else:
            ax.plot(t, arrays["a_raw"] / G0, color="0.7", lw=0.7, label="no filter")
            ax.plot(t, arrays["a"] / G0, color="C0", lw=1.4, label=metrics["filter"])
        if "ideal" in arrays:
            on = arrays["monitored"]
            ax.plot(t, arrays["ideal"] / G0, "k--", lw=1, label=metrics["tolerance"]["against"])
            ax.fill_between(t[on], arrays["lower"][on] / G0, arrays["upper"][on] / G0, color="C2", alpha=0.15,
                            label="tolerance band " + ("PASS" if metrics["tolerance"]["passed"] else "FAIL"))
        p = metrics["pulse"]
        ax.axvspan(p["start"] * 1e3, p["end"] * 1e3, color="C1", alpha=0.07, label="duration above 10% of peak")
        ax.set_xlabel("time [ms]")
        ax.set_ylabel("acceleration [g]")
        ax.set_title(f"{name}: peak {p['peak_g']:.4g} g, {p['duration'] * 1e3:.3g} ms, "
                     f"dV {abs(p['velocity_change']):.4g} m/s, {metrics['shape']['classified']}", fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        return save(fig, path, close=False)

    def srs(self, path: str, name: str, spectrum) -> str:
        """Maximax shock response spectrum in g against natural frequency (log-log)."""
        fig, ax = self._srs
        _clear(ax)
        f = spectrum.frequency
        ax.plot(f, spectrum.maximax / G0, color="C0", lw=1.6, label="maximax")
        ax.plot(f, spectrum.positive / G0, color="C1", lw=0.8, ls="--", label="positive")
        ax.plot(f, spectrum.negative / G0, color="C2", lw=0.8, ls=":", label="negative")
        ax.set_xlabel("natural frequency [Hz]")
        ax.set_ylabel("peak absolute acceleration [g]")
        ax.set_title(f"{name}: shock response spectrum, Q = {spectrum.q:g}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
        return save(fig, path, close=False)


def _clear(ax):
    """Take what the last channel drew off ``ax`` (lines, bands, spans, legend) and forget its data limits,
    keeping the axes, their scales and their ticks."""
    for artist in [*ax.lines, *ax.collections, *ax.patches]:
        artist.remove()
    if ax.get_legend() is not None:
        ax.get_legend().remove()
    ax.relim()
    ax.autoscale()


def _log_axes(ax):
    """Logarithmic axes labelled 20, 100, 1000 (not 10^3: matplotlib's mathematical text is a tenth of a
    second a picture), the minor ticks unlabelled."""
    from matplotlib.ticker import FuncFormatter, NullFormatter
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
        axis.set_minor_formatter(NullFormatter())


def plot_stages(path: str, stages: list[dict]) -> str | None:
    """Velocity ratio (struck body's speed over the launch speed) after each contact event; None (nothing
    drawn) when no stage has one (every body started at rest: ``metrics.stages.NOT_MEASURED``)."""
    stages = [s for s in stages if "velocity_ratio" in s]
    if not stages:
        return None
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    labels = [f"{s['striker']} -> {s['struck']}" for s in stages]
    ratios = [s["velocity_ratio"] for s in stages]
    bars = ax.bar(range(len(stages)), ratios, color="C0")
    for bar, s in zip(bars, stages):
        e = f"e = {s['restitution']:.3f}" if "restitution" in s else "e not applicable"
        ax.annotate(e, (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                    ha="center", va="bottom", fontsize=8)
    ax.set_xticks(range(len(stages)))
    ax.set_xticklabels(labels, rotation=20, fontsize=8)
    ax.set_ylabel("speed after / launch speed")
    ax.set_title("Velocity gain by stage (restitution above each bar)")
    ax.grid(alpha=0.3, axis="y")
    return save(fig, path)
