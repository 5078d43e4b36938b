"""The discrete model of a scene: nodes, cells, lumped masses, bodies, constraints, loads.

Everything the time loop needs is here as plain numpy arrays in dolfinx's local
numbering (owned nodes first, then ghosts); the dolfinx objects (mesh, function space)
are kept for assembly of the mass and for output.
"""
from __future__ import annotations

import math

from dataclasses import dataclass, field

import basix
import numpy as np
import ufl
from dolfinx import fem
from mpi4py import MPI

from .. import compat
from ..geometry import MeshedScene, region_facets
from ..parts.catalog import PARTS
from ..scene import Scene
from ..scene.damping import describe_damping
from . import kinematics as kin
from ..elements import one_point
from ..elements.cells import cell_orientation
from ..materials import layout
from . import mass_scaling
from .materials import parameter_table


@dataclass
class RigidDrive:
    """The prescribed velocity [m/s] of a rigid body's centre of mass along one axis, a piecewise-linear
    history of (times [s], values); the body's other directions stay free (LS-DYNA's
    ``*BOUNDARY_PRESCRIBED_MOTION_RIGID``)."""
    component: int
    times: np.ndarray
    values: np.ndarray

    def value(self, t: float) -> float:
        return float(self.values[0]) if len(self.values) == 1 else float(np.interp(t, self.times, self.values))

    def rate(self, t: float, h: float) -> float:
        """The drive's acceleration at t [m/s^2], its central difference over t +- h (exact on the
        piecewise-linear history away from its corners; one-sided at t = 0)."""
        before, after = max(t - h, 0.0), t + h
        return (self.value(after) - self.value(before)) / (after - before)


@dataclass
class RigidBody:
    """A body that moves rigidly: translation, and rotation in 3D. No stiffness cost.  ``drives``: the
    directions along which its velocity is prescribed (a ``[[boundary]]`` naming the body); ``held_turn``:
    a fixed body's rotation (3D) is held too."""
    index: int
    nodes: np.ndarray            # local node indices, this rank's owned ones first, then its ghosts
    num_owned: int               # how many of ``nodes`` this rank owns
    mass: float                  # [kg], global
    center0: np.ndarray          # initial centre of mass [m]
    inertia0: np.ndarray         # (3, 3) inertia about the centre of mass, 3D only [kg m^2]
    rel0: np.ndarray             # X - center0 for ``nodes``
    drives: list[RigidDrive] = field(default_factory=list)
    held_turn: bool = False
    name: str = ""


@dataclass
class _History:
    """A piecewise-linear history (times [s], values) acting on flat dofs (node * gdim + component)."""
    dofs: np.ndarray
    times: np.ndarray
    values: np.ndarray
    region: str

    def value(self, t: float) -> float:
        if len(self.values) == 1:        # a constant (fixed, symmetry, the axis): no interpolation (np.interp
            return float(self.values[0])  # on a scalar costs 10 us, and the solver asks every step)
        return float(np.interp(t, self.times, self.values))


@dataclass
class Constraint(_History):
    """Prescribed velocity [m/s] on the dofs (zero for fixed, symmetry and axis conditions)."""


@dataclass
class Load(_History):
    """A total force history [N] on a region, shared among its nodes by consistent area."""
    shares: np.ndarray = None    # one per entry of ``dofs``; sums to 1 over the owned nodes of all ranks


