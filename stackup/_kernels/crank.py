"""Newton solution of the crankshaft beam on nonlinear bearings, batched and warm-started.

The numpy twin of the residual and Jacobian is :func:`stackup.crank.law.force`
with :func:`stackup.crank.beam.condensed`; the tests compare both.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit, prange

#: Status of a solve, by code (the API stores it with these CF flag meanings).
STATUS = ("converged", "max_iterations", "not_finite")
CONVERGED, MAX_ITERATIONS, NOT_FINITE = range(len(STATUS))
#: Floating-point licences that keep NaN/inf checks meaningful (no 'nnan', 'ninf').
FAST = {"contract", "arcp", "reassoc", "nsz"}
#: The Newton solve: residual tolerance (share of the load scale), most iterations, the law's rest displacement [m].
Newton = namedtuple("Newton", ("rtol", "max_iterations", "rest"))


@njit(cache=True, inline="always")
def _softplus(x):
    return x + math.log1p(math.exp(-x)) if x > 0.0 else math.log1p(math.exp(x))


@njit(cache=True, inline="always")
def _expit(x):
    if x >= 0.0:
        return 1.0 / (1.0 + math.exp(-x))
    e = math.exp(x)
    return e / (1.0 + e)


@njit(cache=True, inline="always", fastmath=FAST)
def _bearing(u0, u1, clearance, dx, e, sp0, k_lv, k_hv, theta0, dtheta, rest):
    """Force and Jacobian of one bearing; see stackup.crank.law.

    ``e = exp(-J/dx)`` and ``sp0 = softplus(-J/dx)`` are the bearing's constants; below a
    displacement ``rest`` [m] the journal is at rest.
    Returns (f0, f1, j00, j01, j10, j11).
    """
    # displacements are micrometres: the squares cannot overflow; below rest (1e-150 m,
    # where they would start to underflow) the journal is at rest: no force, no stiffness
    mag = math.sqrt(u0 * u0 + u1 * u1)
    if mag < rest:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    c = u0 / mag
    s_abs = abs(u1) / mag
    sign = 1.0 if u1 >= 0.0 else -1.0
    theta = math.atan2(s_abs, c)
    if dx == 0.0:
        g = max(mag - clearance, 0.0)
        dg = 1.0 if mag > clearance else 0.0
    else:
        z = (mag - clearance) / dx
        ez = math.exp(-abs(z))  # shared by softplus(z) and expit(-z)
        softplus = max(z, 0.0) + math.log1p(ez)
        expit_minus = ez / (1.0 + ez) if z >= 0.0 else 1.0 / (1.0 + ez)
        g = dx * (1.0 + e) * (softplus - sp0) - mag * e
        dg = 1.0 - (1.0 + e) * expit_minus
    sg = _expit((theta - theta0) / dtheta)
    kd = k_lv + (k_hv - k_lv) * sg
    dkd = (k_hv - k_lv) * sg * (1.0 - sg) / dtheta
    ux, uy = c, sign * s_abs
    tx, ty = -s_abs, sign * c
    a = kd * dg
    h = kd * g / mag
    t = g * dkd / mag
    return (kd * g * ux, kd * g * uy,
            a * ux * ux + h * tx * tx + t * ux * tx, a * ux * uy + h * tx * ty + t * ux * ty,
            a * uy * ux + h * ty * tx + t * uy * tx, a * uy * uy + h * ty * ty + t * uy * ty)


@njit(cache=True, inline="always", fastmath=FAST)
def _residual(x, kb, f_ext, off, law, consts, rest, r, fb, jb):
    """Residual K_b w - T P + F(w - d) into r; bearing forces into fb (n, 2); Jacobian blocks into jb (n, 4)."""
    n = kb.shape[1]
    for p in range(n):
        for c in range(2):
            acc = -f_ext[p, c]
            for q in range(n):
                acc += kb[c, p, q] * x[2 * q + c]
            r[2 * p + c] = acc
    for p in range(n):
        f0, f1, j00, j01, j10, j11 = _bearing(x[2 * p] - off[p, 0], x[2 * p + 1] - off[p, 1], law[0, p], law[1, p],
                                              consts[0, p], consts[1, p], law[2, p], law[3, p], law[4, p], law[5, p], rest)
        fb[p, 0] = f0
        fb[p, 1] = f1
        jb[p, 0] = j00
        jb[p, 1] = j01
        jb[p, 2] = j10
        jb[p, 3] = j11
        r[2 * p] += f0
        r[2 * p + 1] += f1


@njit(cache=True, fastmath=FAST)
def _solve_dense(a, b):
    """Solve a x = b in place (Gaussian elimination, partial pivoting); returns False if singular."""
    m = b.shape[0]
    for col in range(m):
        piv = col
        big = abs(a[col, col])
        for row in range(col + 1, m):
            if abs(a[row, col]) > big:
                big = abs(a[row, col])
                piv = row
        if big == 0.0:
            return False
        if piv != col:
            for k in range(m):
                a[col, k], a[piv, k] = a[piv, k], a[col, k]
            b[col], b[piv] = b[piv], b[col]
        inv = 1.0 / a[col, col]
        for row in range(col + 1, m):
            factor = a[row, col] * inv
            if factor != 0.0:
                for k in range(col, m):
                    a[row, k] -= factor * a[col, k]
                b[row] -= factor * b[col]
    for row in range(m - 1, -1, -1):
        acc = b[row]
        for k in range(row + 1, m):
            acc -= a[row, k] * b[k]
        b[row] = acc / a[row, row]
    return True


@njit(cache=True)
def _norm(r):
    acc = 0.0
    for v in r:
        acc += v * v
    return math.sqrt(acc)


#: Work arrays of one sequence's Newton solve (n bearings, 2n unknowns): the beam's part of the Newton matrix and
#: the matrix (2n, 2n), the Newton step, a trial point, the residuals there and at the iterate (2n,), the bearing
#: forces (n, 2) and Jacobian blocks (n, 4) at the iterate and at the trial point.
Work = namedtuple("Work", ("template", "jac", "step", "trial", "r", "r_trial", "fb", "jb", "fb_t", "jb_t"))


@njit(cache=True, inline="always")
def _work(kb):
    """The :data:`Work` of a beam ``kb`` (2, n, n), the beam's part of the Newton matrix filled in."""
    n = kb.shape[1]
    size = 2 * n
    template = np.zeros((size, size))
    for c in range(2):
        for p in range(n):
            for q in range(n):
                template[2 * p + c, 2 * q + c] = kb[c, p, q]
    return Work(template, np.zeros((size, size)), np.zeros(size), np.zeros(size), np.zeros(size), np.zeros(size),
                np.zeros((n, 2)), np.zeros((n, 4)), np.zeros((n, 2)), np.zeros((n, 4)))


