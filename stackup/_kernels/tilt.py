r"""Film force and moment on a tilted journal, and the journal's tilt equilibrium (numba).

The readable statement is in :mod:`stackup.film.tilt`; ``tests/film/test_tilt.py`` holds
the numpy twin these kernels must match. Everything is dimensionless as in
:mod:`stackup._kernels.mobility`: journal centre :math:`\boldsymbol\xi` and edge offset
:math:`\mathbf e = \boldsymbol\gamma L/(2c)` in clearances, squeeze velocity
:math:`\bar{\mathbf v}` in :math:`c\omega`, force per :math:`\mu\omega R L^3/c^2`,
moment per :math:`\mu\omega R L^4/c^2`.

Short bearing per line of the film (angle :math:`\theta`, normal :math:`\mathbf n`):
with :math:`\zeta = 2z/L`, :math:`\bar h = h_0(1 - s\zeta)`, :math:`h_0 = 1 - \boldsymbol\xi\cdot\mathbf n`,
:math:`s = \mathbf e\cdot\mathbf n/h_0`, source :math:`a + b\zeta` (:math:`a = \bar{\mathbf v}\cdot\mathbf n`,
:math:`b = \bar{\mathbf u}\cdot\mathbf n`, :math:`\bar{\mathbf u} = -\tfrac12\mathbf k\times\mathbf e`),
the pressure :math:`p = 3\mu\omega(L/c)^2 P` solves :math:`(\bar h^3 P')' = -(a + b\zeta)`,
:math:`P(\pm1) = 0`. Its integrals over the width follow from the axial moments
:math:`H_k = \int_{-1}^{1}\zeta^k\bar h^{-3}d\zeta = K_k(s)/h_0^3`:

.. math:: C = \frac{aH_1 + bH_2/2}{H_0}, \quad
          P_0 = \int P\,d\zeta = aH_2 + \tfrac b2 H_3 - CH_1, \quad
          P_1 = \int P\zeta\,d\zeta = -\tfrac12\left[C(H_2 - H_0) - a(H_3 - H_1) - \tfrac b2(H_4 - H_2)\right]

and :math:`\bar{\mathbf F} = \tfrac32\oint\mathbf n P_0\,d\theta`,
:math:`\bar{\mathbf M} = \tfrac34\oint\mathbf n P_1\,d\theta` over the lines that carry
pressure (:math:`P_0 > 0`: Gümbel's π-film generalised per line; without tilt
exactly the mobility tiers' film).
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit, prange

from .mobility import Correction, bearing_table, table_lookup

#: The film moment's quadrature: Gauss-Legendre nodes and weights on [-1, 1] for the pressure-carrying arc and for
#: the rest of the bearing, and the largest eccentricity Sommerfeld's angle clusters the nodes for.
Quadrature = namedtuple("Quadrature", ("nodes", "weights", "nodes_dry", "weights_dry", "cap"))
#: What every angle's tilt equilibrium shares: the quadrature, the eccentricity limit, the Newton tolerance.
Solver = namedtuple("Solver", ("quadrature", "limit", "tolerance"))
#: One crank angle's balance: journal centre (x0, x1), squeeze velocity (v0, v1), free edge offset (f0, f1),
#: compliance (k0, k1), the finite correction's ratio and turn (cosine, sine) at that centre and squeeze, and the
#: tilt's own squeeze as an implicit Euler step: the last angle's edge offset (p0, p1) and one over the step in
#: journal angle (``rate``, 1/rad; 0 holds the tilt: no tilt squeeze).
Angle = namedtuple("Angle", ("x0", "x1", "v0", "v1", "f0", "f1", "k0", "k1", "ratio", "ct", "st", "p0", "p1", "rate"))
#: The cycle's mid-plane orbits of B bearings: centre and squeeze xi, v (B, n, 2), free edge offset (B, n, 2),
#: compliance (B, 2) and L/D (B,) (the finite correction's, where it applies).
Orbits = namedtuple("Orbits", ("xi", "v", "free", "kappa", "ld"))

#: |s| below which the axial moments K_2..K_4 are summed as a series in s^2 (the closed forms lose 1/s^4 there).
SERIES_BELOW = 0.15
#: Series coefficients (in q = s^2) of K_2, K_3/s and K_4: nine terms leave 1e-12 at |s| = 0.15.
K2_SERIES = tuple([(2 * m + 1) * (2 * m + 2) / (2 * m + 3) for m in range(9)])
K3_SERIES = tuple([(2 * m + 2) * (2 * m + 3) / (2 * m + 5) for m in range(9)])
K4_SERIES = tuple([(2 * m + 1) * (2 * m + 2) / (2 * m + 5) for m in range(9)])
#: Largest angle the tilt may move a boundary of the pressure-carrying arc from the untilted one [rad].
CUT_SHIFT = 1.0
#: Secant steps that place a boundary of that arc.
CUT_STEPS = 4
#: Lines away from that arc count where P_0 > 0, fully once P_0 exceeds this share of |P_0| + |P_1| (a ramp
#: keeps the moment continuous where a line turns wet).
WET_RAMP = 0.1
#: Tilt equilibrium: film moments computed at most per crank angle by the continuation, halvings of a step.
MAX_EVALUATIONS = 10
MAX_HALVINGS = 5
#: Film moments at most from the aligned journal, where the continuation spent its budget further than COLD_FROM
#: thinnest films (1 - limit) from the wall.
MAX_COLD_EVALUATIONS = 16
COLD_FROM = 10.0
#: Edge contact (:func:`_on_wall`): first step in the boundary's direction [rad], largest secant step before a
#: bracket [rad], film moments at most, tolerance on the contact's direction [rad]; a guess outside the lens, or
#: from a contact that does not hold, is taken this share of the way from the aligned journal to the wall.
WALL_STEP = 0.02
WALL_REACH = 0.5
WALL_EVALUATIONS = 12
WALL_TOLERANCE = 0.03
INSIDE = 0.98
#: The tilt march (:func:`marches`): the share of the cycle marched from the aligned journal before the cycle
#: kept (the tilt's squeeze forgets its start within about a quarter of a cycle on the built-in engines), the
#: most cycles marched to close the cycle (the last angle's tilt within the Newton tolerance of the pass before),
#: and its step on a cycle of 720 angles (the same crank angle on other grids, a power of two; against steps of
#: one angle: tests/film/test_tilt.py).
WARMUP = 0.25
MARCH_CYCLES = 3
MARCH_STRIDE = 4
#: Film moments at most per step of the march (the Jacobian differenced at each step, not carried from the last:
#: the tilt's squeeze makes it large and nearly singular, which Broyden's update does not follow).
MARCH_EVALUATIONS = 40
#: Equilibrium states per angle.
EQUILIBRIUM, AT_LIMIT, NOT_SOLVED = 0, 1, 2
#: Outcomes of a Newton inside the lens (:func:`_newton`).
CONVERGED, WALL, STALLED, SPENT = 0, 1, 2, 3


@njit(cache=True, inline="always")
def _horner(coefficients, q):
    out = 0.0
    for i in range(len(coefficients) - 1, -1, -1):
        out = out * q + coefficients[i]
    return out


@njit(cache=True, inline="always")
def axial_moments(s):
    """K_k(s) = integral over [-1, 1] of zeta^k / (1 - s zeta)^3, k = 0..4, for |s| < 1.

    K_0 = 2/(1 - s^2)^2, K_1 = 2s/(1 - s^2)^2 and, with A_1 = ln((1 + s)/(1 - s))/s,
    K_2 = (K_0 - 4/(1 - s^2) + A_1)/s^2, K_3 = (K_0 - 6/(1 - s^2) + 3A_1 - 2)/s^3,
    K_4 = (K_0 - 8/(1 - s^2) + 6A_1 - 6)/s^4 (from z = (1 - u)/s, u = 1 - s z);
    below :data:`SERIES_BELOW` the last three from (1 - s z)^-3 = sum (n+1)(n+2)/2 (s z)^n.
    """
    q = s * s
    d = 1.0 - q
    k0 = 2.0 / (d * d)
    k1 = s * k0
    if abs(s) < SERIES_BELOW:
        return k0, k1, _horner(K2_SERIES, q), s * _horner(K3_SERIES, q), _horner(K4_SERIES, q)
    a2 = 2.0 / d
    a1 = math.log1p(2.0 * s / (1.0 - s)) / s
    return k0, k1, (k0 - 2.0 * a2 + a1) / q, (k0 - 3.0 * a2 + 3.0 * a1 - 2.0) / (q * s), \
        (k0 - 4.0 * a2 + 6.0 * a1 - 6.0) / (q * q)


@njit(cache=True, inline="always")
def line_integrals(h0, g, a, b):
    """P_0 and P_1 of one line: film h0 - g zeta, source a + b zeta (module docstring)."""
    k0, k1, k2, k3, k4 = axial_moments(g / h0)
    c = (a * k1 + 0.5 * b * k2) / k0
    scale = 1.0 / (h0 * h0 * h0)
    p0 = (a * k2 + 0.5 * b * k3 - c * k1) * scale
    p1 = -0.5 * (c * (k2 - k0) - a * (k3 - k1) - 0.5 * b * (k4 - k2)) * scale
    return p0, p1


@njit(cache=True, inline="always")
def _line_p0(theta, x0, x1, v0, v1, e0, e1, u0, u1):
    n0 = math.cos(theta)
    n1 = math.sin(theta)
    return line_integrals(1.0 - x0 * n0 - x1 * n1, e0 * n0 + e1 * n1, v0 * n0 + v1 * n1, u0 * n0 + u1 * n1)[0]


@njit(cache=True, inline="always")
def _cut(theta, x0, x1, v0, v1, e0, e1, u0, u1, step):
    """The boundary of the pressure-carrying arc near ``theta`` (the untilted one): secant steps on P_0.

    At most :data:`CUT_STEPS` steps, each kept within :data:`CUT_SHIFT` of ``theta``.
    """
    p = _line_p0(theta, x0, x1, v0, v1, e0, e1, u0, u1)
    if p == 0.0:
        return theta
    t_prev, p_prev = theta, p
    t = theta + step
    for _ in range(CUT_STEPS):
        p = _line_p0(t, x0, x1, v0, v1, e0, e1, u0, u1)
        if p == p_prev or not math.isfinite(p):
            break
        t_new = t - p * (t - t_prev) / (p - p_prev)
        t_new = max(theta - CUT_SHIFT, min(theta + CUT_SHIFT, t_new))
        t_prev, p_prev = t, p
        if abs(t_new - t) < 1e-7:
            return t_new
        t = t_new
    return t


@njit(cache=True, inline="always")
def _wrap(a):
    return a - 2.0 * math.pi * math.floor((a + math.pi) / (2.0 * math.pi))


@njit(cache=True, inline="always")
def _stretched(phi, k, root):
    """Sommerfeld's angle psi of the film angle phi (from the thinnest film), eccentricity k."""
    c = math.cos(phi)
    d = 1.0 - k * c
    return math.atan2(root * math.sin(phi) / d, (c - k) / d)