@dataclass
class Model:
    """What the solver, contact and outputs need of a scene, on the mesh: arrays per node and cell,
    material rows, constraints and loads, and the few scene entries they read (bodies, contacts,
    springs, accelerometers, stress sections, gravity, plane-strain thickness, safety factor).  Not the scene itself:
    what reaches the time loop is listed here."""
    meshed: MeshedScene
    V: object                                  # P1 vector function space
    gdim: int
    kinematics: int
    dofmap: np.ndarray                         # (cells, nn) local node numbers
    num_owned: int                             # owned nodes come first
    X0: np.ndarray                             # (nodes, gdim) reference positions
    mass: np.ndarray                           # (nodes,) lumped mass [kg]
    node_body: np.ndarray                      # (nodes,) body index
    cell_body: np.ndarray                      # (cells,) body index
    cell_material: np.ndarray                  # (cells,) row of ``params`` (the cell's body)
    kernel_cells: np.ndarray                   # owned cells of deformable bodies
    params: np.ndarray                         # material rows (materials/layout.py)
    curves: np.ndarray                         # hardening curves of plastic materials
    cell_kind: int
    cell_sign: np.ndarray                      # (cells,) orientation of the reference cells
    N: np.ndarray
    dN: np.ndarray
    wq: np.ndarray
    rigid: list[RigidBody] = field(default_factory=list)
    constraints: list[Constraint] = field(default_factory=list)
    loads: list[Load] = field(default_factory=list)
    alpha: float = 0.0                          # mass-proportional damping [1/s]
    body_damping: tuple = ()                    # per body, the damping that acts on it (its own or the scene's)
    body_mass: np.ndarray = None                # (bodies,) global masses [kg]
    one_point: bool = False                     # reduced quads/hexes: elements/one_point.py kernels
    hourglass_form: int = 0                     # one_point.HOURGLASS_FORMS
    hourglass_coefficient: float = 0.0
    bodies: tuple = ()                          # the scene's bodies: name, velocity, spin, position, rigid
    contacts: tuple = ()                        # the scene's contact specs
    springs: tuple = ()                         # the scene's discrete springs
    cavities: tuple = ()                        # the scene's liquid-filled cavities (fluid dashpots)
    penetration: object = None                  # the scene's concrete target (a Penetration), if any
    accelerometers: tuple = ()                  # the scene's shock accelerometers
    sections: tuple = ()                        # the scene's stress sections along slender bodies
    gravity: tuple | None = None                # [m/s^2]
    thickness: float = 1.0                      # plane-strain depth [m]
    safety_factor: float = 0.9                  # of the stable step
    max_time_step: float = 0.0                  # [s] the scene's bound of the step for accuracy; 0: none
    plastic: bool = False                       # does any deformable body yield?
    point_state: bool = False                   # a state at every point (plastic bodies, slotted rings)
    mass_scaling: "mass_scaling.MassScaling | None" = None   # what the scaling added, if the scene asked for it

    @property
    def comm(self):
        return self.meshed.mesh.comm

    @property
    def num_cells_global(self) -> int:
        tdim = self.meshed.mesh.topology.dim
        return self.meshed.mesh.topology.index_map(tdim).size_global

    @property
    def num_quadrature_points(self) -> int:
        return self.wq.shape[0]

    @property
    def axisymmetric(self) -> bool:
        return self.kinematics == kin.CODES["axisymmetric"]

    @property
    def body_names(self) -> list[str]:
        return [b.name for b in self.bodies]

    @property
    def row_body(self) -> np.ndarray:
        """The body of each row of ``params`` (a body's own, and those mass scaling split off it)."""
        return mass_scaling.row_bodies(len(self.params), self.cell_body, self.cell_material)


def slot_width(body, kinematics: str) -> float:
    """The total width of a body's axial slots where its section cannot hold them (a split cone
    in axisymmetry: ``materials/slotted.py``), else 0."""
    if body.shape != "split_cone" or kinematics != "axisymmetric" or body.dims.get("segments", 0) < 2:
        return 0.0
    return body.dims["segments"] * body.dims["slot_width"]


def _lumped_mass(V, cell_rho, scene: Scene, gdim: int) -> np.ndarray:
    """Row-sum lumped mass m_a = int rho N_a dV (positive for linear elements)."""
    mesh = V.mesh
    rho = fem.Function(compat.cell_space(mesh))
    compat.set_cell_values(rho, cell_rho, len(cell_rho))
    w = ufl.TestFunction(V)
    weight = kin.measure_weight(mesh, scene.kinematics, scene.thickness)
    form = fem.form(rho * ufl.dot(w, ufl.as_vector([1.0] * gdim)) * weight * ufl.dx)
    m = fem.Function(V)
    compat.assemble_vector_into(m.x.array, form)
    compat.reverse_add(m)
    m.x.scatter_forward()
    return m.x.array.reshape(-1, gdim)[:, 0].copy()


def region_nodes(V, meshed: MeshedScene, region: str) -> np.ndarray:
    """Local nodes (owned and ghost) of a named region ("body.region")."""
    tdim = meshed.mesh.topology.dim
    return fem.locate_dofs_topological(V, tdim - 1, region_facets(meshed, region))


