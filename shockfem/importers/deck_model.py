"""What an LS-DYNA deck says, keyword by keyword, in the deck's own numbers and ids.

Each mapped keyword has one small reader (``READERS``) that reads its cards into ``DeckModel``; a keyword
without one is counted in the import report with what it would have done.  Nothing here knows about
shockfem's scenes: ``scene_out.py`` turns the model into one, so that the card layouts (this module) and
the meaning given to them (that one) are each in one place.  Card layouts are those of the LS-DYNA Keyword
User's Manual, Volume I (R13), each keyword's section.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from .cards import DeckError, Keyword

W10 = [10]


@dataclass
class Material:
    """A *MAT_ card: its kind (``elastic``, ``plastic_kinematic``, ``piecewise_linear``, ``rigid``,
    ``crushable_foam``) and its named fields in deck units."""
    kind: str
    values: dict
    keyword: Keyword


@dataclass
class Curve:
    """A *DEFINE_CURVE: abscissae and ordinates with its scale factors and offsets applied."""
    x: np.ndarray
    y: np.ndarray
    keyword: Keyword


@dataclass
class Part:
    pid: int
    title: str
    secid: int
    mid: int
    keyword: Keyword
    card: int


@dataclass
class Entry:
    """A keyword's entry that points at others (sets, parts, curves): its fields and where it is, so that
    a dangling reference is reported on its own card."""
    kind: str
    values: dict
    keyword: Keyword
    card: int


@dataclass
class DeckModel:
    title: str = ""
    node_ids: list = field(default_factory=list)
    coords: list = field(default_factory=list)
    node_cards: list = field(default_factory=list)           # (keyword, card) of each of node_ids
    elements: list = field(default_factory=list)             # (eid, pid, node ids, keyword, card, node card)
    parts: dict = field(default_factory=dict)
    sections: dict = field(default_factory=dict)             # secid -> (elform, keyword)
    materials: dict = field(default_factory=dict)
    curves: dict = field(default_factory=dict)
    tables: dict = field(default_factory=dict)               # tbid -> (values, curve ids, keyword)
    node_sets: dict = field(default_factory=dict)
    part_sets: dict = field(default_factory=dict)
    segment_sets: dict = field(default_factory=dict)
    conditions: list = field(default_factory=list)           # Entry: velocity, spc, motion
    contacts: list = field(default_factory=list)             # Entry
    walls: list = field(default_factory=list)                # Entry
    controls: dict = field(default_factory=dict)             # name -> (values, keyword)
    outputs: dict = field(default_factory=dict)              # *DATABASE_ name -> interval (deck time)
    output_keywords: dict = field(default_factory=dict)      # *DATABASE_ name -> its Keyword
    unmapped: Counter = field(default_factory=Counter)
    problems: list = field(default_factory=list)
    unread: set = field(default_factory=set)                 # keywords a card of which was refused


def _strip_title(kw: Keyword) -> Keyword:
    """A keyword with the ``_TITLE`` option: its first card is a title, the layout follows it."""
    if kw.name.endswith("_TITLE"):
        return Keyword(kw.name[:-6], kw.path, kw.line, kw.cards[1:], kw.long_flag, kw.parameters)
    return kw


def _node(kw, m):
    for c in range(len(kw.cards)):
        nid, x, y, z, tc, rc = kw.fields(c, [8, 16, 16, 16, 8, 8], "iffffi", required=1)
        m.node_ids.append(nid)
        m.coords.append((x or 0.0, y or 0.0, z or 0.0))
        m.node_cards.append((kw, c))
        if tc or rc:
            m.conditions.append(Entry("node_constraint", {"nid": nid, "tc": tc or 0, "rc": rc or 0}, kw, c))


def _element_solid(kw, m):
    """Two cards per element (EID PID; then up to ten nodes), or the older single card EID PID N1..N8."""
    c = 0
    while c < len(kw.cards):
        first = kw.fields(c, [8], "i" * 10, required=2)
        if any(first[2:]):
            nodes, node_card = first[2:], c
        else:
            nodes, node_card = kw.fields(c + 1, [8], "i" * 10, required=4), c + 1
        m.elements.append((first[0], first[1], tuple(n for n in nodes if n), kw, c, node_card))
        c = node_card + 1


def _part(kw, m):
    """Pairs of cards: a heading, then PID SECID MID EOSID HGID ..."""
    for c in range(0, len(kw.cards), 2):
        title = kw.cards[c].text.strip()
        pid, secid, mid, eosid, hgid = kw.fields(c + 1, W10, "iiiii", required=3)
        m.parts[pid] = Part(pid, title, secid, mid, kw, c + 1)
        if eosid:
            m.problems.append(kw.error(c + 1, f"part {pid}: an equation of state (EOSID {eosid}) is not mapped; "
                                              "shockfem's solids take their pressure from the material"))
        if hgid:
            m.unmapped["PART (HGID: a part's own *HOURGLASS)"] += 1


def _section_solid(kw, m):
    kw = _strip_title(kw)
    secid, elform = kw.fields(0, W10, "ii", required=1)
    m.sections[secid] = (elform or 1, kw)


# material layouts: kind, then per card the field names (LS-DYNA Keyword Manual, Volume II)
MATERIALS = {
    "ELASTIC": ("elastic", ["MID RO E PR DA DB K"]),
    "PLASTIC_KINEMATIC": ("plastic_kinematic", ["MID RO E PR SIGY ETAN BETA", "SRC SRP FS VP"]),
    "PIECEWISE_LINEAR_PLASTICITY": ("piecewise_linear", ["MID RO E PR SIGY ETAN FAIL TDEL",
                                                         "C P LCSS LCSR VP",
                                                         "EPS1 EPS2 EPS3 EPS4 EPS5 EPS6 EPS7 EPS8",
                                                         "ES1 ES2 ES3 ES4 ES5 ES6 ES7 ES8"]),
    "RIGID": ("rigid", ["MID RO E PR N COUPLE M ALIAS", "CMO CON1 CON2"]),
    "CRUSHABLE_FOAM": ("crushable_foam", ["MID RO E PR LCID TSC DAMP"]),
}
MATERIAL_NUMBERS = {"001": "ELASTIC", "003": "PLASTIC_KINEMATIC", "024": "PIECEWISE_LINEAR_PLASTICITY",
                    "020": "RIGID", "063": "CRUSHABLE_FOAM"}


def material_name(name: str) -> str | None:
    """``MAT_ELASTIC`` / ``MAT_001`` (``_TITLE`` stripped) -> the layout's key, or None when not mapped."""
    base = name[4:]
    base = MATERIAL_NUMBERS.get(base, base)
    return base if base in MATERIALS else None


