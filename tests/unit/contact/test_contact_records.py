"""A contact pass split between ranks adds the same forces, to the bit, as one process (docs/theory.md,
contact under MPI): each rank writes its own slaves' springs as records, sends each record to the
owners of its facet's nodes (``kernels.records_by_rank``) and adds the records it holds in slave order
to its own nodes (``kernels.add_springs``).  The exchange itself is done here by hand, in one process;
``shockfem verify contact_parallel`` runs it under mpirun."""
import numpy as np

from shockfem.contact import kernels


def _surfaces(seed):
    """A 4 x 4 grid of bilinear facets at z = 0 (outward normal +z) and 30 slave nodes just below it,
    some pressing in (up to 0.2 mm), sliding and closing; nodes numbered facets' first."""
    rng = np.random.default_rng(seed)
    grid = np.array([[i, j, 0.0] for j in range(5) for i in range(5)], dtype=float) * [0.01, 0.01, 1.0]
    grid[:, 2] += rng.uniform(-1e-5, 1e-5, len(grid))
    facets = np.array([[j * 5 + i, j * 5 + i + 1, (j + 1) * 5 + i + 1, (j + 1) * 5 + i]
                       for j in range(4) for i in range(4)], dtype=np.int64)
    slaves_x = np.column_stack([rng.uniform(0.0, 0.04, 30), rng.uniform(0.0, 0.04, 30),
                                rng.uniform(-2e-4, 5e-5, 30)])
    x = np.vstack([grid, slaves_x])
    v = np.vstack([np.zeros_like(grid), np.column_stack([rng.uniform(-1, 1, (30, 2)), rng.uniform(-5, 0, 30)])])
    slaves = np.arange(len(grid), len(x), dtype=np.int64)
    mass = rng.uniform(0.5, 2.0, len(x))
    return x, v, mass, slaves, facets


def _one_process(x, v, mass, slaves, facets, stiffness, friction, dt):
    f, ff, stiff = np.zeros_like(x), np.zeros_like(x), np.zeros(len(x))
    ft, gap, offset = np.zeros((len(slaves), 3)), np.zeros(len(slaves)), np.zeros(len(slaves))
    cand_ptr = np.arange(len(slaves) + 1, dtype=np.int64) * len(facets)     # every facet a candidate
    cand_seg = np.tile(np.arange(len(facets), dtype=np.int64), len(slaves))
    active = kernels.node_to_facets(slaves, facets, stiffness, cand_ptr, cand_seg, x, v, mass, 0.1, 0.0, dt, 1e-3,
                                    friction, f, ff, ft, gap, offset, stiff)
    return f, ff, stiff, ft, active


def _two_ranks(x, v, mass, slaves, facets, stiffness, friction, dt, owner):
    """The same pass with the nodes owned by two ranks (``owner``), each rank's slaves on that rank."""
    nf = facets.shape[1]
    cand_ptr = np.arange(len(slaves) + 1, dtype=np.int64) * len(facets)
    cand_seg = np.tile(np.arange(len(facets), dtype=np.int64), len(slaves))
    ft, gap, offset = np.zeros((len(slaves), 3)), np.zeros(len(slaves)), np.zeros(len(slaves))
    best, best_g = np.full(len(slaves), -1, dtype=np.int64), np.zeros(len(slaves))
    records, active = [], 0
    for rank in (0, 1):
        rows = np.flatnonzero(owner[slaves] == rank)
        kernels.closest_facets(slaves, rows, facets, kernels.candidate_facets(cand_seg), cand_ptr, cand_seg, x, 1e-3,
                               best, best_g)
        mine = np.zeros((len(rows), kernels.record_width(nf)))
        n, count = kernels.facet_springs(slaves, rows, facets, stiffness, best, best_g, x, v, mass, 0.1, 0.0, dt,
                                         friction, ft, gap, offset, 0, mine)
        records.append(mine[:count])
        active += n
    f, ff, stiff = np.zeros_like(x), np.zeros_like(x), np.zeros(len(x))
    for rank in (0, 1):
        other = 1 - rank
        sent, counts = kernels.records_by_rank(records[other], owner, nf, other, 2)
        received = sent[counts[:rank].sum():counts[:rank + 1].sum()]
        held = np.concatenate([records[rank], received])
        held = held[np.argsort(held[:, kernels.R_KEY], kind="stable")]
        f_r, ff_r, stiff_r = np.zeros_like(x), np.zeros_like(x), np.zeros(len(x))
        kernels.add_springs(held, owner == rank, nf, True, f_r, ff_r, stiff_r)
        own = owner == rank
        f[own], ff[own], stiff[own] = f_r[own], ff_r[own], stiff_r[own]
    return f, ff, stiff, ft, active, records


def test_two_ranks_add_the_one_process_forces_to_the_bit():
    x, v, mass, slaves, facets = _surfaces(3)
    stiffness = np.full(len(facets), 1e8)
    friction = np.array([0.3, 0.2, 0.5])
    reference = _one_process(x, v, mass, slaves, facets, stiffness, friction, 1e-7)
    assert reference[4] >= 10 and np.abs(reference[1]).max() > 0    # springs act, friction too
    owner = np.random.default_rng(7).integers(0, 2, len(x))
    split = _two_ranks(x, v, mass, slaves, facets, stiffness, friction, 1e-7, owner)
    for a, b in zip(reference[:4], split[:4]):
        np.testing.assert_array_equal(a, b)
    assert split[4] == reference[4]
    # the case the record order is for: master nodes that springs of both ranks' slaves lean on
    nf = facets.shape[1]
    leaned_on = [set(r[:, kernels.R_MASTER:kernels.R_MASTER + nf][r[:, kernels.R_MASTER + nf:] > 0].astype(int))
                 for r in split[5]]
    assert leaned_on[0] & leaned_on[1]
