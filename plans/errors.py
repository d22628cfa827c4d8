"""The few errors the engine raises; the CLI turns each into one line on stderr."""

from __future__ import annotations


class PlansError(Exception):
    """Root of every error the engine raises on purpose."""


class InputError(PlansError, ValueError):
    """A mechanism, table or measurement file that is not valid.

    ``problems`` holds one located message per problem, so that several problems in one
    file are all reported at once.
    """

    def __init__(self, source: str, problems: list[str] | str):
        self.source = source
        self.problems = [problems] if isinstance(problems, str) else list(problems)
        super().__init__("\n".join(f"{source}: {p}" for p in self.problems))


class StructureError(PlansError, ValueError):
    """The chain is not W = 1, or it does not split into class-II groups.
    ``source`` as for :class:`AssemblyError`."""

    def __init__(self, message: str, *, source: str = ""):
        self.source = source
        super().__init__(message)


class AssemblyError(PlansError, ValueError):
    """A group cannot be assembled at this crank angle (its links do not reach).

    ``source``: the mechanism it belongs to (its file, or a table's variant), which the
    command line puts before the message.
    """

    def __init__(self, message: str, *, group: str = "", source: str = ""):
        self.group = group
        self.source = source
        super().__init__(message)


class SingularPlanError(PlansError, ArithmeticError):
    """The two lines of a plan construction are parallel: a singular position.
    ``source`` as for :class:`AssemblyError`."""

    def __init__(self, message: str, *, sine: float = 0.0, source: str = ""):
        self.sine = sine
        self.source = source
        super().__init__(message)
