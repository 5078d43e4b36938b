"""The one-point passes in lanes (quads and hexes): their two copies, the blocks, the material update,
an inverted cell.

Provenance: both copies compute every cell's elastic trial in lanes
(``materials.update.elastic_update_stress``); the general copy runs ``update_stress`` cell by cell for the
rows whose trial is not the answer (``materials.update.elastic_trial_holds``).  The reference here is a
general copy whose rows all take that cell-by-cell path (J2 rows with kinematic hardening, which the lanes
never accept, and a yield stress no cell reaches): the same arithmetic as the elastic lanes, only the
compiler's order of operations may differ (fastmath), so every output must agree to round-off: 1e-13 of
its largest entry (the differences seen are below 1e-15).  Against scalar cell-by-cell kernels of the
same formulas both copies agreed to 4.7e-16 (quads) and 1.6e-15 (hexes) on 50k and 1k shuffled cells.
The forces themselves are checked against the one-point UFL form in ``test_one_point.py``.
"""
import numpy as np
import pytest

from shockfem.elements import blocks, cells as cells_module, kernels, one_point, one_point_hexes, one_point_quads
from shockfem.materials import layout
from shockfem.output.cell_fields import von_mises

from element_helpers import NO_CURVES, NO_STATE, run_pass, steel_params

STIFFNESS, VISCOUS = one_point.HOURGLASS_FORMS["stiffness"], one_point.HOURGLASS_FORMS["viscous"]


def _grid(shape, seed=3):
    """A perturbed grid of quads (2 numbers in ``shape``) or hexes (3) in tensor vertex order, r >= 1 mm."""
    rng = np.random.default_rng(seed)
    axes = [np.linspace(0.001, 0.05, shape[0] + 1)] + [np.linspace(0.0, 0.08, n + 1) for n in shape[1:]]
    x = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, len(shape))
    x += rng.normal(size=x.shape) * 3e-4
    index = np.arange(len(x)).reshape([n + 1 for n in shape])
    corners = [(a & 1, (a >> 1) & 1, (a >> 2) & 1)[:len(shape)] for a in range(2 ** len(shape))]
    cells = np.stack([index[tuple(slice(c, c + n) for c, n in zip(corner, shape))].ravel() for corner in corners], 1)
    return x, np.ascontiguousarray(cells, dtype=np.int32)


def _params():
    """Two elastic rows, the second damped, both with bulk viscosity."""
    p = np.vstack([steel_params(), steel_params(E=70e9, rho=2700.0, beta=2e-8)])
    p[:, layout.P_Q_QUADRATIC], p[:, layout.P_Q_LINEAR] = 1.5, 0.06
    return p


def _j2(yield_stress, kinematic):
    """``_params``' rows made J2 with a flat yield stress [Pa] and a kinematic modulus [Pa]; their curves."""
    p = _params()
    p[:, layout.P_LAW] = layout.J2
    p[:, layout.P_KINEMATIC] = kinematic
    p[:, layout.P_CURVE_POINTS] = 1
    curves = np.zeros((2, 1, 2))
    curves[:, 0, 1] = yield_stress
    return p, curves


def _run(elastic_only, x, dofmap, cells, v, form, axisymmetric=True, sign=None, material=None, rows=None):
    """One pass; ``material`` = (params, curves) of J2 rows (with a fresh state), else ``_params``' elastic ones;
    ``rows`` = (elastic params, each cell's row) instead of ``_params`` and every third cell on row 0."""
    n, gdim = len(dofmap), x.shape[1]
    rng = np.random.default_rng(5)
    sigma = rng.normal(size=(n, 1, 6)) * 1e7
    if gdim == 2:
        sigma[..., 3:5] = 0.0
    hourglass = rng.normal(size=(n, 2 if gdim == 2 else 12)) * 10.0
    f = np.zeros_like(x)
    materials = (np.arange(n) % 3 == 0).astype(np.int32)
    params, curves, state = _params(), NO_CURVES, NO_STATE
    if rows is not None:
        params, materials = rows
    body_energy = np.zeros((len(params), 3))
    sign = np.ones(n) if sign is None else sign
    kernel = kernels.element_pass(cells_module.QUADRILATERAL if gdim == 2 else cells_module.HEXAHEDRON, True,
                                  elastic_only)
    kinematics = (cells_module.AXISYMMETRIC if axisymmetric else cells_module.PLANE_STRAIN) if gdim == 2 else \
        cells_module.THREE_D
    if material is not None:
        (params, curves), state = material, np.zeros((n, 1, layout.STATE_SIZE))
    out = run_pass(kernel, cells, dofmap, materials, sign, x, v, 2e-7, params, curves, state, sigma, f, body_energy,
                   kinematics=kinematics, thickness=0.7, hourglass=hourglass, hourglass_form=form,
                   hourglass_coefficient=0.1)
    return out, {"f": f, "sigma": sigma, "hourglass": hourglass, "body_energy": body_energy, "state": state}