def _material(kw, m):
    kw = _strip_title(kw)
    kind, cards = MATERIALS[material_name(kw.name)]
    values = {}
    for c, names in enumerate(cards):
        names = names.split()
        ints = {"MID", "LCSS", "LCSR", "LCID", "CMO", "CON1", "CON2", "VP", "N", "COUPLE", "ALIAS"}
        row = kw.fields(c, W10, "".join("i" if n in ints else "f" for n in names), required=4 if c == 0 else 0)
        values.update(zip(names, row))
    m.materials[values["MID"]] = Material(kind, values, kw)


def _define_curve(kw, m):
    kw = _strip_title(kw)
    lcid, sidr, sfa, sfo, offa, offo = kw.fields(0, W10, "iiffff", required=1)
    points = [kw.fields(c, [20], "ff", required=2) for c in range(1, len(kw.cards))]
    if not points:
        raise DeckError([kw.error(0, f"curve {lcid} has no points")])
    x, y = np.array(points, dtype=float).T
    m.curves[lcid] = Curve((sfa or 1.0) * (x + (offa or 0.0)), (sfo or 1.0) * (y + (offo or 0.0)), kw)
    if m.tables and m.tables.get("_open"):
        tbid = m.tables["_open"]
        m.tables[tbid][1].append(lcid)
        if len(m.tables[tbid][1]) == len(m.tables[tbid][0]):
            del m.tables["_open"]


def _define_table(kw, m):
    """A table's values (one a card) name the curves that follow it, in order."""
    kw = _strip_title(kw)
    tbid, = kw.fields(0, W10, "i", required=1)
    values = [kw.fields(c, [20], "f", required=1)[0] for c in range(1, len(kw.cards))]
    m.tables[tbid] = (values, [], kw)
    m.tables["_open"] = tbid


