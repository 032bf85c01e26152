"""The ``koenig-check`` command line: one module per sub-command, thin (parse, call the API, print).

``main`` (:mod:`koenig_check.cli.main`) is the console script's entry point.
"""

from koenig_check.cli.main import build_parser, main

__all__ = ["build_parser", "main"]
