"""Accuracy against time for every approximate method but the cam profile's (``cam_profile.py``), one
section each: a sweep's step (:mod:`sweep_step`), the constraint continuation's tolerance
(:mod:`continuation_tolerance`) and the step-through page's slider (:mod:`html_slider`); the date and the
machine's load first.

Usage: ``python benchmarks/accuracy.py [sweep] [continuation] [slider]`` (default: all three).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import continuation_tolerance  # noqa: E402
import html_slider  # noqa: E402
import sweep_step  # noqa: E402
from accuracy_common import machine  # noqa: E402

SECTIONS = {"sweep": ("A sweep's step", sweep_step.tables),
            "continuation": ("The constraint continuation's tolerance", continuation_tolerance.tables),
            "slider": ("The step-through page's slider", html_slider.table)}


def main(argv: list[str]) -> int:
    unknown = [a for a in argv if a not in SECTIONS]
    if unknown:
        print(f"unknown section {unknown[0]!r}; the sections: {', '.join(SECTIONS)}", file=sys.stderr)
        return 2
    print(machine())
    for key in argv or list(SECTIONS):
        title, fn = SECTIONS[key]
        print(f"\n## {title}\n\n{fn()}")
    print(f"\n{machine()}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