@njit(cache=True, fastmath=FAST, inline="always")
def _law_constants(lw):
    """Each bearing's constants exp(-J/dx) and softplus(-J/dx) (2, n) of its law ``lw`` (6, n) (0 where dx = 0)."""
    n = lw.shape[1]
    consts = np.zeros((2, n))
    for p in range(n):
        if lw[1, p] > 0.0:
            consts[0, p] = math.exp(-lw[0, p] / lw[1, p])
            consts[1, p] = _softplus(-lw[0, p] / lw[1, p])
    return consts


@njit(cache=True, fastmath=FAST, inline="always")
def _support_loads(transfer, case, f_ext):
    """The load case's pin loads ``case`` (m, 2) carried to the supports of the rigidly supported beam, into
    ``f_ext`` (n, 2); returns the loads' scale (the sum of their components' sizes)."""
    n, m = f_ext.shape[0], case.shape[0]
    scale = 0.0
    for p in range(n):
        for c in range(2):
            acc = 0.0
            for i in range(m):
                acc += transfer[c, p, i] * case[i, c]
            f_ext[p, c] = acc
    for i in range(m):
        scale += abs(case[i, 0]) + abs(case[i, 1])
    return scale


@njit(cache=True, fastmath=FAST, inline="always")
def _start(a, kb, f_ext, off, lw, solutions, x):
    """Newton's start for load case ``a`` into ``x``: the first, the journals pushed from the offsets ``off`` along
    the rigid-support reactions; then the last solution, extrapolated linearly from the last two, quadratically from
    the last three (``solutions``, the last first)."""
    x_prev, x_prev2, x_prev3 = solutions
    n = f_ext.shape[0]
    if a == 0:
        for p in range(n):
            rx = f_ext[p, 0]
            ry = f_ext[p, 1]
            for q in range(n):
                rx -= kb[0, p, q] * off[q, 0]
                ry -= kb[1, p, q] * off[q, 1]
            mag = math.hypot(rx, ry)
            push = 0.0 if mag == 0.0 else (lw[0, p] + mag / lw[2, p]) / mag
            x[2 * p] = off[p, 0] + push * rx
            x[2 * p + 1] = off[p, 1] + push * ry
    elif a == 1:
        for k in range(x.shape[0]):
            x[k] = x_prev[k]
    elif a == 2:
        for k in range(x.shape[0]):
            x[k] = 2.0 * x_prev[k] - x_prev2[k]
    else:  # quadratic extrapolation along the sequence
        for k in range(x.shape[0]):
            x[k] = 3.0 * (x_prev[k] - x_prev2[k]) + x_prev3[k]


