"""What a contact pair's rank needs of the surface nodes other ranks own, and the exchanges of it.

Under MPI a pair's rank searches and responds for the slave nodes it owns (``pairs.ContactPair``).
Its slaves' master facets may hold nodes other ranks own: those nodes, and only those, come to it.
Every rank knows the surfaces' facets (global numbers, built once) but positions only of the nodes it
owns and of this halo:

- at each search (``find_near``): every rank's box around its slaves, widened by the search's reach and a
  facet size, goes to all (a few numbers a rank); each rank sends each other rank its own master nodes
  inside that rank's box, with their positions.  A facet whose centre is within reach of a slave has all
  its nodes within the widened box, so the receiver's search over the facets it then knows whole finds
  the candidates one process finds.  It then asks the owners for the nodes of its candidate facets
  (``ask_for``): these are the halo until the next search.
- each step (``update``): the halo's positions and velocities from their owners;
- after the springs (``spread``): each spring's record (``kernels.facet_springs``) goes to the ranks
  owning a node of its facet, so that every rank adds, to the nodes it owns, every spring that acts on
  them, in the pair's slave order: the order one process adds them in, so a node's force is the same
  sum, to the bit, on any number of ranks.

In one process none of this runs (the pair holds no halo).
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI

from . import kernels


def exchange_rows(comm, blocks: list[np.ndarray], width: int) -> list[np.ndarray]:
    """Send ``blocks[r]`` (rows of ``width`` doubles) to rank r; returns the rows each rank sent here, by
    rank.  Collective."""
    counts = np.array([len(b) for b in blocks], dtype=np.int64)
    incoming = np.empty_like(counts)
    comm.Alltoall(counts, incoming)
    send = np.concatenate([np.asarray(b, dtype=float).reshape(-1, width) for b in blocks]) if len(blocks) else \
        np.zeros((0, width))
    received = np.empty((int(incoming.sum()), width))
    comm.Alltoallv([send, (counts * width, _starts(counts) * width), MPI.DOUBLE],
                   [received, (incoming * width, _starts(incoming) * width), MPI.DOUBLE])
    return np.split(received, np.cumsum(incoming)[:-1])


def _starts(counts: np.ndarray) -> np.ndarray:
    return np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64)


class SurfaceHalo:
    """One rank's view of a pair's surface nodes (compact numbers) owned by other ranks."""

    def __init__(self, comm, owner: np.ndarray, gdim: int):
        self.comm = comm
        self.gdim = gdim
        self.rank = comm.rank
        self.owner = owner                              # (compact nodes,) the rank owning each
        self.mine = owner == comm.rank
        self.send = [np.zeros(0, dtype=np.int64) for _ in range(comm.size)]   # my nodes each rank asked for
        self.receive = np.zeros(0, dtype=np.int64)      # the halo, rank by rank as the owners send it
        self.receive_counts = np.zeros(comm.size, dtype=np.int64)
        self.sent = np.zeros(0, dtype=np.int64)

    def find_near(self, x: np.ndarray, boxes: list, masters: list[np.ndarray]) -> np.ndarray:
        """Before a search: ``boxes[p]`` is (lo, hi) around this rank's slaves of pass p, widened by the
        reach and a facet size (lo > hi: none); ``masters[p]`` the nodes of pass p's master facets.
        Each rank sends the others its own master nodes inside their boxes, with positions (into ``x``).
        Returns the mask of the nodes this rank knows now (its own and those received).  Collective."""
        gdim = x.shape[1]
        everyone = self.comm.allgather(boxes)
        blocks = []
        for r, their in enumerate(everyone):
            if r == self.rank:
                blocks.append(np.zeros((0, 1 + gdim)))
                continue
            inside = np.zeros(len(self.mine), dtype=bool)
            for (lo, hi), nodes in zip(their, masters):
                own = nodes[self.mine[nodes]]
                p = x[own]
                inside[own[np.all((p >= lo) & (p <= hi), axis=1)]] = True
            sent = np.flatnonzero(inside)
            blocks.append(np.column_stack([sent, x[sent]]))
        known = self.mine.copy()
        for rows in exchange_rows(self.comm, blocks, 1 + gdim):
            nodes = rows[:, 0].astype(np.int64)
            x[nodes] = rows[:, 1:]
            known[nodes] = True
        return known

    def ask_for(self, needed: np.ndarray):
        """After a search: the nodes of this rank's candidate facets that it does not own become its halo,
        asked of their owners, who send them each step until the next search.  Collective."""
        needed = needed[~self.mine[needed]]
        owners = self.owner[needed]
        blocks = [needed[owners == r][:, None] for r in range(self.comm.size)]
        self.receive = np.concatenate([b[:, 0] for b in blocks]).astype(np.int64)
        self.receive_counts = np.array([len(b) for b in blocks], dtype=np.int64)
        asked = exchange_rows(self.comm, blocks, 1)
        self.send = [a[:, 0].astype(np.int64) for a in asked]
        # each step's exchange, laid out once: what goes where, in which buffers (counts and offsets in
        # doubles: a node's row is its position and velocity)
        width = 2 * self.gdim
        self.sent = np.concatenate(self.send)
        counts = np.array([len(s) for s in self.send], dtype=np.int64)
        self.send_layout = np.array([counts * width, _starts(counts) * width])
        self.receive_layout = np.array([self.receive_counts * width, _starts(self.receive_counts) * width])
        self.send_buffer = np.empty((len(self.sent), width))
        self.receive_buffer = np.empty((len(self.receive), width))

    def update(self, x: np.ndarray, v: np.ndarray):
        """The halo's positions and velocities from their owners (this rank's own are in place).
        Collective."""
        kernels.pack_rows(x, v, self.sent, self.send_buffer)
        self.comm.Alltoallv([self.send_buffer, tuple(self.send_layout), MPI.DOUBLE],
                            [self.receive_buffer, tuple(self.receive_layout), MPI.DOUBLE])
        kernels.unpack_rows(self.receive_buffer, self.receive, x, v)

    def spread(self, records: np.ndarray, nf: int) -> np.ndarray:
        """This rank's spring records to the ranks owning a node of their facets; returns the records that
        act on this rank's nodes (its own and those received), in key order.  Collective."""
        width = records.shape[1]
        out, counts = kernels.records_by_rank(records, self.owner, nf, self.rank, self.comm.size)
        incoming = np.empty_like(counts)
        self.comm.Alltoall(counts, incoming)
        held = np.empty((len(records) + int(incoming.sum()), width))
        held[:len(records)] = records
        self.comm.Alltoallv([out, (counts * width, _starts(counts) * width), MPI.DOUBLE],
                            [held[len(records):], (incoming * width, _starts(incoming) * width), MPI.DOUBLE])
        return held[np.argsort(held[:, kernels.R_KEY], kind="stable")]
