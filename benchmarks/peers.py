"""The four-bar sweep against its peers (pylinkage, mechanism) and a plain numpy reference, side by side
in one run: full states per second.  The peers are optional (``pip install .[bench]``); one that is not
installed is named as such.

Usage: ``python benchmarks/peers.py [n ...]`` (default sizes 1e3 .. 1e7; the peers stop at the sizes in
``drafting.app.bench_peers.LARGEST``).
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # run from a checkout, uninstalled

from drafting.app.bench_peers import format_rows, rows  # noqa: E402

if __name__ == "__main__":
    sizes = tuple(int(float(a)) for a in sys.argv[1:]) or (10**3, 10**4, 10**5, 10**6, 10**7)
    print(format_rows(*rows(sizes)))
