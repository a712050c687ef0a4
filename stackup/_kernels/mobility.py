r"""Journal orbits of dynamically loaded bearings by the mobility method (numba).

The readable statement is in :mod:`stackup.film.orbit`; ``tests/film/test_mobility_kernel.py``
holds the numpy twin these kernels must match. Everything here is dimensionless:
position :math:`\xi = x/c`, time :math:`\tau = \omega t`, squeeze velocity
:math:`\bar v = v_s/(c\omega)`, load :math:`\bar w = W c^2/(\mu\omega R L^3)`.

Short bearing with π-film (Gümbel) cavitation: the film force on the bearing is
:math:`\bar F = |\bar v|\,G(\varepsilon, \alpha)\,\mathbf u(\alpha)` in the frame of the
line of centres, :math:`\alpha` the direction of the squeeze velocity, and

.. math:: G = \int_{\alpha-\pi/2}^{\alpha+\pi/2} \frac{\mathbf n\mathbf n^T}{(1-\varepsilon\cos\phi)^3}\,d\phi

in closed form through Sommerfeld's substitution. The finite-length tier scales
and turns that force by a table (ratio :math:`\rho`, turn :math:`\delta`) measured
with the Reynolds tier.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit, prange

PERIODIC, NOT_PERIODIC, COLLAPSED, FAILED = 0, 1, 2, 3
HALF_PI = 0.5 * math.pi
#: Newton on the squeeze direction takes its last step when the step is below this [rad].
STEP_DONE = 1e-3
MAX_NEWTON = 60
#: The peak pressure's search takes its last step when the step is below this [rad] (cubic convergence).
PEAK_STEP_DONE = 1e-4
#: The cycles at two angles per step stop when the orbit closes within this share of the thinnest film.
COARSE_SHARE = 0.02
#: Most cycles at two angles per step.
MAX_COARSE = 3
#: An orbit out of cycles whose thinnest film shrank this many cycles in a row is collapsing.
THINNING_LAPS = 3

#: The finite-length correction (:func:`stackup.film.journal.mobility_table`): tables (n_ld, n_eps, n_alpha, 3) over
#: the L/D nodes ld_nodes and the eccentricity nodes stretched (-ln(1 - eps)), and whether it applies (finite; else
#: the short bearing's force, tables unread but for their shape).
Correction = namedtuple("Correction", ("tables", "ld_nodes", "stretched", "finite"))
#: How an orbit is integrated: the eccentricity limit, the closing tolerance (share of the thinnest film), the most
#: cycles.
Integration = namedtuple("Integration", ("limit", "tolerance", "max_cycles"))


@njit(cache=True, inline="always")
def _matrix(eps, ch, sh):
    """G_rr, G_rt, G_tt for the squeeze direction alpha given by ch = cos(alpha/2) >= 0, sh = sin(alpha/2).

    Sommerfeld's substitution tan(g/2) = sqrt((1+eps)/(1-eps)) tan(phi/2) turns
    every integrand into a trigonometric polynomial in g; the arc's ends
    phi = alpha -/+ pi/2 have half angles alpha/2 -/+ pi/4, written from ch, sh
    (the common factor 1/sqrt(2) cancels), and the arc's length in g from one
    atan2 of the two ends.
    """
    sp = math.sqrt(1.0 + eps)
    sm = math.sqrt(1.0 - eps)
    y1 = sp * (sh - ch)
    x1 = sm * (ch + sh)
    y2 = sp * (sh + ch)
    x2 = sm * (ch - sh)
    r1 = x1 * x1 + y1 * y1
    r2 = x2 * x2 + y2 * y2
    c1 = (x1 * x1 - y1 * y1) / r1
    s1 = 2.0 * x1 * y1 / r1
    c2 = (x2 * x2 - y2 * y2) / r2
    s2 = 2.0 * x2 * y2 / r2
    dg = 2.0 * math.atan2(x1 * y2 - y1 * x2, x1 * x2 + y1 * y2)  # in (0, 2 pi)
    dsc = 0.5 * (s2 * c2 - s1 * c1)
    b2 = (1.0 + eps) * (1.0 - eps)
    b3 = b2 * sp * sm
    rr = (0.5 * dg + dsc + 2.0 * eps * (s2 - s1) + eps * eps * dg) / (b3 * b2)
    tt = (0.5 * dg - dsc) / b3
    rt = (0.5 * (s2 * s2 - s1 * s1) - eps * (c2 - c1)) / (b2 * b2)
    return rr, rt, tt


@njit(cache=True)
def short_matrix(eps, alpha):
    """G_rr, G_rt, G_tt of the π-film short bearing, squeeze along ``alpha`` [rad] in (-pi, pi]."""
    return _matrix(eps, math.cos(0.5 * alpha), math.sin(0.5 * alpha))


@njit(cache=True, inline="always")
def _wrap(a):
    if a > math.pi:
        return a - 2.0 * math.pi
    if a <= -math.pi:
        return a + 2.0 * math.pi
    return a


@njit(cache=True, inline="always")
def _locate(nodes, x):
    """Index i and weight t with nodes[i] <= x <= nodes[i+1] (clamped to the ends)."""
    n = nodes.size
    if x <= nodes[0]:
        return 0, 0.0
    if x >= nodes[n - 1]:
        return n - 2, 1.0
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if nodes[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, (x - nodes[lo]) / (nodes[hi] - nodes[lo])


@njit(cache=True)
def bearing_table(correction, ld):
    """The finite correction's table at a bearing's L/D (linear between the tabulated L/D), or the short one."""
    tables = correction.tables
    if not correction.finite:
        return tables[0]
    i, t = _locate(correction.ld_nodes, ld)
    return (1.0 - t) * tables[i] + t * tables[i + 1]


@njit(cache=True)
def table_lookup(table, stretched, eps, alpha):
    """Finite-length correction at (eps, alpha) from ``table`` (n_eps, n_alpha, 3).

    The table holds the log force ratio, the turn [rad] and the log peak-pressure
    ratio over ``stretched`` nodes -ln(1 - eps) (the corrections are nearly linear
    in it near eps = 1) and alpha in [0, pi] (uniform); the turn is odd in alpha.
    Returns (log ratio, turn, d log ratio/d alpha, d turn/d alpha, log peak ratio).
    """
    i, t = _eps_node(stretched, eps)
    return _table_at(table, i, t, alpha)


@njit(cache=True, inline="always")
def _eps_node(stretched, eps):
    """Index and weight of eps among the table's ``stretched`` nodes -ln(1 - eps) (once per eccentricity)."""
    return _locate(stretched, -math.log1p(-eps))