@njit(cache=True, fastmath=FAST, inline="always")
def _newton(x, case, bearings, newton, tol, k_ref, work):
    """Newton on one load case's residual from ``x``, in place, until it is within ``tol``: the matrix stiffened
    by mu (Levenberg) where it is singular (the law's rest state) or no step along it lowers the residual
    (:func:`_backtrack`), mu dropped after a full step. ``case`` = (kb, f_ext, offsets), ``bearings`` = (law,
    constants); ``work.fb`` ends with the bearing forces at ``x``. Returns (status code, iterations)."""
    kb, f_ext, off = case
    lw, consts = bearings
    n = kb.shape[1]
    size = 2 * n
    r, fb, jb, jac, step = work.r, work.fb, work.jb, work.jac, work.step
    mu = 0.0
    code = MAX_ITERATIONS
    it = 0
    _residual(x, kb, f_ext, off, lw, consts, newton.rest, r, fb, jb)
    res = _norm(r)
    while it < newton.max_iterations:
        if not math.isfinite(res):
            code = NOT_FINITE
            break
        if res <= tol:
            code = CONVERGED
            break
        it += 1
        jac[:, :] = work.template
        for p in range(n):
            jac[2 * p, 2 * p] += jb[p, 0]
            jac[2 * p, 2 * p + 1] += jb[p, 1]
            jac[2 * p + 1, 2 * p] += jb[p, 2]
            jac[2 * p + 1, 2 * p + 1] += jb[p, 3]
        for i in range(size):
            jac[i, i] += mu
            step[i] = -r[i]
        if not _solve_dense(jac, step):
            # singular: the rest state of the law; stiffen the Newton matrix only
            mu = max(10.0 * mu, 1e-9 * k_ref)
            continue
        accepted, t, res_t = _backtrack(x, case, bearings, newton.rest, res, work)
        if accepted:
            _take_trial(x, work)
            res = res_t
            mu = 0.0 if t == 1.0 else mu
        else:
            mu = max(10.0 * mu, 1e-9 * k_ref)
    return code, it


@njit(cache=True, fastmath=FAST, inline="always")
def _backtrack(x, case, bearings, rest, res, work):
    """Newton's step ``work.step`` from ``x`` halved until the residual's norm falls by Armijo's share below
    ``res`` (down to 1e-10 of the step): the trial point, its residual and bearing forces in ``work``. Returns
    (accepted, step length, residual norm there)."""
    kb, f_ext, off = case
    lw, consts = bearings
    trial, r_trial = work.trial, work.r_trial
    t = 1.0
    while t > 1e-10:
        for k in range(x.shape[0]):
            trial[k] = x[k] + t * work.step[k]
        _residual(trial, kb, f_ext, off, lw, consts, rest, r_trial, work.fb_t, work.jb_t)
        res_t = _norm(r_trial)
        if res_t < (1.0 - 1e-4 * t) * res:
            return True, t, res_t
        t *= 0.5
    return False, t, 0.0