CASES = [((9, 7), True), ((9, 7), False), ((4, 3, 5), None)]     # quads axisymmetric, plane strain; hexes


@pytest.mark.parametrize("shape, axisymmetric", CASES)
@pytest.mark.parametrize("form", [STIFFNESS, VISCOUS])
def test_elastic_lanes_agree_with_the_update_cell_by_cell(shape, axisymmetric, form):
    """Shuffled cells (full blocks of LANES and a partial one), velocities that compress some cells and
    stretch others, two rows: every output to round-off, the critical cell exactly."""
    x, dofmap = _grid(shape)
    lanes = (one_point_quads if len(shape) == 2 else one_point_hexes).LANES
    assert len(dofmap) % lanes != 0 and len(dofmap) > lanes
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    # the reference: every cell through update_stress (kinematic hardening), none yielding
    ref_out, ref = _run(False, x, dofmap, cells, v, form, axisymmetric, material=_j2(1e12, 1e9))
    out, got = _run(True, x, dofmap, cells, v, form, axisymmetric)
    assert ref_out[4] == 0.0 and not ref["state"].any()
    del ref["state"], got["state"]
    for name in ref:
        assert np.abs(got[name] - ref[name]).max() <= 1e-13 * np.abs(ref[name]).max(), name
    dt_stable, critical, damping, viscosity, plastic, hourglass_power, bad = out
    assert critical == ref_out[1] and bad == ref_out[6] == -1 and plastic == 0.0
    assert viscosity > 0.0 and damping > 0.0           # both viscous terms ran
    for a, b in zip((dt_stable, damping, viscosity, hourglass_power),
                    (ref_out[0], ref_out[2], ref_out[3], ref_out[5])):
        assert abs(a - b) <= 1e-13 * abs(b)


@pytest.mark.parametrize("shape, axisymmetric", CASES)
def test_a_block_of_one_row_takes_that_rows_constants(shape, axisymmetric):
    """A block whose cells share a row fills the row's constants once (``one_point.block_constants``); a
    mixed block gathers them cell by cell.  Rows 1 and 2 the same damped aluminium, row 0 steel: every
    cell on row 1 (one-row blocks) against cells alternating between rows 1 and 2 (mixed blocks) gives
    the same forces, stresses, resultants, step and powers to the bit; a fill from any other row (steel)
    or in another order (the constants are 7 different numbers) would not."""
    x, dofmap = _grid(shape)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    cells = np.arange(len(dofmap), dtype=np.int32)
    p = _params()
    params = np.ascontiguousarray(np.vstack([p[0], p[1], p[1]]))
    one_row = np.ones(len(dofmap), dtype=np.int32)
    mixed = (1 + np.arange(len(dofmap)) % 2).astype(np.int32)
    for elastic_only in (True, False):
        out, got = _run(elastic_only, x, dofmap, cells, v, STIFFNESS, axisymmetric, rows=(params, one_row))
        ref_out, ref = _run(elastic_only, x, dofmap, cells, v, STIFFNESS, axisymmetric, rows=(params, mixed))
        for name in ("f", "sigma", "hourglass"):
            assert np.array_equal(got[name], ref[name]), name
        assert out == ref_out
        assert out[2] > 0.0          # the damped row's constants ran (steel's beta is 0)


