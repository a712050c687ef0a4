"""numba kernels against their plain-Python twins."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from stackup._kernels.stock import take_shells


def take_shells_reference(pair_code, bearing_lot_start, options, shell_grade, shell_lot_start, n_grades):
    """Readable twin: per lot, bins as lists in production order, first allowed pair in stock."""
    n = len(pair_code)
    upper, lower, option = [-1] * n, [-1] * n, [-1] * n
    left = []
    for lot in range(len(bearing_lot_start) - 1):
        bins = {g: [s for s in range(shell_lot_start[lot], shell_lot_start[lot + 1]) if shell_grade[s] == g]
                for g in range(n_grades)}
        for i in range(bearing_lot_start[lot], bearing_lot_start[lot + 1]):
            if pair_code[i] < 0:
                continue
            for k, (u, l) in enumerate(options[pair_code[i]]):
                if u < 0:
                    break
                enough = len(bins[u]) >= 2 if u == l else (bins[u] and bins[l])
                if enough:
                    upper[i] = bins[u].pop(0)
                    lower[i] = bins[l].pop(0)
                    option[i] = k
                    break
        left.append([len(bins[g]) for g in range(n_grades)])
    return np.array(upper), np.array(lower), np.array(option), np.array(left).reshape(-1, n_grades)


@st.composite
def stock_case(draw):
    n_grades = draw(st.integers(1, 4))
    n_lots = draw(st.integers(1, 3))
    bearings = [draw(st.integers(0, 12)) for _ in range(n_lots)]
    shells = [draw(st.integers(0, 20)) for _ in range(n_lots)]
    n, m = sum(bearings), sum(shells)
    pair_code = np.array(draw(st.lists(st.integers(-1, n_grades * n_grades - 1), min_size=n, max_size=n)), np.int64)
    shell_grade = np.array(draw(st.lists(st.integers(-1, n_grades - 1), min_size=m, max_size=m)), np.int64)
    width = draw(st.integers(1, 3))
    options = np.full((n_grades * n_grades, width, 2), -1, np.int64)
    for p in range(n_grades * n_grades):
        options[p, 0] = divmod(p, n_grades)
        for k in range(1, draw(st.integers(1, width))):
            options[p, k] = (draw(st.integers(0, n_grades - 1)), draw(st.integers(0, n_grades - 1)))
    return (pair_code, np.cumsum([0, *bearings]).astype(np.int64), options, shell_grade,
            np.cumsum([0, *shells]).astype(np.int64), n_grades)


@given(stock_case())
def test_take_shells_matches_reference(case):
    got = take_shells(*case)
    want = take_shells_reference(*case)
    for g, w in zip(got, want):
        np.testing.assert_array_equal(g, w)


@given(stock_case())
def test_take_shells_conserves_shells(case):
    pair_code, b_start, options, grade, s_start, n_grades = case
    upper, lower, option, left = take_shells(*case)
    taken = np.concatenate([upper[upper >= 0], lower[lower >= 0]])
    assert len(set(taken)) == taken.size  # no shell fitted twice
    made = np.bincount(grade[grade >= 0], minlength=n_grades)
    used = np.bincount(grade[taken], minlength=n_grades)
    np.testing.assert_array_equal(made, used + left.sum(axis=0))


def cell_outside_reference(cdf, start, size, step, thin, thick, cell, n_cells):
    """numpy twin of the designer's kernel: np.interp on each pair's points, bincount per cell."""
    out = np.zeros((cdf.shape[0], n_cells))
    for p in range(cdf.shape[0]):
        x = start[p] + step * np.arange(size[p])
        f = cdf[p, :size[p]]
        inside = np.interp(thick, x, f) - np.interp(thin, x, f)
        out[p] = np.bincount(cell, weights=np.clip(1.0 - inside, 0.0, 1.0), minlength=n_cells)
    return out


@given(st.integers(1, 4), st.integers(2, 40), st.integers(0, 60), st.integers(1, 7), st.integers(0, 2**32 - 1))
def test_cell_outside_matches_reference(n_pairs, points, n_bearings, n_cells, seed):
    from stackup._kernels.design import cell_outside

    rng = np.random.default_rng(seed)
    step = 2e-8
    size = rng.integers(2, points + 1, n_pairs).astype(np.int64)
    cdf = np.zeros((n_pairs, points))
    for p in range(n_pairs):
        cdf[p, :size[p]] = np.concatenate(([0.0], np.sort(rng.random(size[p] - 1))))
    start = 3.9e-3 + rng.normal(0.0, 1e-7, n_pairs)
    # wall sums inside, below and beyond every distribution (the interpolation clips at both ends)
    thin = 3.9e-3 + rng.normal(0.0, 3e-7, n_bearings)
    thick = thin + rng.uniform(0.0, 6e-7, n_bearings)
    cell = rng.integers(0, n_cells, n_bearings).astype(np.int64)
    got = cell_outside(cdf, start, size, step, thin, thick, cell, n_cells)
    want = cell_outside_reference(cdf, start, size, step, thin, thick, cell, n_cells)
    np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-9)  # np.interp rounds its slope differently
