r"""Which inputs drive the operating clearance, the film and the life: variance-based and regression views.

:func:`sobol` answers "what should I tighten?": first-order and total Sobol
indices of the root inputs (housing bore, journal, each gauge's error, shell
wall, crush height, process mean shifts, misalignment), each sample drawn
through the real chain (grading, pairing, the shell taken from its grade's
bin, press fit, and for the film and life the crankshaft and the oil film;
:mod:`stackup.study.roots`), with SALib's Saltelli sampling and Jansen
estimators and bootstrap intervals. The first-order index :math:`S_1` is the
share of the output's variance that fixing one input alone would remove; the
total index :math:`S_T` also counts its interactions (grading couples the
gauge errors with the sizes: a reading near a grade boundary), so
:math:`\sum S_1 < 1` measures how much of the spread comes from grading.

:func:`contributions` is the cheap view on a study dataset: standardised
regression coefficients :math:`\mathrm{SRC}_k = b_k\,\sigma_{x_k}/\sigma_y`
of the bearing's measured inputs, whose squares are first-order shares when
the model is near linear (read them with the fit's :math:`R^2`); in selective
assembly the shells are chosen from the measured sizes, so these inputs are
correlated and the regression answers another question than Sobol's.

References
----------
.. [1] Saltelli, A. et al., *Global Sensitivity Analysis: The Primer*, Wiley,
   2008, sec. 1.2.5 (standardised regression coefficients) and ch. 4.
.. [2] Saltelli, A., Annoni, P., Azzini, I., Campolongo, F., Ratto, M.,
   Tarantola, S., "Variance based sensitivity analysis of model output.
   Design and estimator for the total sensitivity index", Comput. Phys.
   Commun. 181 (2010) 259-270.
.. [3] Herman, J., Usher, W., "SALib: An open-source Python library for
   Sensitivity Analysis", J. Open Source Softw. 2 (2017) 97.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ._validate import InRange, Integer, OneOf, validated
from ._random import as_generator, seed_sequence
from .assembly import ASSEMBLED
from .engines import load_engine
from .schemes import load as load_scheme
from .study.chain import mechanical_chain
from .study.pilot import pilot_parts, shell_plan
from .study.roots import RootModel
from .study.scenario import apply as apply_scenario

#: Inputs of a bearing (name -> how to read it from a one-scheme dataset, as (engines, bearings) arrays).
INPUTS = {
    "housing bore": lambda d: np.broadcast_to(d.housing_bore.values, d.status.shape),
    "journal": lambda d: np.broadcast_to(d.journal_d.values, d.status.shape),
    "upper shell wall": lambda d: d.shell_upper_wall.values,
    "lower shell wall": lambda d: d.shell_lower_wall.values,
    "crush height": lambda d: 0.5 * (d.shell_upper_crush.values + d.shell_lower_crush.values),
    "bore gauge error": lambda d: np.broadcast_to(d.housing_bore_reading.values - d.housing_bore.values, d.status.shape),
    "journal gauge error": lambda d: np.broadcast_to(d.journal_d_reading.values - d.journal_d.values, d.status.shape),
    "misalignment": lambda d: np.broadcast_to(np.linalg.norm(d.bore_offset.values, axis=-1), d.status.shape),
}


#: Largest number of bearings a fit uses (a seeded random subsample beyond it); the bootstrap
#: intervals show what that costs in precision.
MAX_BEARINGS = 20_000


def contributions(ds, scheme, *, output="clearance_operating", within_bearing=True, bootstrap=200, rng=0):
    """Variance contributions of the inputs to ``output`` for one scheme.

    Returns a DataFrame indexed by input: ``share`` (SRC^2 normalised to the
    explained variance), its 95 % bootstrap interval, ``src`` (signed), and
    the fit's ``r2`` in ``attrs``. Bearings where the output is not computed
    (NaN, marked by the status variables) are left out of the fit. With
    ``within_bearing`` the means of each main-bearing position are removed
    first: the position (its load) is a design fact, not a tolerance, and
    would otherwise swamp the film's variance.

    In selective assembly the shells are chosen from the measured bore and
    journal, so the inputs are correlated and the shares are a regression
    decomposition, not independent first-order indices; gauge error acts
    through the choice of shells and shows there.
    """
    d = ds.sel(scheme=scheme)
    if "mech_engine" in d[output].dims:  # a result of the mechanical chain: its engines only
        d = d.isel(engine=d.mech_engine.values).drop_vars("mech_engine").rename({"mech_engine": "engine"})
    y = d[output].values
    ok = (d.status.values == ASSEMBLED) & np.isfinite(y)
    columns = [np.array(INPUTS[k](d), dtype=float) for k in INPUTS]
    if within_bearing:
        def centred(a):
            masked = np.where(ok, a, np.nan)
            return a - np.nanmean(masked, axis=0, keepdims=True)

        columns = [centred(a) for a in columns]
        y = centred(y)
    x = np.column_stack([a[ok] for a in columns])
    y = y[ok]
    gen = as_generator(rng)
    if y.size > MAX_BEARINGS:
        pick = gen.choice(y.size, MAX_BEARINGS, replace=False)
        x, y = x[pick], y[pick]
    keep = x.std(axis=0) > 0  # an input with no spread in this study cannot contribute
    names = [k for k, use in zip(INPUTS, keep) if use]
    x = x[:, keep]
    if y.size <= x.shape[1] + 2:
        raise ValueError(f"output {output!r}: {y.size} bearings are too few for {x.shape[1]} inputs")

    def fit(rows):
        xs, ys = x[rows], y[rows]
        zx = (xs - xs.mean(axis=0)) / xs.std(axis=0)
        zy = (ys - ys.mean()) / ys.std()
        coef, *_ = np.linalg.lstsq(zx, zy, rcond=None)
        r2 = 1 - np.sum((zy - zx @ coef) ** 2) / np.sum(zy**2)
        return coef, r2

    coef, r2 = fit(np.arange(y.size))
    boot = np.array([fit(gen.integers(0, y.size, y.size))[0] ** 2 for _ in range(bootstrap)])
    share = coef**2 / np.sum(coef**2)
    boot_share = boot / boot.sum(axis=1, keepdims=True)
    frame = pd.DataFrame({
        "share": share,
        "share_lo": np.quantile(boot_share, 0.025, axis=0),
        "share_hi": np.quantile(boot_share, 0.975, axis=0),
        "src": coef,
    }, index=pd.Index(names, name="input")).sort_values("share", ascending=False)
    frame.attrs.update({"r2": float(r2), "bearings": int(y.size), "output": output, "scheme": str(scheme),
                        "within_bearing": within_bearing})
    return frame


#: Outputs :func:`sobol` can analyse: name -> how one engine's sample gives it (see there).
SOBOL_OUTPUTS = ("clearance_operating", "h_min", "life")
#: Default Saltelli base sample per output (evaluations: n * (groups + 2) engines).
SOBOL_N = {"clearance_operating": 2048, "h_min": 128, "life": 128}


def _power_of_two(values):
    """The Saltelli base sample ``n``, where given, is a power of two."""
    n = values["n"]
    if n is not None and n & (n - 1):
        raise ValueError(f"n: {n} is not a power of two (Sobol points balance at powers of two)")


@validated(output=OneOf(SOBOL_OUTPUTS), n=Integer(minimum=8), bearing=Integer(minimum=1), mean_shift=InRange(0.0, 6.0),
           relations=(_power_of_two,))
def sobol(engine, scheme, *, output="clearance_operating", n=None, seed=0, scenario=None, mean_shift=0.0, bearing=1,
          crank_angle_step=4.0, crank_method="bearing-law", film_method="finite", pilot_engines=20_000,
          bootstrap=200, return_all=False):
    """First-order and total Sobol indices of the root inputs, through the real chain, with 95 % intervals.

    Parameters
    ----------
    engine, scheme : str, path or loaded object
    output : {"clearance_operating", "h_min", "life"}
        The operating clearance of main bearing ``bearing``; the engine's
        smallest cycle-minimum film at the mid-plane (over the width an edge
        held at the wall would be a floor that only the clearance moves); the
        engine's life (its weakest bearing, on the film over the width as the
        study reads it).
    n : int, optional
        Saltelli base sample, a power of two (default :data:`SOBOL_N`); the
        chain runs on ``n * (groups + 2)`` engines.
    seed : int
        Scrambling of the Sobol points and the bootstrap.
    scenario : dict, optional
        A disturbance of the engine (:mod:`stackup.scenarios`).
    mean_shift : float
        Half-range of the process mean shifts of the bore and the journal,
        uniform, in process standard deviations [-]; 0 (default) leaves them
        out (the declared scenarios shift the means by one standard
        deviation), > 0 adds the two inputs.
    bearing : int
        Main-bearing position of the clearance output (1-based).
    crank_angle_step, crank_method, film_method :
        The mechanical chain's grid and tiers (film and life outputs).
    pilot_engines : int
        Pilot sample the shell plan comes from (as in a study).
    bootstrap : int
        Resamples for the intervals.
    return_all : bool
        Return a dict of every output the same sample gives (the film and the
        life come from one run of the mechanical chain).

    Returns
    -------
    pandas.DataFrame
        One row per root input (:data:`stackup.study.roots.GROUPS` that act
        on the output), columns ``S1``, ``S1_lo``, ``S1_hi``, ``ST``,
        ``ST_lo``, ``ST_hi``; ``attrs`` hold the output, its mean and
        standard deviation, the engines evaluated and the share of samples
        not assembled (graded at the limits).
    """
    engine = apply_scenario(load_engine(engine), scenario)
    scheme = load_scheme(scheme)
    if output != "clearance_operating" and engine.crank is None:
        raise ValueError(f"output: {output!r} needs the engine's [crank] section, which {engine.name} has not")
    n = SOBOL_N[output] if n is None else n
    if bearing > engine.main_bearings:
        raise ValueError(f"bearing: {bearing} is not one of 1..{engine.main_bearings}")
    seed_sequence(seed)
    mean_shift = float(mean_shift)
    left_out = {"misalignment"} if output == "clearance_operating" else set()
    if mean_shift == 0.0:
        left_out |= {"bore process mean", "journal process mean"}
    model = RootModel(engine, scheme, shell_plan(engine, scheme, pilot_parts(engine, seed, pilot_engines)).aim,
                      mean_shift=mean_shift)
    groups = tuple(g for g in model.groups if g not in left_out)
    names, owners = model.columns(groups)
    outputs = (output,) if output == "clearance_operating" else ("h_min", "life")
    frames = sobol_indices(
        lambda u: _sobol_outputs(model, u, groups, outputs, bearing - 1, crank_angle_step, crank_method, film_method),
        owners, n=n, seed=seed, bootstrap=bootstrap, outputs=outputs)
    for name, frame in frames.items():
        frame.attrs.update({"output": name, "scheme": scheme.name, "engine": engine.name})
    return frames[output] if not return_all else frames


def sobol_indices(evaluate, groups, *, n, seed=0, bootstrap=200, max_missing=0.01, outputs=None):
    """Sobol indices of a function of independent uniform inputs, by group, with 95 % bootstrap intervals.

    Parameters
    ----------
    evaluate : callable
        ``evaluate(u)`` with ``u`` (samples, inputs) uniform on [0, 1)
        returns the output (samples,); NaN where it cannot be evaluated.
    groups : sequence of str
        The group of each input (an input alone is a group of its own name).
    n : int
        Saltelli base sample (a power of two); ``evaluate`` sees
        ``n * (groups + 2)`` samples.
    max_missing : float
        Largest share of NaN outputs accepted; they are replaced by the mean
        of the others (their share is in the attrs).
    outputs : sequence of str, optional
        Names of several outputs ``evaluate`` returns at once (samples,
        outputs); then a dict of frames by name is returned.

    Returns
    -------
    pandas.DataFrame
        One row per group: ``S1``, ``S1_lo``, ``S1_hi``, ``ST``, ``ST_lo``, ``ST_hi``.
    """
    from SALib.sample import sobol as saltelli

    names = [f"x{k}" for k in range(len(groups))]
    problem = {"num_vars": len(names), "names": names, "bounds": [[0.0, 1.0]] * len(names), "groups": list(groups)}
    u = saltelli.sample(problem, n, calc_second_order=False, scramble=True, seed=seed)
    values = np.asarray(evaluate(u), dtype=float)
    if outputs is not None:
        return {name: _analyse(problem, values[:, k], groups, u, seed, bootstrap, max_missing)
                for k, name in enumerate(outputs)}
    return _analyse(problem, values, groups, u, seed, bootstrap, max_missing)


def _analyse(problem, y, groups, u, seed, bootstrap, max_missing):
    from SALib.analyze import sobol as analyse

    n = u.shape[0] // (len(dict.fromkeys(groups)) + 2)
    missing = ~np.isfinite(y)
    if missing.mean() > max_missing:
        raise ValueError(f"{missing.mean():.1%} of the samples could not be evaluated (not graded or the chain "
                         "failed); the indices would be meaningless")
    y = np.where(missing, np.nanmean(y), y)
    # SALib seeds its bootstrap only for a truthy seed (``if seed:``); seed 0 would draw from numpy's global
    # state and the intervals would change from run to run: pass a nonzero seed derived from ours
    bootstrap_seed = int(np.random.SeedSequence(seed).generate_state(1)[0]) or 1
    result = analyse.analyze(problem, y, calc_second_order=False, num_resamples=bootstrap, conf_level=0.95,
                             seed=bootstrap_seed)
    frame = pd.DataFrame({
        "S1": result["S1"], "S1_lo": result["S1"] - result["S1_conf"], "S1_hi": result["S1"] + result["S1_conf"],
        "ST": result["ST"], "ST_lo": result["ST"] - result["ST_conf"], "ST_hi": result["ST"] + result["ST_conf"],
    }, index=pd.Index(list(dict.fromkeys(groups)), name="input"))
    frame.attrs.update({"n": n, "evaluations": int(u.shape[0]), "mean": float(np.mean(y)), "std": float(np.std(y)),
                        "not_evaluated_share": float(missing.mean()), "method": "Saltelli sampling, Jansen "
                        "estimators (SALib)"})
    return frame


def _sobol_outputs(model, u, groups, outputs, bearing, crank_angle_step, crank_method, film_method):
    """The outputs of each sampled engine (samples, outputs) (see :func:`sobol`)."""
    engines = model.engines(u, groups=groups)
    if outputs == ("clearance_operating",):
        return engines["clearance_operating"][:, bearing, None]
    values = np.full((u.shape[0], len(outputs)), np.nan)
    ok = np.all(np.isfinite(engines["clearance_operating"]), axis=1)
    mech = mechanical_chain(model.engine, clearance=engines["clearance_operating"][ok],
                            journal_d=engines["journal_d"][ok], bore_offset=engines["bore_offset"][ok],
                            journal_eccentricity=engines["journal_eccentricity"][ok],
                            crank_angle=np.arange(0.0, 720.0, crank_angle_step), crank_method=crank_method,
                            film_method=film_method, tilt_method="equilibrium")  # the study's lives: over the width
    converged = mech["crank_status"] == 0
    for k, name in enumerate(outputs):
        # the film at the mid-plane: over the width an edge held at the wall is a floor only the clearance moves
        value = mech["h_min_midplane" if name == "h_min" else name]
        values[np.flatnonzero(ok)[converged], k] = value[converged].min(axis=1)  # the engine's weakest bearing
    return values