def _region_shares(V, meshed: MeshedScene, region: str, scene: Scene, gdim: int) -> np.ndarray:
    """Consistent nodal shares int_region N_a dA / area of a region (axisymmetric: with 2 pi r)."""
    mesh = meshed.mesh
    ds = ufl.Measure("ds", domain=mesh, subdomain_data=meshed.facet_tags,
                     subdomain_id=meshed.region_ids[region])
    w = ufl.TestFunction(V)
    weight = kin.measure_weight(mesh, scene.kinematics, scene.thickness)
    area = fem.Function(V)
    compat.assemble_vector_into(area.x.array,
                                fem.form(ufl.dot(w, ufl.as_vector([1.0] * gdim)) * weight * ds))
    compat.reverse_add(area)
    a = area.x.array.reshape(-1, gdim)[:, 0].copy()
    num_owned = V.dofmap.index_map.size_local
    total = mesh.comm.allreduce(a[:num_owned].sum(), op=MPI.SUM)
    return a / total


def _reference_positions(mesh, dofmap: np.ndarray, num_nodes: int, gdim: int) -> np.ndarray:
    """The nodes' positions, copied from the mesh's own coordinates.  (``tabulate_dof_coordinates``
    computes each node's from one of its cells through the coordinate map, 1e-17 m apart from one
    partition to another: enough for two surfaces that start touching, one of them a layer sum like
    -0.006 + 2 x 0.003 = 1e-18 m, to start one node inside or outside the other on two ranks and not on
    one.)"""
    X0 = np.empty((num_nodes, gdim))
    X0[dofmap] = mesh.geometry.x[compat.geometry_nodes(mesh, dofmap.shape[1])[:len(dofmap)]][:, :, :gdim]
    return X0


