"""Taking shells from per-grade stock bins, bearing after bearing."""

import numpy as np
from numba import njit


@njit(cache=True)
def take_shells(pair_code, bearing_lot_start, options, shell_grade, shell_lot_start, n_grades):
    """Assign shells to bearings from the bins of their production lot.

    Parameters
    ----------
    pair_code : int64 (n,)
        Preferred pair ``upper * n_grades + lower`` of each bearing in
        assembly order; -1 for a bearing that is not built.
    bearing_lot_start : int64 (n_lots + 1,)
        First bearing of each lot, and n at the end.
    options : int64 (n_grades**2, k, 2)
        Allowed (upper, lower) pairs per preferred pair, preferred first,
        -1 padded.
    shell_grade : int64 (m,)
        Grade of each shell made, in production order; -1 = scrapped.
    shell_lot_start : int64 (n_lots + 1,)
        First shell of each lot, and m at the end.

    Returns
    -------
    upper, lower : int64 (n,)
        Index of the shell taken (into ``shell_grade``), -1 if none.
    option : int64 (n,)
        Which allowed pair was used (0 = preferred), -1 = stock-out or not built.
    left : int64 (n_lots, n_grades)
        Shells left in each bin at the end of each lot.
    """
    n = pair_code.shape[0]
    n_lots = bearing_lot_start.shape[0] - 1
    upper = np.full(n, -1, np.int64)
    lower = np.full(n, -1, np.int64)
    option = np.full(n, -1, np.int64)
    left = np.zeros((n_lots, n_grades), np.int64)
    for lot in range(n_lots):
        s0 = shell_lot_start[lot]
        s1 = shell_lot_start[lot + 1]
        # Counting sort of the lot's shells into bins, production order kept.
        count = np.zeros(n_grades, np.int64)
        for s in range(s0, s1):
            g = shell_grade[s]
            if g >= 0:
                count[g] += 1
        ptr = np.zeros(n_grades, np.int64)
        for g in range(1, n_grades):
            ptr[g] = ptr[g - 1] + count[g - 1]
        end = ptr + count
        fill = ptr.copy()
        bins = np.empty(s1 - s0, np.int64)
        for s in range(s0, s1):
            g = shell_grade[s]
            if g >= 0:
                bins[fill[g]] = s
                fill[g] += 1
        for i in range(bearing_lot_start[lot], bearing_lot_start[lot + 1]):
            p = pair_code[i]
            if p < 0:
                continue
            for k in range(options.shape[1]):
                u = options[p, k, 0]
                lo = options[p, k, 1]
                if u < 0:
                    break
                if u == lo:
                    ok = end[u] - ptr[u] >= 2
                else:
                    ok = end[u] - ptr[u] >= 1 and end[lo] - ptr[lo] >= 1
                if ok:
                    upper[i] = bins[ptr[u]]
                    ptr[u] += 1
                    lower[i] = bins[ptr[lo]]
                    ptr[lo] += 1
                    option[i] = k
                    break
        for g in range(n_grades):
            left[lot, g] = end[g] - ptr[g]
    return upper, lower, option, left
