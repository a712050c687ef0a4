"""The main job as a library call: a scheme comparison with its declared scenarios."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import xarray as xr

from ..scenarios import DECLARED
from ..sensitivity import INPUTS, contributions
from . import ISO_SCHEMES, Study

#: Engines of the mechanical chain in a scenario that disturbs it (misalignment); the
#: clearance-only scenarios run no mechanics.
SCENARIO_MECHANICS_ENGINES = 50
#: Outputs of the contributor chart.
SENSITIVITY_OUTPUTS = ("clearance_operating", "h_min")


@dataclass(frozen=True)
class Comparison:
    """What the main job computes; every part is a dataset, so a report needs nothing else.

    Attributes
    ----------
    dataset : xarray.Dataset
        The study (every engine kept).
    scenarios : dict of str -> xarray.Dataset
        The same study under each declared scenario, with the same seed
        (common random numbers), as streaming summaries.
    sensitivity : xarray.Dataset
        Contributions of the inputs to the variance of each output per scheme
        (:func:`sensitivity_dataset`).
    tails : xarray.Dataset
        Shares of bearings beyond each edge of the design window per scheme,
        by subset simulation (:func:`tails_dataset`), which the ranking uses
        where the study counts too few bearings outside the window.
    """

    dataset: xr.Dataset
    scenarios: dict
    sensitivity: xr.Dataset
    tails: xr.Dataset


def compare(engine="iso-example", schemes=ISO_SCHEMES, n_engines=100_000, seed=0, *, scenarios=DECLARED,
            progress=None, log=None, **study_options):
    """Compare selective-fitting schemes on an engine: the study, its scenarios and what drives the spread.

    Parameters
    ----------
    engine : str or path
        Built-in engine name or engine TOML file.
    schemes : sequence of str or path
    n_engines : int
    seed : int
    scenarios : dict of str -> dict
        Label -> scenario (:mod:`stackup.scenarios`); each is run with the
        same seed on the clearance stages, and on
        :data:`SCENARIO_MECHANICS_ENGINES` engines of the mechanical chain
        where it disturbs that chain (misalignment). Empty for none.
    progress : bool or None
        Progress bars (None: only on a terminal).
    log : callable or None
        Called with one line of text as each stage starts (the study, each
        scenario, the sensitivity), e.g. ``print`` for logs.
    **study_options
        Further :class:`~stackup.study.Study` parameters.

    Returns
    -------
    Comparison
    """
    log = log or (lambda line: None)
    study = Study(engine=engine, schemes=tuple(schemes), n_engines=n_engines, seed=seed, progress=progress,
                  **study_options)
    log(f"study: {study.n_engines:,} engines x {len(study.schemes)} schemes")
    ds = study.run()
    runs = {}
    for k, (label, change) in enumerate((scenarios or {}).items(), start=1):
        log(f"scenario {k}/{len(scenarios)}: {label}")
        runs[label] = replace(study, scenario=change, keep="summaries",
                              mechanics_engines=SCENARIO_MECHANICS_ENGINES if "misalignment_scale" in change else 0).run()
    log("sensitivity: contributions of the inputs")
    sensitivity = sensitivity_dataset(ds)
    log("tails: shares beyond the design window by subset simulation")
    return Comparison(ds, runs, sensitivity, tails_dataset(engine, schemes, window=study_options.get("window"),
                                                          seed=seed, pilot_engines=study.pilot_engines))


def sensitivity_dataset(ds, *, outputs=SENSITIVITY_OUTPUTS, bootstrap=100, seed=0):
    """Regression contributions of the inputs to each output per scheme (:func:`stackup.sensitivity.contributions`).

    Variables on (output, scheme, input): ``share`` with ``share_lo`` and
    ``share_hi`` (95 % bootstrap interval) and ``src``; ``r2`` on (output,
    scheme). NaN where an output was not computed or an input has no spread.
    """
    outputs = [o for o in outputs if np.isfinite(ds[o].values).any()]
    schemes = [str(s) for s in ds.scheme.values]
    inputs = list(INPUTS)
    shape = (len(outputs), len(schemes), len(inputs))
    values = {k: np.full(shape, np.nan) for k in ("share", "share_lo", "share_hi", "src")}
    r2 = np.full(shape[:2], np.nan)
    for i, output in enumerate(outputs):
        for j, scheme in enumerate(schemes):
            try:
                frame = contributions(ds, scheme, output=output, bootstrap=bootstrap, rng=seed)
            except ValueError:  # too few bearings with this output
                continue
            for name in values:
                values[name][i, j] = frame[name].reindex(inputs).to_numpy()
            r2[i, j] = frame.attrs["r2"]
    dims = ("output", "scheme", "input")
    data = {
        "share": (dims, values["share"], {"units": "1", "long_name": "share of the explained variance (SRC^2, normalised)"}),
        "share_lo": (dims, values["share_lo"], {"units": "1", "long_name": "lower 95 % bootstrap bound of share"}),
        "share_hi": (dims, values["share_hi"], {"units": "1", "long_name": "upper 95 % bootstrap bound of share"}),
        "src": (dims, values["src"], {"units": "1", "long_name": "standardised regression coefficient"}),
        "r2": (dims[:2], r2, {"units": "1", "long_name": "coefficient of determination of the linear fit"}),
    }
    coords = {"output": ("output", outputs, {"long_name": "output variable of the study dataset"}),
              "scheme": ("scheme", schemes, {"long_name": "selective-fitting scheme"}),
              "input": ("input", inputs, {"long_name": "input of a bearing"})}
    return xr.Dataset(data, coords=coords, attrs={"method": "standardised regression coefficients within each "
                                                            "bearing position, bootstrap over bearings",
                                                  "bootstrap": bootstrap, "seed": seed})


def tails_dataset(engine, schemes, *, window=None, seed=0, pilot_engines=20_000, n_level=2_000):
    """Share of bearings below and above the design window per scheme, by subset simulation (:mod:`stackup.tail`).

    Variables on (scheme, side): ``tail_share`` and its ``tail_standard_error``,
    with the chain evaluations each estimate cost (``tail_bearings``).
    """
    from ..engines import load_engine
    from ..schemes import load as load_scheme
    from ..tail import clearance_tail

    engine = load_engine(engine)
    window = engine.clearance_window if window is None else window
    loaded = [load_scheme(s) for s in schemes]
    sides = ("lower", "upper")
    shares, errors, cost = (np.full((len(loaded), 2), np.nan) for _ in range(3))
    for i, scheme in enumerate(loaded):
        for j, side in enumerate(sides):
            if not np.isfinite(window[j]) or (side == "lower" and window[j] <= 0):
                continue
            t = clearance_tail(engine, scheme, side=side, threshold=window[j], seed=seed,
                               pilot_engines=pilot_engines, n_level=n_level)
            shares[i, j], errors[i, j], cost[i, j] = t.share, t.standard_error, t.bearings
    dims = ("scheme", "side")
    return xr.Dataset(
        {"tail_share": (dims, shares, {"units": "1", "long_name": "share of assembled bearings beyond the window edge "
                                                                   "(subset simulation)"}),
         "tail_standard_error": (dims, errors, {"units": "1", "long_name": "standard error of tail_share"}),
         "tail_bearings": (dims, cost, {"units": "1", "long_name": "chain evaluations of the estimate"})},
        coords={"scheme": ("scheme", [s.name for s in loaded], {"long_name": "selective-fitting scheme"}),
                "side": ("side", list(sides), {"long_name": "edge of the design window"})},
        attrs={"window": list(map(float, window)), "method": "subset simulation (stackup.tail)", "seed": seed})