@njit(cache=True, inline="always")
def _table_at(table, i, t, alpha):
    """:func:`table_lookup` with the eccentricity's node ``i`` and weight ``t`` (:func:`_eps_node`)."""
    n_a = table.shape[1]
    a = abs(alpha)
    sign = 1.0 if alpha >= 0.0 else -1.0
    step = math.pi / (n_a - 1)
    j = min(int(a / step), n_a - 2)
    u = a / step - j
    ratio = 0.0
    turn = 0.0
    peak = 0.0
    d_ratio = 0.0
    d_turn = 0.0
    for di in range(2):
        wi = t if di == 1 else 1.0 - t
        row = table[i + di]
        ratio += wi * ((1.0 - u) * row[j, 0] + u * row[j + 1, 0])
        turn += wi * ((1.0 - u) * row[j, 1] + u * row[j + 1, 1])
        peak += wi * ((1.0 - u) * row[j, 2] + u * row[j + 1, 2])
        d_ratio += wi * (row[j + 1, 0] - row[j, 0]) / step
        d_turn += wi * (row[j + 1, 1] - row[j, 1]) / step
    return ratio, sign * turn, sign * d_ratio, d_turn, peak


@njit(cache=True, inline="always")
def _turned(c, s, step):
    """Cosine and sine of an angle turned by a small ``step`` [rad] from its cosine ``c`` and sine ``s``.

    Taylor series to the fourth and fifth order: below a step of 1e-3 their
    error (step^6/720, step^7/5040) is below double precision.
    """
    q = step * step
    cs = 1.0 - 0.5 * q * (1.0 - q / 12.0)
    ss = step * (1.0 - q / 6.0 * (1.0 - q / 20.0))
    return c * cs - s * ss, s * cs + c * ss


