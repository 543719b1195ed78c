"""Accuracy against time for every approximate method but the cam profile's (``cam_profile.py``), one
section each: a sweep's step (:mod:`sweep_step`), the constraint continuation's tolerance
(:mod:`continuation_tolerance`) and the step-through page's slider (:mod:`html_slider`); the date and the
machine's load before and after.

Usage: ``python benchmarks/accuracy.py [sweep] [continuation] [slider] [--charts DIR]`` (default: all
three; ``--charts``: each section's log-log chart as DIR/<section>-accuracy-time.svg and a PNG beside it).
"""

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import continuation_tolerance  # noqa: E402
import html_slider  # noqa: E402
import loglog_chart  # noqa: E402
import sweep_step  # noqa: E402
from accuracy_common import machine  # noqa: E402

SECTIONS = {
    "sweep": ("A sweep's step", sweep_step.measure, sweep_step.tables, sweep_step.chart_series,
              "sweep and its extremes (ms, median of 5)", "largest error, relative (no unit)"),
    "continuation": ("The constraint continuation's tolerance", continuation_tolerance.measure,
                     continuation_tolerance.tables, continuation_tolerance.chart_series,
                     "continuation over 360 angles (ms, median of 3)",
                     "largest velocity or acceleration error / largest value"),
    "slider": ("The step-through page's slider", html_slider.rows, html_slider.report, html_slider.chart_series,
               "the slider card's size (kB)", "largest error between poses (relative)"),
}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sections", nargs="*",
                    help=f"any of {', '.join(SECTIONS)} (default: all)")
    ap.add_argument("--charts", type=Path, help="write each section's chart into this folder")
    a = ap.parse_args(argv)
    unknown = [s for s in a.sections if s not in SECTIONS]
    if unknown:
        ap.error(f"unknown section {unknown[0]!r}; the sections: {', '.join(SECTIONS)}")
    print(machine())
    for key in a.sections or list(SECTIONS):
        title, measure, fmt, series, x_title, y_title = SECTIONS[key]
        measured = measure()
        print(f"\n## {title}\n\n{fmt(measured)}")
        if a.charts:
            path = a.charts / f"{key}-accuracy-time.svg"
            loglog_chart.chart(series(measured), path, x_title, y_title)
            print(f"\nwrote {path} and {path.with_suffix('.png')}")
    print(f"\n{machine()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
