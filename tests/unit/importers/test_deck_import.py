"""LS-DYNA decks to scenes: the mapped keywords, a deck in every format reading as its plain form, the
import report, and bad decks refused naming the keyword, card and line (exit 2)."""
import os
import pathlib

import numpy as np
import pytest

from shockfem.cli import main
from shockfem.importers import import_model
from shockfem.importers.lsdyna import deck_to_scene
from shockfem.importers.mesh_out import signed_volumes
from shockfem.importers.unit_sets import unit_set
from shockfem.scene import SceneError, load_scene
from shockfem.units import to_si

DECKS = pathlib.Path(__file__).parent / "decks"
PLAIN = DECKS / "block_plain.k"
MM_MS = unit_set("mm-ms-kg-kN")
# a deck's number times pint's factors (powers of ten, exact in decimal): round-off only; a wrong unit
# or factor is off by 10^3 or more
EXACT = 1e-12


def _lines():
    return PLAIN.read_text().splitlines()


def _write(tmp_path, lines, name="bad.k"):
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def test_every_format_reads_as_the_plain_deck():
    """block_fancy.k is block_plain.k with *PARAMETER, *INCLUDE (long-format nodes, single-card elements),
    free format, _TITLE / _ID options and MAT_024 by number: the same scene and meshes, bit for bit."""
    plain, fancy = deck_to_scene(str(PLAIN), MM_MS), deck_to_scene(str(DECKS / "block_fancy.k"), MM_MS)
    plain.scene["scene"]["name"] = fancy.scene["scene"]["name"]
    assert plain.scene == fancy.scene
    assert plain.meshes.keys() == fancy.meshes.keys()
    for name, mesh in plain.meshes.items():
        other = fancy.meshes[name]
        assert np.array_equal(mesh.coords, other.coords) and np.array_equal(mesh.cells, other.cells)
        assert mesh.regions.keys() == other.regions.keys()


def test_the_plain_deck_maps_every_keyword():
    out = deck_to_scene(str(PLAIN), MM_MS)
    s = out.scene
    # values from the deck's cards, converted by hand: 7.85e-6 kg/mm^3 = 7850 kg/m^3, 210 kN/mm^2 = 210 GPa,
    # 50 mm/ms = 50 m/s, 0.05 ms; 1e-12 relative: pint's factors are exact decimal powers (round-off only)
    assert to_si(s["materials"]["mat1"]["density"], "density") == pytest.approx(7850.0, rel=EXACT)
    assert to_si(s["materials"]["mat1"]["youngs_modulus"], "pressure") == pytest.approx(210e9, rel=EXACT)
    assert to_si(s["materials"]["mat1"]["cowper_symonds_D"], "strain_rate") == pytest.approx(40.4e3, rel=EXACT)
    assert s["materials"]["mat1"]["rate_form"] == "plastic-strain-rate"                       # VP = 1
    assert s["materials"]["mat1"]["isotropic_fraction"] == 0.5
    curve = s["materials"]["mat2"]["hardening_curve"]
    assert [c[0] for c in curve] == [0.0, 0.1, 0.5]
    assert to_si(curve[1][1], "pressure") == pytest.approx(310e6, rel=EXACT)
    assert to_si(s["scene"]["end_time"], "time") == pytest.approx(50e-6, rel=EXACT)
    # DT2MS = -1e-5 ms with TSSFAC 0.8: the scaled elements' step TSSFAC |DT2MS| = 0.008 us (below the
    # elements' own 0.067 us: nothing is scaled when it runs)
    assert to_si(s["scene"]["mass_scaling_step"], "time") == pytest.approx(0.008e-6, rel=EXACT)
    assert s["scene"]["safety_factor"] == 0.8 and s["scene"]["hourglass"] == "stiffness"
    block = next(b for b in s["bodies"] if b["name"] == "block")
    assert [to_si(v, "velocity") for v in block["velocity"]] == [0.0, 0.0, pytest.approx(-50.0, rel=EXACT)]
    assert s["boundary"] == [{"region": "plate.nodes5", "type": "fixed"}]
    # the two bottom faces of the block's two hexes (segment set 1), the plate's base (node set 5)
    assert len(out.meshes["block"].regions["segments1"]) == 2 and len(out.meshes["plate"].regions["nodes5"]) == 1
    contact, = s["contact"]
    assert (contact["a"], contact["b"], contact["friction"], contact["friction_dynamic"]) == (
        "block.segments1", "plate", 0.3, 0.2)
    assert contact["damping"] == 0.1 and contact["penalty_scale"] == 0.1       # VDC 10 %, SLSFAC 0.1 x SFS 1
    # DC 0.5 ms/mm = 0.5e-3 s / 1e-3 m = 0.5 s/m
    assert to_si(contact["friction_decay"], "slowness") == pytest.approx(0.5, rel=EXACT)
    # the mesh in metres: the block spans x 0..2 mm
    assert np.ptp(out.meshes["block"].coords[:, 0]) == pytest.approx(2e-3, rel=EXACT)
    assert {k: n for k, (n, _) in out.unmapped.items()} == {"DATABASE_EXTENT_BINARY": 1, "DATABASE_HISTORY_NODE": 2}


