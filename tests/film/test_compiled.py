"""The kernels give the same numbers on a study's first run, which compiles them, and on the next, which loads
them from numba's cache: each run in a fresh interpreter with its own empty cache folder."""

import os
import subprocess
import sys

import numpy as np
import pytest

pytestmark = pytest.mark.slow

#: One bearing of the example engine through the crankshaft and the mass-conserving film tier (whose kernels once
#: took floating-point shortcuts that made the compiled and the cached code sum in other orders), the mobility
#: tier beside it.
SCRIPT = """
import sys
import numpy as np
from stackup.crank import BellakhdharLaw, reactions
from stackup.engines import load_engine
from stackup.film.orbit import orbit

crank = load_engine("iso-example").crank
angle = np.arange(720.0)
r = reactions(crank.pin_loads(angle), spans=crank.spans, EI=crank.ei, law=BellakhdharLaw(clearance=37e-6))
loads = r.reactions[:, 1:2].swapaxes(0, 1)
films = [orbit(loads, angle, journal_d=46e-3, bearing_width=22e-3, clearance=40e-6, viscosity=0.008,
               speed=crank.speed, method=method).h_min for method in ("elrod-coarse", "mobility-finite")]
np.savez(sys.argv[1], reactions=r.reactions, elrod=films[0], mobility=films[1])
"""


def test_compiled_and_cached_kernels_give_the_same_numbers(tmp_path):
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba-cache")}
    script = tmp_path / "one_bearing.py"
    script.write_text(SCRIPT, encoding="utf-8")
    for run in ("compiled", "cached"):
        done = subprocess.run([sys.executable, str(script), str(tmp_path / f"{run}.npz")], env=env,
                              capture_output=True, text=True, timeout=1800)
        assert done.returncode == 0, done.stderr
    compiled, cached = np.load(tmp_path / "compiled.npz"), np.load(tmp_path / "cached.npz")
    assert any((tmp_path / "numba-cache").rglob("*.nbi"))  # the first run left a cache for the second
    for name in ("reactions", "elrod", "mobility"):
        np.testing.assert_array_equal(cached[name], compiled[name], err_msg=name)
