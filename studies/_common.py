"""What the benchmark studies share: the timing rule, the environment line and writing the report."""

from __future__ import annotations

import platform
import time
from pathlib import Path

import numba
import numpy as np

import stackup


def best_time(fn, repeat):
    """Shortest wall time [s] of ``repeat`` calls of ``fn`` after one warm-up call (compilation, caches)."""
    fn()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def environment():
    """One line naming the versions and the machine the numbers come from."""
    return (f"stackup {stackup.__version__}, Python {platform.python_version()}, numpy {np.__version__}, "
            f"numba {numba.__version__}, {platform.machine()}")


def write_report(path, lines):
    """Write the markdown lines to ``path`` (folders made) and say so."""
    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out}")
    return out
