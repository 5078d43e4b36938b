"""Compile numba's kernels into its cache before the suite's workers start (``conftest.pytest_sessionstart``).

On a clean checkout numba's cache is empty, and the suite's first tests start several processes at once (a
study and its cases, two MPI ranks, the two workers themselves) that would each compile the same kernels:
about 95 s of one core for the first plastic run's alone.  Two processes of this script (one per group,
one per core) compile them once, each scene run for a few steps through ``run_scene`` (histories, fields
and metrics as a test's run); later processes load them from the cache.

    python tests/warm_kernels.py axisymmetric|3d
"""
import os
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPS_S = 2e-6           # a few steps of each scene: enough to call every kernel it has

# what the suite's long first tests and most others run: quads (elastic, J2, foam, rubber), triangles,
# contact with friction, cavities, springs and the penetration target; hexes and tetrahedra in 3D
GROUPS = {
    "axisymmetric": ["foundation/bar_impact.toml", "metrics/rod_pulse.toml", "gallery/dashpot.toml",
                     "gallery/foam_pad.toml", "gallery/rubber_pad.toml", "gallery/split_cone.toml",
                     "gallery/penetration.toml", "gallery/projectile_payload.toml", "gallery/shrink_fit.toml"],
    "3d": ["gallery/tilted_drop.toml", "taylor_3d", "two_rods_3d", "tet_rod"],
}


def _scene(name: str) -> dict:
    from shockfem.scene import read_toml
    from shockfem.verify.contact_cases import two_rods_scene
    from shockfem.verify.plasticity_cases import taylor_scene
    from shockfem.verify.scenes import rod_scene
    if name == "taylor_3d":
        return taylor_scene(0.0016, kinematics="3d", end_time=STEPS_S)
    if name == "two_rods_3d":
        return two_rods_scene(0.005, "3d")
    if name == "tet_rod":
        return rod_scene("tet_rod", "3d", element="tet", h=0.004, velocity=-5.0)
    return read_toml(os.path.join(REPO, "studies", name))


def _warm_halo_kernels():
    """The kernels only a contact pair under MPI calls (``contact/halo.py``), with the types it calls them
    with, so that two ranks do not compile them at once."""
    import numpy as np
    from shockfem.contact import kernels
    x, nodes = np.zeros((2, 3)), np.arange(2, dtype=np.int64)
    rows = np.zeros((2, 6))
    kernels.pack_rows(x, x, nodes, rows)
    kernels.unpack_rows(rows, nodes, x, x)
    kernels.records_by_rank(np.zeros((1, kernels.record_width(4))), np.zeros(2, dtype=np.int64), 4, 0, 2)


def main(group: str) -> int:
    from shockfem.runner import run_scene
    from shockfem.scene import resolve
    if group == "3d":
        _warm_halo_kernels()
    with tempfile.TemporaryDirectory() as out:
        os.environ.setdefault("SHOCKFEM_MESH_CACHE", os.path.join(out, "meshes"))
        for k, name in enumerate(GROUPS[group]):
            raw = _scene(name)
            raw["scene"]["end_time"] = STEPS_S
            run_scene(resolve(raw), os.path.join(out, str(k)), progress=False, quiet=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