@pytest.mark.parametrize("shape", [(9, 7), (4, 3, 5)])
@pytest.mark.parametrize("elastic_only", [True, False])
def test_an_inverted_cell_is_reported(shape, elastic_only):
    """A cell of negative volume (its orientation flipped) is reported by both copies."""
    x, dofmap = _grid(shape)
    cells = np.arange(len(dofmap), dtype=np.int32)
    sign = np.ones(len(dofmap))
    sign[40] = -1.0
    out, _ = _run(elastic_only, x, dofmap, cells, np.zeros_like(x), STIFFNESS, sign=sign)
    assert out[6] == 40


@pytest.mark.parametrize("shape, axisymmetric", CASES)
def test_points_inside_the_yield_surface_take_the_lanes_trial(shape, axisymmetric):
    """J2 rows without kinematic hardening, a yield stress (50 MPa) that some cells' trial stress exceeds
    and others' does not: the general copy takes the lanes' trial for the latter
    (``elastic_trial_holds``) and returns the former cell by cell.  The reference runs every cell through
    ``update_stress`` (a kinematic modulus of 1e-30 Pa, which the lanes never accept and which changes
    the return by round-off): every output to 1e-12 of its largest entry (the stresses that yield by a
    few per cent are returned by the same law)."""
    x, dofmap = _grid(shape)
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    ref_out, ref = _run(False, x, dofmap, cells, v, STIFFNESS, axisymmetric, material=_j2(5e7, 1e-30))
    out, got = _run(False, x, dofmap, cells, v, STIFFNESS, axisymmetric, material=_j2(5e7, 0.0))
    yielded = ref["state"][:, 0, layout.S_EPS] > 0.0
    assert 0.1 < yielded.mean() < 0.9              # both paths ran
    np.testing.assert_array_equal(got["state"][:, 0, layout.S_EPS] > 0.0, yielded)
    for name in ref:
        scale = np.abs(ref[name]).max()
        assert np.abs(got[name] - ref[name]).max() <= 1e-12 * scale, name
    assert out[4] == pytest.approx(ref_out[4], rel=1e-12) and out[4] > 0.0


def _linear_j2(yield_stress, tangent_modulus):
    """Two identical J2 rows (steel's elastic constants, bulk viscosity) of linear hardening: a one-point
    curve (perfectly plastic) without a tangent modulus, a two-point one with it; their curves."""
    p = np.vstack([steel_params(), steel_params()])
    p[:, layout.P_Q_QUADRATIC], p[:, layout.P_Q_LINEAR] = 1.5, 0.06
    p[:, layout.P_LAW] = layout.J2
    p[:, layout.P_CURVE_POINTS] = 2 if tangent_modulus else 1
    curves = np.zeros((2, 2, 2))
    curves[:, 0] = 0.0, yield_stress
    curves[:, 1] = 1.0, yield_stress + tangent_modulus
    return p, curves


@pytest.mark.parametrize("shape, axisymmetric", CASES)
@pytest.mark.parametrize("tangent_modulus", [0.0, 2e9])
def test_a_j2_row_of_linear_hardening_returns_in_lanes(shape, axisymmetric, tangent_modulus):
    """A block of one J2 row of linear hardening returns every cell in lanes
    (``materials.j2.linear_hardening_return``); a mixed block returns cell by cell (``update_from_trial``:
    ``radial_return``'s Newton, which takes the same step).  Every cell on row 0 against cells alternating
    between rows 0 and 1, the same material, with a yield stress that some cells' trial exceeds and
    others' does not (150 MPa for these quads, 50 MPa for the hexes): the same cells yield, and every
    output (forces, stresses, resultants, plastic strain and its rate, energies) agrees to 1e-12 of its
    largest entry (the compiler orders the two differently).  A lane return with the hardening slope left
    out of 3 mu + H fails it."""
    x, dofmap = _grid(shape)
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    material = _linear_j2(1.5e8 if len(shape) == 2 else 5e7, tangent_modulus)
    one_row = np.zeros(len(dofmap), dtype=np.int32)
    mixed = (np.arange(len(dofmap)) % 2).astype(np.int32)
    out, got = _run(False, x, dofmap, cells, v, STIFFNESS, axisymmetric, material=material,
                    rows=(material[0], one_row))
    ref_out, ref = _run(False, x, dofmap, cells, v, STIFFNESS, axisymmetric, material=material,
                        rows=(material[0], mixed))
    yielded = ref["state"][:, 0, layout.S_EPS] > 0.0
    assert 0.1 < yielded.mean() < 0.9              # both branches of the return ran
    np.testing.assert_array_equal(got["state"][:, 0, layout.S_EPS] > 0.0, yielded)
    got["body_energy"] = got["body_energy"].sum(axis=0)    # by row: row 0 only against rows 0 and 1
    ref["body_energy"] = ref["body_energy"].sum(axis=0)
    for name in ref:
        scale = np.abs(ref[name]).max()
        assert np.abs(got[name] - ref[name]).max() <= 1e-12 * scale, name
    assert out[4] == pytest.approx(ref_out[4], rel=1e-12) and out[4] > 0.0


