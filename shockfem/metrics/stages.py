"""Contact events and the stage table of a chain of bodies.

A contact event is a time interval over which a contact pair carries normal force.  Faces
that chatter (touch, open for a moment, touch again) as two thick bodies part belong to one
event: gaps shorter than ``MERGE_GAP`` of the event so far are closed.

For each event the table gives both bodies' rigid-body velocities along the shock axis at
its start and after it (just before either body's next event, or at the end of the record), the momentum and kinetic energy the struck body gained, the
restitution e = -(v_a' - v_b') / (v_a - v_b), the struck body's velocity over the launch
speed, and the energy left in vibration: kinetic plus stored elastic energy, less the
kinetic energy of the bodies' mean motion (translation only: spin counts as vibration).
When every body starts at rest (the motion comes from a prescribed boundary or a load) there is
no launch speed or energy to divide by: those ratios are left out, with the reason
(``NOT_MEASURED``).
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

# force above this fraction of the pair's largest force counts as contact
FORCE_THRESHOLD = 1e-3
# a gap shorter than this fraction of the event before it joins the event
MERGE_GAP = 0.25
# an event is an impact stage only if its bodies close at more than this fraction of the fastest speed along
# the axis in the record; slower (a body resting or sliding on a surface, chatter, a fit from rest) it is a
# sustained contact: no restitution to speak of (the closing speed would divide it)
STAGE_APPROACH = 0.02
# a body "starts at rest" when its speed at the first sample is below this fraction of the fastest speed in the
# record: what a settled preload or round-off leaves (a true launch speed divides a velocity ratio of order 1-100;
# that residue would divide it into 1e6 and more)
AT_REST = 1e-6


@dataclass
class ContactEvent:
    pair: str
    start: float       # [s]
    end: float         # [s]
    peak_force: float  # [N]
    impulse: float     # integral of |F| dt [N s]


def contact_events(pair: str, t: np.ndarray, force: np.ndarray) -> list[ContactEvent]:
    """Events of one pair from its normal-force magnitude history ``force`` [N]."""
    t = np.asarray(t, dtype=float)
    force = np.asarray(force, dtype=float)
    if len(t) < 2 or not np.any(force > 0):
        return []
    on = force > FORCE_THRESHOLD * force.max()
    spans: list[list[int]] = []
    i = 0
    while i < len(on):
        if on[i]:
            j = i
            while j + 1 < len(on) and on[j + 1]:
                j += 1
            # from the last sample without force to the first sample without force again
            lo, hi = max(i - 1, 0), min(j + 1, len(t) - 1)
            if spans and t[lo] - t[spans[-1][1]] <= MERGE_GAP * (t[spans[-1][1]] - t[spans[-1][0]]):
                spans[-1][1] = hi
            else:
                spans.append([lo, hi])
            i = j + 1
        else:
            i += 1
    events = []
    for lo, hi in spans:
        sl = slice(lo, hi + 1)
        events.append(ContactEvent(pair, float(t[lo]), float(t[hi]), float(force[sl].max()),
                                   float(np.trapz(force[sl], t[sl]))))
    return events


@dataclass
class Stage:
    pair: str
    striker: str               # the body that lost kinetic energy
    struck: str                # the other body (or "wall")
    start: float               # [s]
    end: float
    striker_before: float      # velocities along the axis [m/s]
    striker_after: float
    struck_before: float
    struck_after: float
    momentum_transferred: float    # struck body's momentum change [N s]
    energy_transferred: float      # struck body's kinetic energy change [J]
    restitution: float
    velocity_ratio: float          # struck body's speed after / launch speed
    vibration_energy: float        # in all bodies at the end of the event [J]
    vibration_share: float         # of the kinetic energy at launch
    peak_force: float              # [N]

    def as_dict(self) -> dict:
        """Plain data; a ratio with no meaning is left out and named in ``not_measured`` with the reason
        (strict JSON has no NaN)."""
        out = asdict(self)
        absent = {k: NOT_MEASURED[k] for k, v in out.items() if isinstance(v, float) and not np.isfinite(v)}
        for k in absent:
            del out[k]
        if absent:
            out["not_measured"] = absent
        return out


# why a stage's ratio can have no value
NOT_MEASURED = {
    "restitution": "the bodies did not close (no approach speed to divide by)",
    "velocity_ratio": "every body starts at rest, so there is no launch speed to divide by (the motion comes "
                      "from a prescribed boundary or a load)",
    "vibration_share": "every body starts at rest, so there is no launch energy to divide by",
}


def vibration_energy(h: dict, bodies: dict[str, float], axes: tuple[str, ...]) -> np.ndarray:
    """Kinetic plus stored energy less the kinetic energy of every body's mean translation
    along ``axes`` [J], over the history ``h`` (columns of history.csv)."""
    rigid = sum(0.5 * m * sum(h[f"{b}.v_{ax}"] ** 2 for ax in axes) for b, m in bodies.items())
    return h["energy.kinetic"] + h["energy.internal"] - rigid


def stage_table(h: dict, bodies: dict[str, float], contacts: list[dict], axis: str,
                translation_axes: tuple[str, ...], sustained: list | None = None) -> list[Stage]:
    """The impact stages of a run, in time order; contact events whose bodies did not close at more than
    ``STAGE_APPROACH`` of the record's fastest speed are no stages, and go to ``sustained`` if given
    (``ContactEvent``s).

    Parameters
    ----------
    h : history columns (``read_history_csv``)
    bodies : body name -> mass [kg]
    contacts : ``{name, a, b, wall_velocity}`` with ``a``/``b`` body names (``b`` None for a
        rigid surface, whose velocity along the axis is ``wall_velocity``)
    axis : the shock axis ("z", "x"...)
    translation_axes : the axes along which a body translates as a whole (axisymmetric: z only)
    """
    t = h["time"]
    v = {b: h[f"{b}.v_{axis}"] for b in bodies}
    fastest = max((float(np.abs(x).max()) for x in v.values()), default=0.0)
    at_rest = AT_REST * fastest
    launch = max((abs(x[0]) for x in v.values()), default=0.0)
    launch = launch if launch > at_rest else 0.0
    e_launch = sum(0.5 * m * sum(h[f"{b}.v_{ax}"][0] ** 2 for ax in translation_axes) for b, m in bodies.items())
    e_launch = e_launch if e_launch > 0.5 * sum(bodies.values()) * at_rest ** 2 else 0.0
    vib = vibration_energy(h, bodies, translation_axes)
    events = []
    for c in contacts:
        cols = [k for k in h if k.startswith(f"contact.{c['name']}.normal_")]
        if cols:
            force = np.sqrt(sum(h[k] ** 2 for k in cols))
            events += [(ev, c) for ev in contact_events(c["name"], t, force)]
    events.sort(key=lambda e: e[0].start)
    stages = []
    for k, (ev, c) in enumerate(events):
        a, b = c["a"].split(".")[0], c["b"].split(".")[0] if c.get("b") else None
        # "after" is just before either body's next event (or the end of the record): the body
        # flies free in between, and force tails below the threshold have done their work
        later = [e.start for e, c2 in events[k + 1:] if {a, b} & {c2["a"].split(".")[0],
                                                                  (c2.get("b") or "").split(".")[0]}]
        i0 = int(np.searchsorted(t, ev.start))
        i1 = max(int(np.searchsorted(t, min(later), side="right")) - 1, int(np.searchsorted(t, ev.end))) \
            if later else len(t) - 1
        va0, va1 = float(v[a][i0]), float(v[a][i1])
        if b is None:
            vb0 = vb1 = float(c.get("wall_velocity", 0.0))
            striker, struck = a, "wall"
        else:
            vb0, vb1 = float(v[b][i0]), float(v[b][i1])
            # the striker loses kinetic energy in the collision
            a_loses = bodies[a] * (va1 ** 2 - va0 ** 2) <= bodies[b] * (vb1 ** 2 - vb0 ** 2)
            striker, struck = (a, b) if a_loses else (b, a)
            if not a_loses:
                va0, va1, vb0, vb1 = vb0, vb1, va0, va1
        m_struck = bodies.get(struck, 0.0)
        approach = va0 - vb0
        if not abs(approach) > STAGE_APPROACH * fastest:
            if sustained is not None:
                sustained.append(ev)
            continue
        i_end = int(np.searchsorted(t, ev.end))
        stages.append(Stage(
            ev.pair, striker, struck, ev.start, ev.end, va0, va1, vb0, vb1,
            m_struck * (vb1 - vb0), 0.5 * m_struck * (vb1 ** 2 - vb0 ** 2),
            -(va1 - vb1) / approach if approach else float("nan"),
            abs(vb1 if struck != "wall" else va1) / launch if launch else float("nan"),
            float(vib[i_end]), float(vib[i_end] / e_launch) if e_launch else float("nan"), ev.peak_force))
    return sorted(stages, key=lambda s: s.start)


def first_impacts(stages) -> dict[str, float]:
    """Each pair's restitution at its first impact between bodies, in time order (``stages``: the
    stage table's rows, as ``Stage`` or as dicts): later events of a pair are re-contacts of bodies
    already moving together, whose closing speed is too small for a meaningful ratio."""
    first: dict[str, float] = {}
    for st in stages:
        st = st if isinstance(st, dict) else asdict(st)
        if st["struck"] != "wall":
            first.setdefault(st["pair"], st["restitution"])
    return first
