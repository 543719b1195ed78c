"""Errors of the drawing layer, in a module every layer may import (nothing here imports the layout).

- :class:`LayoutError`: a block does not fit even on an empty page; the message says what to change.
- :class:`DrawingError`: the record holds an entity the drawing layer has no drawer for; the message
  names the entity's type and its diagram (an entity is never silently left out of a sheet).
- :class:`StyleError`: a role (or style name) that has no style; the message names it.
"""

from __future__ import annotations

__all__ = ["LayoutError", "DrawingError", "StyleError"]


class LayoutError(Exception):
    """The content does not fit the paper; the message says what to change (e.g. use A3)."""


class DrawingError(TypeError):
    """An entity the drawing layer cannot draw (no drawer registered for its type)."""


class StyleError(LookupError):
    """A role or style name without a style.  ``str()`` is the plain sentence (no KeyError quotes)."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""
