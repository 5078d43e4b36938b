"""The [shock] table: the accelerometers, the pulse specification and the filters of a run's
shock metrics."""
from __future__ import annotations

from .checker import Checker
from .specs import Accelerometer, CFC_CLASSES, PULSE_SHAPES, PulseSpec, Shock


def read_shock(ck: Checker, raw: dict, body_regions: dict, kin: str, end_time: float) -> Shock:
    """``[shock]``: test articles, axis, CFC class, SRS settings, accelerometers, pulse spec."""
    if "shock" not in raw:
        return Shock()
    d = ck.table(raw, "shock", "shock")
    ck.unknown(d, ("test_articles", "axis", "cfc", "srs_q", "srs_frequencies", "srs_points_per_octave",
                   "accelerometers", "spec"), "shock")
    gdim = 3 if kin == "3d" else 2
    axes = "rz" if kin == "axisymmetric" else "xyz"[:gdim]
    articles = d.get("test_articles", [])
    if not isinstance(articles, list) or not all(isinstance(a, str) for a in articles):
        ck.fail("shock.test_articles", f"must be a list of body names, got {articles!r}")
        articles = []
    for j, a in enumerate(articles):
        if a not in body_regions:
            ck.fail(f"shock.test_articles[{j}]", f"unknown body {a!r} (bodies: {', '.join(body_regions)})")
    axis = d.get("axis", axes[-1])
    if axis not in axes or (kin == "axisymmetric" and axis != "z"):
        allowed = "z (the axis of symmetry)" if kin == "axisymmetric" else ", ".join(axes)
        ck.fail("shock.axis", f"must be one of {allowed}, got {axis!r}")
        axis = axes[-1]
    cfc = d.get("cfc", 1000)
    if cfc == "none":
        cfc = 0
    if cfc not in CFC_CLASSES and cfc != 0:
        ck.fail("shock.cfc", f"must be a channel frequency class {', '.join(map(str, CFC_CLASSES))} "
                             f"(SAE J211) or 'none', got {cfc!r}")
        cfc = 1000
    q = ck.quantity(d, "srs_q", "shock", "dimensionless", default=10.0, positive=True)
    band = None            # the metrics take it from the pulse (metrics/srs.pulse_band)
    if "srs_frequencies" in d:
        pair = d["srs_frequencies"]
        if not isinstance(pair, list) or len(pair) != 2:
            ck.fail("shock.srs_frequencies", f"must be [lowest, highest], e.g. ['10 Hz', '10 kHz'], got {pair!r}")
        else:
            lo = ck.quantity({"srs_frequencies[0]": pair[0]}, "srs_frequencies[0]", "shock", "frequency",
                             positive=True)
            hi = ck.quantity({"srs_frequencies[1]": pair[1]}, "srs_frequencies[1]", "shock", "frequency",
                             positive=True)
            if not lo < hi:
                ck.fail("shock.srs_frequencies", f"the lowest frequency must be below the highest, got {pair!r}")
            band = (lo, hi)
    ppo = d.get("srs_points_per_octave", 12)
    if not isinstance(ppo, int) or isinstance(ppo, bool) or ppo < 1:
        ck.fail("shock.srs_points_per_octave", f"must be a whole number >= 1, got {ppo!r}")
        ppo = 12
    meters = []
    names = set()
    fields = ("name", "body", "at", "section")
    for path, m in ck.entries(d, "accelerometers", "shock.accelerometers", fields):
        ck.unknown(m, fields, path)
        name = m.get("name")
        if not isinstance(name, str) or not name.isidentifier() or name in names:
            ck.fail(f"{path}.name", f"needs a unique name made of letters, digits and _, got {name!r}")
            name = f"accelerometer{len(meters)}"
        names.add(name)
        body = m.get("body")
        if body not in body_regions:
            ck.fail(f"{path}.body", f"unknown body {body!r} (bodies: {', '.join(body_regions)})")
        if "at" not in m:
            ck.fail(f"{path}.at", f"missing (the point, {gdim} coordinates with units)")
        at = ck.vector(m, "at", path, "length", gdim, [0.0] * gdim)
        section = ck.quantity(m, "section", path, "length", default=0.0, positive="section" in m)
        meters.append(Accelerometer(name, str(body), at, section))
    spec = None
    if "spec" in d:
        sp = ck.table(d, "spec", "shock.spec")
        ck.unknown(sp, ("shape", "peak", "duration"), "shock.spec")
        shape = ck.choice(sp, "shape", "shock.spec", PULSE_SHAPES)
        peak = ck.quantity(sp, "peak", "shock.spec", "acceleration", positive=True)
        duration = ck.quantity(sp, "duration", "shock.spec", "time", positive=True)
        spec = PulseSpec(shape, peak, duration)
        if not articles and not meters:
            ck.fail("shock.spec", "a pulse spec needs a test article or an accelerometer to check")
    return Shock(tuple(articles), axis, int(cfc), q, tuple(band) if band else None, ppo, tuple(meters), spec)
