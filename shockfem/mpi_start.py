"""MPI's start for a process that no MPI launcher started (``shockfem run scene.toml``, a batch's case,
the Python API): Open MPI then makes the process a singleton, and by default probes its UCX transport and
keeps a daemon beside it for processes it might spawn, about 0.3 s of every run's start-up on this
machine (``python -c "from mpi4py import MPI"``: 0.38 s, 0.06 s without).  One process needs neither:
it talks to itself only.  ``start_mpi`` initialises MPI with Open MPI's singleton kept to itself
(``ess_singleton_isolated``, ``pml ob1``, ``btl self``), then takes those settings out of the
environment again, so that an ``mpirun`` this process starts (a batch's case on k ranks, a verification's
two-rank run) gets the transports it needs.  Under a launcher (``mpirun``, ``srun``) nothing is changed.
A setting the user gave in the environment is kept as given."""
from __future__ import annotations

import importlib
import os
import sys

SINGLETON = {"OMPI_MCA_ess_singleton_isolated": "1", "OMPI_MCA_pml": "ob1", "OMPI_MCA_btl": "self"}
# what Open MPI's mpirun, PMIx (srun) and MPICH's hydra set in the processes they start
LAUNCHED_BY = ("OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE")


def start_mpi():
    """Initialise MPI (``mpi4py.MPI``) for this process; a no-op if it is initialised already."""
    if "mpi4py.MPI" in sys.modules:
        return
    launched = any(name in os.environ for name in LAUNCHED_BY)
    added = {} if launched else {k: v for k, v in SINGLETON.items() if k not in os.environ}
    os.environ.update(added)
    try:
        importlib.import_module("mpi4py.MPI")       # mpi4py initialises MPI as it is imported
    finally:
        for name in added:
            os.environ.pop(name, None)