@njit(cache=True)
def squeeze_velocity(eps, w_r, w_t, alpha, table, stretched, finite):
    """Squeeze velocity (|v|, direction alpha) whose film force equals the load (w_r, w_t).

    Line-of-centres frame. Newton on the direction: the force turns monotonically
    with alpha (d angle/d alpha = det G / |G u|^2 > 0, since dG/d alpha u = 0), its
    magnitude scales with |v|. Once a step is below 1e-3 rad the next error is
    about 1e-6 rad (quadratic convergence): the step is taken and |F| corrected to
    first order instead of evaluating again, which balances the load to about
    1e-5 (below the midpoint rule's own step error). Returns (speed, alpha, ok).
    """
    speed, alpha, _, _, ok = _squeeze(eps, w_r, w_t, alpha, table, stretched, finite)
    return speed, alpha, ok


@njit(cache=True, inline="always")
def _squeeze(eps, w_r, w_t, alpha, table, stretched, finite):
    """:func:`squeeze_velocity` with the cosine and sine of the direction: (speed, alpha, cos, sin, ok).

    The last step's cosine and sine turned from the last evaluated direction's (:func:`_turned`).
    """
    w = math.hypot(w_r, w_t)
    if w == 0.0:
        return 0.0, alpha, math.cos(alpha), math.sin(alpha), True
    node, weight = _eps_node(stretched, eps) if finite else (0, 0.0)
    for _ in range(MAX_NEWTON):
        ch = math.cos(0.5 * alpha)
        sh = math.sin(0.5 * alpha)
        rr, rt, tt = _matrix(eps, ch, sh)
        ca = ch * ch - sh * sh
        sa = 2.0 * sh * ch
        f_r = rr * ca + rt * sa
        f_t = rt * ca + tt * sa
        fp_r = -rr * sa + rt * ca  # d f / d alpha = G u_perp
        fp_t = -rt * sa + tt * ca
        f2 = f_r * f_r + f_t * f_t
        size = math.sqrt(f2)
        slope = (rr * tt - rt * rt) / f2
        d_size = (f_r * fp_r + f_t * fp_t) / size
        if finite:
            log_ratio, turn, d_log_ratio, d_turn, _ = _table_at(table, node, weight, alpha)
            ratio = math.exp(log_ratio)
            ct = math.cos(turn)
            st = math.sin(turn)
            f_r, f_t = ct * f_r - st * f_t, st * f_r + ct * f_t
            slope = max(slope + d_turn, 0.1 * slope)
            d_size = ratio * (d_size + size * d_log_ratio)
            size *= ratio
        cross = f_r * w_t - f_t * w_r
        dot = f_r * w_r + f_t * w_t
        # angle from F to the load; atan(x) = x to 3e-7 below x = 1e-3 (saves the atan2 near the root)
        d = cross / dot if dot > 0.0 and abs(cross) < 1e-3 * dot else math.atan2(cross, dot)
        step = d / slope
        if abs(step) < STEP_DONE:
            ct, st = _turned(ca, sa, step)
            return w / (size + step * d_size), _wrap(alpha + step), ct, st, True
        if step > 0.7:
            step = 0.7
        elif step < -0.7:
            step = -0.7
        alpha = _wrap(alpha + step)
    return w / size, alpha, math.cos(alpha), math.sin(alpha), False


@njit(cache=True)
def rate(x0, x1, w0, w1, alpha, limit, table, stretched, finite):
    """d xi / d tau at position (x0, x1) under load (w0, w1), engine frame.

    d xi/d tau = v + (1/2) k x xi (journal turning at +1, bearing fixed).
    Returns (dx0, dx1, v0, v1, alpha, ok).
    """
    eps = math.hypot(x0, x1)
    if eps > 0.0:
        e0 = x0 / eps
        e1 = x1 / eps
    else:
        e0 = 1.0
        e1 = 0.0
    eps_film = min(eps, limit)
    w_r = w0 * e0 + w1 * e1
    w_t = -w0 * e1 + w1 * e0
    speed, alpha, ca, sa, ok = _squeeze(eps_film, w_r, w_t, alpha, table, stretched, finite)
    v_r = speed * ca
    v_t = speed * sa
    v0 = v_r * e0 - v_t * e1
    v1 = v_r * e1 + v_t * e0
    return v0 - 0.5 * x1, v1 + 0.5 * x0, v0, v1, alpha, ok