def test_written_scene_loads_and_report_lists_unmapped(tmp_path):
    done = import_model(str(PLAIN), str(tmp_path / "block.toml"), "mm-ms-kg-kN")
    scene = load_scene(done.scene)
    assert [b.name for b in scene.bodies] == ["block", "plate"]
    assert all(os.path.exists(b.mesh_file) for b in scene.bodies)
    assert scene.materials["mat1"].rho == pytest.approx(7850.0, rel=EXACT)
    text = pathlib.Path(done.report).read_text()
    assert "*DATABASE_HISTORY_NODE" in text and "   2  listed nodes" in text


def _problems(path, units="mm-ms-kg-kN"):
    with pytest.raises(SceneError) as e:
        import_model(path, None, units)
    return e.value.problems


def test_missing_node_names_the_element_card_and_line(tmp_path):
    lines = _lines()
    k = lines.index(next(l for l in lines if l.startswith("       5 ")))       # node 5
    del lines[k]
    element = lines.index("       1       2       5       4       7       8      11      10") + 1
    path = _write(tmp_path, lines)
    assert f"bad.k:{element}: *ELEMENT_SOLID card 2: element 1: node 5 is not defined by any *NODE" in _problems(path)


def test_unknown_part_names_the_element_card_and_line(tmp_path):
    lines = _lines()
    k = lines.index("       3       2")
    lines[k] = "       3       9"
    problems = _problems(_write(tmp_path, lines))
    assert f"bad.k:{k + 1}: *ELEMENT_SOLID card 5: element 3: part 9 is not defined by any *PART" in problems


def test_truncated_card_names_keyword_card_and_line(tmp_path):
    lines = _lines()
    k = lines.index("*MAT_PLASTIC_KINEMATIC") + 1
    lines[k] = lines[k][:20]                                  # MID and RO only: E, PR missing
    problems = _problems(_write(tmp_path, lines))
    assert any(p.startswith(f"bad.k:{k + 1}: *MAT_PLASTIC_KINEMATIC card 1: field 3 is blank") for p in problems)


def test_non_finite_numbers_and_huge_ids_are_refused_by_card(tmp_path):
    """NaN, infinity and a number beyond a double in a real field, and in an integer field (where int() of
    them raised ValueError / OverflowError: the import fuzz found it), and an id beyond 32 bits."""
    lines = _lines()
    hourglass = lines.index("*CONTROL_HOURGLASS") + 1
    lines[hourglass] = f"{'nan':>10}{'inf':>10}"
    timestep = lines.index("*CONTROL_TIMESTEP") + 1
    lines[timestep] = f"{0.0:10}{'1e400':>10}"
    part = lines.index("block") + 1
    lines[part] = f"{'9999999999':>10}{1:10}{1:10}"
    problems = "\n".join(_problems(_write(tmp_path, lines)))
    assert f"bad.k:{hourglass + 1}: *CONTROL_HOURGLASS card 1: field 1: 'nan' is not a finite number" in problems
    assert f"bad.k:{timestep + 1}: *CONTROL_TIMESTEP card 1: field 2: '1e400' is not a finite number" in problems
    assert f"bad.k:{part + 1}: *PART card 2: field 1: '9999999999' is beyond the largest id" in problems


