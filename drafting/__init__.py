"""Sheets, scene files and the command line of the tom-drafting engine; the Python API is
``drafting.load`` / ``drafting.loads`` (:mod:`drafting.api`), imported on first use so that the command
line starts without it."""

__all__ = ["load", "loads"]


def __getattr__(name):
    if name in __all__:
        from . import api
        return getattr(api, name)
    raise AttributeError(f"module 'drafting' has no attribute {name!r}")