def build_model(scene: Scene, meshed: MeshedScene) -> Model:
    """Turn a meshed scene into the arrays of the explicit solver."""
    mesh = meshed.mesh
    comm = mesh.comm
    gdim = scene.gdim
    tdim = mesh.topology.dim
    V = compat.vector_space(mesh, 1)
    imap = V.dofmap.index_map
    num_nodes = imap.size_local + imap.num_ghosts
    cell_map = mesh.topology.index_map(tdim)
    num_cells = cell_map.size_local + cell_map.num_ghosts
    cell_name = mesh.topology.cell_name()
    nn = {"triangle": 3, "quadrilateral": 4, "tetrahedron": 4, "hexahedron": 8}[cell_name]
    dofmap = np.ascontiguousarray(compat.cell_dofs(V, nn)[:num_cells])
    X0 = _reference_positions(mesh, dofmap, num_nodes, gdim)

    cell_body = np.full(num_cells, -1, dtype=np.int32)
    cell_body[meshed.cell_tags.indices] = meshed.cell_tags.values - 1
    node_body = np.full(num_nodes, -1, dtype=np.int32)
    node_body[dofmap.ravel()] = np.repeat(cell_body, nn)

    # one row of kernel parameters per body: its material, and its own damping or the scene's
    cell_material = cell_body
    params, curves = parameter_table([scene.material_of(b) for b in scene.bodies],
                                     [b.damping or scene.damping for b in scene.bodies], scene.bulk_viscosity,
                                     [slot_width(b, scene.kinematics) for b in scene.bodies])
    rigid_ids = [i for i, b in enumerate(scene.bodies) if b.rigid]
    scaling = None
    if scene.mass_scaling_step > 0:
        # elements below the target step get rows of their own with a higher density
        steps = mass_scaling.element_steps(X0, dofmap, cell_name, params[cell_body, layout.P_WAVE_SPEED],
                                           scene.safety_factor)
        deformable = (cell_body >= 0) & ~np.isin(cell_body, rigid_ids)
        params, curves, cell_material, factor = mass_scaling.scale_rows(params, curves, cell_body, steps,
                                                                        scene.mass_scaling_step, deformable)
    mass = _lumped_mass(V, params[cell_material, layout.P_RHO], scene, gdim)
    if scene.mass_scaling_step > 0:
        scaling = _mass_scaling_report(scene, comm, mass - _lumped_mass(V, params[cell_body, layout.P_RHO], scene,
                                                                          gdim),
                                       mass, node_body, cell_body, factor, imap.size_local, cell_map.size_local)

    owned_cells = np.arange(cell_map.size_local, dtype=np.int32)
    kernel_cells = owned_cells[~np.isin(cell_body[owned_cells], rigid_ids)]

    points, wq, N, dN = kin.quadrature(cell_name, scene.kinematics, scene.integration)
    one_point_cells = kin.one_point(cell_name, scene.integration)
    slotted = [b.name for b in scene.bodies if slot_width(b, scene.kinematics) > 0 and not b.rigid]
    if slotted and not one_point_cells:
        from ..errors import ModelError
        raise ModelError(f"body {slotted[0]!r}: the slotted split cone's hoop model (open slots carry no hoop "
                         f"stress) runs in the default one-point quadrilaterals; this scene has {cell_name}s "
                         f"with integration = {scene.integration!r}. Use element = \"quad\" and "
                         f"integration = \"reduced\", or run it in 3d with real slots")
    if one_point_cells:
        one_point.check_vertex_order(basix.geometry(kin.BASIX_CELLS[cell_name]))
    alpha = scene.damping.coefficients()[0] if scene.damping else 0.0

    owned = np.arange(num_nodes) < imap.size_local
    body_mass = np.array([comm.allreduce(mass[owned & (node_body == i)].sum(), op=MPI.SUM)
                          for i in range(len(scene.bodies))])

    cell_sign = cell_orientation(dofmap, X0, dN)
    plastic = any(scene.material_of(b).law != "elastic" for b in scene.bodies if not b.rigid)
    model = Model(meshed=meshed, V=V, gdim=gdim, kinematics=kin.CODES[scene.kinematics], dofmap=dofmap,
                  num_owned=imap.size_local, X0=X0, mass=mass, node_body=node_body, cell_body=cell_body,
                  cell_material=cell_material, kernel_cells=kernel_cells, params=params, curves=curves,
                  cell_kind=kin.CELL_KINDS[cell_name], cell_sign=cell_sign, N=N, dN=dN, wq=wq, alpha=alpha,
                  body_mass=body_mass,
                  body_damping=tuple(b.damping or scene.damping for b in scene.bodies),
                  one_point=one_point_cells, hourglass_form=one_point.HOURGLASS_FORMS[scene.hourglass],
                  hourglass_coefficient=scene.hourglass_coefficient, bodies=tuple(scene.bodies),
                  contacts=tuple(scene.contacts), springs=tuple(scene.springs), cavities=tuple(scene.cavities),
                  penetration=scene.penetration,
                  accelerometers=tuple(scene.shock.accelerometers),
                  sections=tuple(scene.outputs.sections), gravity=scene.gravity,
                  thickness=scene.thickness, safety_factor=scene.safety_factor,
                  max_time_step=scene.max_time_step, plastic=plastic,
                  point_state=plastic or bool(slotted), mass_scaling=scaling)
    model.rigid = [_rigid_body(model, i) for i in rigid_ids]
    _add_boundaries(model, scene)
    return model


def _mass_scaling_report(scene: Scene, comm, added: np.ndarray, mass: np.ndarray, node_body, cell_body, factor,
                         owned_nodes: int, owned_cells: int) -> mass_scaling.MassScaling:
    """The added mass per body, over all ranks; refuses (ModelError) a scaling above the scene's limit."""
    report = mass_scaling.MassScaling(scene.mass_scaling_step)
    report.largest_factor = comm.allreduce(float(factor.max(initial=1.0)), op=MPI.MAX)
    over = []
    for i, body in enumerate(scene.bodies):
        nodes = node_body[:owned_nodes] == i
        added_i = comm.allreduce(float(added[:owned_nodes][nodes].sum()), op=MPI.SUM)
        total = comm.allreduce(float(mass[:owned_nodes][nodes].sum()), op=MPI.SUM)
        report.cells[body.name] = comm.allreduce(int((factor[:owned_cells][cell_body[:owned_cells] == i] > 1).sum()),
                                                 op=MPI.SUM)
        report.added_mass[body.name] = added_i
        report.share[body.name] = added_i / max(total - added_i, 1e-300)
        if report.share[body.name] > scene.mass_scaling_limit:
            over.append(f"{body.name} +{report.share[body.name]:.1%}")
    if over:
        from ..errors import ModelError
        raise ModelError(f"scene.mass_scaling_step = {scene.mass_scaling_step:.4g} s would add more mass than "
                         f"scene.mass_scaling_limit = {scene.mass_scaling_limit:g} allows ({', '.join(over)} of the "
                         f"body's mass): lower the step, refine less or coarsen the small elements, or raise the "
                         f"limit if that inertia is acceptable")
    return report