def test_a_node_defined_twice_names_both_lines(tmp_path):
    """A keyword line deleted makes the next keyword's cards nodes (the import fuzz found the message
    without a line): each repeated id is said at its second card, with where the first is."""
    lines = _lines()
    k = lines.index(next(l for l in lines if l.startswith("       5 ")))       # node 5
    lines.insert(k + 3, lines[k])
    assert f"bad.k:{k + 4}: *NODE card 8: node 5 is defined 2 times (first at bad.k:{k + 1})" in _problems(
        _write(tmp_path, lines))


def test_end_time_problems_name_the_keyword_or_the_deck(tmp_path):
    lines = _lines()
    k = lines.index("*CONTROL_TERMINATION")
    lines[k + 1] = f"{0.0:10}"
    assert f"bad.k:{k + 2}: *CONTROL_TERMINATION card 1: ENDTIM is blank or 0" in "\n".join(
        _problems(_write(tmp_path, lines)))
    del lines[k:k + 2]
    assert "bad.k: no *CONTROL_TERMINATION: the run needs an end time" in "\n".join(
        _problems(_write(tmp_path, lines)))


def test_values_the_scene_refuses_are_said_at_their_deck_card(tmp_path):
    """A value the cards allow but the scene does not (a negative density, a negative end time, a safety
    factor above 1) is refused at import, at the card it came from, and no scene is left behind."""
    lines = _lines()
    mat = lines.index("*MAT_PLASTIC_KINEMATIC") + 1
    lines[mat] = lines[mat].replace("  7.85e-06", " -7.85e-06")
    end = lines.index("*CONTROL_TERMINATION") + 1
    lines[end] = f"{-0.05:10}"
    step = lines.index("*CONTROL_TIMESTEP") + 1
    lines[step] = f"{0.0:10}{1.5:10}"
    deck = _write(tmp_path, lines)
    with pytest.raises(SceneError) as e:
        import_model(deck, str(tmp_path / "bad.toml"), "mm-ms-kg-kN")
    problems = "\n".join(e.value.problems)
    assert f"bad.k:{mat + 1}: *MAT_PLASTIC_KINEMATIC card 1: materials.mat1.density: must be > 0" in problems
    assert f"bad.k:{end + 1}: *CONTROL_TERMINATION card 1: scene.end_time: must be > 0" in problems
    assert f"bad.k:{step + 1}: *CONTROL_TIMESTEP card 1: scene.safety_factor:" in problems
    assert not (tmp_path / "bad.toml").exists()


def test_no_unit_set_is_refused_by_the_command(tmp_path, capsys):
    assert main(["import", str(PLAIN), "--out", str(tmp_path / "x.toml")]) == 2
    err = capsys.readouterr().err
    assert "--units" in err and "mm-ms-kg-kN" in err
    assert main(["import", str(PLAIN), "--out", str(tmp_path / "x.toml"), "--units", "mm-s-kg-N"]) == 2
    assert "not consistent" in capsys.readouterr().err


def test_the_command_writes_scene_meshes_and_report(tmp_path, capsys, monkeypatch):
    assert main(["import", str(PLAIN), "--out", str(tmp_path / "x.toml"), "--units", "mm-ms-kg-kN"]) == 0
    assert (tmp_path / "x.toml").exists() and (tmp_path / "x_meshes" / "block.msh").exists()
    assert "Keywords not mapped" in capsys.readouterr().out
    # checked from another folder: the meshes are found beside the scene
    monkeypatch.chdir(DECKS)
    assert main(["check", str(tmp_path / "x.toml")]) == 0


def test_refused_material_shell_and_missing_set(tmp_path):
    lines = _lines()
    lines[lines.index("*MAT_PIECEWISE_LINEAR_PLASTICITY")] = "*MAT_JOHNSON_COOK"
    k = lines.index("*BOUNDARY_SPC_SET") + 1
    lines[k] = lines[k].replace("         5", "         6", 1)
    lines[-1:-1] = ["*ELEMENT_SHELL", "      10       3       1       2       3       4",
                    "*LOAD_NODE_SET", f"{5:10}{3:10}{1:10}", "*CONTACT_TIED_SURFACE_TO_SURFACE", f"{1:10}{2:10}"]
    problems = "\n".join(_problems(_write(tmp_path, lines)))
    assert "*MAT_JOHNSON_COOK: this material is not mapped" in problems
    assert "part 2 (plate) uses material 2, *MAT_JOHNSON_COOK" in problems
    assert "*ELEMENT_SHELL: shell elements" in problems
    assert "*LOAD_NODE_SET: loads are not mapped" in problems and "*CONTACT_TIED_SURFACE_TO_SURFACE: this contact" in problems
    assert f"bad.k:{k + 1}: *BOUNDARY_SPC_SET card 1: node set 6 is not defined" in problems


