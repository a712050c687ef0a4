"""Synthetic measurements from stated true processes, and how often the fits' intervals hold the truth.

The readings are drawn with the library's own sampler (a
:class:`stackup.tolerances.Dimension` with the true process, its gauge and
its shared share: what an engine file's entry means), so a fit that recovers
the truth recovers what the engine file would say. The fitting tests are made
with :func:`stackup.fit.press_fit` at a known housing outer diameter plus gauge
noise. Used by the tests (``tests/measure/test_measure_coverage.py``) and by
``studies/measured_data.py``, which writes the measured coverage to
``reports/measured_data.md``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import materials
from .._random import as_generator
from ..engines import load_engine
from ..fit import press_fit
from ..tolerances import Dimension, Gauge, Mixture, Normal, SkewNormal, ToolWear, quantile_cpk
from .process import fit_candidates, fit_process

#: Drawing limits of the example engine's housing bore [m] (ISO 13778's example).
BORE_LIMITS = (50.000e-3, 50.018e-3)
#: True processes of the coverage cases (housing bores of the example engine) [m].
TRUE_PROCESSES = {
    "normal": Normal(50.0095e-3, 2.0e-6),
    "skew-normal": SkewNormal(50.0085e-3, 2.2e-6, 0.6),
    "mixture": Mixture((Normal(50.0065e-3, 1.4e-6), Normal(50.0115e-3, 1.6e-6)), (0.55, 0.45)),
    "drift": ToolWear(50.0060e-3, 50.0120e-3, 1.5e-6),
}
#: Each case's own random stream (a seed of one case shares no random numbers with the same seed of another).
_CASE_KEY = {case: k for k, case in enumerate(TRUE_PROCESSES)}
#: The gauge of the synthetic readings: repeatability 0.5 um, read-out 0.1 um [m].
GAUGE = Gauge(repeatability=0.5e-6, resolution=0.1e-6)
#: Groups (blocks) and parts per group of a synthetic sample, and the true shared share.
GROUPS, PER_GROUP, SHARED = 60, 5, 0.3


def synthetic_readings(process, rng, *, groups=GROUPS, per_group=PER_GROUP, shared=SHARED, gauge=GAUGE,
                       limits=BORE_LIMITS):
    """Readings [m] of ``groups`` x ``per_group`` parts, their group labels and their manufacturing order.

    Parts are made in the order 0 .. n-1; a drifting (tool-wear) process
    draws each part at its place in the tool life, the first part at
    ``start`` and the last at ``end``, without a group effect.
    """
    rng = as_generator(rng)
    n = groups * per_group
    if isinstance(process, ToolWear):
        if shared:
            raise ValueError("shared: a drifting process's synthetic parts share no group effect; give shared=0")
        true = process.start + (process.end - process.start) * np.arange(n) / (n - 1) \
            + process.sigma * rng.standard_normal(n)
    else:
        dim = Dimension("synthetic", *limits, process, gauge, shared)
        true = dim.true_sizes(rng.standard_normal(groups), rng.standard_normal((groups, per_group))).ravel()
    readings = gauge.read(true, rng.standard_normal(n))
    return readings, np.repeat(np.arange(groups), per_group), np.arange(n)


@dataclass(frozen=True)
class Coverage:
    """Hits of the stated intervals over seeds, and the models chosen."""

    case: str
    seeds: int
    cpk_hits: int
    shared_hits: int | None
    chosen: dict
    true_cpk: float
    mean_cpk_width: float


def coverage(case, seeds, *, grouped=True, resamples=1000, first_seed=0):
    """How often the Cpk (and shared-share) intervals of :func:`fit_process` hold the truth of ``case``."""
    process = TRUE_PROCESSES[case]
    truth = quantile_cpk(process, *BORE_LIMITS)
    cpk_hits, shared_hits, chosen, widths = 0, 0, {}, []
    for seed in range(first_seed, first_seed + seeds):
        rng = np.random.default_rng([seed, 35, _CASE_KEY[case]])
        x, groups, order = synthetic_readings(process, rng, shared=SHARED if grouped else 0.0)
        fit = fit_process(x, limits=BORE_LIMITS, gauge_repeatability=GAUGE.repeatability,
                          groups=groups if grouped else None, sequence=order if case == "drift" else None,
                          resamples=resamples, seed=seed)
        cpk_hits += fit.cpk_ci[0] <= truth <= fit.cpk_ci[1]
        widths.append(fit.cpk_ci[1] - fit.cpk_ci[0])
        if grouped:
            shared_hits += fit.shared_ci[0] <= SHARED <= fit.shared_ci[1]
        chosen[fit.model] = chosen.get(fit.model, 0) + 1
    return Coverage(case, seeds, int(cpk_hits), int(shared_hits) if grouped else None, chosen, truth,
                    float(np.mean(widths)))


def choice_rate(case, n, seeds, *, first_seed=0):
    """Share of ``seeds`` independent samples of ``n`` readings of ``case`` whose least-BIC model is the true one."""
    process = TRUE_PROCESSES[case]
    right = 0
    for seed in range(first_seed, first_seed + seeds):
        rng = np.random.default_rng([seed, 36, _CASE_KEY[case]])
        x, _, order = synthetic_readings(process, rng, groups=n, per_group=1, shared=0.0)
        t = order / (n - 1) if case == "drift" else None
        candidates, _ = fit_candidates(x, t, GAUGE.repeatability)
        best = min((c for c in candidates if not c.note), key=lambda c: c.bic)
        right += best.model == case
    return right / seeds


# --- fitting tests -----------------------------------------------------------------------------------------

#: Gauge noise of the synthetic fitting tests [m]: bore and walls 0.5 um, crush heights 1 um, assembled bore 1 um.
TEST_NOISE = {"housing_bore": 0.5e-6, "shell_upper_wall": 0.5e-6, "shell_lower_wall": 0.5e-6,
              "shell_upper_crush": 1e-6, "shell_lower_crush": 1e-6, "assembled_bore": 1e-6}


def synthetic_fitting_tests(n, housing_outer, rng, *, engine="iso-example", temperatures=(18.0, 26.0)):
    """``n`` fitting tests on ``engine`` with a housing of outer diameter ``housing_outer`` [m].

    Parts are drawn uniformly within the drawing (bore, crush) and the
    walls' usual range, the test temperature uniformly in ``temperatures``;
    the assembled bore is :func:`stackup.fit.press_fit`'s shell bore at that
    temperature; bore and walls are read at the test temperature (grown from
    the assembly temperature by their materials' expansion); every reading gets
    :data:`TEST_NOISE`. Returns the table (dict of arrays, m and degC).
    """
    rng = as_generator(rng)
    eng = load_engine(engine)
    spec = eng.press_fit
    kwargs = {k: v for k, v in spec.kwargs().items() if k not in ("housing_outer", "temperature")}
    bore = rng.uniform(eng.housing_bore.lo, eng.housing_bore.hi, n)
    wall_mid = 0.5 * (eng.housing_bore.lo - eng.journal_d.hi) - 0.015e-3
    walls = rng.uniform(wall_mid - 0.009e-3, wall_mid + 0.009e-3, (2, n))
    crush = rng.uniform(eng.shell_wall.crush.lo, eng.shell_wall.crush.hi, (2, n))
    temperature = rng.uniform(*temperatures, n)
    fit = press_fit(housing_bore=bore, housing_outer=housing_outer, shell_wall=walls.mean(axis=0),
                    crush_height=crush.mean(axis=0), temperature=temperature, **kwargs)
    dt = temperature - spec.assembly_temperature
    grow_h = 1.0 + materials.get(spec.housing_material).expansion * dt
    grow_s = 1.0 + materials.get(spec.shell_material).expansion * dt
    table = {"housing_bore": bore * grow_h, "shell_upper_wall": walls[0] * grow_s,
             "shell_lower_wall": walls[1] * grow_s, "shell_upper_crush": crush[0], "shell_lower_crush": crush[1],
             "assembled_bore": fit.shell_bore}
    table = {k: v + TEST_NOISE[k] * rng.standard_normal(n) for k, v in table.items()}
    table["temperature"] = temperature
    return table
