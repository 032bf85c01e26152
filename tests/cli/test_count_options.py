"""A count (``--poses``, ``--jobs``) is read by one parser on every command: the same usage error, exit status 2."""

from __future__ import annotations

import pytest

from koenig_check.cli.main import build_parser, main

#: The options that take a count of things (poses, processes).
COUNTS = ("--poses", "--jobs")


def _count_options() -> list[tuple[str, str]]:
    """(command, option) for every count option of every sub-command, read from the parser."""
    sub = next(a for a in build_parser()._actions if a.dest == "command")
    return [
        (name, option) for name, p in sub.choices.items() for option in COUNTS if option in p._option_string_actions
    ]


@pytest.mark.parametrize("value", ["x", "1.5", "0", "-2"])
def test_every_count_option_refuses_a_bad_count_in_the_same_words(
    value: str, capsys: pytest.CaptureFixture[str]
) -> None:
    options = _count_options()
    assert ("export", "--poses") in options and ("compare", "--jobs") in options  # the parser was read
    said = {}
    for command, option in options:
        with pytest.raises(SystemExit) as exit_:
            main([command, option, value])
        out, err = capsys.readouterr()
        assert exit_.value.code == 2 and not out, (command, option)
        error = err.strip().splitlines()[-1]  # after the usage line: "koenig-check CMD: error: argument OPT: ..."
        said[command, option] = error.split(f"argument {option}: ", 1)[1].removesuffix(
            f" (see koenig-check {command} --help)"
        )
    assert len(set(said.values())) == 1, said