def _id_list(kw, m, store):
    """*SET_NODE_LIST / *SET_PART_LIST: SID on the first card, then eight ids a card."""
    kw = _strip_title(kw)
    sid, = kw.fields(0, W10, "i", required=1)
    ids = []
    for c in range(1, len(kw.cards)):
        ids += [i for i in kw.fields(c, W10, "i" * 8) if i]
    store.setdefault(sid, []).extend(ids)
    return sid


def _set_node(kw, m):
    _id_list(kw, m, m.node_sets)


def _set_part(kw, m):
    _id_list(kw, m, m.part_sets)


def _set_segment(kw, m):
    kw = _strip_title(kw)
    sid, = kw.fields(0, W10, "i", required=1)
    segs = [tuple(n for n in kw.fields(c, W10, "iiii", required=3) if n) for c in range(1, len(kw.cards))]
    m.segment_sets.setdefault(sid, []).extend((s, kw, c + 1) for c, s in enumerate(segs))


def _initial_velocity_generation(kw, m):
    """ID STYP OMEGA VX VY VZ IVATN ICID; XC YC ZC NX NY NZ PHASE IRIGID."""
    row = kw.fields(0, W10, "iifffffi", required=2)
    m.conditions.append(Entry("velocity_generation", dict(zip("ID STYP OMEGA VX VY VZ IVATN ICID".split(), row)),
                              kw, 0))


def _initial_velocity(kw, m):
    """NSID NSIDEX BOXID IRIGID ICID; VX VY VZ VXR VYR VZR."""
    nsid, nsidex, boxid = kw.fields(0, W10, "iii", required=1)
    v = kw.fields(1, W10, "ffffff", required=0)
    m.conditions.append(Entry("initial_velocity", {"NSID": nsid, "NSIDEX": nsidex, "BOXID": boxid,
                                                   "V": [x or 0.0 for x in v[:3]], "VR": v[3:]}, kw, 0))


def _boundary_spc(kw, m):
    """*BOUNDARY_SPC_NODE / _SET: (N)ID CID DOFX DOFY DOFZ DOFRX DOFRY DOFRZ, a card per node or set."""
    target = "node" if kw.name.endswith("_NODE") else "set"
    for c in range(len(kw.cards)):
        row = kw.fields(c, W10, "iiiiiiii", required=1)
        m.conditions.append(Entry("spc", {"target": target, "ID": row[0], "CID": row[1],
                                          "DOF": [bool(d) for d in row[2:5]]}, kw, c))


def _prescribed_motion(kw, m):
    """*BOUNDARY_PRESCRIBED_MOTION_SET / _RIGID: (N)SID|PID DOF VAD LCID SF VID DEATH BIRTH (VAD blank: 0,
    a velocity, LS-DYNA's default)."""
    target = "set" if kw.name.endswith("_SET") else "rigid"
    for c in range(len(kw.cards)):
        row = kw.fields(c, W10, "iiiififf", required=2)
        row[2] = row[2] or 0
        m.conditions.append(Entry("motion", {"target": target, **dict(zip("ID DOF VAD LCID SF VID DEATH BIRTH"
                                                                          .split(), row))}, kw, c))


def _contact(kw, m):
    """*CONTACT_AUTOMATIC_...: SSID MSID SSTYP MSTYP ...; FS FD DC VC VDC ...; SFS SFM ... (the _ID or
    _TITLE option puts an id card first)."""
    name = kw.name
    first = 1 if name.endswith("_ID") or name.endswith("_TITLE") else 0
    base = name.removesuffix("_ID").removesuffix("_TITLE")
    row = kw.fields(first, W10, "iiii", required=1)
    friction = kw.fields(first + 1, W10, "fffff")
    scales = kw.fields(first + 2, W10, "ff")
    m.contacts.append(Entry(base.removeprefix("CONTACT_AUTOMATIC_").lower(),
                            {"SSID": row[0], "MSID": row[1] or 0, "SSTYP": row[2] or 0, "MSTYP": row[3] or 0,
                             "FS": friction[0] or 0.0, "FD": friction[1], "DC": friction[2] or 0.0,
                             "VDC": friction[4] or 0.0, "SFS": scales[0] or 1.0, "SFM": scales[1] or 1.0},
                            kw, first))


