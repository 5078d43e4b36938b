"""A deck's sets, initial velocities, constraints, prescribed motions, contacts and rigid walls as the scene's
regions, body velocities, ``[[boundary]]`` and ``[[contact]]`` entries.

shockfem puts conditions on regions (a body's boundary facets) and initial velocities on whole bodies; a
node set becomes, on each body it touches, the region of the boundary facets all of whose nodes are in it.
"""
from __future__ import annotations

import itertools

import numpy as np

AXES = "xyz"


class Regions:
    """Named regions of each body's boundary facets; a facet carries one region only (the scene's rule)."""

    def __init__(self, mapper):
        self.mapper = mapper
        self.owner: dict[str, dict[int, str]] = {}      # body -> facet row -> region

    def add(self, body: str, name: str, rows: np.ndarray, error) -> str | None:
        """Region ``name`` of ``body`` on facet ``rows``; None (and a problem) when empty or overlapping."""
        mesh = self.mapper.meshes[body]
        if name in mesh.regions:
            return f"{body}.{name}"
        if not len(rows):
            return None
        owner = self.owner.setdefault(body, {})
        taken = {owner[r] for r in rows.tolist() if r in owner}
        if taken:
            self.mapper.problems.append(error(f"on body {body} it shares facets with {', '.join(sorted(taken))}: "
                                              "a shockfem facet carries one region; split the sets so they do "
                                              "not overlap"))
            return None
        owner.update({r: name for r in rows.tolist()})
        mesh.regions[name] = rows
        return f"{body}.{name}"

    def from_nodes(self, node_ids, name: str, error) -> list[str]:
        """The regions a node set makes, one per body it covers facets of; a problem when it covers none."""
        node_ids = set(int(n) for n in node_ids)
        bodies = sorted({b for n in node_ids for b in self.mapper.node_body.get(n, ())})
        out = []
        for body in bodies:
            rows = self.mapper.meshes[body].facets_within(node_ids)
            region = self.add(body, name, rows, error)
            if region:
                out.append(region)
        if not out:
            self.mapper.problems.append(error("its nodes cover no whole boundary facet of any body: shockfem puts "
                                              "conditions and contacts on facets; give the nodes of whole faces"))
            return out
        covered = {int(n) for r in out for n in self.mapper.meshes[r.split(".")[0]].region_nodes(name)}
        if len(node_ids - covered):
            self.mapper.notes.append(error(f"{len(node_ids - covered)} of its {len(node_ids)} nodes are on no whole "
                                           "boundary facet of the set: left out of the region (shockfem puts "
                                           "conditions on facets)"))
        return out

    def from_segments(self, segments, name: str, error) -> list[str]:
        """The regions of a segment set's faces, one per body they lie on; a problem for faces of no body."""
        out, missed = [], [s for s, _, _ in segments]
        for body, mesh in self.mapper.meshes.items():
            rows, missed_here = mesh.facets_matching([s for s, _, _ in segments])
            missed = [s for s in missed if s in missed_here]
            region = self.add(body, name, rows, error)
            if region:
                out.append(region)
        if missed:
            self.mapper.problems.append(error(f"{len(missed)} of its {len(segments)} segments (the first "
                                              f"{list(missed[0])}) are no boundary face of any solid"))
        return out


def node_set(mapper, sid: int, error) -> list[int] | None:
    if sid not in mapper.m.node_sets:
        mapper.problems.append(error(f"node set {sid} is not defined by any *SET_NODE_LIST"))
        return None
    return mapper.m.node_sets[sid]


def part_bodies(mapper, pids, error) -> list[str]:
    out = []
    for pid in pids:
        if pid not in mapper.body_of_part:
            mapper.problems.append(error(f"part {pid} is not a part with solid elements (no *PART {pid}, or none "
                                         "of its elements read)"))
        else:
            out.append(mapper.body_of_part[pid])
    return out


