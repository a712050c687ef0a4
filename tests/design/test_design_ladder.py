"""The designer's ladder of shell grades and its independent check (issue 31).

- nested: a design asked for more shell grades is never worse on the design objective than one of fewer, each
  rung's J recomputed from its scheme alone on the same design sample;
- the guard: where a rung's own design does worse than the one below, the one below is kept and said so;
- the check: the result carries the designed scheme's figures on a sample no decision saw, beside the design
  sample's, and the command prints both.
"""

import numpy as np
import pytest

import stackup.design as design_mod
from stackup.design import ladder
from stackup.design.problem import Weights, build_problem
from stackup.engines import load_engine
from stackup.patterns import adapt

QUICK = dict(n_engines=600, generations=0, scenarios={})
SHELL_GRADES = 3


def quick_problem(shell_grades):
    """The design problem :func:`stackup.design.design` builds for ``QUICK`` on the example engine."""
    engine = load_engine("iso-example")
    return build_problem(engine, window=engine.clearance_window, shell_grades=shell_grades, housing_grades=3,
                         journal_grades=3, scenarios={}, seed=0, n_engines=QUICK["n_engines"], sort_share=0.5,
                         readout=1e-7, mixed=True, weights=Weights())


@pytest.fixture(scope="module")
def designed():
    return design_mod.design("iso-example", shell_grades=SHELL_GRADES, **QUICK)


@pytest.mark.integration
def test_more_shell_grades_are_never_worse_on_the_objective_recomputed_from_each_scheme(designed):
    problem = quick_problem(SHELL_GRADES)
    assert [step.asked for step in designed.levels] == [1, 2, 3]
    recomputed = [problem.expected_objective(step.scheme) for step in designed.levels]
    # each rung's J is its scheme's own, on the same design sample (not a number the search kept)
    np.testing.assert_allclose(recomputed, [step.objective for step in designed.levels], rtol=1e-9)
    assert all(b <= a for a, b in zip(recomputed, recomputed[1:])), recomputed
    for step in designed.levels:
        assert len(step.scheme.shell.labels) == step.grades <= step.asked
    # on this engine every rung gains: one grade leaves hundreds of ppm outside, three leave about one
    assert recomputed[-1] < 0.1 * recomputed[0]
    assert designed.objective == pytest.approx(recomputed[-1], rel=1e-9)


@pytest.mark.integration
def test_a_rung_that_does_worse_than_the_one_below_keeps_the_design_below(monkeypatch):
    real = ladder.rung

    def worse_at_two(problem, *args, **kwargs):
        level = real(problem, *args, **kwargs)
        if problem.shell_grades == 2:  # as if the 2-grade search had gone astray
            return ladder.replace(level, objective=1.0, candidates={"search": 1.0})
        return level

    monkeypatch.setattr(ladder, "rung", worse_at_two)
    problem = quick_problem(2)
    levels = ladder.climb(problem, adapt("iso13778-5", problem.engine), generations=0, seed=0,
                          log=lambda line: None)
    assert [level.grades for level in levels] == [1, 1]
    assert levels[1].scheme is levels[0].scheme and levels[1].objective == levels[0].objective
    assert levels[1].origin == "kept from 1 grades"
    from stackup.design.explain import ladder_lines

    text = "\n".join(ladder_lines([level.step(k) for k, level in enumerate(levels, start=1)]))
    assert "No 2-grade design found did better than the 1-grade one" in text


def test_nested_starts_split_each_grade_wide_enough_and_add_one_at_each_end():
    problem = quick_problem(3)
    step = problem.shell_step
    narrowest = np.ceil(problem.min_width / step) * step  # on the shell grid, as designed limits are
    wide = np.array([0.0, 4.0, 5.0]) * narrowest + 1.98e-3  # a grade 4 x the narrowest, one 1 x
    starts = ladder.nested_starts(wide, problem)
    assert len(starts) == 3  # the wide grade split at its middle; one added below, one above
    for edges in starts:
        assert edges.size == 4 and np.all(np.diff(edges) >= narrowest - 1e-12)
    np.testing.assert_allclose(starts[0], [wide[0], wide[0] + 2 * narrowest, wide[1], wide[2]],
                               atol=0.5 * step + 1e-12)  # the split on the shell grid


@pytest.mark.integration
def test_the_result_carries_the_check_on_an_independent_sample_beside_the_design_sample(designed):
    check = designed.check
    assert set(check.outside) == set(designed.outside) == {"nominal"}
    assert check.samples >= 2 and check.engines == QUICK["n_engines"]
    for label, share in check.outside.items():
        lo, hi = check.interval[label]
        assert 0.0 <= lo <= share <= hi
    lo, hi = check.objective_interval
    assert lo <= check.objective <= hi
    # other parts: the figures differ from the design sample's, and both are in the scheme's notes
    assert check.objective != designed.objective
    text = "\n".join(designed.scheme.notes)
    assert "Result on the design sample" in text and "Independent check" in text
    assert "Ladder" in text