def _rigid_body(model: Model, index: int) -> RigidBody:
    comm = model.comm
    nodes = np.flatnonzero(model.node_body == index)
    owned = nodes < model.num_owned
    m = model.mass[nodes]
    M = comm.allreduce(m[owned].sum(), op=MPI.SUM)
    c = comm.allreduce((m[owned, None] * model.X0[nodes][owned]).sum(axis=0), op=MPI.SUM) / M
    rel = model.X0[nodes] - c
    inertia = np.zeros((3, 3))
    if model.gdim == 3:
        r2 = (rel[owned] ** 2).sum(axis=1)
        local = (np.eye(3)[None] * (m[owned] * r2)[:, None, None]
                 - m[owned, None, None] * rel[owned][:, :, None] * rel[owned][:, None, :]).sum(axis=0)
        inertia = comm.allreduce(local, op=MPI.SUM)
    # a rank numbers its owned nodes first, so the owned ones lead ``nodes`` (sorted)
    return RigidBody(index, nodes, int(np.count_nonzero(owned)), M, c, inertia, rel, name=model.bodies[index].name)


def _drive_rigid(model: Model, bc) -> None:
    """A ``[[boundary]]`` naming a rigid body: its centre's velocity prescribed along the condition's
    direction (``velocity``), or along every one with its turn held (``fixed``)."""
    rb = next(r for r in model.rigid if r.name == bc.region)
    times = np.array([p[0] for p in bc.history])
    values = np.array([p[1] for p in bc.history])
    for comp in bc.components:
        if model.axisymmetric and comp == 0:
            continue                       # a body of revolution moves along z only (``_rigid_loads``)
        rb.drives = [d for d in rb.drives if d.component != comp]      # a later condition replaces an earlier
        rb.drives.append(RigidDrive(comp, times, values if bc.kind == "velocity" else np.array([0.0])))
    rb.held_turn = rb.held_turn or bc.kind == "fixed"


def _add_boundaries(model: Model, scene: Scene):
    V, gdim = model.V, model.gdim
    if scene.kinematics == "axisymmetric":
        # Nodes on the axis cannot move radially (u_r = 0 at r = 0 by symmetry).
        axis = np.flatnonzero(np.abs(model.X0[:, 0]) < 1e-12 * max(1.0, np.abs(model.X0).max()))
        model.constraints.append(Constraint(axis * gdim, np.array([0.0]), np.array([0.0]), "axis"))
    for bc in scene.boundaries:
        if "." not in bc.region:           # a rigid body, driven whole (``scene/boundaries.py``)
            _drive_rigid(model, bc)
            continue
        nodes = region_nodes(V, model.meshed, bc.region)
        times = np.array([p[0] for p in bc.history])
        values = np.array([p[1] for p in bc.history])
        if bc.kind == "fixed":
            dofs = (nodes[:, None] * gdim + np.arange(gdim)[None, :]).ravel()
            model.constraints.append(Constraint(dofs, np.array([0.0]), np.array([0.0]), bc.region))
        elif bc.kind == "symmetry":
            comp = plane_normal_axis(model.X0[nodes], model.comm, bc.region)
            model.constraints.append(Constraint(nodes * gdim + comp, np.array([0.0]), np.array([0.0]),
                                                bc.region))
        elif bc.kind == "velocity":
            model.constraints.append(Constraint(nodes * gdim + bc.components[0], times, values, bc.region))
        else:
            shares = _region_shares(V, model.meshed, bc.region, scene, gdim)[nodes]
            model.loads.append(Load(nodes * gdim + bc.components[0], times, values, bc.region, shares))