def _bodies_of_set(mapper, nodes, error, what: str) -> list[str]:
    """The bodies a node set covers whole (shockfem gives initial velocities to whole bodies)."""
    nodes = set(int(n) for n in nodes)
    out = []
    for body, mesh in mapper.meshes.items():
        inside = np.isin(mesh.node_ids, list(nodes))
        if inside.all():
            out.append(body)
        elif inside.any():
            mapper.problems.append(error(f"{what} covers {int(inside.sum())} of body {body}'s {len(inside)} nodes: "
                                         "shockfem gives an initial velocity to whole bodies"))
    return out


def velocities(mapper):
    """*INITIAL_VELOCITY_GENERATION (STYP 1 part set, 2 part, 3 node set) and *INITIAL_VELOCITY."""
    given: dict[str, list] = {}
    for e in mapper.m.conditions:
        error = lambda msg, e=e: e.keyword.error(e.card, msg)
        v = e.values
        if e.kind == "velocity_generation":
            if v["OMEGA"]:
                mapper.problems.append(error("OMEGA: an initial spin is not mapped (shockfem's spin is about a "
                                             "body's own axis: give it in the scene, bodies[i].spin)"))
            if v["STYP"] == 2:
                bodies = part_bodies(mapper, [v["ID"]], error)
            elif v["STYP"] == 1:
                bodies = part_bodies(mapper, mapper.m.part_sets.get(v["ID"], []), error)
            elif v["STYP"] == 3:
                nodes = node_set(mapper, v["ID"], error)
                bodies = _bodies_of_set(mapper, nodes or [], error, f"node set {v['ID']}")
            else:
                mapper.problems.append(error(f"STYP {v['STYP']} is not mapped (1 part set, 2 part, 3 node set)"))
                continue
            vel = [v["VX"] or 0.0, v["VY"] or 0.0, v["VZ"] or 0.0]
        elif e.kind == "initial_velocity":
            if v["NSIDEX"] or v["BOXID"]:
                mapper.problems.append(error("NSIDEX / BOXID: exempted nodes and boxes are not mapped"))
            nodes = (node_set(mapper, v["NSID"], error) if v["NSID"]
                     else [int(n) for n in mapper.node_body])
            bodies = _bodies_of_set(mapper, nodes or [], error, f"node set {v['NSID']}")
            vel = v["V"]
        else:
            continue
        for body in bodies:
            if body in given and given[body][0] != vel:
                mapper.problems.append(error(f"body {body} already has the initial velocity {given[body][0]}"))
            given[body] = (vel, error)
    for i, b in enumerate(mapper.scene["bodies"]):
        if b["name"] in given:
            vel, error = given[b["name"]]
            b["velocity"] = [mapper.u.quantity(x, "velocity") for x in vel]
            mapper.origins[f"bodies[{i}].velocity"] = error


def constraints(mapper, regions: Regions):
    """*BOUNDARY_SPC_SET / _NODE and the nodes' own TC: all three translations held -> fixed, fewer ->
    each held direction a zero velocity (rotations: solids have none)."""
    single: dict[tuple, list] = {}
    for e in mapper.m.conditions:
        error = lambda msg, e=e: e.keyword.error(e.card, msg)
        v = e.values
        if e.kind == "node_constraint":
            dof = {1: "x", 2: "y", 3: "z", 4: "xy", 5: "yz", 6: "zx", 7: "xyz"}.get(v["tc"], "")
            if v["tc"]:
                single.setdefault(tuple(a in dof for a in AXES) + (e.keyword.where(),), []).append(v["nid"])
            continue
        if e.kind != "spc":
            continue
        if v["CID"]:
            mapper.problems.append(error(f"CID {v['CID']}: constraints in a local coordinate system are not mapped"))
            continue
        if v["target"] == "node":
            single.setdefault(tuple(v["DOF"]) + (e.keyword.where(),), []).append(v["ID"])
            continue
        nodes = node_set(mapper, v["ID"], error)
        if nodes:
            _held(mapper, regions.from_nodes(nodes, f"nodes{v['ID']}", error), v["DOF"], error)
    for key, nodes in single.items():
        error = lambda msg, where=key[3]: f"{where}: *BOUNDARY_SPC_NODE / *NODE TC: {msg}"
        name = f"held_{''.join(a for a, d in zip(AXES, key[:3]) if d)}"
        _held(mapper, regions.from_nodes(nodes, name, error), key[:3], error)