@njit(cache=True, inline="always")
def _take_trial(x, work):
    """The trial point, its residual, bearing forces and Jacobian blocks become the iterate's."""
    for k in range(x.shape[0]):
        x[k] = work.trial[k]
        work.r[k] = work.r_trial[k]
    for p in range(work.fb.shape[0]):
        work.fb[p, 0], work.fb[p, 1] = work.fb_t[p, 0], work.fb_t[p, 1]
        for k in range(4):
            work.jb[p, k] = work.jb_t[p, k]


@njit(cache=True, fastmath=FAST)
def _sequence(b, beam, loads, offsets, law, newton, out):
    """Solve sequence ``b`` along its load cases, warm-starting each from the previous ones.

    ``beam`` = (kb, transfer) as :func:`solve` takes them, ``newton``: :data:`Newton`; writes into
    ``out`` = (reactions, deflections, status, iterations). Each load case: its loads on the supports
    (:func:`_support_loads`), Newton (:func:`_newton`) from a start extrapolated along the sequence
    (:func:`_start`).
    """
    kb, transfer = beam
    reactions, deflections, status, iterations = out
    n = kb.shape[1]
    size = 2 * n
    x = np.zeros(size)
    solutions = (np.zeros(size), np.zeros(size), np.zeros(size))  # the last three load cases', the last first
    f_ext = np.zeros((n, 2))
    work = _work(kb)
    lw = law[b]
    bearings = (lw, _law_constants(lw))
    k_ref = 0.0
    for p in range(n):
        k_ref = max(k_ref, lw[2, p])
    for a in range(loads.shape[1]):
        off = offsets[b, a]
        scale = _support_loads(transfer, loads[b, a], f_ext)
        # residual floor: the loads' scale, or the force of a nanometre on the stiffest bearing
        tol = newton.rtol * max(scale, k_ref * 1e-9)
        _start(a, kb, f_ext, off, lw, solutions, x)
        code, it = _newton(x, (kb, f_ext, off), bearings, newton, tol, k_ref, work)
        x_prev, x_prev2, x_prev3 = solutions
        for k in range(size):
            x_prev3[k] = x_prev2[k]
            x_prev2[k] = x_prev[k]
            x_prev[k] = x[k]
        for p in range(n):
            reactions[b, a, p, 0] = work.fb[p, 0]
            reactions[b, a, p, 1] = work.fb[p, 1]
            deflections[b, a, p, 0] = x[2 * p]
            deflections[b, a, p, 1] = x[2 * p + 1]
        status[b, a] = code
        iterations[b, a] = it


@njit(cache=True)
def _outputs(loads, n):
    n_b, n_a = loads.shape[0], loads.shape[1]
    return (np.zeros((n_b, n_a, n, 2)), np.zeros((n_b, n_a, n, 2)), np.zeros((n_b, n_a), np.int8),
            np.zeros((n_b, n_a), np.int32))


@njit(cache=True, parallel=True)
def solve(kb, transfer, loads, offsets, law, newton):
    """Bearing forces and support deflections over sequences of load cases, sequences in parallel.

    kb (2, n, n), transfer (2, n, m); loads (B, A, m, 2); offsets (B, A, n, 2);
    law (B, 6, n), constant along each sequence; ``newton``: :data:`Newton`. Each of
    the B sequences is solved along A in order, each step warm-started from the previous ones.
    Returns reactions (B, A, n, 2), deflections (B, A, n, 2), status (B, A), iterations (B, A).
    """
    reactions, deflections, status, iterations = _outputs(loads, kb.shape[1])
    # numba's parallel loop takes arrays and numbers, not tuples of them: packed again in the loop
    rtol, max_iterations, rest = newton
    for b in prange(loads.shape[0]):
        _sequence(b, (kb, transfer), loads, offsets, law, Newton(rtol, max_iterations, rest),
                  (reactions, deflections, status, iterations))
    return reactions, deflections, status, iterations


@njit(cache=True)
def solve_serial(kb, transfer, loads, offsets, law, newton):
    """:func:`solve` on the calling thread (no thread-pool dispatch: for one or few sequences)."""
    out = _outputs(loads, kb.shape[1])
    for b in range(loads.shape[0]):
        _sequence(b, (kb, transfer), loads, offsets, law, newton, out)
    return out