def _material_deck(tmp_path, material_cards, extra=()):
    lines = _lines()
    start = lines.index("*MAT_PIECEWISE_LINEAR_PLASTICITY")
    end = lines.index("*NODE")
    lines[start:end] = list(material_cards) + list(extra)
    return _write(tmp_path, lines)


def test_table_of_one_curve_maps_and_of_two_is_refused(tmp_path):
    card = ["*MAT_PIECEWISE_LINEAR_PLASTICITY", f"{2:10}{2.7e-6:10}{70.0:10}{0.33:10}",
            f"{0.0:10}{0.0:10}{20:10}"]
    curve = lambda lcid, y: ["*DEFINE_CURVE", f"{lcid:10}", f"{0.0:20}{y:20}", f"{0.2:20}{y + 0.1:20}"]
    one = _material_deck(tmp_path, card, ["*DEFINE_TABLE", f"{20:10}", f"{0.0:20}"] + curve(21, 0.3))
    s = deck_to_scene(one, MM_MS).scene
    assert to_si(s["materials"]["mat2"]["hardening_curve"][1][1], "pressure") == pytest.approx(400e6, rel=EXACT)
    two = _material_deck(tmp_path, card, ["*DEFINE_TABLE", f"{20:10}", f"{0.0:20}", f"{100.0:20}"]
                         + curve(21, 0.3) + curve(22, 0.35))
    assert "*DEFINE_TABLE of 2 strain rates" in "\n".join(_problems(two))


def test_foam_and_rigid_materials(tmp_path):
    foam = ["*MAT_CRUSHABLE_FOAM", f"{2:10}{5e-8:10}{0.15:10}{0.0:10}{30:10}{1e-4:10}",
            "*DEFINE_CURVE", f"{30:10}", f"{0.0:20}{0.001:20}", f"{0.6:20}{0.001:20}", f"{0.8:20}{0.03:20}"]
    s = deck_to_scene(_material_deck(tmp_path, foam), MM_MS).scene
    m = s["materials"]["mat2"]
    assert [c[0] for c in m["crush_curve"]] == [0.0, 0.6, 0.8]
    assert to_si(m["crush_curve"][2][1], "pressure") == pytest.approx(30e6, rel=EXACT)
    assert to_si(m["tension_cutoff"], "pressure") == pytest.approx(0.1e6, rel=EXACT)
    rigid = ["*MAT_RIGID", f"{2:10}{7.85e-6:10}{210.0:10}{0.3:10}"]
    s = deck_to_scene(_material_deck(tmp_path, rigid), MM_MS).scene
    assert next(b for b in s["bodies"] if b["name"] == "plate")["rigid"] is True


def test_unit_sets():
    # 1 kg mm / ms^2 = 1 kN; 1 tonne mm / s^2 = 1 N: consistent by construction
    assert unit_set("mm-s-tonne-N").si(1.0, "pressure") == pytest.approx(1e6, rel=EXACT)
    assert unit_set("m-s-kg-N").unit("density") == "kg/m**3"
    assert unit_set("in-s-lbf*s**2/in-lbf").si(1.0, "pressure") == pytest.approx(6894.757, rel=1e-6)   # psi given to 7 digits


def test_wedges_and_hexahedra_cut_into_tetrahedra_that_meet_face_to_face(tmp_path):
    """The plate turned into LS-DYNA's degenerate wedge (N5 = N6, N7 = N8): the deck mixes hexahedra and a
    wedge, so every cell is cut into tetrahedra about its centre; the volumes are kept and the two block
    hexahedra's shared face is cut the same way from both sides (no inner face left on the boundary)."""
    lines = _lines()
    k = lines.index("     101     102     104     103     105     106     108     107")
    lines[k] = "     101     102     104     103     105     105     107     107"
    out = deck_to_scene(_write(tmp_path, lines), MM_MS)
    assert out.scene["scene"]["element"] == "tet"
    block, plate = out.meshes["block"], out.meshes["plate"]
    assert len(block.cells) == 2 * 12 and len(plate.cells) == 8           # 6 quad faces x 2; 3 x 2 + 2 x 1
    volume = lambda m: signed_volumes(m.coords, m.cells, "tet").sum() / 6.0
    # block 2 x 1 x 1 mm, wedge half of 2 x 1 x 0.9 mm; 1e-12: the sum of positive round-off-level terms
    assert volume(block) == pytest.approx(2e-9, rel=EXACT) and volume(plate) == pytest.approx(0.9e-9, rel=EXACT)
    assert (signed_volumes(block.coords, block.cells, "tet") > 0).all()
    assert len(block.facets) == 2 * 10                                      # 10 outer quad faces, 2 triangles each
    assert any("cut into tetrahedra" in n for n in out.notes)