@njit(cache=True, inline="always")
def _log_peak_slopes(eps, ca, sa, cp, sp):
    """First three derivatives of ln(cos(phi - alpha) / (1 - eps cos phi)^3) in phi.

    From the cosines and sines of alpha (ca, sa) and phi (cp, sp): two trigonometric calls per point, not four.
    """
    d = 1.0 - eps * cp
    c = cp * ca + sp * sa  # cos(phi - alpha)
    t = (sp * ca - cp * sa) / c  # tan(phi - alpha)
    first = -t - 3.0 * eps * sp / d
    second = -1.0 / (c * c) - 3.0 * eps * (cp - eps) / (d * d)
    third = -2.0 * t / (c * c) + 3.0 * eps * sp * (d + 2.0 * eps * (cp - eps)) / (d * d * d)
    return first, second, third


@njit(cache=True)
def peak_factor(eps, alpha, phi0):
    """Largest cos(phi - alpha) / (1 - eps cos phi)^3 over the squeezed arc, and where (line-of-centres frame).

    The factor can have two peaks on the arc (eps near 1 with the squeeze turned away from the thinnest film:
    one near alpha, one towards phi = 0), and a search started on one stays there: :func:`_peak_from` from
    ``phi0`` (the last angle's peak) and from the arc's point nearest the thinnest film, the larger kept.
    Returns (factor, phi).
    """
    factor, phi = _peak_from(eps, alpha, phi0)
    # the arc's point nearest phi = 0, kept an eighth of pi inside its ends (where the factor's logarithm falls
    # to minus infinity and a search does not start well)
    towards = min(max(_wrap(-alpha), -3.0 * math.pi / 8.0), 3.0 * math.pi / 8.0)
    other, where = _peak_from(eps, alpha, alpha + towards)
    if other > factor * (1.0 + 1e-12):
        return other, where
    return factor, phi


@njit(cache=True)
def _peak_from(eps, alpha, phi0):
    """The peak of :func:`peak_factor`'s factor that a search from ``phi0`` reaches.

    Halley's method on the derivative of its logarithm: its three derivatives
    share one cosine and sine of phi, and it converges cubically, so a step
    below PEAK_STEP_DONE leaves phi within about 1e-12 and the factor (flat at
    its peak) within rounding; the step is taken without evaluating again
    (:func:`_turned`). A scan of the arc and bisection where the iteration does
    not settle. Returns (factor, phi).
    """
    lo = alpha - HALF_PI
    hi = alpha + HALF_PI
    ca = math.cos(alpha)
    sa = math.sin(alpha)
    phi = alpha + _wrap(phi0 - alpha)
    if not lo < phi < hi:
        phi = alpha
    for _ in range(12):
        cp = math.cos(phi)
        sp = math.sin(phi)
        first, second, third = _log_peak_slopes(eps, ca, sa, cp, sp)
        if second >= 0.0:
            break
        denominator = 2.0 * second * second - first * third
        # Halley's step where it points as Newton's does and is within twice it, Newton's otherwise
        step = -2.0 * first * second / denominator if denominator > second * second else -first / second
        if abs(step) < PEAK_STEP_DONE:
            cp, sp = _turned(cp, sp, step)
            return (cp * ca + sp * sa) / (1.0 - eps * cp) ** 3, phi + step
        new = phi + step
        if new <= lo:
            new = 0.5 * (phi + lo)
        elif new >= hi:
            new = 0.5 * (phi + hi)
        phi = new
    best = 0.0
    n = 16
    for k in range(1, n):
        trial = lo + math.pi * k / n
        g = math.cos(trial - alpha) / (1.0 - eps * math.cos(trial)) ** 3
        if g > best:
            best = g
            phi = trial
    left = phi - math.pi / n
    right = phi + math.pi / n
    for _ in range(50):
        mid = 0.5 * (left + right)
        if _log_peak_slopes(eps, ca, sa, math.cos(mid), math.sin(mid))[0] > 0.0:
            left = mid
        else:
            right = mid
    mid = 0.5 * (left + right)
    g = math.cos(mid - alpha) / (1.0 - eps * math.cos(mid)) ** 3
    return (g, mid) if g > best else (best, phi)


@njit(cache=True)
def _load_at(w, tau, k, kn, t):
    """Load at time t in [tau[k], tau[kn]], linear between the samples (w is periodic: w[n] = w[0])."""
    n = w.shape[0]
    j = k
    while j + 1 < kn and tau[j + 1] <= t:
        j += 1
    u = (t - tau[j]) / (tau[j + 1] - tau[j])
    jn = j + 1 if j + 1 < n else 0
    return (1.0 - u) * w[j, 0] + u * w[jn, 0], (1.0 - u) * w[j, 1] + u * w[jn, 1]


