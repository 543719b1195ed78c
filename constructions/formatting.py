"""How the engine writes a number into a caption or a message.

The engine works in SI; the application passes a :data:`Formatter` that writes values in the scene's
own units.  :func:`si_format` is the default when there is no scene.
"""

from __future__ import annotations

from typing import Callable

Formatter = Callable[[str, float], str]
"""Formats an SI value of a named quantity ("length", "velocity", "angular velocity", "angle")."""

SI_UNITS = {"length": "m", "velocity": "m/s", "angular velocity": "rad/s", "angle": "rad"}


def si_format(quantity: str, value: float) -> str:
    return f"{value:.4g} {SI_UNITS[quantity]}"
