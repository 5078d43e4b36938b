"""Shock metrics of a run directory: what ``shockfem run`` adds to summary.json and plots.

Reads ``resolved_scene.json``, ``summary.json`` and ``history.csv`` (outputs are files, and
metrics read files), so ``shockfem metrics RUN_DIR`` can redo them later, e.g. with another
filter class.  For every channel (a test article's rigid-body motion, an accelerometer):

1. acceleration along the shock axis as the interval mean of the recorded velocity
2. the CFC filter (SAE J211), if the scene asks for one
3. the main pulse (``pulse``), its shape (``shapes.classify``) and the tolerance-band check
   against the scene's spec, or against the fitted classical shape when there is no spec
4. the velocity change of the filtered record against the rigid-body velocity change
5. the shock response spectrum of the acceleration without a filter (the filter is a measuring
   channel's, the spectrum a property of the motion)

and for the run, the stage table of its contact events (``stages``).
"""
from __future__ import annotations

import json
import os
from dataclasses import asdict

import numpy as np

from ..output.history_file import read_history_csv
from ..output.rundir import write_json_atomic
from . import filters, shapes
from .pulse import pulse_metrics
from .signals import acceleration_from_velocity
from .srs import log_frequencies, pulse_band, shock_response_spectrum
from .stages import stage_table
from ..units import G0

# A channel whose record integrates to a velocity change this far off its body's gets a note.
VELOCITY_CHANGE_MISMATCH = 0.01


def _read(run_dir: str, name: str) -> dict:
    with open(os.path.join(run_dir, name)) as fh:
        return json.load(fh)


def channels(scene: dict) -> list[tuple[str, str, str]]:
    """(channel name, velocity column stem, body) of every test article and accelerometer."""
    out = [(b, b, b) for b in scene["shock"]["test_articles"]]
    out += [(m["name"], f"accelerometer.{m['name']}", m["body"]) for m in scene["shock"]["accelerometers"]]
    return out


def channel_metrics(t: np.ndarray, v: np.ndarray, v_body: np.ndarray, shock: dict) -> tuple[dict, dict]:
    """Metrics of one channel (velocity history ``v`` along the axis, its body's ``v_body``),
    and the arrays the plots need."""
    t_mid, a_raw = acceleration_from_velocity(t, v)
    dt = float(t_mid[1] - t_mid[0])
    cfc = shock["cfc"]
    notes = []
    if cfc:
        problem = filters.check_sampling(cfc, dt)
        if problem:
            notes.append(problem)
        a = a_raw if filters.above_nyquist(cfc, dt) else filters.cfc_filter(a_raw, dt, cfc)
    else:
        a = a_raw
    out: dict = {"filter": f"CFC {cfc} (SAE J211)" if cfc else "none", "sample_interval": dt, "notes": notes}
    arrays = {"t": t_mid, "a_raw": a_raw, "a": a}
    dv_rigid = float(v_body[-1] - v_body[0])
    dv_record = float(a.sum() * dt)
    out["velocity_change_record"] = dv_record
    out["velocity_change_rigid_body"] = dv_rigid
    if not dv_rigid:
        # a point that vibrates on a body that ends as it began: no velocity change to compare with
        out["not_measured"] = {"velocity_change_mismatch": "its body's velocity does not change (no velocity change "
                                                           "to divide by)"}
    else:
        out["velocity_change_mismatch"] = (dv_record - dv_rigid) / dv_rigid
    if dv_rigid and abs(out["velocity_change_mismatch"]) > VELOCITY_CHANGE_MISMATCH:
        response = f"; CFC {cfc}'s response lasts about {1 / (2 * cfc * 2.0775):.3g} s" if cfc else ""
        notes.append(f"the {'filtered ' if cfc else ''}record's velocity change is "
                     f"{out['velocity_change_mismatch']:+.1%} off its body's: the record is too short for "
                     f"the pulse to settle{response}, or the point vibrates about its body's motion")
    if not np.any(a):
        out["pulse"] = None
        notes.append("no pulse: the channel never accelerates")
        return out, arrays
    p = pulse_metrics(t_mid, a)
    out["pulse"] = {**p.as_dict(), "peak_g": p.peak / G0, "mean_acceleration_g": p.mean_acceleration / G0}
    y = p.sign * a
    cls = shapes.classify(t_mid, a, p)
    out["shape"] = {"classified": cls.shape, "misfits": cls.misfits,
                    "fitted": cls.ideal.as_dict() if cls.ideal else None}
    spec = shock.get("spec")
    if spec:
        ideal = shapes.place(shapes.specified(spec["shape"], spec["peak"], spec["duration"]), t_mid, y, p)
        against = f"spec: {spec['shape']}, {spec['peak'] / G0:.5g} g, {spec['duration'] * 1e3:.4g} ms"
    else:
        ideal = cls.ideal
        against = f"fitted {cls.ideal.shape}" if cls.ideal else None
    if ideal is not None:
        band = shapes.band_check(t_mid, y, ideal)
        out["tolerance"] = {"against": against, "standard": "MIL-STD-810 Method 516 classical pulse (as read: "
                            "+/-20% of peak on the pulse, 20% outside, velocity change +/-10%)",
                            "ideal": ideal.as_dict(), **band.as_dict()}
        lower, upper, monitored = shapes.tolerance_band(ideal, t_mid)
        arrays.update(ideal=p.sign * ideal(t_mid), lower=p.sign * lower, upper=p.sign * upper,
                      monitored=monitored)
    band = shock.get("srs_frequencies") or pulse_band(p.duration, dt)
    f = log_frequencies(*band, shock["srs_points_per_octave"])
    s = shock_response_spectrum(a_raw, dt, f, shock["srs_q"])
    out["srs"] = {"q": s.q, "band": list(band),
                  "band_from": "the scene" if shock.get("srs_frequencies") else
                               f"the pulse ({p.duration:.3g} s: up to 10 / duration, down to 0.05 / duration)",
                  "frequency": s.frequency.tolist(), "maximax_g": (s.maximax / G0).tolist(),
                  "positive_g": (s.positive / G0).tolist(), "negative_g": (s.negative / G0).tolist(),
                  "peak_g": float(s.maximax.max() / G0),
                  "frequency_of_peak": float(s.frequency[np.argmax(s.maximax)]),
                  "input": "interval-mean acceleration, no filter"}
    arrays["srs"] = s
    return out, arrays


