"""Where the tests find the checkout's files: its root, the gallery of scenes, and the benchmark scripts
(not a package: :func:`benchmark_module` loads one by its path, once, with its sibling modules
importable)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "gallery"
BENCHMARKS = ROOT / "benchmarks"


def benchmark_module(name: str) -> ModuleType:
    """``benchmarks/<name>.py`` as the module ``name`` (shared by every test that loads it)."""
    if name in sys.modules:
        return sys.modules[name]
    if str(BENCHMARKS) not in sys.path:                  # its siblings (fuzz_scenes imports fuzz_mutations)
        sys.path.insert(0, str(BENCHMARKS))
    spec = importlib.util.spec_from_file_location(name, BENCHMARKS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module