def _von_mises2(sigma):
    """The squared von Mises stress of each point of ``sigma`` (cells, points, 6), in numpy
    (``output.cell_fields.von_mises``, squared)."""
    return von_mises(sigma) ** 2


@pytest.mark.parametrize("shape, axisymmetric", CASES)
@pytest.mark.parametrize("elastic_only", [True, False])
def test_each_row_keeps_its_peak_stress_with_when_and_where(shape, axisymmetric, elastic_only):
    """Shuffled cells on two rows (every third cell on row 1): after a pass each row's peak is the largest
    squared von Mises stress of its cells' new stresses (to 1e-12: the lanes' formula, in another order), at
    the pass's time, in the first cell of ``cells`` that holds it (exactly); a second pass whose stresses
    stay below it (no motion: the stresses do not change, ``elastic_update_stress`` adds zero) keeps the
    peak, when and where; a higher one (the stresses doubled) moves them."""
    x, dofmap = _grid(shape)
    n, gdim = len(dofmap), x.shape[1]
    cells = np.random.default_rng(7).permutation(n).astype(np.int32)
    rows = (np.arange(n) % 3 == 0).astype(np.int32)
    params = _params()
    kernel = kernels.element_pass(cells_module.QUADRILATERAL if gdim == 2 else cells_module.HEXAHEDRON, True,
                                  elastic_only)
    kinematics = (cells_module.AXISYMMETRIC if axisymmetric else cells_module.PLANE_STRAIN) if gdim == 2 else \
        cells_module.THREE_D
    sigma = np.random.default_rng(5).normal(size=(n, 1, 6)) * 1e7
    if gdim == 2:
        sigma[..., 3:5] = 0.0
    hourglass = np.zeros((n, 2 if gdim == 2 else 12))
    peak = blocks.no_peak(len(params))

    def step(v, t):
        run_pass(kernel, cells, dofmap, rows, np.ones(n), x, v, 2e-7, params, NO_CURVES, NO_STATE, sigma,
                 np.zeros_like(x), np.zeros((len(params), 3)), kinematics=kinematics, thickness=0.7,
                 hourglass=hourglass, t_np1=t, peak=peak)

    def expected(t):
        vm2 = _von_mises2(sigma)[:, 0]
        out = []
        for r in range(len(params)):
            mine = cells[rows[cells] == r]
            out.append((vm2[mine].max(), t, mine[np.argmax(vm2[mine])]))
        return np.array(out)

    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    step(v, 1e-6)
    first = expected(1e-6)
    np.testing.assert_allclose(peak[:, blocks.PEAK_VM2], first[:, 0], rtol=1e-12)
    np.testing.assert_array_equal(peak[:, 1:], first[:, 1:])
    kept = peak.copy()
    step(np.zeros_like(x), 2e-6)
    np.testing.assert_array_equal(peak, kept)
    sigma *= 2.0
    step(np.zeros_like(x), 3e-6)
    np.testing.assert_allclose(peak[:, blocks.PEAK_VM2], 4.0 * first[:, 0], rtol=1e-12)
    np.testing.assert_array_equal(peak[:, 1:], expected(3e-6)[:, 1:])
