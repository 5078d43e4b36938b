"""Shared inputs of the kernel tests: a distorted mesh and a material table."""
import numpy as np
from dolfinx import mesh
from mpi4py import MPI

from shockfem.elements import blocks
from shockfem.materials import layout

# elastic materials read neither hardening curves nor plastic state: one-entry stubs
NO_CURVES = np.zeros((1, 1, 2))
NO_STATE = np.zeros((1, 1, layout.STATE_SIZE))


def distorted_mesh(kinematics, cell):
    comm = MPI.COMM_SELF
    if kinematics == "3d":
        m = mesh.create_box(comm, [np.array([0.1, 0.0, 0.0]), np.array([0.4, 0.2, 0.3])], [3, 2, 3], cell)
    else:
        m = mesh.create_rectangle(comm, [np.array([0.0, 0.0]), np.array([0.3, 0.5])], [3, 4], cell)
    # distort the mesh so that Jacobians vary from point to point
    x = m.geometry.x
    x[:, 0] += 0.02 * np.sin(7 * x[:, 1]) * x[:, 0]
    x[:, 1] += 0.03 * np.cos(5 * x[:, 0])
    return m


def steel_params(E=200e9, nu=0.3, rho=7800.0, beta=0.0):
    p = np.zeros((1, layout.NUM_PARAMS))
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    p[0, [layout.P_RHO, layout.P_LAMBDA, layout.P_MU, layout.P_WAVE_SPEED, layout.P_BETA]] = \
        [rho, lam, mu, np.sqrt((lam + 2 * mu) / rho), beta]
    return p


# a one-point rule's stand-ins for the passes that read no rule (one-point quads and hexes)
ONE_POINT_RULE = (np.ones((1, 1)), np.zeros((1, 1, 1)), np.ones(1))


def run_pass(kernel, cells, dofmap, cell_material, cell_sign, x, v, dt, params, curves, state, sigma, f, body_energy,
             rule=ONE_POINT_RULE, kinematics=2, thickness=1.0, cell_kind=-1, mean_dilatation=True, hourglass=None,
             hourglass_form=0, hourglass_coefficient=0.0, t_np1=1e-6, peak=None):
    """``kernel`` called with every pass's arguments (``shockfem.elements.blocks.PASS_ARGUMENTS``), the ones a
    test leaves out at values the pass does not read: (N, dN, wq) ``rule``, no hourglass resultants, a fresh
    ``peak`` of one row per row of ``params``.  Returns the pass's seven figures."""
    N, dN, wq = rule
    hourglass = np.zeros((len(dofmap), 0)) if hourglass is None else hourglass
    peak = blocks.no_peak(len(params)) if peak is None else peak
    return kernel(cells, dofmap, cell_material, cell_sign, x, v, t_np1, dt, N, dN, wq, kinematics, thickness,
                  cell_kind, mean_dilatation, hourglass_form, hourglass_coefficient, params, curves, state, sigma,
                  hourglass, f, body_energy, peak)
