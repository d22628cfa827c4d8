"""The command line: the only part of plans that imports drawing."""

from .common import main

__all__ = ["main"]
