"""What kind of mode a mode shape is.

The body's axis is one of its own principal axes through its centroid (``principal_axis``: the
longest of a slender body, the normal of a flat one), so a beam lying along x or a tilted part is
labelled as one along z would be.  A mode's displacement energy (node-weighted, all nodes alike)
splits into axial, radial and circumferential parts about that axis:

* axial dominant: ``longitudinal`` in a body at least half as long as it is wide, ``bending``
  (out of plane) in a flatter one (a plate or disc)
* transverse (radial and circumferential) dominant: ``bending`` in a slender body whose
  cross-sections mostly translate (slices along z keep most of the transverse energy in their
  mean motion); else ``torsional`` if circumferential dominates, else ``radial`` (breathing,
  ovalling, and the in-plane modes of a disc)
* none above half: ``mixed``

In axisymmetry there is no circumferential part and no bending (modes are n = 0).  In plane
strain the split is along x and y, named ``x`` and ``y``.
"""
from __future__ import annotations

import numpy as np
from dolfinx import fem

DOMINANT = 0.5          # share of the energy that names a mode
SLICES = 20             # slices along the axis for the section-translation test


def _body_nodes(V, cells):
    dofs = fem.locate_dofs_topological(V, V.mesh.topology.dim, cells)
    return dofs, V.tabulate_dof_coordinates()[dofs]


def principal_axis(x: np.ndarray) -> np.ndarray:
    """The unit axis of a body from its node coordinates ``x`` (n, 3): of the principal directions of
    their spread, the one that stands apart from the other two (the largest for a rod or beam, the
    smallest for a plate or disc)."""
    rel = x - x.mean(axis=0)
    spread, directions = np.linalg.eigh(rel.T @ rel / len(x))        # ascending
    small, middle, large = np.maximum(spread, 1e-300)
    return directions[:, 2] if large / middle >= middle / small else directions[:, 0]


def _axis_frame(axis: np.ndarray) -> np.ndarray:
    """A right-handed orthonormal basis (columns) whose third vector is ``axis``."""
    helper = np.eye(3)[np.argmin(np.abs(axis))]
    first = np.cross(helper, axis)
    first /= np.linalg.norm(first)
    return np.column_stack([first, np.cross(axis, first), axis])


def label_modes(modes, cells) -> list[dict]:
    """A label and the energy shares of each mode of ``modes`` (``eigen.BodyModes``)."""
    V = modes.space
    dofs, x = _body_nodes(V, cells)
    gdim = V.dofmap.index_map_bs
    out = []
    if modes.kinematics == "plane-strain":
        for f in modes.shapes:
            u = f.x.array.reshape(-1, gdim)[dofs]
            e = (u ** 2).sum(axis=0)
            shares = {"x": float(e[0] / e.sum()), "y": float(e[1] / e.sum())}
            out.append({"label": max(shares, key=shares.get) if max(shares.values()) > DOMINANT else "mixed",
                        "shares": shares})
        return out
    axisymmetric = modes.kinematics == "axisymmetric"
    frame = np.eye(3)
    if not axisymmetric:
        # coordinates and displacements in the body's own frame, its axis third
        frame = _axis_frame(principal_axis(x[:, :3]))
        x = (x[:, :3] - x[:, :3].mean(axis=0)) @ frame
    centre = np.zeros(2) if axisymmetric else x[:, :2].mean(axis=0)
    rel = x[:, :2] - centre if not axisymmetric else np.column_stack([x[:, 0], np.zeros(len(x))])
    r = np.linalg.norm(rel, axis=1)
    er = np.where(r[:, None] > 1e-12 * max(r.max(), 1e-300), rel / np.maximum(r, 1e-300)[:, None], 0.0)
    et = np.column_stack([-er[:, 1], er[:, 0]])
    z = x[:, 1] if axisymmetric else x[:, 2]
    length = z.max() - z.min()
    width = 2 * r.max()
    slender = length >= 0.5 * width
    slice_of = np.minimum(((z - z.min()) / max(length, 1e-300) * SLICES).astype(int), SLICES - 1)
    for f in modes.shapes:
        u = f.x.array.reshape(-1, gdim)[dofs]
        if axisymmetric:
            ur, ut, uz = u[:, 0], np.zeros(len(u)), u[:, 1]
            transverse = np.zeros((len(u), 2))
        else:
            u = u @ frame
            transverse = u[:, :2]
            ur, ut, uz = (transverse * er).sum(axis=1), (transverse * et).sum(axis=1), u[:, 2]
        e_r, e_t, e_z = (ur ** 2).sum(), (ut ** 2).sum(), (uz ** 2).sum()
        total = e_r + e_t + e_z
        shares = {"axial": float(e_z / total), "radial": float(e_r / total), "circumferential": float(e_t / total)}
        if shares["axial"] > DOMINANT:
            label = "longitudinal" if slender else "bending"
        elif axisymmetric:
            label = "radial" if shares["radial"] > DOMINANT else "mixed"
        else:
            # section translation: the slices' mean transverse motion against all of it (a
            # bending mode's transverse energy splits about evenly between radial and
            # circumferential, so this test comes before theirs)
            means = np.zeros((SLICES, 2))
            np.add.at(means, slice_of, transverse)
            counts = np.bincount(slice_of, minlength=SLICES)[:, None]
            means = means / np.maximum(counts, 1)
            translated = (means[slice_of] ** 2).sum() / max((transverse ** 2).sum(), 1e-300)
            shares["section_translation"] = float(translated)
            if slender and translated > DOMINANT:
                label = "bending"
            elif shares["circumferential"] > DOMINANT:
                label = "torsional"
            elif shares["radial"] + shares["circumferential"] > DOMINANT:
                label = "radial"
            else:
                label = "mixed"
        out.append({"label": label, "shares": shares})
    return out


def firsts(labels: list[dict], frequencies) -> dict:
    """The lowest frequency of each kind of mode [Hz]."""
    out = {}
    for lab, f in zip(labels, frequencies):
        out.setdefault(lab["label"], float(f))
    return out