@njit(cache=True, inline="always")
def _line(cp, sp, weight, journal, frame, wet):
    """Weighted contribution (F0, F1, M0, M1) of the line at Sommerfeld's angle psi (cp, sp its cosine and sine).

    ``journal`` (x0, x1, v0, v1, e0, e1, u0, u1) and ``frame`` (c0, c1, k, root) as :func:`_arc` takes them.
    """
    x0, x1, v0, v1, e0, e1, u0, u1 = journal
    c0, c1, k, root = frame
    d = 1.0 + k * cp
    cphi = (k + cp) / d
    sphi = root * sp / d
    n0 = c0 * cphi - c1 * sphi
    n1 = c1 * cphi + c0 * sphi
    a = v0 * n0 + v1 * n1
    b = u0 * n0 + u1 * n1  # tilt held: u = -(1/2) k x e
    if not wet and a + abs(b) <= 0.0:
        return 0.0, 0.0, 0.0, 0.0  # the source is negative over the whole width: no pressure on this line
    p0, p1 = line_integrals(1.0 - x0 * n0 - x1 * n1, e0 * n0 + e1 * n1, a, b)
    if p0 <= 0.0:
        if not wet:
            return 0.0, 0.0, 0.0, 0.0
        p0 = 0.0
    elif not wet:
        p1 *= min(1.0, p0 / (WET_RAMP * (p0 + abs(p1))))
    w = weight / d
    return w * p0 * n0, w * p0 * n1, w * p1 * n0, w * p1 * n1


