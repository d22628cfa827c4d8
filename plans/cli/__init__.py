"""The command line: the only part of plans that imports drawing.

``main`` (:mod:`plans.cli.main`) parses the arguments and runs one command's module;
:mod:`plans.cli.common` holds what the commands share, :mod:`plans.cli.output` where
their outputs go. Note that ``plans.cli.main`` names the function once the package is
imported: reach the module's other names with ``from plans.cli.main import …``.
"""

from .main import main

__all__ = ["main"]
