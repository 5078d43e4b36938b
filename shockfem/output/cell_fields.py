"""What a cell field is: one value per cell, from the solver's stress points and the cell's motion.

The stress is stored per point as ``[s11, s22, s33, s23, s13, s12]`` (``elements/cells.py``); a cell's
value is the mean over its points.  Components are named by the kinematics' axes: ``rr, zz, hoop, rz``
in axisymmetry (coordinates (r, z), index 2 the hoop direction), ``xx, yy, zz, xy`` in plane strain
(``zz`` out of plane), ``xx, yy, zz, yz, xz, xy`` in 3D.

The strain is the logarithmic (Hencky) strain of the cell's deformation at its centre,
h = 1/2 ln(F F^T) in the current axes (the axes of the Cauchy stress): exact for any stretch and
rotation, equal to the engineering strain to second order when the strain is small (0.1%:
1e-6 apart), and the measure whose rate is the deformation rate d the kernels integrate, so that
a uniaxial bar's strain reads ln(l / l0).  F is dx/dX at the cell's reference centre (the
one-point elements' own point); in axisymmetry F_hoop = r / R at the centre.
"""
from __future__ import annotations

import numpy as np

from ..elements.cells import AXISYMMETRIC, PLANE_STRAIN
from ..materials.layout import S_EPS, S_RATE
from ..model import kinematics as kin

# (axis suffix, stress-storage column) per kinematics code
COMPONENTS = {
    AXISYMMETRIC: (("rr", 0), ("zz", 1), ("hoop", 2), ("rz", 5)),
    PLANE_STRAIN: (("xx", 0), ("yy", 1), ("zz", 2), ("xy", 5)),
}
COMPONENTS_3D = (("xx", 0), ("yy", 1), ("zz", 2), ("yz", 3), ("xz", 4), ("xy", 5))

# the scene's ``outputs.fields`` names of cell fields and the unit of each value they give
SCALARS = {"von_mises": "Pa", "pressure": "Pa", "plastic_strain": "-", "plastic_strain_rate": "1/s"}
TENSORS = {"stress": "Pa", "strain": "-"}


def components(kinematics: int) -> tuple:
    """The (axis suffix, storage column) pairs of a symmetric tensor in ``kinematics``."""
    return COMPONENTS.get(kinematics, COMPONENTS_3D)


def von_mises(sigma: np.ndarray) -> np.ndarray:
    """sqrt(3/2 s:s) of stresses stored as [..., 6] = [11, 22, 33, 23, 13, 12] [Pa]."""
    p = sigma[..., :3].mean(axis=-1)
    s = sigma[..., :3] - p[..., None]
    return np.sqrt(1.5 * ((s ** 2).sum(axis=-1) + 2.0 * (sigma[..., 3:] ** 2).sum(axis=-1)))


def pressure(sigma: np.ndarray) -> np.ndarray:
    """-tr(sigma)/3 [Pa], positive in compression."""
    return -sigma[..., :3].mean(axis=-1)


def deformation_gradient(X: np.ndarray, x: np.ndarray, dofmap: np.ndarray, cell: str,
                         axisymmetric: bool) -> np.ndarray:
    """F = dx/dX at the reference centre of every cell of ``dofmap``, (cells, 3, 3).

    X, x: (nodes, gdim) reference and current positions; ``cell`` the dolfinx cell name.  In 2D the
    third direction is the hoop (F_33 = r / R at the centre) or the plane-strain depth (1)."""
    dN = kin.centre_gradients(cell)                       # (nn, tdim), reference cell
    Xe, xe = X[dofmap], x[dofmap]                         # (cells, nn, gdim)
    J0 = np.swapaxes(Xe, 1, 2) @ dN                       # dX/dxi (cells, gdim, tdim)
    J = np.swapaxes(xe, 1, 2) @ dN                        # dx/dxi
    gdim = X.shape[1]
    F = np.zeros((len(dofmap), 3, 3))
    F[:, :gdim, :gdim] = J @ np.linalg.inv(J0)
    if gdim == 2:
        F[:, 2, 2] = xe[:, :, 0].mean(axis=1) / Xe[:, :, 0].mean(axis=1) if axisymmetric else 1.0
    return F


def hencky_strain(F: np.ndarray) -> np.ndarray:
    """h = 1/2 ln(F F^T) of (cells, 3, 3) deformation gradients, stored as (cells, 6) [11, 22, 33, 23, 13, 12]."""
    w, V = np.linalg.eigh(F @ np.swapaxes(F, 1, 2))
    h = (V * (0.5 * np.log(w))[:, None, :]) @ np.swapaxes(V, 1, 2)
    return h[:, (0, 1, 2, 1, 0, 0), (0, 1, 2, 2, 2, 1)]


def cell_fields(solver, names, cells: int | None = None) -> dict[str, np.ndarray]:
    """The requested cell fields (``SCALARS`` and ``TENSORS`` names) of the first ``cells`` cells (all by
    default): ``{field name: (cells,) values}``, a tensor as one entry per component
    (``stress_rr``, ``strain_xy``, ...)."""
    m = solver.model
    n = len(m.dofmap) if cells is None else cells
    sigma = solver.sigma[:n].mean(axis=1)
    out = {}
    for name in names:
        if name == "von_mises":
            out[name] = von_mises(sigma)
        elif name == "pressure":
            out[name] = pressure(sigma)
        elif name in ("plastic_strain", "plastic_strain_rate"):
            column = S_EPS if name == "plastic_strain" else S_RATE
            out[name] = (solver.plastic_state[:n, :, column].mean(axis=1) if m.plastic else np.zeros(n))
        elif name in TENSORS:
            if name == "stress":
                tensor = sigma
            else:
                F = deformation_gradient(m.X0, solver.x, m.dofmap[:n], m.meshed.mesh.topology.cell_name(),
                                         m.axisymmetric)
                tensor = hencky_strain(F)
            for axes, column in components(m.kinematics):
                out[f"{name}_{axes}"] = np.ascontiguousarray(tensor[:, column])
    return out


def units(solver, names) -> dict[str, str]:
    """The unit of every value ``cell_fields`` gives for ``names``."""
    out = {}
    for name in names:
        if name in SCALARS:
            out[name] = SCALARS[name]
        elif name in TENSORS:
            for axes, _ in components(solver.model.kinematics):
                out[f"{name}_{axes}"] = TENSORS[name]
    return out