def _held(mapper, region_names, dofs, error):
    """Each region held along ``dofs`` (x, y, z flags); on a rigid body the body itself is held (its nodes
    move with it, ``scene/boundaries.py``): fixed when all three are (its turn held too), else its centre
    along each one, free to turn."""
    rigid = {b["name"] for b in mapper.scene["bodies"] if b.get("rigid")}
    done = set()
    for region in region_names:
        body = region.split(".")[0]
        if body in rigid:
            if body in done:
                continue
            done.add(body)
            mapper.notes.append(f"{region}: nodes of the rigid body {body} held: the body held "
                                + ("(fixed)" if all(dofs) else f"along {', '.join(a for a, d in zip(AXES, dofs) if d)}, "
                                   "free to turn"))
            region = body
        if all(dofs):
            mapper.add("boundary", {"region": region, "type": "fixed"}, error)
        else:
            for axis, held in zip(AXES, dofs):
                if held:
                    mapper.add("boundary", {"region": region, "type": "velocity", "direction": axis,
                                            "value": mapper.u.quantity(0.0, "velocity")}, error)


# *MAT_RIGID CON1 (CMO 1): the global translations it holds
RIGID_HELD = {0: "", 1: "x", 2: "y", 3: "z", 4: "xy", 5: "yz", 6: "zx", 7: "xyz"}


def rigid_constraints(mapper):
    """*MAT_RIGID CMO 1: its parts' bodies held along CON1's global axes (a zero velocity of the centre),
    or fixed when CON1 and CON2 hold every translation and rotation; a rotation held alone is refused
    (a shockfem rigid body's turn is held only with its translations)."""
    for mid, mat in mapper.m.materials.items():
        v = mat.values
        if mat.kind != "rigid" or v.get("CMO") != 1:
            continue
        error = lambda msg, mat=mat: mat.keyword.error(1, msg)
        con1, con2 = v.get("CON1") or 0, v.get("CON2") or 0
        if con1 not in RIGID_HELD or con2 not in RIGID_HELD:
            mapper.problems.append(error(f"CON1 {con1} / CON2 {con2}: each is a code 0 to 7 (CMO 1)"))
            continue
        if con2 and (con1, con2) != (7, 7):
            mapper.problems.append(error(f"CON2 {con2}: a rigid body's rotations are held only with all of its "
                                         "translations and rotations (CON1 7, CON2 7); else give CON2 0"))
            continue
        bodies = [mapper.body_of_part[p.pid] for p in mapper.m.parts.values()
                  if p.mid == mid and p.pid in mapper.body_of_part]
        for body in bodies:
            if con2:
                mapper.add("boundary", {"region": body, "type": "fixed"}, error)
            for axis in ("" if con2 else RIGID_HELD[con1]):
                mapper.add("boundary", {"region": body, "type": "velocity", "direction": axis,
                                        "value": mapper.u.quantity(0.0, "velocity")}, error)


def motions(mapper, regions: Regions, end_time: float | None):
    """*BOUNDARY_PRESCRIBED_MOTION_SET (on the regions of a node set) and _RIGID (the rigid body of a
    *MAT_RIGID part, driven whole: ``scene/boundaries.py``) with VAD = 0 (a velocity), DOF 1-3, the curve
    LCID times SF as the velocity's history."""
    for e in mapper.m.conditions:
        if e.kind != "motion":
            continue
        error = lambda msg, e=e: e.keyword.error(e.card, msg)
        v = e.values
        history = _motion_history(mapper, v, error, end_time)
        if history is None:
            continue
        if v["target"] == "rigid":
            targets = _driven_body(mapper, v["ID"], error)
        else:
            nodes = node_set(mapper, v["ID"], error)
            targets = regions.from_nodes(nodes or [], f"nodes{v['ID']}", error) if nodes else []
        for region in targets:
            mapper.add("boundary", {"region": region, "type": "velocity", "direction": AXES[v["DOF"] - 1],
                                    "history": history}, error)