@njit(cache=True)
def _midpoint(x0, x1, k, kn, w, tau, alpha, turn_mid, limit, bearing, out):
    """One step of the explicit midpoint rule from angle k to kn of the journal at (x0, x1).

    Its rate at k under the load there (Newton on the squeeze direction from ``alpha``), whose centre, squeeze
    velocity and direction go into ``out`` = (xi, v, alpha_out) at k, then the rate at the step's middle (the
    direction from there turned by ``turn_mid``, the last step's turn to its middle). ``bearing``: the finite
    correction (table, stretched, finite). Returns (x0, x1 at kn, the direction at k, its turn to the middle's,
    whether both squeeze velocities were found).
    """
    table, stretched, finite = bearing
    xi, v, alpha_out = out
    h = tau[kn] - tau[k]
    a0, a1, va, vb, alpha, ok1 = rate(x0, x1, w[k, 0], w[k, 1], alpha, limit, table, stretched, finite)
    xi[k, 0] = x0
    xi[k, 1] = x1
    v[k, 0] = va
    v[k, 1] = vb
    alpha_out[k] = alpha
    wm0, wm1 = _load_at(w, tau, k, kn, tau[k] + 0.5 * h)
    b0, b1, _, _, alpha_mid, ok2 = rate(x0 + 0.5 * h * a0, x1 + 0.5 * h * a1, wm0, wm1, _wrap(alpha + turn_mid),
                                        limit, table, stretched, finite)
    return x0 + h * b0, x1 + h * b1, alpha, _wrap(alpha_mid - alpha), ok1 and ok2


@njit(cache=True, inline="always")
def _lap_film(film, thinnest, collapsed, limit, tolerance, thinning):
    """At a lap's end: its thinnest film [c] from its largest eccentricity ``thinnest`` (the limit's where the
    journal was held there), and the laps in a row whose film was thinner by ``tolerance`` than the lap's before
    (``film``) (:data:`THINNING_LAPS` of them: a collapsing orbit)."""
    thinner = 1.0 - (limit if collapsed else thinnest)
    return thinner, thinning + 1 if thinner < (1.0 - tolerance) * film else 0


@njit(cache=True)
def _orbit(w, tau, integration, bearing, start, warm, xi, v, alpha_out):
    """One bearing's periodic orbit from the bearing centre (or from ``start`` (2,) when ``warm``), by the explicit
    midpoint rule (:func:`_midpoint`); ``integration``: :data:`Integration`, ``bearing``: its (table, stretched,
    finite) correction.

    Laps of the cycle at two angles per step until the journal comes back to
    within COARSE_SHARE of the thinnest film of where it was one lap before,
    then laps at every angle, from that angle on, until it comes back to within
    ``tolerance`` of the thinnest film (a contracting orbit stays there: the
    rest of the record is the last lap's). Out of ``max_cycles``, one lap at
    every angle is still run for the record; an orbit out of cycles whose film
    still thins cycle after cycle (:func:`_lap_film`) is collapsing. A warm
    start (a position near the periodic orbit's at the first angle, e.g. from a
    coarser or nearby orbit) skips the coarse laps. Writes xi, v (n, 2) and
    alpha_out (n,). Returns (status, cycles integrated).
    """
    limit, tolerance, max_cycles = integration
    n = w.shape[0]
    lap_of = np.full(n, -1)  # lap in which each angle was last recorded
    x0 = start[0] if warm else 0.0
    x1 = start[1] if warm else 0.0
    alpha = -HALF_PI  # steady rotation: squeeze against the turning direction
    alpha_last = alpha
    turn_mid = 0.0
    stride = 1 if warm else 2
    k = 0
    lap = 0
    in_lap = 0  # angles advanced in this lap
    phase_first_lap = 0  # first lap of the current stride
    advanced = 0  # angles advanced
    film = 1.0  # thinnest film of the last full lap [c]
    thinnest = 0.0
    collapsed_lap = False
    collapsed_last = False
    thinning = 0  # laps in a row whose thinnest film was thinner than the lap's before
    while advanced < max_cycles * n or stride > 1 or lap == phase_first_lap:
        out_of_time = advanced >= max_cycles * n
        if out_of_time and stride > 1 or lap_of[k] == lap - 1 and lap - 1 >= phase_first_lap:
            gap = math.hypot(x0 - xi[k, 0], x1 - xi[k, 1])
            if stride > 1:
                if out_of_time or gap <= COARSE_SHARE * film or lap - phase_first_lap >= MAX_COARSE:
                    stride = 1
                    lap += 1
                    phase_first_lap = lap
                    in_lap = 0
                    thinnest = 0.0
                    collapsed_lap = False
            elif gap <= tolerance * film:
                return (COLLAPSED if collapsed_lap or collapsed_last else PERIODIC), advanced / n
        kn = k + stride if k + stride < n else n
        guess = _wrap(alpha + _wrap(alpha - alpha_last))  # the squeeze direction turns smoothly: extrapolate
        alpha_last = alpha
        lap_of[k] = lap
        thinnest = max(thinnest, math.hypot(x0, x1))
        x0, x1, alpha, turn_mid, ok = _midpoint(x0, x1, k, kn, w, tau, guess, turn_mid, limit, bearing,
                                                (xi, v, alpha_out))
        if not (ok and math.isfinite(x0) and math.isfinite(x1)):
            return FAILED, advanced / n
        e = math.hypot(x0, x1)
        if e > limit:
            x0 *= limit / e
            x1 *= limit / e
            collapsed_lap = True
        advanced += kn - k
        in_lap += kn - k
        k = kn if kn < n else 0
        if in_lap >= n:
            lap += 1
            in_lap -= n
            film, thinning = _lap_film(film, thinnest, collapsed_lap, limit, tolerance, thinning)
            collapsed_last = collapsed_lap
            collapsed_lap = False
            thinnest = 0.0
    if collapsed_last or thinning >= THINNING_LAPS:
        return COLLAPSED, advanced / n
    return NOT_PERIODIC, advanced / n


