"""Run every benchmark side by side and print the tables (same as `drafting bench`)."""

import sys

from drafting.app.bench import run_benchmarks

if __name__ == "__main__":
    from drafting.app.parallel import tune_gc
    tune_gc()                                   # as the drafting command does in its own process
    print(run_benchmarks(quick="--quick" in sys.argv))
