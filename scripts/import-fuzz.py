"""Every mutation of the decks of ``studies/lsdyna`` (``tests/unit/importers/test_deck_fuzz.py``): each field
of each card of the hand-written decks replaced by each bad value, cut after each field, deleted, each keyword
line deleted, the mesh include missing; of the mesh includes' cards, the first of each keyword and
``MESH_CARDS`` a deck drawn at random (the same every run).  Counts the outcomes, and prints every traceback, every hang (an import over
``TIMEOUT_S``), every problem that does not say where it is, and every deck that the import read but whose
scene the scene check refused (a bad value the import let through).

    python scripts/import-fuzz.py [DECK...]
"""
import pathlib
import signal
import sys
import tempfile
import traceback
from collections import Counter

sys.path.insert(0, str(pathlib.Path(__file__).parents[1] / "tests" / "unit" / "importers"))
from test_deck_fuzz import DECKS, import_mutated, mesh_cards, mutations  # noqa: E402

MESH_CARDS = 10
TIMEOUT_S = 60


def _alarm(*_):
    raise TimeoutError


signal.signal(signal.SIGALRM, _alarm)
outcomes = Counter()
work = pathlib.Path(tempfile.mkdtemp())
for name in sys.argv[1:] or list(DECKS):
    for file, label, line, text in mutations(name, mesh_cards(name, MESH_CARDS)):
        signal.alarm(TIMEOUT_S)
        try:
            outcome = import_mutated(name, file, line, text, work / "deck")
        except AssertionError as e:
            outcome = "problem not named"
            print(f"{name}: {label}: problems that do not say where: {e}")
        except TimeoutError:
            outcome = "hang"
            print(f"{name}: {label}: over {TIMEOUT_S} s")
        except Exception:
            outcome = "traceback"
            print(f"{name}: {label}:\n{traceback.format_exc(limit=3)}")
        finally:
            signal.alarm(0)
        if outcome == "refused by the scene check":
            print(f"{name}: {label}: imported, its scene refused by the scene check")
        outcomes[outcome] += 1
        sys.stdout.flush()
print(dict(outcomes))
