"""Print the throughput table of the analytic full-cycle sweep.

Usage: ``python benchmarks/analytic_sweep.py [n ...]`` (default sizes 1e3 .. 1e7, 5 repeats each).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from drafting.bench_sweep import format_table, sweep_rows  # noqa: E402

if __name__ == "__main__":
    sizes = tuple(int(float(a)) for a in sys.argv[1:]) or (10**3, 10**4, 10**5, 10**6, 10**7)
    print(format_table(sweep_rows(sizes=sizes)))
