"""Contact zones of Levanov's wear chart (method 2): which points of the bearing surface the film leaves in contact.

The readable statement is :func:`stackup.life.levanov_method2`; ``tests/life/test_life_kernels.py``
holds the numpy twin this kernel must match. One pass over the journal positions finds the
crank angles whose minimum film :math:`c - |\\mathbf x|` is below the critical film, a second
lists, at those angles only, the chart points whose film
:math:`c - \\mathbf x\\cdot(\\cos\\theta_p, \\sin\\theta_p)` is below it: the dense film over every
point and angle is never formed.
"""

import math

import numpy as np
from numba import njit


@njit(cache=True)
def contact_zones(x, c, critical, cos_p, sin_p, weights):
    """Chart points inside the contact zone at each crank angle, and each row's share of the cycle in contact.

    Parameters
    ----------
    x : float64 (rows, steps, 2)
        Journal centre [m].
    c, critical : float64 (rows,)
        Radial clearance and critical film [m].
    cos_p, sin_p : float64 (points,)
        Direction of each chart point.
    weights : float64 (steps,)
        Share of the cycle each step stands for (summing to 1).

    Returns
    -------
    share : float64 (rows,)
        Share of the cycle with the minimum film below ``critical``.
    row, step, point : int64 (K,)
        The chart points in contact, by row, step and point, in that order.
    film : float64 (K,)
        Their film [m].
    zone : int64 (K,)
        Points in contact at their row and step (the zone's size).
    """
    rows, steps, points = x.shape[0], x.shape[1], cos_p.shape[0]
    share = np.zeros(rows)
    count = 0
    for r in range(rows):
        for s in range(steps):
            if c[r] - math.hypot(x[r, s, 0], x[r, s, 1]) < critical[r]:
                share[r] += weights[s]
                for p in range(points):
                    if c[r] - x[r, s, 0] * cos_p[p] - x[r, s, 1] * sin_p[p] < critical[r]:
                        count += 1
    row = np.empty(count, np.int64)
    step = np.empty(count, np.int64)
    point = np.empty(count, np.int64)
    film = np.empty(count)
    zone = np.empty(count, np.int64)
    k = 0
    for r in range(rows):
        for s in range(steps):
            if c[r] - math.hypot(x[r, s, 0], x[r, s, 1]) < critical[r]:
                first = k
                for p in range(points):
                    h = c[r] - x[r, s, 0] * cos_p[p] - x[r, s, 1] * sin_p[p]
                    if h < critical[r]:
                        row[k] = r
                        step[k] = s
                        point[k] = p
                        film[k] = h
                        k += 1
                for i in range(first, k):
                    zone[i] = k - first
    return share, row, step, point, film, zone