def _rigidwall_planar(kw, m):
    """NSID NSIDEX BOXID OFFSET BIRTH DEATH RWKSF; XT YT ZT XH YH ZH FRIC WVEL."""
    nsid, nsidex, boxid = kw.fields(0, W10, "iii", required=0)
    pts = kw.fields(1, W10, "ffffffff", required=6)
    m.walls.append(Entry("planar", {"NSID": nsid or 0, "NSIDEX": nsidex or 0, "BOXID": boxid or 0,
                                    "tail": [v or 0.0 for v in pts[:3]], "head": [v or 0.0 for v in pts[3:6]],
                                    "FRIC": pts[6] or 0.0, "WVEL": pts[7] or 0.0}, kw, 1))


CONTROLS = {
    "CONTROL_TERMINATION": ("ENDTIM", "f"),
    "CONTROL_TIMESTEP": ("DTINIT TSSFAC ISDO TSLIMT DT2MS", "fffff"),
    "CONTROL_HOURGLASS": ("IHQ QH", "if"),
    "CONTROL_BULK_VISCOSITY": ("Q1 Q2", "ff"),
    "CONTROL_CONTACT": ("SLSFAC", "f"),
}


def _control(kw, m):
    names, kinds = CONTROLS[kw.name]
    m.controls[kw.name] = (dict(zip(names.split(), kw.fields(0, W10, kinds))), kw)


def _database(kw, m):
    dt, = kw.fields(0, W10, "f", required=1)
    m.outputs[kw.name] = dt
    m.output_keywords[kw.name] = kw


READERS = {
    "NODE": _node, "ELEMENT_SOLID": _element_solid, "PART": _part, "SECTION_SOLID": _section_solid,
    "DEFINE_CURVE": _define_curve, "DEFINE_TABLE": _define_table,
    "SET_NODE_LIST": _set_node, "SET_PART_LIST": _set_part, "SET_SEGMENT": _set_segment,
    "INITIAL_VELOCITY_GENERATION": _initial_velocity_generation, "INITIAL_VELOCITY": _initial_velocity,
    "BOUNDARY_SPC_NODE": _boundary_spc, "BOUNDARY_SPC_SET": _boundary_spc,
    "BOUNDARY_PRESCRIBED_MOTION_SET": _prescribed_motion, "BOUNDARY_PRESCRIBED_MOTION_RIGID": _prescribed_motion,
    "RIGIDWALL_PLANAR": _rigidwall_planar,
    **{name: _control for name in CONTROLS},
    **{f"DATABASE_{name}": _database for name in ("GLSTAT", "MATSUM", "RCFORC", "NODOUT", "BINARY_D3PLOT")},
}
CONTACTS = ("SURFACE_TO_SURFACE", "NODES_TO_SURFACE", "SINGLE_SURFACE")

# keywords refused outright: the model would be wrong without them (what they are, and the way round)
REFUSED = {
    "ELEMENT_SHELL": "shell elements: shockfem meshes solids only; mesh the part with solid elements",
    "ELEMENT_BEAM": "beam elements: shockfem meshes solids only; mesh the part with solid elements "
                    "or model the member as a [[spring]]",
    "ELEMENT_TSHELL": "thick shells: mesh the part with solid elements",
    "SECTION_SHELL": "shell sections: shockfem meshes solids only",
    "SECTION_BEAM": "beam sections: shockfem meshes solids only",
    "PARAMETER_EXPRESSION": "parameter expressions are not evaluated; give the values as *PARAMETER",
    "INCLUDE_TRANSFORM": "transformed includes are not read; include the file as it is",
}

