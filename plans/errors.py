"""The few errors the engine raises; the CLI turns each into one line on stderr."""

from __future__ import annotations

import copy
from collections.abc import Callable


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


class PositionError(PlansError):
    """An error at one crank angle: a group that cannot be assembled there
    (:class:`AssemblyError`), or a plan that is singular there (:class:`SingularPlanError`).

    It keeps its numbers: ``phi``, the crank angle (rad from +x; None where it is not
    known), ``group``, the group's label ("group 2–3 (RRR)"), and those of its kind; and
    ``at``, the crank angle in the words its message says it in. ``source``: the
    mechanism it belongs to (its file, or a table's variant), which the command line puts
    before the message.

    ``str(err)`` is a whole sentence. The kinematics words the crank angle as the file
    gives it, in [0°, 360°); a layer that knows more of the motion words it its own way
    (the cycle: "−99.7°" beside a crank range through 0°) and says the same error again
    with :meth:`at_words`.
    """

    def __init__(self, message: str, *, source: str = "", phi: float | None = None,
                 group: str = "", at: str = "", words: Callable[[str], str] | None = None):
        self.source = source
        self.phi = phi
        self.group = group
        self.at = at
        #: the message as a function of the crank angle's words (None: it has no other)
        self.words = words
        super().__init__(message)

    def at_words(self, at: str) -> PositionError:
        """This error, its crank angle said in the words ``at`` (its whole message said
        again); itself where it has no words of its own, or they are these."""
        if self.words is None or at == self.at:
            return self
        out = copy.copy(self)
        out.args = (self.words(at),)
        out.at = at
        return out


class AssemblyError(PositionError, ValueError):
    """A group cannot be assembled at this crank angle (its links do not reach).

    Its numbers (:class:`PositionError`) and ``gap``, by how much it misses (m), and
    ``admissible``, the condition it needs in words ("BD within [0.05, 0.25] m").
    """

    def __init__(self, message: str, *, gap: float | None = None, admissible: str = "",
                 **numbers):
        self.gap = gap
        self.admissible = admissible
        super().__init__(message, **numbers)


class SingularPlanError(PositionError, ArithmeticError):
    """The two lines of a plan construction are parallel: a singular position.

    Its numbers (:class:`PositionError`) and ``sine``, the figure found singular (the
    sine between the two lines, or a slotted link's pivot figure; 0 at a dead point).
    """

    def __init__(self, message: str, *, sine: float = 0.0, **numbers):
        self.sine = sine
        super().__init__(message, **numbers)