def test_motion_wall_single_surface_and_node_constraints(tmp_path):
    lines = _lines()
    k = lines.index("*BOUNDARY_SPC_SET")
    lines[k:k + 2] = ["*DEFINE_CURVE", f"{9:10}", f"{0.0:20}{0.0:20}", f"{0.01:20}{1.0:20}", f"{1.0:20}{1.0:20}",
                      "*BOUNDARY_PRESCRIBED_MOTION_SET", f"{5:10}{3:10}{0:10}{9:10}{-2.0:10}",
                      "*RIGIDWALL_PLANAR", f"{0:10}", f"{0.0:10}{0.0:10}{-1.0:10}{0.0:10}{0.0:10}{0.0:10}",
                      "*SET_PART_LIST", f"{3:10}", f"{1:10}{2:10}",
                      "*CONTACT_AUTOMATIC_SINGLE_SURFACE", f"{3:10}{0:10}{2:10}", f"{0.0:10}", f"{1.0:10}",
                      "*BOUNDARY_SPC_NODE"] + [f"{n:10}{0:10}{1:10}{0:10}{0:10}" for n in (9, 12, 6, 3, 1)]
    out = deck_to_scene(_write(tmp_path, lines), MM_MS)
    s = out.scene
    assert any("1 of its 5 nodes are on no whole boundary facet" in n for n in out.notes)
    held, motion = s["boundary"]            # constraints first, then motions
    assert (motion["region"], motion["type"], motion["direction"]) == ("plate.nodes5", "velocity", "z")
    # the curve times SF = -2: 0 -> -2 mm/ms (= m/s) over 0.01 ms, then held
    assert [[to_si(t, "time"), to_si(v, "velocity")] for t, v in motion["history"]] == [
        [0.0, 0.0], [pytest.approx(1e-5, rel=EXACT), pytest.approx(-2.0, rel=EXACT)], [pytest.approx(1e-3, rel=EXACT), pytest.approx(-2.0, rel=EXACT)]]
    # nodes 3, 6, 9, 12 are the block's x = 2 mm face: held in x (a fifth, node 1, is on no facet of the set)
    assert held == {"region": "block.held_x", "type": "velocity", "direction": "x", "value": "0.0 mm/ms"}
    walls = [c for c in s["contact"] if c.get("method") == "constraint"]
    assert [w["a"] for w in walls] == ["block", "plate"]
    assert walls[0]["wall"]["normal"] == [0.0, 0.0, 1.0]
    assert to_si(walls[0]["wall"]["point"][2], "length") == pytest.approx(-1e-3, rel=EXACT)
    single = [c for c in s["contact"] if c["name"] == "contact1"]       # the first in the deck
    assert [(c["a"], c["b"]) for c in single] == [("block", "plate")]