# families of keywords that change what is modelled: one not mapped is refused, not listed (loads, joints,
# contacts, constraints, initial states, equations of state, discrete masses and springs)
REFUSED_FAMILIES = {
    "CONTACT_": "this contact is not mapped (shockfem maps the AUTOMATIC surface-to-surface, nodes-to-surface "
                "and single-surface contacts)",
    "CONSTRAINED_": "constraints (joints, welds, merged rigid bodies) are not mapped",
    "LOAD_": "loads are not mapped; give them in the scene ([[boundary]] force, scene.gravity)",
    "BOUNDARY_": "this boundary condition is not mapped (shockfem maps *BOUNDARY_SPC_SET / _NODE and "
                 "*BOUNDARY_PRESCRIBED_MOTION_SET / _RIGID)",
    "INITIAL_": "this initial condition is not mapped (shockfem maps *INITIAL_VELOCITY and "
                "*INITIAL_VELOCITY_GENERATION)",
    "EOS_": "equations of state are not mapped; shockfem's solids take their pressure from the material",
    "ELEMENT_": "only *ELEMENT_SOLID is mapped (discrete masses, springs and other elements are not): give "
                "springs as [[spring]] in the scene",
    "DAMPING_": "damping is not mapped; give it in the scene ([damping], bodies[i].damping)",
}

# what common keywords not mapped would have done, for the import report
WOULD_HAVE = {
    "DATABASE_HISTORY_NODE": "listed nodes for nodout (shockfem: [shock] accelerometers)",
    "DATABASE_EXTENT_BINARY": "chose the d3plot's extra variables (shockfem writes its own fields)",
    "DATABASE_SPCFORC": "written constraint forces", "DATABASE_ELOUT": "written element histories",
    "DATABASE_BNDOUT": "written boundary forces", "DATABASE_SLEOUT": "written sliding interface energies",
    "DATABASE_SECFORC": "written section forces (shockfem: outputs.sections)",
    "CONTROL_ENERGY": "chose which energies are computed (shockfem computes all of them)",
    "CONTROL_SOLID": "set solid element options", "CONTROL_SHELL": "set shell options (no shells here)",
    "CONTROL_OUTPUT": "set printed output", "CONTROL_ACCURACY": "set objective stress update and accuracy "
                                                               "options (shockfem's update is objective)",
    "HOURGLASS": "set a part's own hourglass control (shockfem: one for the scene, *CONTROL_HOURGLASS)",
}


def read_model(title: str, keywords: list[Keyword]) -> DeckModel:
    """Every keyword read into a ``DeckModel``; problems (refused keywords, bad cards) gathered in
    ``model.problems`` so that a deck's every problem is listed at once."""
    m = DeckModel(title=title)
    for kw in keywords:
        reader = _reader(kw)
        if reader is None:
            base = kw.name.removesuffix("_TITLE").removesuffix("_ID")
            family = next((f for f in REFUSED_FAMILIES if base.startswith(f)), None)
            if base in REFUSED or base.startswith("ELEMENT_SHELL"):
                m.problems.append(kw.error(None, REFUSED.get(base, REFUSED["ELEMENT_SHELL"])))
            elif family:
                m.problems.append(kw.error(None, REFUSED_FAMILIES[family]))
            elif base.startswith("MAT_"):
                m.problems.append(kw.error(None, "this material is not mapped (shockfem maps *MAT_ELASTIC, "
                                                 "*MAT_PLASTIC_KINEMATIC, *MAT_PIECEWISE_LINEAR_PLASTICITY, "
                                                 "*MAT_RIGID and *MAT_CRUSHABLE_FOAM); the parts that use it "
                                                 "are listed below"))
                m.unmapped[f"{base} (refused)"] += 1
                m.materials.setdefault(_mid(kw), Material("refused", {}, kw))
            else:
                m.unmapped[base] += 1
            continue
        try:
            reader(kw, m)
        except DeckError as e:
            m.problems += e.problems
            m.unread.add(kw.name)
    m.tables.pop("_open", None)
    return m


def _mid(kw: Keyword) -> int | None:
    try:
        return _strip_title(kw).fields(0, W10, "i")[0]
    except DeckError:
        return None


def _reader(kw: Keyword):
    name = kw.name
    if name in READERS:
        return READERS[name]
    base = name.removesuffix("_TITLE")
    if base in READERS and base.startswith(("SECTION_", "DEFINE_", "SET_")):
        return READERS[base]
    if name.startswith("MAT_") and material_name(base) is not None:
        return _material
    contact = name.removesuffix("_ID").removesuffix("_TITLE")
    if contact.startswith("CONTACT_AUTOMATIC_") and contact.removeprefix("CONTACT_AUTOMATIC_") in CONTACTS:
        return _contact
    return None
