"""The pads' finite-element runs (``shockfem/machine/pads.py``) and the amplifier's stages built on them
(``shockfem/machine/amplifier.py``), at smoke size: a three-mass chain small enough for polyurethane pads
to hold every limit of their closed-form sizing.  The run's own check of the pad, its peak contact force
over the pad's face against the working stress, reads 1.17 of it at the first interface (1.165 and 1.173
measured at smoke size; the ratio is the same at 2 m/s: the sizing scales the pad with the force): the
closed form under-estimates the peak force, and the pad is not resized on its run, so that one limit
breaks and the design is not feasible."""

FE_CONTACT = "stress (FE contact)"
import dataclasses
import json
import math

import pytest

from shockfem.amplifier.gain import cylinder_size
from shockfem.machine.amplifier import _amplifier, _chain_gain, _measure
from shockfem.machine.pads import RunCache
from shockfem.machine.spec import read_spec

RHO = 7850.0


@pytest.fixture(scope="module")
def chain(tmp_path_factory):
    spec = dataclasses.replace(read_spec({"article": "1 lb"}), launch_speed=3.0)
    masses = [8.0, 4.0, 2.0]
    bodies = [{"name": f"m{k + 1}", "shape": "cylinder", **cylinder_size(m, RHO, 1.0)} for k, m in enumerate(masses)]
    folder = str(tmp_path_factory.mktemp("pads"))
    cache = RunCache(folder)
    stages = _measure(spec, masses, bodies, 0.6, cache, "smoke", None)
    return spec, masses, bodies, stages, folder, cache


def test_small_chain_takes_polyurethane_inside_its_limits(chain):
    spec, masses, bodies, stages, _, cache = chain
    assert cache.misses == 2 and cache.hits == 0
    for st in stages:
        assert st.pad_kind == "elastomer" and st.measured, st
        sized = [lim for lim in st.limits if lim.quantity != FE_CONTACT]
        assert all(lim.holds for lim in sized), [lim.describe() for lim in sized if not lim.holds]
        # the run's check of the pad's stress: present, and 1.17 of the working stress at the first
        # interface (above); 1.4 bounds it from above, a stress lost from the run reads near 0
        contact = [lim.ratio for lim in st.limits if lim.quantity == FE_CONTACT]
        assert len(contact) == 1 and 0.5 < contact[0] < 1.4, contact
        quantities = {lim.quantity for lim in st.limits}
        assert {"stress", "strain", "stored energy per volume", "temperature rise a shot", "slenderness",
                "stress (FE, von Mises)"} <= quantities
        # light, compact pads between compact masses restitute about as rigid masses on the pad's
        # spring-dashpot (sqrt of the rebound resilience, 0.671 for 90A): the smoke meshes' runs (2 cells
        # through the 10 mm pads) measured 0.6981 and 0.6977, 4.0% above it; 10% allows the mesh
        # (``verify pad_rigid`` checks a pad at coarse size within 6%); a lost damping (e near 1) or a pad
        # that bottoms out (steel on steel) moves it by far more
        assert st.restitution == pytest.approx(math.sqrt(0.45), rel=0.10), st.restitution
    gain = _chain_gain(spec, masses, bodies, [st.restitution for st in stages])
    # a rigid three-mass chain of halving masses gains (1 + e_1) (1 + e_2) / 1.5^2 on its first pass, and
    # this one has no later collision (measured equal to 2e-8: the two restitutions are close, so their
    # mean's square differs from their product by (e_1 - e_2)^2 / 4, 1e-7)
    e = sum(st.restitution for st in stages) / 2
    assert gain == pytest.approx(((1 + e) / 1.5) ** 2, rel=1e-6)


def test_the_cache_answers_the_same_interface_again(chain):
    spec, masses, bodies, stages, folder, _ = chain
    cache = RunCache(folder)               # read back from pad_runs.json
    again = _measure(spec, masses, bodies, 0.6, cache, "smoke", None)
    assert cache.hits == 2 and cache.misses == 0
    assert [st.restitution for st in again] == [st.restitution for st in stages]
    assert [st.run for st in again] == [st.run for st in stages]


def test_the_amplifier_carries_every_stage_limit(chain):
    """``Amplifier.limits``: every stage's limits, in order, and the JSON of the design names each one's ratio."""
    spec, masses, bodies, stages, _, cache = chain
    gain = _chain_gain(spec, masses, bodies, [st.restitution for st in stages])
    amp = _amplifier(spec, (masses, bodies, stages, gain), 0.6, [], gain * spec.launch_speed, 690e6, cache, 0.0)
    assert amp.limits == [lim for st in stages for lim in st.limits]
    over = [lim for lim in amp.limits if not lim.holds]
    assert over and {lim.quantity for lim in over} == {FE_CONTACT}, [lim.describe() for lim in over]
    assert not amp.feasible
    raw = json.loads(json.dumps(amp.as_dict()))
    assert [lim["ratio"] for lim in raw["limits"]] == pytest.approx([lim.ratio for lim in amp.limits], rel=1e-12)
    assert raw["restitutions"] == [st.restitution for st in stages]