def plane_normal_axis(points: np.ndarray, comm, region: str) -> int:
    """The coordinate axis normal to a planar region, from points on it (over all ranks), for
    symmetry conditions in the explicit model and in the modal solver alike."""
    gdim = points.shape[1]
    lo = comm.allreduce(points.min(axis=0) if len(points) else np.full(gdim, np.inf), op=MPI.MIN)
    hi = comm.allreduce(points.max(axis=0) if len(points) else np.full(gdim, -np.inf), op=MPI.MAX)
    span = hi - lo
    flat = np.flatnonzero(span <= 1e-9 * max(span.max(), 1e-30))
    if len(flat) != 1:
        from ..errors import ModelError
        raise ModelError(f"boundary region {region}: a symmetry condition needs a plane normal to a "
                         f"coordinate axis; this region spans {span} m")
    return int(flat[0])


def _obliquity(sc: Scene, pn) -> str:
    """The projectile's angle of attack on the face (its velocity against the face's inward normal), said
    when it is not square: the crater is measured along the normal and the whole nose loaded in it, and
    an oblique face's free-surface relief (what turns an oblique shot) is not modelled."""
    body = next((b for b in sc.bodies if b.name == pn.nose.split(".")[0]), None)
    v = np.asarray(body.velocity if body is not None else (), dtype=float)
    if sc.kinematics == "axisymmetric" or not len(v) or not np.linalg.norm(v):
        return ""
    cos = float(-(v @ np.asarray(pn.normal)) / np.linalg.norm(v))
    angle = math.degrees(math.acos(max(-1.0, min(1.0, cos))))
    if angle < 0.5:
        return ""
    return (f"; oblique: the path {angle:.3g} deg from the face's normal (the crater measured along the normal, "
            "the free surface's asymmetric relief not modelled: outside what the load is verified for)")


def _drive_said(model: Model, sc: Scene, index: int) -> str:
    """", its velocity prescribed along z (...)" of a driven rigid body, or ""."""
    rb = next((r for r in model.rigid if r.index == index), None)
    if rb is None or not rb.drives:
        return ""
    axes = "rz" if sc.kinematics == "axisymmetric" else "xyz"
    free = [a for k, a in enumerate(axes[:model.gdim]) if k not in {d.component for d in rb.drives}]
    notes = [f"free along {', '.join(free)}"] if free and sc.kinematics != "axisymmetric" else []
    if model.gdim == 3:
        notes.append("its turn held" if rb.held_turn else "free to turn")
    return (f", its centre's velocity prescribed along {', '.join(axes[d.component] for d in rb.drives)}"
            + (f" ({'; '.join(notes)})" if notes else ""))