def test_rigid_motion_drives_the_rigid_body(tmp_path):
    """*BOUNDARY_PRESCRIBED_MOTION_RIGID on a *MAT_RIGID part: the body driven whole along DOF's axis with the
    curve times SF (VAD blank is LS-DYNA's default, a velocity); on a deformable part, with a DOF, a VAD or a
    curve not mapped, refused on its card."""
    rigid = ["*MAT_RIGID", f"{2:10}{7.85e-6:10}{210.0:10}{0.3:10}",
             "*DEFINE_CURVE", f"{9:10}", f"{0.0:20}{0.0:20}", f"{0.01:20}{1.0:20}", f"{1.0:20}{1.0:20}",
             "*BOUNDARY_PRESCRIBED_MOTION_RIGID", f"{2:10}{3:10}{'':10}{9:10}{-4.0:10}"]
    s = deck_to_scene(_material_deck(tmp_path, rigid), MM_MS).scene
    drive = s["boundary"][-1]
    assert (drive["region"], drive["type"], drive["direction"]) == ("plate", "velocity", "z")
    assert [[to_si(t, "time"), to_si(v, "velocity")] for t, v in drive["history"]] == [
        [0.0, 0.0], [pytest.approx(1e-5, rel=EXACT), pytest.approx(-4.0, rel=EXACT)],
        [pytest.approx(1e-3, rel=EXACT), pytest.approx(-4.0, rel=EXACT)]]
    scene = load_scene(import_model(_material_deck(tmp_path, rigid), str(tmp_path / "s.toml"),
                                    "mm-ms-kg-kN").scene)
    assert [(b.region, b.components) for b in scene.boundaries][-1] == ("plate", (2,))
    bad = rigid[:-1] + [f"{1:10}{3:10}{0:10}{9:10}", f"{2:10}{5:10}{0:10}{9:10}", f"{2:10}{4:10}{0:10}{9:10}",
                        f"{2:10}{1:10}{2:10}{9:10}", f"{2:10}{1:10}{0:10}{8:10}", f"{2:10}{1:10}"]
    problems = "\n".join(_problems(_material_deck(tmp_path, bad)))
    for card, words in ((1, "part 1 is not rigid (its material is no *MAT_RIGID)"),
                        (2, "DOF 5 (a rotation): only x, y, z translations"),
                        (3, "DOF 4 (a translation along the vector VID)"),
                        (4, "VAD 2: only a prescribed velocity (VAD 0) is mapped"),
                        (5, "LCID 8 is not defined by any *DEFINE_CURVE"),
                        (6, "LCID is blank")):
        assert f"*BOUNDARY_PRESCRIBED_MOTION_RIGID card {card}: {words}" in problems, (card, problems)


def test_rigid_material_constraints_hold_the_body(tmp_path):
    """*MAT_RIGID CMO 1: CON1 holds the body's centre along its axes, CON1 7 CON2 7 fixes it; a rotation held
    alone and a local system (CMO -1) are refused on the material's second card."""
    rigid = lambda card2: ["*MAT_RIGID", f"{2:10}{7.85e-6:10}{210.0:10}{0.3:10}", card2]
    s = deck_to_scene(_material_deck(tmp_path, rigid(f"{1.0:10}{5:10}{0:10}")), MM_MS).scene
    assert [(b["region"], b["type"], b.get("direction")) for b in s["boundary"] if b["region"] == "plate"] == [
        ("plate", "fixed", None), ("plate", "velocity", "y"), ("plate", "velocity", "z")]    # the SPC set, CON1 5
    s = deck_to_scene(_material_deck(tmp_path, rigid(f"{1.0:10}{7:10}{7:10}")), MM_MS).scene
    assert [b["type"] for b in s["boundary"] if b["region"] == "plate"] == ["fixed", "fixed"]
    for card2, words in ((f"{1.0:10}{0:10}{4:10}", "CON2 4: a rigid body's rotations are held only with"),
                         (f"{-1.0:10}{0:10}{4:10}", "CMO -1: constraints of a rigid material in a local system")):
        assert f"*MAT_RIGID card 2: {words}" in "\n".join(_problems(_material_deck(tmp_path, rigid(card2))))


def test_partial_initial_velocity_is_refused(tmp_path):
    lines = _lines()
    k = lines.index("*BOUNDARY_SPC_SET")
    lines[k:k + 2] = ["*INITIAL_VELOCITY", f"{5:10}", f"{0.0:10}{0.0:10}{1.0:10}"]
    problems = "\n".join(_problems(_write(tmp_path, lines)))
    assert "*INITIAL_VELOCITY card 1: node set 5 covers 4 of body plate's 8 nodes" in problems


def test_default_scene_never_overwrites_a_scene_of_its_own(tmp_path):
    """Beside the deck by default, written again by a later import, but a hand-written scene of the same
    name is kept (--out names another)."""
    deck = tmp_path / "block.k"
    deck.write_text(PLAIN.read_text())
    first = import_model(str(deck), None, "mm-ms-kg-kN")
    assert first.scene == str(tmp_path / "block.toml")
    import_model(str(deck), None, "mm-ms-kg-kN")                        # its own: written again
    (tmp_path / "block.toml").write_text("[scene]\n")
    assert "was not written by shockfem import" in _problems(str(deck))[0]
