"""The one error hierarchy of the engine.

Every error says *where* (the position of the mechanism, e.g. "crank angle 90 deg") and *why*, in one
sentence a student can act on.  The application turns them into exit codes; the engine only raises.
"""

from __future__ import annotations


class ConstructionError(Exception):
    """A construction cannot be completed.

    Parameters
    ----------
    reason:
        What is wrong, in the words of the method ("the circles about B and O2 are 3.2 mm apart").
    position:
        Where the mechanism stands ("crank angle 70 deg"), or None when it does not apply.
    """

    def __init__(self, reason: str, *, position: str | None = None) -> None:
        self.reason = reason
        self.position = position
        super().__init__(f"at {position}: {reason}" if position else reason)

    def at(self, position: str) -> "ConstructionError":
        """The same error, told at a named position (keeps the type and extra attributes)."""
        clone = self.__class__.__new__(self.__class__)
        clone.__dict__.update(self.__dict__)
        ConstructionError.__init__(clone, self.reason, position=position)
        return clone


class CannotAssemble(ConstructionError):
    """The links cannot be put together at this position (a circle misses a circle or a line)."""


class IndeterminatePosition(ConstructionError):
    """The position is singular (toggle, dead centre, lock): two trial lines are parallel.

    ``kind`` names the singularity and ``condition`` is the sine of the angle between the trial lines.
    """

    def __init__(self, reason: str, *, position: str | None = None, kind: str = "singular position",
                 condition: float = 0.0) -> None:
        self.kind = kind
        self.condition = condition
        super().__init__(reason, position=position)


class DegenerateInput(ConstructionError):
    """The input describes no figure: a zero-length link, coincident centres, a zero direction."""
