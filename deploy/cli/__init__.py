"""The ``porter`` command line: sim, deploy, replay, log, regress, bench."""

from deploy.cli.porter import build_parser, main

__all__ = ["build_parser", "main"]