def describe_channel(name: str, m: dict) -> str:
    """One line for the run log."""
    p = m.get("pulse")
    if not p:
        return f"pulse on {name}: none ({'; '.join(m['notes'])})"
    line = (f"pulse on {name} ({m['filter']}): peak {p['peak_g']:.5g} g at {p['time_of_peak'] * 1e3:.4g} ms, "
            f"duration {p['duration'] * 1e3:.4g} ms (>10%), rise {p['rise_time'] * 1e3:.3g} ms, "
            f"velocity change {abs(p['velocity_change']):.5g} m/s (record {abs(m['velocity_change_record']):.5g}, "
            f"rigid body {abs(m['velocity_change_rigid_body']):.5g}); shape {m['shape']['classified']} "
            f"(misfit {min(m['shape']['misfits'].values()):.1%}")
    fitted = m["shape"]["fitted"]
    if fitted:
        line += f"; fitted {fitted['shape']} {fitted['peak'] / G0:.5g} g, {fitted['duration'] * 1e3:.4g} ms)"
    else:
        line += ")"
    tol = m.get("tolerance")
    if tol:
        line += (f"; tolerance band vs {tol['against']}: {'PASS' if tol['passed'] else 'FAIL'} "
                 f"(worst excess {tol['worst_excess']:.1%} of peak at {tol['time_of_worst'] * 1e3:.4g} ms, "
                 f"velocity change {tol['velocity_change_error']:+.1%})")
    return line