@njit(cache=True, parallel=True)
def orbits(w, tau, start, warm, ld, integration, correction, out):
    """Orbits of many bearings (prange over bearings); ``start`` (B, 2) the first angle's centres where ``warm``.

    w (B, n, 2) dimensionless loads at times tau[:n] (tau (n+1,), tau[n] the cycle's end); ld (B,) L/D of each
    bearing (the finite tier's table, ``correction``: :data:`Correction`); ``integration``: :data:`Integration`.
    Writes into ``out`` = (xi, v (B, n, 2), peak (B, n), status, cycles (B,)): centres, squeeze velocities, the
    dimensionless peak pressure factor max cos(phi - alpha)/h^3 (times the finite tier's peak ratio), status and
    cycles integrated.
    """
    # numba's parallel loop takes arrays and numbers, not tuples holding arrays: the packed inputs are taken apart
    # here and put together again in the loop
    xi, v, peak, status, cycles = out
    tables, ld_nodes, stretched, finite = correction
    limit = integration.limit
    n_b = w.shape[0]
    n = w.shape[1]
    for b in prange(n_b):
        table = bearing_table(Correction(tables, ld_nodes, stretched, finite), ld[b])
        alpha = np.empty(n)
        s, c = _orbit(w[b], tau, integration, (table, stretched, finite), start[b], warm, xi[b], v[b], alpha)
        status[b] = s
        cycles[b] = c
        phi = 0.0
        for k in range(n):
            eps = min(math.hypot(xi[b, k, 0], xi[b, k, 1]), limit)
            g, phi = peak_factor(eps, alpha[k], phi)
            if finite:
                g *= math.exp(table_lookup(table, stretched, eps, alpha[k])[4])
            peak[b, k] = g * math.hypot(v[b, k, 0], v[b, k, 1])


@njit(cache=True)
def steady_peak_factors(eps, ld, correction, out):
    """Peak-pressure factor of steady films (squeeze direction -pi/2), many at once; writes ``out``.

    eps, ld (m,) eccentricity and L/D of each film; the short-bearing factor
    :func:`peak_factor` times the finite tier's peak ratio where the correction
    (:data:`Correction`) applies (the loops of the quasi-static tiers, compiled).
    """
    alpha = -0.5 * math.pi
    for m in range(eps.shape[0]):
        g = peak_factor(eps[m], alpha, 0.0)[0]
        if correction.finite:
            g *= math.exp(table_lookup(bearing_table(correction, ld[m]), correction.stretched, eps[m], alpha)[4])
        out[m] = g
