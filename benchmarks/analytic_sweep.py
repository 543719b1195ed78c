"""Print the throughput table of the analytic full-cycle sweep (full states: positions, velocities and
accelerations), the four-bar and slider-crank closed forms and the dyad chain on a six-bar side by side,
then the per-call detail (wall, best, CPU user/system time).

Usage: ``python benchmarks/analytic_sweep.py [n ...]`` (default sizes 1e3 .. 1e7, 5 repeats each; the
dyad chain runs up to 1e6).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from drafting.app.bench_sweep import format_detail, format_table, sweep_rows  # noqa: E402

if __name__ == "__main__":
    sizes = tuple(int(float(a)) for a in sys.argv[1:]) or (10**3, 10**4, 10**5, 10**6, 10**7)
    rows = sweep_rows(sizes=sizes)
    print(format_table(rows))
    print()
    print(format_detail(rows))