def _motion_history(mapper, v: dict, error, end_time: float | None) -> list | None:
    """A prescribed motion's velocity history, the curve LCID times SF, in the scene's units; None (and a
    problem) for what is not mapped: VAD other than 0, DOF other than 1-3, a missing curve, a BIRTH or a
    DEATH inside the run."""
    if v["VAD"] != 0:
        mapper.problems.append(error(f"VAD {v['VAD']}: only a prescribed velocity (VAD 0) is mapped; give the "
                                     "velocity's curve (a displacement's slope, an acceleration's integral)"))
        return None
    if v["DOF"] not in (1, 2, 3):
        what = ("a translation along the vector VID" if v["DOF"] in (4, -4) else
                "a rotation" if v["DOF"] in (5, 6, 7, 9, 10, 11, -9, -10, -11) else "not a DOF code")
        mapper.problems.append(error(f"DOF {v['DOF']} ({what}): only x, y, z translations (1, 2, 3) are mapped; "
                                     "give one card per axis"))
        return None
    curve = mapper.m.curves.get(v["LCID"])
    if curve is None:
        mapper.problems.append(error("LCID is blank: a prescribed motion needs the curve of its velocity" if
                                     v["LCID"] is None else f"LCID {v['LCID']} is not defined by any *DEFINE_CURVE"))
        return None
    if (v["BIRTH"] or 0.0) > 0 or (v["DEATH"] and end_time and v["DEATH"] < end_time):
        mapper.problems.append(error("BIRTH / DEATH inside the run: a motion that starts or stops is not "
                                     "mapped; put it in the curve"))
        return None
    sf = v["SF"] if v["SF"] is not None else 1.0
    return [[mapper.u.quantity(t, "time"), mapper.u.quantity(sf * y, "velocity")] for t, y in zip(curve.x, curve.y)]


def _driven_body(mapper, pid: int, error) -> list[str]:
    """The body of the rigid part ``pid`` a *BOUNDARY_PRESCRIBED_MOTION_RIGID drives, or none (and a problem:
    not a part, or a deformable one)."""
    bodies = part_bodies(mapper, [pid], error)
    body = next((b for b in mapper.scene["bodies"] if bodies and b["name"] == bodies[0]), None)
    if body is not None and not body.get("rigid"):
        mapper.problems.append(error(f"part {pid} is not rigid (its material is no *MAT_RIGID): drive the nodes "
                                     "of a deformable part with *BOUNDARY_PRESCRIBED_MOTION_SET"))
        return []
    return bodies


def _surfaces(mapper, regions: Regions, sid: int, styp: int, error, name: str) -> list[str]:
    """A contact side: 0 segment set, 2 part set, 3 part, 4 node set; 5 / 6 (all) as every body."""
    if styp == 0:
        if sid not in mapper.m.segment_sets:
            mapper.problems.append(error(f"segment set {sid} is not defined by any *SET_SEGMENT"))
            return []
        return regions.from_segments(mapper.m.segment_sets[sid], f"segments{sid}", error)
    if styp == 2:
        if sid not in mapper.m.part_sets:
            mapper.problems.append(error(f"part set {sid} is not defined by any *SET_PART_LIST"))
            return []
        return part_bodies(mapper, mapper.m.part_sets[sid], error)
    if styp == 3:
        return part_bodies(mapper, [sid], error)
    if styp == 4:
        nodes = node_set(mapper, sid, error)
        return regions.from_nodes(nodes or [], f"nodes{sid}", error) if nodes else []
    if styp in (5, 6) or (styp == 0 and sid == 0):
        return list(mapper.meshes)
    mapper.problems.append(error(f"{name}TYP {styp} is not mapped (0 segment set, 2 part set, 3 part, 4 node set)"))
    return []


