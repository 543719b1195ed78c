"""The Python API, for scripts and notebooks.

    import drafting
    study = drafting.load("gallery/notes-velocity-example-1.toml")   # or a dict, or drafting.loads(text)
    study.results["V_C"].graphical            # the value read off the construction (SI)
    study.results["V_C"].graphical.to("mm/s")  # the same as a pint Quantity (.in_scene_units(): the scene's)
    print(study.table())                      # the results table: rows in the scene's units (.to_csv())
    sheets = study.sheets()                   # the worked sheets, one or more pages
    sheets[0].save("example.pdf")             # .svg, .pdf or .png, by the suffix
    study                                     # in Jupyter: the results table and the first sheet, inline

Everything is what the command line does, without the command line: the same scene reader (a scene is
untrusted input, read strictly, errors one sentence naming the file and key as
:class:`~drafting.scene.reader.SceneError`), the same lazy study (only the analyses the scene asks for), the
same sheets.  Scene, Study, Sheet and Construction display themselves in Jupyter (``_repr_html_``,
``_repr_svg_``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

from .scene.reader import Scene, load_scene, parse_scene, scene_from_data
from .study.study import Study

__all__ = ["load", "loads", "lab_for", "write_lab", "dimensioned", "run_batch"]


def __getattr__(name: str):
    """A scene's lab sheets and a batch of variants, from the application's rooms, imported on first use:
    ``drafting.api.lab_for(study)``, ``write_lab``, ``dimensioned``, ``run_batch``."""
    if name in ("lab_for", "write_lab", "dimensioned"):
        from .app import lab
        return getattr(lab, name)
    if name == "run_batch":
        from .app.batch import run_batch
        return run_batch
    raise AttributeError(f"module 'drafting.api' has no attribute {name!r}")


def load(source: str | Path | Mapping[str, Any] | Scene, *, paper: str | None = None) -> Study:
    """A solved study of a scene file (a path), of a scene given as a dict (the TOML's tables), or of a
    :class:`Scene` already read.  ``paper`` ("A4" or "A3") overrides the scene's.  Raises SceneError for
    bad input and ConstructionError where the mechanism cannot be drawn (a singular position names
    itself)."""
    if isinstance(source, Scene):
        scene = source
    elif isinstance(source, Mapping):
        scene = scene_from_data(dict(source), "<dict>")
    elif isinstance(source, (str, Path)):
        scene = load_scene(source)
    else:
        raise TypeError(f"load() takes a scene file's path, a dict or a Scene, not {type(source).__name__}")
    return _study(scene, paper)


def loads(text: str, *, name: str = "<text>", paper: str | None = None) -> Study:
    """A solved study of a scene given as TOML text (``name`` stands for the file in errors)."""
    return _study(parse_scene(text, name), paper)


def _study(scene: Scene, paper: str | None) -> Study:
    if paper is not None:
        from dataclasses import replace
        from .scene.reader import PAPERS
        if paper not in PAPERS:
            raise ValueError(f"paper must be one of {', '.join(PAPERS)}, not {paper!r}")
        scene = replace(scene, paper=paper)
    return Study(scene).run()