@njit(cache=True)
def _arc(psi_lo, span, journal, nodes, weights, frame, wet):
    """Gauss-Legendre over Sommerfeld's angles [psi_lo, psi_lo + span] about the thinner edge.

    ``journal``: centre, squeeze velocity, edge offset and tilt squeeze (x0, x1, v0, v1, e0, e1, u0, u1);
    ``frame``: the thinner edge's direction (c0, c1), eccentricity k and sqrt(1 - k^2). ``wet``: the arc carries pressure (its lines count, P_0 clipped at 0);
    else only lines with P_0 > 0 count, through the ramp :data:`WET_RAMP`.
    The nodes are symmetric about the arc's middle: each pair's cosines and
    sines from one cosine and sine of its offset and the middle's.
    Returns (F0, F1, M0, M1) before the factors 3/2 and 3/4.
    """
    root = frame[3]
    half = 0.5 * span
    middle = psi_lo + half
    cm = math.cos(middle)
    sm = math.sin(middle)
    f0 = f1 = m0 = m1 = 0.0
    n = nodes.shape[0]
    for j in range(n // 2):
        offset = half * nodes[n - 1 - j]
        co = math.cos(offset)
        so = math.sin(offset)
        weight = weights[j] * half * root
        for cp, sp in ((cm * co - sm * so, sm * co + cm * so), (cm * co + sm * so, sm * co - cm * so)):
            a0, a1, b0, b1 = _line(cp, sp, weight, journal, frame, wet)
            f0 += a0
            f1 += a1
            m0 += b0
            m1 += b1
    if n % 2:
        a0, a1, b0, b1 = _line(cm, sm, weights[n // 2] * half * root, journal, frame, wet)
        f0 += a0
        f1 += a1
        m0 += b0
        m1 += b1
    return f0, f1, m0, m1


@njit(cache=True)
def film_moment(x0, x1, v0, v1, e0, e1, quadrature):
    """Film force and moment (F0, F1, M0, M1) under a tilted journal whose tilt is held (:func:`squeeze_moment`
    with the tilt squeeze :math:`\\bar{\\mathbf u} = -\\tfrac12\\mathbf k\\times\\mathbf e`)."""
    return squeeze_moment(x0, x1, v0, v1, e0, e1, 0.5 * e1, -0.5 * e0, quadrature)


@njit(cache=True)
def squeeze_moment(x0, x1, v0, v1, e0, e1, u0, u1, quadrature):
    """Film force and moment (F0, F1, M0, M1) on the bearing under a tilted journal, short bearing.

    ``(u0, u1)``: the tilt's squeeze velocity, dimensionless,
    :math:`\\bar{\\mathbf u} = \\dot{\\mathbf e}/\\omega - \\tfrac12\\mathbf k\\times\\mathbf e` (a line's source
    is :math:`a + b\\zeta` with :math:`b = \\bar{\\mathbf u}\\cdot\\mathbf n`).

    The lines carry pressure (P_0 > 0) on the half of the bearing the squeeze
    velocity points into when the journal is aligned; the tilt moves the two
    boundaries, each found by a Newton step on P_0 from the untilted one. That
    arc is integrated by Gauss-Legendre (``quadrature``: :data:`Quadrature`) in
    Sommerfeld's angle about the thinnest film over the width (eccentricity k
    of that edge, capped at the quadrature's ``cap``), which makes the thin film's
    peak smooth; every line of it counts (P_0 clipped at 0), so the moment
    is continuous as the boundaries move. The rest of the bearing by the
    ``dry`` nodes: pressure where the tilt makes any there (lines with P_0 > 0,
    through the ramp :data:`WET_RAMP`).
    """
    rp = math.hypot(x0 + e0, x1 + e1)
    rm = math.hypot(x0 - e0, x1 - e1)
    # the thinner edge; a tie decided by the edges' positions alone, so the tilt reversed (the edges swapped) gives
    # the same nodes
    if rp > rm or rp == rm and (x0 + e0, x1 + e1) >= (x0 - e0, x1 - e1):
        r, c0, c1 = rp, x0 + e0, x1 + e1
    else:
        r, c0, c1 = rm, x0 - e0, x1 - e1
    if r > 0.0:
        c0 /= r
        c1 /= r
    else:
        c0, c1 = 1.0, 0.0
    k = min(r, quadrature.cap)
    root = math.sqrt((1.0 - k) * (1.0 + k))
    alpha = math.atan2(v1, v0)
    # a step in theta of 1e-3 of the local spacing of Sommerfeld's angle
    step = 1e-3 * root / (1.0 + k)
    lo = _cut(alpha - 0.5 * math.pi, x0, x1, v0, v1, e0, e1, u0, u1, step)
    hi = _cut(alpha + 0.5 * math.pi, x0, x1, v0, v1, e0, e1, u0, u1, step)
    if hi <= lo:
        hi = lo + 1e-12
    # the arc's ends in Sommerfeld's angle about the thinner edge: the pressure-carrying arc, then the rest
    centre = math.atan2(c1, c0)
    psi_lo = _stretched(_wrap(lo - centre), k, root)
    psi_hi = _stretched(_wrap(hi - centre), k, root)
    span = psi_hi - psi_lo
    if span <= 0.0:
        span += 2.0 * math.pi
    journal = (x0, x1, v0, v1, e0, e1, u0, u1)
    frame = (c0, c1, k, root)
    f0, f1, m0, m1 = _arc(psi_lo, span, journal, quadrature.nodes, quadrature.weights, frame, True)
    g0, g1, n0, n1 = _arc(psi_hi, 2.0 * math.pi - span, journal, quadrature.nodes_dry, quadrature.weights_dry, frame,
                          False)
    return 1.5 * (f0 + g0), 1.5 * (f1 + g1), 0.75 * (m0 + n0), 0.75 * (m1 + n1)


@njit(cache=True, inline="always")
def wall_room(x0, x1, e0, e1, d0, d1, limit):
    """Largest t >= 0 with both edges inside the limit: |x + (e + t d)| <= limit and |x - (e + t d)| <= limit."""
    best = math.inf
    for sign in (1.0, -1.0):
        px = x0 + sign * e0
        py = x1 + sign * e1
        qx = sign * d0
        qy = sign * d1
        a = qx * qx + qy * qy
        if a == 0.0:
            continue
        b = px * qx + py * qy
        c = px * px + py * py - limit * limit  # <= 0 inside
        disc = b * b - a * c
        t = (-b + math.sqrt(max(disc, 0.0))) / a
        best = min(best, max(t, 0.0))
    return best


@njit(cache=True, inline="always")
def _edge(x0, x1, e0, e1):
    """Thinnest film over the width [c]: 1 - the larger eccentricity of the two edges."""
    return 1.0 - max(math.hypot(x0 + e0, x1 + e1), math.hypot(x0 - e0, x1 - e1))


@njit(cache=True, inline="always")
def _broyden(jac, s0, s1, y0, y1):
    """Broyden's update of jac (2, 2) in place for the step s and the residual's change y."""
    ss = s0 * s0 + s1 * s1
    if ss > 0.0:
        y0 -= jac[0, 0] * s0 + jac[0, 1] * s1
        y1 -= jac[1, 0] * s0 + jac[1, 1] * s1
        jac[0, 0] += y0 * s0 / ss
        jac[0, 1] += y0 * s1 / ss
        jac[1, 0] += y1 * s0 / ss
        jac[1, 1] += y1 * s1 / ss


@njit(cache=True, inline="always")
def _wall_normal(x0, x1, e0, e1):
    """Outward normal, in e, of the wall of the thinner edge (|x + e| or |x - e| = limit): (n0, n1)."""
    p0, p1 = x0 + e0, x1 + e1
    q0, q1 = x0 - e0, x1 - e1
    rp = math.hypot(p0, p1)
    rq = math.hypot(q0, q1)
    if rp >= rq:
        return p0 / rp, p1 / rp
    return -q0 / rq, -q1 / rq


@njit(cache=True)
def _residual(a, e0, e1, quadrature):
    """e + kappa (rho R(turn) M(e, u)) - e_free at the angle ``a`` (:data:`Angle`), with the tilt's squeeze
    u = rate (e - p) - 1/2 k x e (rate 0: the tilt held, :func:`film_moment`)."""
    u0 = a.rate * (e0 - a.p0) + 0.5 * e1
    u1 = a.rate * (e1 - a.p1) - 0.5 * e0
    _, _, m0, m1 = squeeze_moment(a.x0, a.x1, a.v0, a.v1, e0, e1, u0, u1, quadrature)
    return e0 + a.k0 * a.ratio * (a.ct * m0 - a.st * m1) - a.f0, e1 + a.k1 * a.ratio * (a.st * m0 + a.ct * m1) - a.f1


@njit(cache=True)
def _difference_jacobian(a, e0, e1, r0, r1, solver, jac):
    """Forward differences into jac (2, 2) at the edge offset e, residual r there, each step pointed away from the
    nearer wall. Returns evaluations."""
    delta = 1e-6 + 1e-4 * _edge(a.x0, a.x1, e0, e1)
    for j in range(2):
        d0 = delta if j == 0 else 0.0
        d1 = delta if j == 1 else 0.0
        if wall_room(a.x0, a.x1, e0, e1, d0, d1, solver.limit) < 1.0:
            d0, d1 = -d0, -d1
        q0, q1 = _residual(a, e0 + d0, e1 + d1, solver.quadrature)
        h = d0 + d1
        jac[0, j] = (q0 - r0) / h
        jac[1, j] = (q1 - r1) / h
    return 2


@njit(cache=True, inline="always")
def _lens_point(x0, x1, theta, limit):
    """The edge offset on the lens's boundary (an edge at the limit) in the direction theta."""
    d0 = math.cos(theta)
    d1 = math.sin(theta)
    rho = wall_room(x0, x1, 0.0, 0.0, d0, d1, limit)
    return rho * d0, rho * d1


@njit(cache=True)
def _wall_residual(a, theta, solver):
    """At the lens point in direction theta: (e0, e1, across, outward).

    ``across``: the residual's part across the edge contact's direction kappa*n (n the wall's outward normal: a
    contact at the edge adds kappa*lambda*n, lambda >= 0, to the residual), zero where a contact can close the
    balance; ``outward``: r.n, <= 0 there where the contact presses (the root lies beyond the wall).
    """
    e0, e1 = _lens_point(a.x0, a.x1, theta, solver.limit)
    r0, r1 = _residual(a, e0, e1, solver.quadrature)
    n0, n1 = _wall_normal(a.x0, a.x1, e0, e1)
    return e0, e1, a.k0 * n0 * r1 - a.k1 * n1 * r0, n0 * r0 + n1 * r1


@njit(cache=True)
def _on_wall(a, theta, solver, budget, slope):
    """Edge contact at the angle ``a``: the point of the lens's boundary where the residual is -lambda kappa n,
    lambda >= 0.

    A secant in the boundary's direction theta from ``theta`` (its first step
    Newton's with ``slope[0]``, d across / d theta at the last contact, in and
    out, where it is known, else :data:`WALL_STEP`) until ``across`` changes
    sign, then Illinois inside that bracket until it is at most :data:`WALL_TOLERANCE`
    rad wide. Returns (e0, e1, found, outward, evaluations) at the evaluated end
    of the bracket with the smaller ``across`` (``outward`` there: <= 0, the
    contact holds); ``found`` False where no bracket closed within the budget.
    """
    tolerance = WALL_TOLERANCE
    ta = theta
    a0, a1, ga, oa = _wall_residual(a, ta, solver)
    if ga == 0.0:
        return a0, a1, True, oa, 1
    step = WALL_STEP
    if slope[0] != 0.0:
        step = max(-WALL_REACH, min(WALL_REACH, -ga / slope[0]))
        if abs(step) < 0.5 * tolerance:  # as below: past the root by half the tolerance
            step = math.copysign(0.5 * tolerance, step)
    tb = ta + step
    b0, b1, gb, ob = _wall_residual(a, tb, solver)
    used = 2
    weight = ga  # Illinois halves the weight of an end kept twice; ga stays its value
    bracket = ga * gb < 0.0
    while gb != 0.0:
        if bracket and abs(tb - ta) <= tolerance:
            slope[0] = (gb - ga) / (tb - ta)
            if abs(ga) < abs(gb):
                return a0, a1, True, oa, used
            return b0, b1, True, ob, used
        if used >= budget or gb == weight:
            slope[0] = 0.0
            return b0, b1, False, ob, used
        tn = tb - gb * (tb - ta) / (gb - weight)
        if not bracket:
            tn = max(tb - WALL_REACH, min(tb + WALL_REACH, tn))
        if abs(tn - tb) < 0.5 * tolerance:
            # a root this near: step half the tolerance past it, so that the next point brackets it within that
            tn = tb + math.copysign(0.5 * tolerance, tn - tb)
        n0, n1, gn, on = _wall_residual(a, tn, solver)
        used += 1
        if not bracket or gn * gb < 0.0:
            ta, a0, a1, ga, oa, weight = tb, b0, b1, gb, ob, gb
        else:
            weight *= 0.5
        tb, b0, b1, gb, ob = tn, n0, n1, gn, on
        bracket = bracket or ga * gb < 0.0
    slope[0] = (gb - ga) / (tb - ta)
    return b0, b1, True, ob, used


@njit(cache=True, inline="always")
def _direction(jac, det, r0, r1):
    """Newton's step -jac^-1 r for the Jacobian jac (2, 2) with determinant det."""
    return -(jac[1, 1] * r0 - jac[0, 1] * r1) / det, -(-jac[1, 0] * r0 + jac[0, 0] * r1) / det


@njit(cache=True, inline="always")
def _step_ends(x0, x1, e0, e1, d0, d1, limit, tolerance):
    """Where Newton's step d from e ends: (room, converged, pressed). ``room``: the share of d the lens leaves
    (:func:`wall_room`); converged: d is below ``tolerance`` times the edge film and stays inside; pressed: d
    points beyond the wall and the room left is below ``tolerance`` times the limit's film."""
    size = math.hypot(d0, d1)
    room = wall_room(x0, x1, e0, e1, d0, d1, limit)
    return (room, size <= tolerance * _edge(x0, x1, e0, e1) and room >= 1.0,
            room < 1.0 and room * size <= tolerance * (1.0 - limit))


@njit(cache=True)
def _backtrack(a, e0, e1, d0, d1, t, merit, quadrature):
    """The step t d from e, halved at most :data:`MAX_HALVINGS` times until the residual's square falls by
    Armijo's share of t below ``merit``: (n0, n1, q0, q1, t, lowered, evaluations) at the last point tried."""
    lowered = False
    used = 0
    for _ in range(MAX_HALVINGS):
        n0 = e0 + t * d0
        n1 = e1 + t * d1
        q0, q1 = _residual(a, n0, n1, quadrature)
        used += 1
        if q0 * q0 + q1 * q1 <= (1.0 - 1e-4 * t) * merit:
            lowered = True
            break
        t *= 0.5
    return n0, n1, q0, q1, t, lowered, used


@njit(cache=True)
def _newton(a, e0, e1, jac, fresh, solver, budget):
    """Damped Newton at the angle ``a`` inside the lens from (e0, e1), with Broyden's update of ``jac`` (differences
    where not ``fresh`` or a step fails). Returns (e0, e1, outcome, evaluations), outcome one of CONVERGED, WALL (on
    the wall, the step points beyond it), STALLED (no step lowers the residual: a minimum that is not a root) or
    SPENT (the budget)."""
    x0, x1, limit, tolerance = a.x0, a.x1, solver.limit, solver.tolerance
    r0, r1 = _residual(a, e0, e1, solver.quadrature)
    evaluations = 1
    differenced = False
    if not fresh:
        evaluations += _difference_jacobian(a, e0, e1, r0, r1, solver, jac)
        differenced = True
    while evaluations < budget:
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        if det == 0.0 or not math.isfinite(det):
            if differenced:
                return e0, e1, STALLED, evaluations
            evaluations += _difference_jacobian(a, e0, e1, r0, r1, solver, jac)
            differenced = True
            continue
        d0, d1 = _direction(jac, det, r0, r1)
        room, converged, pressed = _step_ends(x0, x1, e0, e1, d0, d1, limit, tolerance)
        if converged:
            return e0 + d0, e1 + d1, CONVERGED, evaluations
        if pressed:
            return e0, e1, WALL, evaluations
        # an edge may go as far as the wall, not past it
        n0, n1, q0, q1, _, accepted, used = _backtrack(a, e0, e1, d0, d1, min(1.0, room), r0 * r0 + r1 * r1,
                                                      solver.quadrature)
        evaluations += used
        if accepted:
            _broyden(jac, n0 - e0, n1 - e1, q0 - r0, q1 - r1)
            e0, e1, r0, r1 = n0, n1, q0, q1
            differenced = False
        elif not differenced:
            evaluations += _difference_jacobian(a, e0, e1, r0, r1, solver, jac)
            differenced = True
        else:
            return e0, e1, STALLED, evaluations
    return e0, e1, SPENT, evaluations


@njit(cache=True)
def equilibrium(a, g0, g1, on_wall, jac, slope, fresh, solver, budget=MAX_EVALUATIONS):
    """Tilt e with e + kappa M(x, v, e) = e_free at the angle ``a`` (:data:`Angle`), both edges inside the limit, or
    edge contact.

    The tilt lies in the lens of offsets with both edges inside the limit. A
    root inside is EQUILIBRIUM; an edge that touches is AT_LIMIT, at the
    boundary point where the residual is balanced by a contact at the edge (the
    residual -lambda kappa n, n the wall's outward normal, lambda >= 0; a
    variational inequality on the lens, :func:`_on_wall`). The film's moment is
    not monotone in the tilt, so a root inside and a contact can both balance
    the journal: a guess on the wall keeps the contact while one holds there,
    a guess inside takes the root Newton reaches.

    Damped Newton (:func:`_newton`) from the guess (g0, g1), with the Jacobian
    ``jac`` in and out (usable where ``fresh``); it stops when the step is
    below the solver's ``tolerance`` times the edge film. A Newton that reaches the wall,
    stalls (the film's moment is not monotone in the tilt: its residual can
    have a minimum inside the lens that is not a root) or a guess on the wall
    (``on_wall``: the last angle's state) passes to the boundary. A contact
    point there whose residual points out of the lens (a root inside after
    all) hands back to Newton once, from just inside it; a root so near the
    wall that this Newton meets it again counts as AT_LIMIT (the edge film is
    the limit's within a Newton step). Returns (e0, e1, state, evaluations);
    NOT_SOLVED where neither is found.
    """
    x0, x1, limit = a.x0, a.x1, solver.limit
    if math.hypot(x0, x1) >= limit * (1.0 - 1e-12):
        return 0.0, 0.0, (EQUILIBRIUM if a.f0 == 0.0 and a.f1 == 0.0 else AT_LIMIT), 0

    def contact(theta):
        """The edge contact of this angle along the wall from ``theta`` (:func:`_on_wall`)."""
        return _on_wall(a, theta, solver, WALL_EVALUATIONS, slope)

    evaluations = 0
    from_wall = False
    if on_wall:
        e0, e1, found, outward, used = contact(math.atan2(g1, g0))
        evaluations += used
        if found and outward <= 0.0:
            return e0, e1, AT_LIMIT, evaluations
        g0, g1 = INSIDE * e0, INSIDE * e1
        fresh = False  # the Jacobian is the last angle's, at the wall
        from_wall = found
    room = wall_room(x0, x1, 0.0, 0.0, g0, g1, limit)
    if room < 1.0:  # the guess inside the lens, towards the aligned journal
        g0 *= INSIDE * room
        g1 *= INSIDE * room
    e0, e1, outcome, used = _newton(a, g0, g1, jac, fresh, solver, budget)
    evaluations += used
    for _ in range(2):
        if outcome == CONVERGED:
            return e0, e1, EQUILIBRIUM, evaluations
        if outcome == SPENT and _edge(x0, x1, e0, e1) > COLD_FROM * (1.0 - limit):
            return e0, e1, NOT_SOLVED, evaluations  # far from the wall and still moving: the caller may start afresh
        if from_wall and outcome == WALL:
            # the contact's residual points in, Newton's step out: the root lies at the wall
            room = wall_room(x0, x1, 0.0, 0.0, e0, e1, limit)
            return room * e0, room * e1, AT_LIMIT, evaluations
        b0, b1, found, outward, used = contact(math.atan2(e1, e0))
        evaluations += used
        if found and outward <= 0.0:
            return b0, b1, AT_LIMIT, evaluations
        if not found or from_wall:
            break
        from_wall = True
        e0, e1, outcome, used = _newton(a, INSIDE * b0, INSIDE * b1, jac, False, solver, WALL_EVALUATIONS)
        evaluations += used
    return e0, e1, NOT_SOLVED, evaluations


@njit(cache=True)
def _angle(b, k, orbits, bearing, limit, p0, p1, rate):
    """The :data:`Angle` of bearing b at angle k (``orbits``: :data:`Orbits`; ``bearing``: its finite correction,
    as :func:`_solve_at`), the tilt's squeeze a step from the edge offset p at ``rate`` (0: the tilt held)."""
    xi, v, free, kappa = orbits.xi, orbits.v, orbits.free, orbits.kappa
    table, stretched, finite = bearing
    x0 = xi[b, k, 0]
    x1 = xi[b, k, 1]
    ratio, ct, st = 1.0, 1.0, 0.0
    if finite:
        alpha = math.atan2(v[b, k, 1], v[b, k, 0]) - math.atan2(x1, x0)
        alpha = math.atan2(math.sin(alpha), math.cos(alpha))
        log_ratio, turn, _, _, _ = table_lookup(table, stretched, min(math.hypot(x0, x1), limit), alpha)
        ratio = math.exp(log_ratio)
        ct = math.cos(turn)
        st = math.sin(turn)
    return Angle(x0, x1, v[b, k, 0], v[b, k, 1], free[b, k, 0], free[b, k, 1], kappa[b, 0], kappa[b, 1], ratio, ct, st,
                 p0, p1, rate)


@njit(cache=True)
def _solve_at(b, k, g0, g1, on_wall, fresh, orbits, bearing, solver, memory, out):
    """Tilt equilibrium of bearing b at angle k from the guess (g0, g1); writes the tilt and state into ``out``.

    ``orbits``: :data:`Orbits`; ``bearing``: the bearing's finite correction (table, eccentricity nodes, whether
    it applies); ``memory``: the Jacobian (2, 2) and the wall's slope (1,), in and out (usable where ``fresh``).
    Returns (evaluations, whether the Jacobian is usable at the next angle).
    """
    jac, slope = memory
    tilt, state = out
    limit = solver.limit
    if orbits.free[b, k, 0] == 0.0 and orbits.free[b, k, 1] == 0.0:
        tilt[b, k, 0] = 0.0
        tilt[b, k, 1] = 0.0
        state[b, k] = EQUILIBRIUM
        return 0, fresh
    a = _angle(b, k, orbits, bearing, limit, 0.0, 0.0, 0.0)
    x0, x1 = a.x0, a.x1
    e0, e1, s, used = equilibrium(a, g0, g1, on_wall, jac, slope, fresh, solver)
    if s == NOT_SOLVED and _edge(x0, x1, e0, e1) > COLD_FROM * (1.0 - limit):
        # far from the wall: start again from the aligned journal (no film moment; Newton's first step is the
        # film's linear tilt stiffness against the crankshaft's), with a fresh Jacobian and more film moments
        e0, e1, s, more = equilibrium(a, 0.0, 0.0, False, jac, slope, False, solver, MAX_COLD_EVALUATIONS)
        used += more
    tilt[b, k, 0] = e0
    tilt[b, k, 1] = e1
    state[b, k] = s
    return used, s != NOT_SOLVED


@njit(cache=True, inline="always")
def _turn_back_between(free, tilt, b, k, kp, kn, share):
    """Edge offset of bearing b at angle k that takes the film's turn-back (free minus tilt) of the angles kp and
    kn interpolated, ``share`` of the way from kp to kn (the free tilt carries the beam's fast changes)."""
    return (free[b, k, 0] - ((1.0 - share) * (free[b, kp, 0] - tilt[b, kp, 0])
                             + share * (free[b, kn, 0] - tilt[b, kn, 0])),
            free[b, k, 1] - ((1.0 - share) * (free[b, kp, 1] - tilt[b, kp, 1])
                             + share * (free[b, kn, 1] - tilt[b, kn, 1])))


@njit(cache=True, parallel=True)
def equilibria(orbits, correction, solver, interpolate, stride, tilt, state, evaluations):
    """Tilt equilibrium at every angle of many bearings (prange over bearings).

    ``orbits`` (:data:`Orbits`): xi, v (B, n, 2) the journal centre and squeeze
    velocity of each angle; free (B, n, 2) the free edge offset; kappa (B, 2)
    the dimensionless compliance per component; ld (B,) each bearing's L/D. The
    short-bearing moment is scaled and turned by the finite tier's force
    correction (``correction``, :data:`stackup._kernels.mobility.Correction`) at
    (|xi|, squeeze direction) where it applies; ``solver``: :data:`Solver`.

    Every ``stride``-th angle (a power of two) is solved in turn, from the last
    two solutions' film turn-back (free minus tilt) extrapolated (the free tilt
    carries the beam's fast changes), or along the wall from the last two
    contacts' directions, with the last Jacobian (:func:`_solve_strided`).
    Then, halving the spacing down to one angle, each angle midway between two
    known ones of the same state whose turn-backs differ by less than
    ``interpolate`` times their thinner edge film takes their turn-back
    interpolated (onto the wall where they are at the limit); the others are
    solved from their neighbour's Jacobian (the one in equilibrium where the
    states differ) (:func:`_solve_between`). Writes tilt (B, n, 2), state (B, n)
    and evaluations (B, n): film moments computed at each angle.
    """
    # numba's parallel loop takes arrays and numbers, not tuples holding arrays: the packed inputs are taken apart
    # here and put together again in the loop
    xi, v, free, kappa, ld = orbits
    tables, ld_nodes, stretched, finite = correction
    (nodes, weights, nodes_dry, weights_dry, cap), limit, tolerance = solver
    n = xi.shape[1]
    for b in prange(xi.shape[0]):
        cycle = Orbits(xi, v, free, kappa, ld)
        rule = Solver(Quadrature(nodes, weights, nodes_dry, weights_dry, cap), limit, tolerance)
        bearing = (bearing_table(Correction(tables, ld_nodes, stretched, finite), ld[b]), stretched, finite)
        memory = (np.eye(2), np.zeros(1))
        # each angle's Jacobian and wall slope, and whether they are usable, from which the angles between are solved
        known = (np.empty((n, 2, 2)), np.zeros(n), np.zeros(n, np.bool_))
        out = (tilt, state)
        _solve_strided(b, stride, cycle, bearing, rule, memory, known, out, evaluations)
        half = stride // 2
        while half >= 1:
            for k in range(half, n, 2 * half):
                _solve_between(b, k, half, interpolate, cycle, bearing, rule, memory, known, out, evaluations)
            half //= 2


@njit(cache=True)
def _solve_strided(b, stride, cycle, bearing, solver, memory, known, out, evaluations):
    """Tilt equilibrium of bearing b at every ``stride``-th angle in turn (:func:`_solve_at`), each from the guess of
    :func:`_strided_guess`, with the Jacobian and wall slope of the angle before (``memory``); each angle's kept in
    ``known`` = (Jacobians, wall slopes, usable)."""
    jac, slope = memory
    jacs, slopes, usable = known
    tilt, state = out
    fresh = False
    last = -1
    before = -1
    for k in range(0, cycle.xi.shape[1], stride):
        g0, g1 = _strided_guess(b, k, last, before, cycle.free, tilt, state)
        on_wall = last >= 0 and state[b, last] == AT_LIMIT
        evaluations[b, k], fresh = _solve_at(b, k, g0, g1, on_wall, fresh, cycle, bearing, solver, memory, out)
        jacs[k] = jac
        slopes[k] = slope[0]
        usable[k] = fresh
        before = last
        last = k


@njit(cache=True, inline="always")
def _strided_guess(b, k, last, before, free, tilt, state):
    """The guess at angle k from the solved angles ``last`` and ``before`` it (-1: none): the film's turn-back
    (free minus tilt) extrapolated from both in equilibrium (the free tilt carries the beam's fast changes), the
    contact's direction from both at the limit, the turn-back kept from the last alone, else the free tilt."""
    if before >= 0 and state[b, last] == EQUILIBRIUM and state[b, before] == EQUILIBRIUM:
        g0 = free[b, k, 0] - 2.0 * (free[b, last, 0] - tilt[b, last, 0]) + (free[b, before, 0] - tilt[b, before, 0])
        g1 = free[b, k, 1] - 2.0 * (free[b, last, 1] - tilt[b, last, 1]) + (free[b, before, 1] - tilt[b, before, 1])
    elif before >= 0 and state[b, last] == AT_LIMIT and state[b, before] == AT_LIMIT:
        # along the wall: the contact's direction extrapolated
        turn = math.atan2(tilt[b, last, 1], tilt[b, last, 0])
        turn += _wrap(turn - math.atan2(tilt[b, before, 1], tilt[b, before, 0]))
        g0 = math.cos(turn)
        g1 = math.sin(turn)
    elif last >= 0:
        g0 = free[b, k, 0] - (free[b, last, 0] - tilt[b, last, 0])
        g1 = free[b, k, 1] - (free[b, last, 1] - tilt[b, last, 1])
    else:
        g0, g1 = free[b, k, 0], free[b, k, 1]
    return g0, g1


@njit(cache=True)
def _solve_between(b, k, half, interpolate, cycle, bearing, solver, memory, known, out, evaluations):
    """Angle k of bearing b, ``half`` angles from the known ones either side: their turn-back interpolated where
    that holds (:func:`_interpolated`), else solved (:func:`_solve_at`) from the neighbour's Jacobian, the one in
    equilibrium where the states differ; its Jacobian, wall slope and usability kept in ``known``."""
    n = cycle.xi.shape[1]
    free = cycle.free
    jac, slope = memory
    jacs, slopes, usable = known
    tilt, state = out
    kp = k - half
    kn = k + half if k + half < n else 0  # the cycle closes on its first angle
    # its share of the way from kp to kn (a half but where n is not a multiple of the stride)
    share = half / (min(k + half, n) - kp)
    evaluations[b, k] = 0
    if state[b, kp] == state[b, kn] and state[b, kp] != NOT_SOLVED:
        taken, e0, e1 = _interpolated(b, k, kp, kn, share, interpolate, cycle, solver.limit, out)
        if taken:
            jacs[k] = jacs[kp]
            slopes[k] = slopes[kp]
            usable[k] = usable[kp]
            return
        near = kp
    else:
        # from the neighbour in equilibrium where there is one: Newton reaches the wall from inside more
        # cheaply than the contact's search finds its way in
        near = kn if state[b, kn] == EQUILIBRIUM else kp
        e0 = free[b, k, 0] - free[b, near, 0] + tilt[b, near, 0]
        e1 = free[b, k, 1] - free[b, near, 1] + tilt[b, near, 1]
    jac[:] = jacs[near]
    slope[0] = slopes[kp] if state[b, kp] == AT_LIMIT else slopes[kn]
    evaluations[b, k], usable[k] = _solve_at(b, k, e0, e1, state[b, near] == AT_LIMIT, usable[near], cycle,
                                             bearing, solver, memory, out)
    jacs[k] = jac
    slopes[k] = slope[0]


@njit(cache=True)
def _interpolated(b, k, kp, kn, share, interpolate, cycle, limit, out):
    """Angle k of bearing b between kp and kn of one state: the film's turn-back (free minus tilt) interpolated
    ``share`` of the way (:func:`_turn_back_between`), taken where it changes between them by less than
    ``interpolate`` times their thinner edge film (onto the wall where they are at the limit or it falls outside
    the lens): writes its tilt and state into ``out``. Returns (taken, the turn-back's edge offset e0, e1)."""
    xi, free = cycle.xi, cycle.free
    tilt, state = out
    # the film's turn-back is interpolated: its change between the neighbours
    gap = math.hypot(free[b, kn, 0] - tilt[b, kn, 0] - free[b, kp, 0] + tilt[b, kp, 0],
                     free[b, kn, 1] - tilt[b, kn, 1] - free[b, kp, 1] + tilt[b, kp, 1])
    film = min(_edge(xi[b, kp, 0], xi[b, kp, 1], tilt[b, kp, 0], tilt[b, kp, 1]),
               _edge(xi[b, kn, 0], xi[b, kn, 1], tilt[b, kn, 0], tilt[b, kn, 1]))
    e0, e1 = _turn_back_between(free, tilt, b, k, kp, kn, share)
    if state[b, kp] == AT_LIMIT:
        # both on the wall: the edge film is the limit's whatever the tilt, whose direction the
        # mean keeps within about interpolate / 2 rad
        film = max(film, math.hypot(e0, e1))
    if not gap <= interpolate * film:
        return False, e0, e1
    room = wall_room(xi[b, k, 0], xi[b, k, 1], 0.0, 0.0, e0, e1, limit)
    if state[b, kp] == AT_LIMIT or room < 1.0:
        # onto the wall, as its neighbours (the mean of two points on it lies inside the lens)
        e0 *= room
        e1 *= room
    tilt[b, k, 0] = e0
    tilt[b, k, 1] = e1
    state[b, k] = state[b, kp]
    return True, e0, e1


@njit(cache=True)
def _march_step(a, solver, budget):
    """One implicit Euler step of the tilt at the angle ``a`` (:data:`Angle`, its squeeze from the last angle's
    edge offset p): damped Newton from p inside the lens, the Jacobian differenced at the first iterate and
    again after a step the line search had to shorten (chord iterations between), each step going at most
    :data:`INSIDE` of the way to the wall. Returns (e0, e1, state, evaluations): EQUILIBRIUM where
    the step falls below the solver's tolerance times the edge film, AT_LIMIT where Newton presses the edge onto
    the wall (its step beyond it, the room left below that tolerance times the limit's film; the edge is put on
    the wall), NOT_SOLVED where the budget ends first (the last iterate)."""
    x0, x1, limit, tolerance = a.x0, a.x1, solver.limit, solver.tolerance
    if math.hypot(x0, x1) >= limit * (1.0 - 1e-12):
        return 0.0, 0.0, AT_LIMIT, 0
    e0, e1 = a.p0, a.p1
    room = wall_room(x0, x1, 0.0, 0.0, e0, e1, limit)
    if room < 1.0:  # the orbit's centre moved the wall onto the last tilt
        e0 *= INSIDE * room
        e1 *= INSIDE * room
    jac = np.empty((2, 2))
    r0, r1 = _residual(a, e0, e1, solver.quadrature)
    evaluations = 1
    stale = True
    while evaluations < budget:
        if stale:
            evaluations += _difference_jacobian(a, e0, e1, r0, r1, solver, jac)
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        if det == 0.0 or not math.isfinite(det):
            break
        d0, d1 = _direction(jac, det, r0, r1)
        room, converged, pressed = _step_ends(x0, x1, e0, e1, d0, d1, limit, tolerance)
        if converged:
            return e0 + d0, e1 + d1, EQUILIBRIUM, evaluations
        if pressed:
            return e0 + room * d0, e1 + room * d1, AT_LIMIT, evaluations  # the edge onto the wall
        e0, e1, r0, r1, t, lowered, used = _backtrack(a, e0, e1, d0, d1, min(1.0, INSIDE * room),
                                                      r0 * r0 + r1 * r1, solver.quadrature)
        evaluations += used
        # the step's Jacobian serves its chord iterations while they lower the residual
        stale = not lowered or t < 1.0
    return e0, e1, NOT_SOLVED, evaluations


@njit(cache=True, inline="always")
def _bdf2(e0, e1, b0, b1, h, h_before):
    """The last tilt and rate of the variable-step BDF2 derivative (e - p) rate at a step h after the edge offsets
    e (one step back) and b (two steps back, a step h_before before e; h_before 0: implicit Euler): (p0, p1,
    rate)."""
    if h_before <= 0.0:
        return e0, e1, 1.0 / h
    w = h / h_before
    c = (1.0 + w) * (1.0 + w)
    return (c * e0 - w * w * b0) / (1.0 + 2.0 * w), (c * e1 - w * w * b1) / (1.0 + 2.0 * w), \
        (1.0 + 2.0 * w) / ((1.0 + w) * h)


@njit(cache=True, parallel=True)
def marches(orbits, correction, solver, tau, period, stride, warmup, cycles, tilt, state, evaluations):
    """The tilt marched over the cycle with its own squeeze, many bearings (prange over bearings).

    Every ``stride``-th angle is a step (``tau`` (n,): each angle's journal angle [rad], ``period`` the cycle's):
    the tilt :math:`\\mathbf e` with
    :math:`\\mathbf e + \\kappa\\mathbf M(\\mathbf x, \\mathbf v, \\mathbf e, \\bar{\\mathbf u}) = \\mathbf e_{free}`,
    :math:`\\bar{\\mathbf u} = \\dot{\\mathbf e} - \\tfrac12\\mathbf k\\times\\mathbf e` with
    :math:`\\dot{\\mathbf e}` by the variable-step BDF2 formula over the last two steps (:func:`_bdf2`; A-stable,
    as the squeeze makes the tilt stiff), solved by :func:`_march_step`. The march starts from the aligned
    journal ``warmup`` steps before the cycle's end and runs whole cycles until the last step's tilt is within
    the solver's tolerance of the pass before (times the edge film; at most ``cycles``); the last cycle is kept.
    An angle between two steps takes their film's turn-back (free minus tilt) interpolated
    (:func:`_turn_back_between`), as :func:`equilibria` does (onto the wall where both are at the limit or the
    mean falls outside the lens).
    ``orbits``, ``correction``, ``solver`` as :func:`equilibria`. Writes tilt (B, n, 2), state (B, n) and
    evaluations (B, n): film moments computed at each step over every pass (0 between steps).
    """
    xi, v, free, kappa, ld = orbits
    tables, ld_nodes, stretched, finite = correction
    (nodes, weights, nodes_dry, weights_dry, cap), limit, tolerance = solver
    n_b = xi.shape[0]
    n = xi.shape[1]
    m = (n + stride - 1) // stride
    for b in prange(n_b):
        cycle = Orbits(xi, v, free, kappa, ld)
        rule = Solver(Quadrature(nodes, weights, nodes_dry, weights_dry, cap), limit, tolerance)
        bearing = (bearing_table(Correction(tables, ld_nodes, stretched, finite), ld[b]), stretched, finite)
        for k in range(n):
            evaluations[b, k] = 0
        e0, e1, b0, b1, h_before = 0.0, 0.0, 0.0, 0.0, 0.0
        last0, last1 = 0.0, 0.0
        for p in range(cycles + 1):
            for j in range(m - warmup if p == 0 else 0, m):
                k = j * stride
                h = tau[k] - tau[(j - 1) * stride] if j > 0 else tau[0] + period - tau[(m - 1) * stride]
                p0, p1, rate = _bdf2(e0, e1, b0, b1, h, h_before)
                a = _angle(b, k, cycle, bearing, limit, p0, p1, rate)
                n0, n1, s, used = _march_step(a, rule, MARCH_EVALUATIONS)
                b0, b1, e0, e1, h_before = e0, e1, n0, n1, h
                tilt[b, k, 0] = e0
                tilt[b, k, 1] = e1
                state[b, k] = s
                evaluations[b, k] += used
            k = (m - 1) * stride
            if p > 0 and math.hypot(e0 - last0, e1 - last1) <= tolerance * _edge(xi[b, k, 0], xi[b, k, 1], e0, e1):
                break
            last0, last1 = e0, e1
        for j in range(m):
            kp = j * stride
            kn = kp + stride if j < m - 1 else n  # the cycle closes on its first angle
            for k in range(kp + 1, min(kn, n)):
                q = kn if kn < n else 0
                share = (tau[k] - tau[kp]) / (tau[kn] - tau[kp] if kn < n else tau[0] + period - tau[kp])
                t0, t1 = _turn_back_between(free, tilt, b, k, kp, q, share)
                wall = state[b, kp] == AT_LIMIT and state[b, q] == AT_LIMIT
                room = wall_room(xi[b, k, 0], xi[b, k, 1], 0.0, 0.0, t0, t1, limit)
                if wall or room < 1.0:
                    t0 *= room
                    t1 *= room
                    wall = True
                tilt[b, k, 0] = t0
                tilt[b, k, 1] = t1
                if wall:
                    state[b, k] = AT_LIMIT
                elif state[b, kp] == state[b, q]:
                    state[b, k] = state[b, kp]
                else:
                    state[b, k] = EQUILIBRIUM
