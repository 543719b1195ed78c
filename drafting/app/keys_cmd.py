"""``drafting keys [KIND] [--markdown]``: the scene reference, generated from the readers' key tables
(:mod:`drafting.app.reference`): one kind's sections on the terminal, or every kind as Markdown (what
docs/scene-reference.md holds)."""

from __future__ import annotations

from ..families.registry import families
from .reference import markdown, text
from .solving import UserError


def kind_named(name: str) -> str:
    """The registered kind ``name`` stands for: case, hyphens and underscores aside ("gear-pair" is
    "gear pair"); a UserError listing the kinds for anything else."""
    wanted = " ".join(name.lower().replace("-", " ").replace("_", " ").split())
    kinds = sorted(families())
    if wanted not in kinds:
        raise UserError(f"{name!r} is not a scene kind; choose from {', '.join(kinds)}")
    return wanted


def cmd_keys(kind: str | None, as_markdown: bool) -> int:
    if as_markdown:
        if kind is not None:
            raise UserError("keys --markdown writes the reference of every kind; leave KIND out")
        print(markdown(), end="")
        return 0
    if kind is None:
        kinds = sorted(families())
        print(f"scene kinds: {', '.join(kinds)}\n"
              f"drafting keys KIND prints a kind's keys (e.g. drafting keys \"{kinds[0]}\"); "
              f"drafting keys --markdown every kind's, as docs/scene-reference.md holds them")
        return 0
    print(text(kind_named(kind)), end="")
    return 0


def run_command(args) -> int:
    """``drafting keys [KIND] [--markdown]``."""
    return cmd_keys(args.kind, args.markdown)
