"""Two MPI ranks (``mpirun -n 2``): what the ranks agree on in one reduction a step, and the field file the
last rank writes.

- A non-finite state or an inverted cell on one rank stops both, each with the diagnosis of the rank that
  holds the node or cell: the step's reductions say that some rank has one (a count of non-finite nodes in
  the step's sums, the highest inverted cell with the stable step), and the ranks then take that rank's
  words (``ExplicitSolver._stop_on_every_rank``).  Before, both ranks took the larger node or cell number
  and looked it up in their own arrays.
- The fields a two-rank run writes (gathered to the last rank, ``output/fields.py``) are the one-process
  run's: the same node positions, displacements and cell values, in the ranks' order.
"""
import os
import shutil
import subprocess
import sys
import textwrap

import meshio
import numpy as np
import pytest

from shockfem.scene.toml_writer import dumps
from shockfem.verify.contact_cases import two_rods_scene

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", SHOCKFEM_PICTURES="0")

FAULT_ON_RANK_ONE = textwrap.dedent("""
    import sys
    import numpy as np
    from mpi4py import MPI
    from shockfem.errors import UnstableRun
    from shockfem.geometry import build_mesh
    from shockfem.model import build_model
    from shockfem.scene.load import load_scene
    from shockfem.solver.explicit import ExplicitSolver

    scene = load_scene(sys.argv[1])
    solver = ExplicitSolver(build_model(scene, build_mesh(scene, MPI.COMM_WORLD, log=lambda *a: None)))
    m = solver.model
    said = ""
    if solver.comm.rank == 1:
        # the owned node farthest from every ghost: no other rank sees the NaN within a step
        ghosts = m.X0[m.num_owned:]
        owned = m.X0[:m.num_owned]
        far = np.min(np.linalg.norm(owned[:, None, :] - ghosts[None, :, :], axis=2), axis=1) if len(ghosts) else np.ones(len(owned))
        node = int(np.argmax(far))
        body = m.bodies[m.node_body[node]].name
        if sys.argv[3] == "nan":
            solver.v[node, 1] = np.nan
            said = f"body '{body}', node {node}"
        else:       # "invert": the node pushed 20 mm out and up, past the far corner of the cell beyond it
            solver.x[node] += 0.02
            said = f"body '{body}', element"
    try:
        for _ in solver.steps(scene.end_time):
            pass
        words = "completed"
    except UnstableRun as e:
        holder = solver.comm.bcast(said, root=1)
        words = f"stopped at step {solver.step}; holder's words: {holder in e.diagnosis}; {e.diagnosis}"
    with open(f"{sys.argv[2]}.{solver.comm.rank}", "w") as fh:     # a file a rank: mpirun interleaves stdout
        fh.write(f"rank {solver.comm.rank}: {words}")
""")


def _mpirun():
    mpirun = shutil.which("mpirun")
    assert mpirun, "mpirun not found (apt-get install openmpi-bin)"
    return mpirun


def _scene_file(tmp_path, end_time):
    raw = two_rods_scene(0.0025)
    raw["scene"]["end_time"] = end_time
    raw["outputs"].pop("field_interval")       # the default: a tenth of the run, 11 frames
    path = tmp_path / "two_rods.toml"
    path.write_text(dumps(raw))
    return path


@pytest.mark.parametrize("fault, words", [("nan", "not finite"), ("invert", "the element inverted")])
def test_a_fault_on_one_rank_stops_both_with_its_diagnosis(tmp_path, fault, words):
    """A NaN velocity, or a node pushed through its cells, on rank 1 only: both ranks stop at step 1 with
    rank 1's diagnosis (on the tree before, rank 0 looked rank 1's node or cell number up in its own arrays)."""
    scene = _scene_file(tmp_path, 5e-6)
    script = tmp_path / "fault_on_rank_one.py"
    script.write_text(FAULT_ON_RANK_ONE)
    said = tmp_path / "said"
    p = subprocess.run([_mpirun(), "-n", "2", sys.executable, str(script), str(scene), str(said), fault],
                       capture_output=True, text=True, env=ENV, timeout=600)
    assert p.returncode == 0, p.stderr[-3000:]
    lines = [(tmp_path / f"said.{rank}").read_text() for rank in range(2)]
    for rank, line in enumerate(lines):
        assert line.startswith(f"rank {rank}: stopped at step 1; holder's words: True;"), line
        assert words in line
    assert lines[0].split("; ", 2)[2] == lines[1].split("; ", 2)[2]      # the same words on both ranks


def _fields(out):
    reader = meshio.xdmf.TimeSeriesReader(str(out / "fields.xdmf"))
    points, cells = reader.read_points_cells()
    frames = [reader.read_data(k) for k in range(reader.num_steps)]
    return points, cells, frames


def test_two_ranks_write_the_one_process_fields(tmp_path):
    scene = _scene_file(tmp_path, 20e-6)
    exe = [sys.executable, "-m", "shockfem", "run", str(scene), "--no-progress"]
    for n, launcher in ((1, []), (2, [_mpirun(), "-n", "2"])):
        p = subprocess.run(launcher + exe + ["--out", str(tmp_path / f"np{n}")], capture_output=True, text=True,
                           env=ENV, timeout=600)
        assert p.returncode == 0, p.stderr[-3000:]
    p1, c1, f1 = _fields(tmp_path / "np1")
    p2, c2, f2 = _fields(tmp_path / "np2")
    assert len(p1) == len(p2) and len(f1) == len(f2) == 11
    # nodes matched by their reference position (unique), cells by their nodes' positions
    o1, o2 = np.lexsort(p1.T[::-1]), np.lexsort(p2.T[::-1])
    np.testing.assert_array_equal(p1[o1], p2[o2])
    cell_order = [np.lexsort(p[c[0].data].mean(axis=1).T[::-1]) for p, c in ((p1, c1), (p2, c2))]
    for (t1, nodal1, cell1), (t2, nodal2, cell2) in zip(f1, f2):
        assert t1 == t2
        for name in ("displacement", "velocity"):
            scale = max(np.abs(nodal1[name]).max(), 1e-30)
            # the sums of the two ranks' forces at shared nodes are added in another order: round-off
            assert np.abs(nodal1[name][o1] - nodal2[name][o2]).max() <= 1e-9 * scale, name
        for name in ("von_mises", "strain_zz", "stress_rz", "body"):
            a, b = cell1[name][0][cell_order[0]], cell2[name][0][cell_order[1]]
            assert np.abs(a - b).max() <= 1e-9 * max(np.abs(a).max(), 1e-30), name