def describe(model: Model, sc: Scene) -> str:
    """One line per body of the scene ``sc`` saying which model runs for it ("model only what a
    scene needs")."""
    lines = []
    cell = model.meshed.mesh.topology.cell_name()
    if model.one_point:
        element = (f"{cell}s, one point + {sc.hourglass} hourglass control "
                   f"(coefficient {sc.hourglass_coefficient:g})")
    else:
        element = f"{cell}s, {model.num_quadrature_points}-point Gauss" + (
            ", mean dilatation" if cell in ("quadrilateral", "hexahedron") else "")
    for i, b in enumerate(sc.bodies):
        material = sc.material_of(b)
        kind = "rigid body (no stiffness)" + _drive_said(model, sc, i) if b.rigid else (
            f"{material.model}, updated Lagrangian, {element}")
        lines.append(f"  {b.name}: {kind}, {sc.kinematics}, mass {model.body_mass[i]:.6g} kg")
        if b.shape in PARTS:
            lines += [f"    approximation: {note}" for note in PARTS[b.shape].approximations(b.dims, model.gdim)]
        if material.source and not b.rigid:
            lines.append(f"    material {material.name} from the {material.source}")
    q1, q2 = sc.bulk_viscosity
    lines.append(f"  bulk viscosity: Q1 = {q1:g} (quadratic), Q2 = {q2:g} (linear), in compression"
                 if q1 or q2 else "  bulk viscosity: off")
    for c in sc.contacts:
        friction = (f", Coulomb friction mu_s = {c.friction[0]:g}, mu_d = {c.friction[1]:g}"
                    if c.friction[0] > 0 else ", frictionless")
        how = (f"two-pass node-to-{'segment' if model.gdim == 2 else 'face'} penalty" if c.b
               else f"node-to-{c.rigid.kind} penalty")
        lines.append(f"  contact {c.name}: {c.a} <-> {c.b or c.rigid.describe()}, {how} ({c.penalty}, scale "
                     f"{c.penalty_scale:g}), damping {c.damping:g} of critical{friction}")
    for sp in sc.springs:
        law = (f"tabulated curve of {len(sp.curve)} points" if sp.curve else f"k = {sp.stiffness:.4g} N/m")
        lines.append(f"  spring {sp.name}: {sp.a} <-> {sp.b}, {law}, c = {sp.damping:.4g} N s/m"
                     + (", compression only" if sp.compression_only else ""))
    for cv in sc.cavities:
        law = "linear" if cv.tait_exponent == 1.0 else f"Tait, n = {cv.tait_exponent:g}"
        orifice = (f"fixed orifice {cv.orifice[0][1] * 1e6:.4g} mm^2" if len(cv.orifice) == 1
                   else f"metering pin, {len(cv.orifice)}-point area table over {cv.orifice[-1][0] * 1e3:.4g} mm "
                        f"of stroke")
        orifice += (f", fixed Cd {cv.discharge:g} (no velocity of approach, no jet reaction)" if cv.law == "fixed_cd"
                    else ", Idelchik's sharp-edged law with the velocity of approach and the jet's reaction")
        liquid = f"liquid {cv.density:g} kg/m^3, K {cv.bulk_modulus / 1e9:.4g} GPa ({law})"
        if cv.model == "column":
            lines.append(f"  cavity {cv.name}: {liquid}, {orifice}; a 1D compressible column of {cv.cells} finite "
                         f"volumes from the floor {cv.walls[0]} to the piston face {cv.walls[1]}: the liquid's mass "
                         f"and waves, cavitation at {cv.vapour_pressure / 1e6:.4g} MPa gauge; no friction on the "
                         f"bore, no return flow through the orifice, no lateral flow")
            continue
        lines.append(f"  cavity {cv.name}: {liquid}, "
                     f"{cv.volume * 1e6:.4g} cm^3 at {cv.initial_pressure / 1e6:.4g} MPa, {orifice}; "
                     f"walls {', '.join(cv.walls)} (the rest held still); lumped control volume: one pressure, "
                     f"quasi-steady orifice capped at the sound speed, no liquid inertia or waves, no "
                     f"cavitation below 0 gauge")
    if sc.penetration:
        pn = sc.penetration
        S = (f"S = {pn.strength_factor:.4g}" if pn.strength_factor else "S from Forrestal's fit 82.6 (f'c/MPa)^-0.544")
        crater = (f"{pn.crater_depth * 1e3:.4g} mm" if pn.crater_depth >= 0 else "two calibres (4a)")
        lines.append(f"  penetration of {pn.nose}: concrete f'c {pn.compressive_strength / 1e6:.4g} MPa, "
                     f"{pn.density:g} kg/m^3, {S}; normal stress S f'c + rho v_n^2 on the advancing facets beyond "
                     f"the face (Forrestal's spherical cavity expansion), crater {crater} with the force rising "
                     f"linearly with depth; "
                     + (f"friction torque mu F a / 2, mu = {pn.friction:g}; " if pn.friction else "no friction; ")
                     + ("a rigid tunnel behind the nose" if pn.tunnel else "no tunnel")
                     + _obliquity(sc, pn)
                     + ". Left out: the target's own deformation, free surfaces, scabbing and perforation, "
                       "sliding friction along the nose")
    if sc.gravity:
        lines.append(f"  gravity: {sc.gravity} m/s^2")
    if sc.damping:
        lines.append(f"  damping: {describe_damping(sc.damping)}"
                     + (", bodies with their own below" if any(b.damping for b in sc.bodies) else ""))
    for b in sc.bodies:
        if b.damping and not b.rigid:
            lines.append(f"  damping of {b.name}: {describe_damping(b.damping)}")
    if model.mass_scaling is not None:
        lines.append("  " + model.mass_scaling.describe())
    return "\n".join(lines)

