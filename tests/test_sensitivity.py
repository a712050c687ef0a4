"""Variance-based sensitivity: a function of known indices, a linear chain, and what grading does to gauges."""

import numpy as np
import pandas as pd
import pytest

from stackup.engines import load_engine
from stackup.schemes import load
from stackup.sensitivity import sobol, sobol_indices
from stackup.study.pilot import pilot_parts, shell_plan
from stackup.study.roots import RootModel


def test_indices_of_the_ishigami_function_match_their_closed_form():
    # Ishigami & Homma (1990), a = 7, b = 0.1: S1 = (0.3139, 0.4424, 0), ST = (0.5576, 0.4424, 0.2437)
    # (Saltelli et al., Global Sensitivity Analysis: The Primer, 2008, sec. 4.8)
    def ishigami(u):
        x = np.pi * (2 * u - 1)
        return np.sin(x[:, 0]) + 7 * np.sin(x[:, 1]) ** 2 + 0.1 * x[:, 2] ** 4 * np.sin(x[:, 0])

    f = sobol_indices(ishigami, ["x1", "x2", "x3"], n=8192, seed=1)
    np.testing.assert_allclose(f.S1, [0.3139, 0.4424, 0.0], atol=0.02)
    np.testing.assert_allclose(f.ST, [0.5576, 0.4424, 0.2437], atol=0.02)
    assert np.all((f.S1_lo <= f.S1) & (f.S1 <= f.S1_hi)) and np.all(f.ST_hi - f.ST_lo < 0.1)


def test_grouped_inputs_add_their_variances():
    # y = x1 + x2 + 2 x3 with x uniform: variances 1 : 1 : 4; group x1 and x2
    f = sobol_indices(lambda u: u[:, 0] + u[:, 1] + 2 * u[:, 2], ["a", "a", "b"], n=4096, seed=2)
    np.testing.assert_allclose(f.loc["a", ["S1", "ST"]], [1 / 3, 1 / 3], atol=0.02)
    np.testing.assert_allclose(f.loc["b", ["S1", "ST"]], [2 / 3, 2 / 3], atol=0.02)


def test_ungraded_scheme_1_is_linear_so_sobol_equals_the_squared_standardised_coefficients():
    f = sobol("iso-example", "iso13778-1", n=2048, seed=3)
    # the same root inputs drawn at random through the same chain, and a least-squares fit
    engine, scheme = load_engine("iso-example"), load("iso13778-1")
    model = RootModel(engine, scheme, shell_plan(engine, scheme, pilot_parts(engine, 3, 20_000)).aim)
    groups = tuple(f.index)
    names, owners = model.columns(groups)
    u = np.random.default_rng(4).random((40_000, len(names)))
    y = model.engines(u, groups=groups)["clearance_operating"][:, 0]
    from scipy import special

    x = special.ndtri(np.clip(u, 1e-12, 1 - 1e-12))  # every input; the other bearings' get no weight
    owner = np.array(owners)
    zx = (x - x.mean(axis=0)) / x.std(axis=0)
    coef, *_ = np.linalg.lstsq(np.column_stack([zx, np.ones(len(y))]), (y - y.mean()) / y.std(), rcond=None)
    src2 = {g: float(np.sum(coef[:-1][owner == g] ** 2)) for g in groups}
    for g in groups:
        assert f.loc[g, "S1_lo"] - 0.02 <= src2[g] <= f.loc[g, "S1_hi"] + 0.02, (g, src2[g], f.loc[g].to_dict())
    assert f.S1.sum() == pytest.approx(1.0, abs=0.05)  # no interactions in a linear chain


def test_graded_schemes_make_gauge_repeatability_matter():
    ungraded, graded = sobol("iso-example", "iso13778-1", n=1024), sobol("iso-example", "iso13778-4", n=1024)
    assert ungraded.loc["bore gauge error", "ST"] < 0.01  # nothing is chosen from a reading
    # misgrading near grade boundaries; the journal is read four times (two planes, two directions): less
    assert graded.loc["bore gauge error", "ST_lo"] > 0.1 and graded.loc["journal gauge error", "ST_lo"] > 0.02
    assert graded.S1.sum() < 0.85  # a share of the spread comes from the grading's interactions


def test_bad_sobol_input():
    with pytest.raises(ValueError, match="n: 1000 is not a power of two"):
        sobol("iso-example", "iso13778-4", n=1000)
    with pytest.raises(ValueError, match="output: 'film' is not one of"):
        sobol("iso-example", "iso13778-4", output="film")


def test_bootstrap_intervals_repeat_with_seed_zero():
    # SALib draws its bootstrap from numpy's global state when its seed is 0: the intervals must not
    from stackup.sensitivity import sobol_indices

    def evaluate(u):
        return u[:, 0] + u[:, 1] ** 2 + 0.1 * u[:, 2]

    first, second = (sobol_indices(evaluate, ["a", "b", "c"], n=64, seed=0) for _ in range(2))
    np.random.seed(12345)  # whatever the global state, the same intervals
    third = sobol_indices(evaluate, ["a", "b", "c"], n=64, seed=0)
    pd.testing.assert_frame_equal(first, second)
    pd.testing.assert_frame_equal(first, third)


def test_the_film_output_is_the_mid_plane_film_and_the_life_the_studys():
    """The Sobol outputs come from the study's chain (tilt balanced at the supports): the film at the mid-plane (over
    the width an edge held at the wall is a floor only the clearance moves), the life on the film over the width."""
    from types import SimpleNamespace
    from unittest import mock

    from stackup import sensitivity

    engines = {"clearance_operating": np.full((2, 5), 40e-6), "journal_d": np.full((2, 5), 46e-3),
               "bore_offset": np.zeros((2, 5, 2)), "journal_eccentricity": np.zeros((2, 5, 2))}
    model = SimpleNamespace(engines=lambda u, groups: engines, engine=None)
    out = {"crank_status": np.zeros(2, int), "h_min": np.full((2, 5), 0.1e-6),
           "h_min_midplane": np.array([[2e-6, 1e-6, 3e-6, 1e-6, 2e-6]] * 2), "life": np.full((2, 5), 3.6e6)}
    seen = {}

    def chain(engine, **kwargs):
        seen.update(kwargs)
        return out

    with mock.patch.object(sensitivity, "mechanical_chain", chain):
        values = sensitivity._sobol_outputs(model, np.zeros((2, 3)), None, ("h_min", "life"), 0, 8.0, "bearing-law",
                                            "mobility-finite")
    assert seen["tilt_method"] == "equilibrium"
    np.testing.assert_array_equal(values, [[1e-6, 3.6e6]] * 2)
