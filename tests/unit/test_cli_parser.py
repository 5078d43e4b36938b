"""The command line's parser as a user reads it (``shockfem --help``, ``shockfem COMMAND --help``): a
version, help on every option, the same name and choices for the same option in every command, and the
studies offered from the study registry."""
import argparse

import pytest

from shockfem import cli
from shockfem.study.registry import SIZES, STUDIES
from shockfem.version import __version__


def _subparsers():
    parser = cli._parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return sub.choices


def test_version(capsys):
    with pytest.raises(SystemExit) as stopped:
        cli.main(["--version"])
    assert stopped.value.code == 0 and capsys.readouterr().out.strip() == f"shockfem {__version__}"


def test_every_command_and_option_has_help():
    commands = _subparsers()
    assert set(commands) == set(cli.COMMANDS)
    missing = [f"{name} {action.dest}" for name, p in commands.items() for action in p._actions
               if not action.help and not isinstance(action, argparse._HelpAction)]
    assert missing == [], f"options without help: {missing}"


def test_an_option_has_the_same_choices_in_every_command():
    """--shape, --architecture, --size...: where two commands take the same option with choices, the choices
    agree, and an option taken as free text in one command is not a list of choices in another."""
    seen = {}
    for name, p in _subparsers().items():
        for action in p._actions:
            if not action.option_strings or action.option_strings[0] == "-h" or action.dest == "size":
                continue        # (--size: a study's smoke/default and verify's mesh sizes are not one option)
            seen.setdefault(action.option_strings[0], {})[name] = action.choices
    differing = {opt: by for opt, by in seen.items() if len({repr(c) for c in by.values()}) > 1}
    assert differing == {}, differing


def test_run_without_a_scene_prints_the_usage(capsys):
    with pytest.raises(SystemExit) as stopped:
        cli.main(["run"])
    err = capsys.readouterr().err
    assert stopped.value.code == 2 and err.startswith("usage: shockfem run") and "--resume RUN_DIR" in err


def test_the_study_command_takes_its_studies_from_the_registry():
    study = _subparsers()["study"]
    name = next(a for a in study._actions if a.dest == "name")
    size = next(a for a in study._actions if a.dest == "size")
    assert tuple(name.choices) == tuple(STUDIES) and tuple(size.choices) == SIZES
    for study_name in STUDIES:         # and every study names a module that runs it
        assert cli._parser().parse_args(["study", study_name]).name == study_name


def test_every_verification_case_has_a_one_line_summary():
    """``shockfem verify --list`` prints each case's docstring's first line: a case without one has nothing
    to say there (and the listing would fail on it)."""
    from shockfem.verify import CASES
    assert [name for name, case in CASES.items() if not (case.__doc__ or "").strip()] == []
