"""Run every benchmark side by side and print the tables (same as `drafting bench`)."""

import sys

from drafting.bench import run_benchmarks

if __name__ == "__main__":
    print(run_benchmarks(quick="--quick" in sys.argv))
