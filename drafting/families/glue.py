"""What the families built around one main analysis share in their registration: its measured values,
scales, construction and model name, each read off that analysis only when the scene asks for it."""

from __future__ import annotations

from typing import Any, Callable


def measured_of(name: str) -> Callable[[Any], list]:
    """``Family.measured``: the measured quantities of analysis ``name``, none unless the scene asks for it."""
    def measured(study) -> list:
        r = study.result(name)
        return r.measured() if r is not None else []
    return measured


def scales_of(name: str) -> Callable[[Any], dict]:
    """``Family.scales``: the scales of analysis ``name`` (empty unless the scene asks for it)."""
    def scales(study) -> dict:
        r = study.result(name)
        return r.scales() if r is not None else {}
    return scales


def construction_of(name: str) -> Callable[[Any], Any]:
    """``Family.construction``: the record analysis ``name`` drew."""
    return lambda study: study.get(name).construction


def model_if_asked(name: str, model: str) -> Callable[[Any], str | None]:
    """``Family.model_name``: ``model`` when the scene asks for analysis ``name``, else None."""
    return lambda study: model if study.asked(name) else None
