"""``shockfem import DECK [--out scene.toml] [--units SET]``: its arguments, and the import with its report on
the terminal."""
from __future__ import annotations

from ..errors import EXIT_OK
from . import import_model

HELP = ("an LS-DYNA keyword deck (or an Abaqus .inp mesh) as a scene with its bodies' meshes beside it, and a "
        "report of what was not mapped (docs/import.md)")


def import_arguments(parser):
    parser.add_argument("deck", help="LS-DYNA keyword file (.k, .key, .dyn) or Abaqus input file (.inp)")
    parser.add_argument("--out", help="scene file to write (default: the deck's name with .toml, beside it)")
    parser.add_argument("--units", help="the deck's consistent unit set, length-time-mass-force: mm-ms-kg-kN, "
                                        "mm-s-tonne-N, m-s-kg-N, ... (required: decks carry no units)")


def import_command(args) -> int:
    """Import ``args.deck`` and print what was written and the report; a bad deck raises ``SceneError``
    (the CLI lists its problems, exit 2)."""
    done = import_model(args.deck, args.out, args.units)
    print(done.text, end="")
    print(f"wrote {done.scene}, meshes in {done.mesh_dir}/, report {done.report}")
    print(f"run it: shockfem run {done.scene}")
    return EXIT_OK
