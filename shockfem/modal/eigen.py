"""The generalised eigenproblem of one body: K x = omega^2 M x.

K and M are assembled over the body's cells only (``dx(body)``), with Lagrange elements of
degree 1 (the solver's) or 2 (thin plates and shells lock with linear solids; quadratic ones do
not), under the scene's kinematics (``model/kinematics.py`` holds the forms).  The dofs of the
other bodies, and of the body's fixed, symmetry and velocity conditions when the body is
``constrained``, get a unit diagonal in K and a zero one in M: their eigenvalues are infinite
and shift-invert never finds them.

SLEPc solves by shift-and-invert about a small negative shift, so a free body's rigid modes
(omega = 0) come out first and K - sigma M is never singular; the LU factorisation is MUMPS.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import ufl
from dolfinx import fem
from dolfinx.mesh import compute_midpoints
from mpi4py import MPI
from petsc4py import PETSc

from .. import compat
from ..errors import ModelError
from ..model import kinematics as kin
from ..model.model import plane_normal_axis
from ..scene import Scene

# Rigid-body modes per kinematics (free body): translations and rotations the strain misses.
RIGID_MODES = {"axisymmetric": 1, "plane-strain": 3, "3d": 6}


@dataclass
class BodyModes:
    body: str
    kinematics: str
    degree: int
    constrained: bool
    mass: str                       # consistent | lumped
    frequencies: np.ndarray         # [Hz], elastic modes, ascending
    rigid: int                      # rigid-body modes found (omega ~ 0), not in frequencies
    shapes: list                    # fem.Function per elastic mode, max |u| = 1
    space: object                   # the function space of the shapes
    dofs: int
    wall_time_s: float
    conditions: list[str]           # the conditions that held the body
    damping: object = None          # the scene Damping acting on the body in a run (its own or the scene's)


def _blocked_dofs(V, cells) -> np.ndarray:
    return fem.locate_dofs_topological(V, V.mesh.topology.dim, cells)


def _conditions(scene: Scene, meshed, V, body_index: int, constrained: bool):
    """Dirichlet conditions: the other bodies' dofs, the axis (axisymmetric), and the body's
    own boundary conditions when constrained.  Returns (bcs, names)."""
    mesh = V.mesh
    tdim, fdim = mesh.topology.dim, mesh.topology.dim - 1
    gdim = mesh.geometry.dim if scene.kinematics == "3d" else 2
    body_cells = meshed.cell_tags.find(body_index + 1)
    n_cells = mesh.topology.index_map(tdim).size_local + mesh.topology.index_map(tdim).num_ghosts
    others = np.setdiff1d(np.arange(n_cells, dtype=np.int32), body_cells)
    zero = np.zeros(gdim, dtype=PETSc.ScalarType)
    bcs = [fem.dirichletbc(zero, _blocked_dofs(V, others), V)] if len(others) else []
    names = []
    if scene.kinematics == "axisymmetric":
        # u_r = 0 on the axis (the explicit solver holds it too)
        V0 = compat.collapse(V.sub(0))
        axis = fem.locate_dofs_geometrical((V.sub(0), V0), lambda x: np.isclose(x[0], 0.0))
        bcs.append(fem.dirichletbc(PETSc.ScalarType(0), axis[0], V.sub(0)))
    if not constrained:
        return bcs, names
    mesh.topology.create_connectivity(fdim, tdim)
    body = scene.bodies[body_index]
    for bc in scene.boundaries:
        if bc.region.partition(".")[0] != body.name or bc.kind == "force":
            continue
        facets = meshed.facet_tags.find(meshed.region_ids[bc.region])
        if bc.kind == "fixed":
            bcs.append(fem.dirichletbc(zero, fem.locate_dofs_topological(V, fdim, facets), V))
            names.append(f"{bc.region} fixed")
            continue
        if bc.kind == "symmetry":
            mid = compute_midpoints(mesh, fdim, facets)[:, :gdim]
            comp = plane_normal_axis(mid, mesh.comm, bc.region)
        else:
            comp = bc.components[0]
        Vi = compat.collapse(V.sub(comp))
        dofs = fem.locate_dofs_topological((V.sub(comp), Vi), fdim, facets)
        bcs.append(fem.dirichletbc(PETSc.ScalarType(0), dofs[0], V.sub(comp)))
        names.append(f"{bc.region} held along {'rz'[comp] if scene.kinematics == 'axisymmetric' else 'xyz'[comp]}")
    return bcs, names


def _shift(material, extent: float) -> float:
    """A shift well below the first elastic eigenvalue (about (pi c / L)^2) and of its order, so
    K - sigma M is well conditioned and the rigid modes (0) come first."""
    return -(0.05 * material.c_bar / extent) ** 2


def body_modes(scene: Scene, meshed, body: str, count: int = 10, degree: int = 1, constrained: bool = True,
               mass: str = "consistent") -> BodyModes:
    """The ``count`` lowest elastic natural frequencies and mode shapes of ``body``."""
    t0 = time.perf_counter()
    names = [b.name for b in scene.bodies]
    if body not in names:
        raise ModelError(f"--body: unknown body {body!r} (bodies: {', '.join(names)})")
    index = names.index(body)
    if scene.bodies[index].rigid:
        raise ModelError(f"body {body} is rigid: it has no natural frequencies")
    mesh = meshed.mesh
    mat = scene.material_of(scene.bodies[index])
    V = compat.vector_space(mesh, degree)
    u, w = ufl.TrialFunction(V), ufl.TestFunction(V)
    dx = ufl.Measure("dx", domain=mesh, subdomain_data=meshed.cell_tags)(index + 1)
    lam, mu, rho = (fem.Constant(mesh, PETSc.ScalarType(v)) for v in (mat.lam, mat.mu, mat.rho))
    k_form = fem.form(kin.elastic_energy_form(u, w, lam, mu, scene.kinematics, scene.thickness) * dx)
    m_form = fem.form(kin.inertia_form(u, w, rho, scene.kinematics, scene.thickness) * dx)
    bcs, conditions = _conditions(scene, meshed, V, index, constrained)
    K = compat.assemble_petsc_matrix(k_form, bcs, diagonal=1.0)
    M = compat.assemble_petsc_matrix(m_form, bcs, diagonal=0.0)
    if mass == "lumped":
        M = _lumped(M)
    extent = _extent(mesh, meshed.cell_tags.find(index + 1))
    # ask for room for the rigid modes a free (or partly held) body has
    lams, vecs = _solve(K, M, count + RIGID_MODES[scene.kinematics], _shift(mat, extent), mesh.comm)
    rigid_limit = 1e-4 * (mat.c_bar / extent) ** 2
    elastic = [i for i, lam_i in enumerate(lams) if lam_i > rigid_limit][:count]
    shapes = []
    for i in elastic:
        f = fem.Function(V, name=f"mode_{len(shapes) + 1}")
        vecs[i].copy(f.vector)
        f.x.scatter_forward()
        peak = mesh.comm.allreduce(float(np.abs(f.x.array).max()) if len(f.x.array) else 0.0, op=MPI.MAX)
        f.x.array[:] /= peak if peak > 0 else 1.0
        shapes.append(f)
    freqs = np.sqrt(np.maximum(np.array([lams[i] for i in elastic]), 0.0)) / (2 * math.pi)
    dofs = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    return BodyModes(body, scene.kinematics, degree, constrained, mass, freqs,
                     sum(1 for v in lams if v <= rigid_limit), shapes, V, dofs, time.perf_counter() - t0, conditions,
                     scene.bodies[index].damping or scene.damping)


def _extent(mesh, cells) -> float:
    """Largest bounding-box side of the given cells [m]."""
    from dolfinx.mesh import compute_midpoints
    mid = compute_midpoints(mesh, mesh.topology.dim, cells)
    lo = mesh.comm.allreduce(mid.min(axis=0) if len(mid) else np.full(3, np.inf), op=MPI.MIN)
    hi = mesh.comm.allreduce(mid.max(axis=0) if len(mid) else np.full(3, -np.inf), op=MPI.MAX)
    return float((hi - lo).max())


def _lumped(M):
    """Row-sum lumped mass as a diagonal PETSc matrix."""
    ones = M.createVecRight()
    ones.set(1.0)
    d = M.createVecLeft()
    M.mult(ones, d)
    L = PETSc.Mat().createAIJ(M.getSizes(), nnz=1, comm=M.comm)
    L.setDiagonal(d)
    L.assemble()
    return L


def _solve(K, M, nev: int, shift: float, comm):
    """The ``nev`` eigenpairs of K x = lambda M x nearest ``shift`` (lambda = omega^2)."""
    from slepc4py import SLEPc
    eps = SLEPc.EPS().create(comm)
    eps.setOperators(K, M)
    eps.setProblemType(SLEPc.EPS.ProblemType.GHEP)
    eps.setDimensions(nev, max(2 * nev, nev + 15))
    eps.setTarget(shift)
    eps.setWhichEigenpairs(SLEPc.EPS.Which.TARGET_REAL)
    st = eps.getST()
    st.setType(SLEPc.ST.Type.SINVERT)
    st.setShift(shift)
    ksp = st.getKSP()
    ksp.setType("preonly")
    pc = ksp.getPC()
    pc.setType("lu")
    pc.setFactorSolverType("mumps")
    eps.setTolerances(1e-10, 200)
    eps.solve()
    n = eps.getConverged()
    if n < nev:
        raise ModelError(f"modal analysis: SLEPc converged {n} of the {nev} eigenpairs asked for")
    pairs = []
    for i in range(n):
        vr = K.createVecRight()
        lam = eps.getEigenpair(i, vr).real
        pairs.append((lam, vr))
    pairs.sort(key=lambda p: p[0])
    return [p[0] for p in pairs[:nev]], [p[1] for p in pairs[:nev]]