def contacts(mapper, regions: Regions):
    """*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE, _NODES_TO_SURFACE and _SINGLE_SURFACE as penalty contacts
    between bodies (shockfem's segment penalty is LS-DYNA's SOFT = 0 stiffness, k = SLSFAC SFS K A^2 / V)."""
    values, kw = mapper.m.controls.get("CONTROL_CONTACT", ({}, None))
    slsfac = values.get("SLSFAC") or 0.1
    if slsfac < 0:
        mapper.problems.append(kw.error(0, f"SLSFAC {slsfac:g}: the penalty scale must be positive"))
        slsfac = 0.1
    for n, e in enumerate(mapper.m.contacts, start=1):
        error = lambda msg, e=e: e.keyword.error(e.card, msg)
        v = e.values
        a = _surfaces(mapper, regions, v["SSID"], v["SSTYP"], error, "SSID")
        if e.kind == "single_surface":
            pairs = list(itertools.combinations(a, 2))
            mapper.notes.append(f"contact {n} (single surface): as contacts between each pair of its {len(a)} "
                                "bodies; a body's contact with itself is not modelled")
        else:
            b = _surfaces(mapper, regions, v["MSID"], v["MSTYP"], error, "MSID")
            pairs = [(x, y) for x in a for y in b if x.split(".")[0] != y.split(".")[0]]
            if e.kind == "nodes_to_surface":
                mapper.notes.append(f"contact {n} (nodes to surface): shockfem's contact is two-sided, both "
                                    "surfaces push")
        for k, (x, y) in enumerate(pairs):
            entry = {"name": f"contact{n}" + (f"_{k + 1}" if len(pairs) > 1 else ""), "a": x, "b": y,
                     "penalty": "segment", "penalty_scale": slsfac * max(v["SFS"], v["SFM"]),
                     "damping": v["VDC"] / 100.0}
            if v["FS"]:
                entry["friction"] = v["FS"]
                entry["friction_dynamic"] = v["FD"] if v["FD"] is not None else v["FS"]
                if v["DC"]:
                    entry["friction_decay"] = mapper.u.quantity(v["DC"], "slowness")
            mapper.add("contact", entry, error)


def walls(mapper, regions: Regions):
    """*RIGIDWALL_PLANAR: the constraint wall of the scene (``method = "constraint"``), frictionless."""
    for n, e in enumerate(mapper.m.walls, start=1):
        error = lambda msg, e=e: e.keyword.error(e.card, msg)
        v = e.values
        if v["FRIC"]:
            mapper.problems.append(error(f"FRIC {v['FRIC']:g}: shockfem's constraint wall is frictionless; set "
                                         "FRIC 0, or use a rigid body and a contact with friction"))
        if v["NSIDEX"] or v["BOXID"]:
            mapper.problems.append(error("NSIDEX / BOXID: exempted nodes and boxes are not mapped"))
        if v["NSID"]:
            nodes = node_set(mapper, v["NSID"], error)
            surfaces = regions.from_nodes(nodes or [], f"nodes{v['NSID']}", error) if nodes else []
        else:
            surfaces = list(mapper.meshes)
        normal = np.subtract(v["head"], v["tail"])
        if not np.linalg.norm(normal):
            mapper.problems.append(error("the head XH YH ZH is the tail XT YT ZT: the wall has no normal"))
            continue
        for k, surface in enumerate(surfaces):
            mapper.add("contact", {
                "name": f"wall{n}" + (f"_{k + 1}" if len(surfaces) > 1 else ""), "a": surface, "method": "constraint",
                "wall": {"point": [mapper.u.quantity(x, "length") for x in v["tail"]],
                         "normal": [float(x) for x in normal]}}, error)
