"""Models from other codes as shockfem scenes: LS-DYNA keyword decks (``lsdyna.py``) and Abaqus ``.inp``
meshes (``abaqus.py``), each written as a scene TOML with its bodies' meshes beside it (``docs/import.md``).
"""
from __future__ import annotations

import os

ABAQUS_FILES = (".inp",)


def import_model(source: str, out: str | None = None, units: str | None = None):
    """Import ``source`` (an LS-DYNA deck, or an Abaqus ``.inp``) into the scene ``out`` (default: the
    source's name with ``.toml``, beside it); returns the ``Imported`` paths and the report's text.

    Raises ``SceneError`` listing every problem (each naming the file, line, keyword and card), as
    ``shockfem import`` reports them with exit code 2."""
    from ..scene import SceneError
    from ..units import UnitError
    from .cards import DeckError
    from .unit_sets import unit_set
    from .write import write_import
    if not os.path.isfile(source):
        raise SceneError([f"{source}: no such file"])
    if out is None:
        out = os.path.splitext(source)[0] + ".toml"
        if os.path.exists(out) and not _written_by_import(out):
            raise SceneError([f"{out} exists and was not written by shockfem import: give the scene's name "
                              "with --out"])
    try:
        if source.lower().endswith(ABAQUS_FILES):
            from .abaqus import inp_to_scene
            units_set = unit_set(units)
            model = inp_to_scene(source, units_set)
        else:
            from .lsdyna import deck_to_scene
            units_set = unit_set(units)
            model = deck_to_scene(source, units_set)
    except UnitError as e:
        raise SceneError([f"--units: {e}"]) from None
    except DeckError as e:
        raise SceneError(e.problems) from None
    done = write_import(model, out, source, units_set.name)
    if not source.lower().endswith(ABAQUS_FILES):     # an Abaqus mesh's scene waits for its materials
        _check_written(done, model)
    return done


def _check_written(done, model):
    """The written scene through the scene check: a value the deck's cards allow but the scene refuses (a
    negative density, an end time below zero) is refused here, said at the deck card it came from, and the
    scene and report are removed (a later ``shockfem run`` finds no scene to run)."""
    from ..scene import SceneError, read_toml, resolve
    try:
        resolve(read_toml(done.scene), base_dir=os.path.dirname(os.path.abspath(done.scene)))
    except SceneError as e:
        for path in (done.scene, done.report):
            os.remove(path)
        raise SceneError([model.locate(p) for p in e.problems]) from None


def _written_by_import(path: str) -> bool:
    """Whether a scene file is one an import wrote (its first line says so), safe to write again."""
    with open(path, errors="replace") as fh:
        return fh.readline().startswith("# Imported by `shockfem import`")