def shock_report(run_dir: str, cfc: int | None = None, plots: bool = True) -> tuple[dict, list[str]]:
    """Compute the shock metrics of a run directory, add them to its summary.json (key
    ``shock``) and draw the plots; returns the metrics and the lines for the run log.

    ``cfc`` overrides the scene's filter class (0: no filter, the scene's "none").
    """
    scene = _read(run_dir, "resolved_scene.json")
    summary = _read(run_dir, "summary.json")
    h = read_history_csv(os.path.join(run_dir, "history.csv"))
    shock = dict(scene["shock"])
    if cfc is not None:
        shock["cfc"] = cfc
    axisymmetric = scene["kinematics"] == "axisymmetric"
    labels = "rz" if axisymmetric else "xyz"[:3 if scene["kinematics"] == "3d" else 2]
    axis = shock["axis"] or labels[-1]
    translation = ("z",) if axisymmetric else tuple(labels)     # a body translates along these
    result: dict = {"axis": axis, "channels": {}, "stages": []}
    lines = []
    arrays = {}
    t = h["time"]
    if len(t) >= 3:
        for name, stem, body in channels(scene):
            m, arr = channel_metrics(t, h[f"{stem}.v_{axis}"], h[f"{body}.v_{axis}"], shock)
            result["channels"][name] = m
            arrays[name] = arr
            lines.append(describe_channel(name, m))
            lines += [f"  note: {n}" for n in m["notes"]]
    masses = {b: summary["bodies"][b]["mass"] for b in summary["bodies"]}
    contacts = [{"name": c["name"], "a": c["a"], "b": c["b"],
                 "wall_velocity": c["rigid"]["velocity"][labels.index(axis)] if c.get("rigid") else 0.0}
                for c in scene["contacts"]
                # an impact meets a plane or another body; a cylinder or a tunnel guides a body along the
                # axis, and its contact is no stage of a chain
                if not (c.get("rigid") and c["rigid"]["kind"] in ("cylinder", "tunnel"))]
    sustained = []
    stages = stage_table(h, masses, contacts, axis, translation, sustained) if len(t) >= 2 else []
    result["stages"] = [s.as_dict() for s in stages]
    result["sustained_contacts"] = [asdict(ev) for ev in sustained]
    for ev in sustained:
        lines.append(f"contact {ev.pair}: carried force from {ev.start * 1e6:.4g} to {ev.end * 1e6:.4g} us (peak "
                     f"{ev.peak_force:.4g} N) without the bodies closing: a sustained contact (resting, sliding, a "
                     "fit), not an impact stage")
    lines += [describe_stage(s) for s in result["stages"]]
    summary["shock"] = result
    write_json_atomic(os.path.join(run_dir, "summary.json"), summary)
    if plots:
        try:
            lines += _draw(run_dir, result, arrays)
        except Exception as e:          # the metrics are written: a figure that cannot be drawn costs only itself
            lines.append(f"WARNING: the shock metrics' figures were not drawn ({type(e).__name__}: {e})")
    return result, lines


# a stage's ratios in the run log: key, name, and the value's wording
STAGE_RATIOS = (("restitution", "restitution", "restitution {:.4f}"),
                ("velocity_ratio", "velocity ratio", "velocity ratio {:.4f}"),
                ("vibration_share", "vibration share", "{:.1%} of the launch energy in vibration"))


def not_applicable(stage: dict, key: str) -> str:
    """The wording of a stage's ratio that has no value (``Stage.as_dict`` left it out, with its reason)."""
    name = next(n for k, n, _ in STAGE_RATIOS if k == key)
    return f"{name} not applicable: {stage['not_measured'][key]}"


def describe_stage(stage: dict) -> str:
    """One line for the run log from a row of the stage table (``Stage.as_dict``): the velocities, then each
    ratio, or why it does not apply."""
    s = stage
    line = (f"stage {s['pair']}: {s['striker']} {s['striker_before']:.4g} -> {s['striker_after']:.4g} m/s, "
            f"{s['struck']} {s['struck_before']:.4g} -> {s['struck_after']:.4g} m/s over "
            f"{(s['end'] - s['start']) * 1e6:.4g} us")
    ratios = [wording.format(s[key]) if key in s else not_applicable(s, key) for key, _, wording in STAGE_RATIOS]
    return line + "; " + "; ".join(ratios)


def _draw(run_dir: str, result: dict, arrays: dict) -> list[str]:
    """The pulse and spectrum of each channel with a pulse, and the stages' velocity gain; returns the run
    log's lines for a figure that does not apply."""
    from ..output.plots import ChannelPlots, plot_stages
    drawn = [name for name in arrays if result["channels"][name].get("pulse")]
    if drawn:
        with ChannelPlots() as plots:
            for name in drawn:
                plots.pulse(os.path.join(run_dir, f"pulse_{name}.png"), name, arrays[name],
                            result["channels"][name])
                plots.srs(os.path.join(run_dir, f"srs_{name}.png"), name, arrays[name]["srs"])
    stages = result["stages"]
    if stages and plot_stages(os.path.join(run_dir, "stages.png"), stages) is None:
        return [f"stage figure not drawn: {not_applicable(stages[0], 'velocity_ratio')}"]
    return []

