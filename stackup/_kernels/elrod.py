r"""The ``elrod-coarse`` cycle tier's kernels: Elrod's universal variable on a coarse grid, Newton per step (numba).

The readable statement (equations, units, sources) is in :mod:`stackup.film.elrod`;
``tests/film/test_elrod.py`` holds the numpy twins these kernels must match. Everything
is dimensionless as in :mod:`stackup.film.transient`: :math:`\bar h = h/c`,
:math:`\bar z = z/R`, :math:`\tau = \omega t`, :math:`\bar p = p c^2/(\mu\omega R^2)`.

One unknown per free node, Elrod's universal variable :math:`\phi`:
pressure :math:`\bar p = \max(\phi, 0)`, fill :math:`g = \min(1 + \phi, 1)`. The
discrete content balance of a node (finite volumes, the same stencil as the
reference kernel :func:`stackup._kernels.reynolds.elrod_adams`, on a z grid that may be
uneven) is

.. math:: R = \sum_{nb} a_{nb}(\bar p_{nb} - \bar p_P)
              - \tfrac{6}{\Delta\Theta}(g_P \bar h_e - g_W \bar h_w) - c_t\,g_P\bar h_P + H_P = 0

(:math:`c_t g_P \bar h_P - H_P` is 12 times the content's time derivative by BDF2). The
residual is piecewise linear in :math:`\phi`: the step's nodes and the journal centre
:math:`\xi` are solved together by a semismooth Newton method (the tilt slopes
:math:`s` are imposed; :func:`assemble` also gives their columns, ``n_unknowns`` 4,
for a tilt equilibrium the tier does not solve yet), the force balance :math:`\bar F(\phi) = \bar W`
bordering the field's Jacobian, which is block cyclic tridiagonal (a block per
angle: the nodes over the width) and is factored directly.

The orbit's march (:func:`march`) reads as the method does: a cycle at a time
(:func:`_lap`), each step predicted (:func:`_predict`: the content's history term,
the centre and the field extrapolated), balanced (:func:`balance_step`), its size
controlled (:func:`_step_size` ends the cycle on a step, :func:`_rejected` redoes a
step at half the size, :func:`_next_step` sizes the next one), a journal crossing
the clearance sought on the guide, then by leaps (:func:`_cross`, :func:`leap`);
``tests/film/test_elrod_controller.py`` holds the controller's plain-Python twin.
What a caller builds once comes as named tuples (:data:`Grid`, :data:`Cycle`,
:data:`Control`), each step's equations as :data:`Balance`.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit

PERIODIC, NOT_PERIODIC, COLLAPSED, FAILED = 0, 1, 2, 3
#: Floating-point shortcuts the kernels may take (no NaN or inf reaches them: the inputs are checked). Not
#: "reassoc": with it the code numba compiles in the process and the code it loads from its cache summed in other
#: orders, and the adaptive march took other steps (the same orbit 0.13 um apart at one angle, cycle minima nm
#: apart): a study must give the same numbers on its first run and its next (tests/film/test_compiled.py).
FAST = {"contract", "arcp", "nsz"}

#: The grid: angles (n_t,), their normals at the nodes (2, n_t) and at the east faces (2, n_t), axial nodes z
#: (n_z,) and north faces z_n (n_z - 1,), cell widths (n_z,), force weights (n_z,), the first free row j0
#: (0: node 0 is the mid-plane of a half grid, mirrored; 1: node 0 is the bearing's end), nodes kept fixed
#: (n_t, n_z) and their pressure, the thinnest film the tier allows (1 - limit eccentricity).
Grid = namedtuple("Grid", ("dtheta", "normal", "normal_east", "z", "z_north", "width", "weight", "j0", "fixed",
                           "p_fixed", "floor"))
#: Newton's stopping rule: force within ``force`` of the cycle's largest load, node balances within ``balance``
#: of the content rate of a full film (c_time), at most ``iterations`` per step; and the width of the band about
#: phi = 0 over which the switch between pressure and fill is smoothed (:func:`split`).
Newton = namedtuple("Newton", ("force", "balance", "iterations", "smoothing"))


@njit(cache=True, inline="always", fastmath=FAST)
def _held(h, floor):
    """Film where a journal would pass the thinnest film allowed: f/(2 - h/f) below f (continuous in value and
    slope); returns (film, d film / d h)."""
    if h >= floor:
        return h, 1.0
    r = min(h / floor, 1.0)
    d = 2.0 - r
    return floor / d, 1.0 / (d * d)


@njit(cache=True, fastmath=FAST)
def film(xi, slope, grid, h, dh, he, dhe, hn, dhn):
    """Film at the nodes (h), east faces (he) and north faces (hn), and its slope against the raw film, in place.

    Raw film 1 - (xi + z slope) . n; ``slope`` (2,) is the tilt in clearances per radius (gamma R / c).
    """
    n_t, n_z = h.shape
    for i in range(n_t):
        c0 = grid.normal[0, i]
        s0 = grid.normal[1, i]
        ce = grid.normal_east[0, i]
        se = grid.normal_east[1, i]
        for j in range(n_z):
            z = grid.z[j]
            h[i, j], dh[i, j] = _held(1.0 - (xi[0] + z * slope[0]) * c0 - (xi[1] + z * slope[1]) * s0, grid.floor)
            he[i, j], dhe[i, j] = _held(1.0 - (xi[0] + z * slope[0]) * ce - (xi[1] + z * slope[1]) * se,
                                        grid.floor)
            if j < n_z - 1:
                zn = grid.z_north[j]
                hn[i, j], dhn[i, j] = _held(1.0 - (xi[0] + zn * slope[0]) * c0 - (xi[1] + zn * slope[1]) * s0,
                                            grid.floor)


@njit(cache=True, fastmath=FAST, inline="always")
def split(phi, smoothing):
    """Pressure, its slope, fill and its slope of the universal variable ``phi``.

    p - (1 - g) = phi with p (1 - g) = smoothing^2 / 4 (Chen-Harker-Kanzow-Smale): p = max(phi, 0) and
    g = min(1 + phi, 1) but for a band of width ``smoothing`` about phi = 0, so Newton's merit is smooth.
    """
    s = math.sqrt(phi * phi + smoothing * smoothing)
    if phi >= 0.0:
        p = 0.5 * (phi + s)
        short = 0.5 * smoothing * smoothing / (s + phi)  # 1 - g, without cancellation
    else:
        short = 0.5 * (s - phi)
        p = 0.5 * smoothing * smoothing / (s - phi)
    return p, 0.5 * (1.0 + phi / s), 1.0 - short, 0.5 * (1.0 - phi / s)


@njit(cache=True, fastmath=FAST)
def fields(phi, grid, smoothing, pressure, d_pressure, fill, d_fill):
    """Pressure, fill and their slopes against phi at every node, in place (fixed nodes: their pressure, full)."""
    n_t, n_z = phi.shape
    for i in range(n_t):
        for j in range(n_z):
            if grid.fixed[i, j]:
                pressure[i, j] = grid.p_fixed[i, j]
                d_pressure[i, j] = 0.0
                fill[i, j] = 1.0
                d_fill[i, j] = 0.0
            else:
                pressure[i, j], d_pressure[i, j], fill[i, j], d_fill[i, j] = split(phi[i, j], smoothing)


@njit(cache=True, fastmath=FAST)
def assemble(state, films, history, c_time, grid, n_unknowns, residual, diag, west, east, coupling, force_rows):
    """Residual and Jacobian of the node balances, in place; returns the film force (2,).

    ``state`` = (pressure, d_pressure, fill, d_fill) of :func:`fields`; ``films`` = (h, dh, he, dhe, hn, dhn) of
    :func:`film`. Rows of a block are the nodes j0 .. n_z - 2 of an angle; ``diag`` (n_t, m, m) their couplings
    within the angle, ``west`` / ``east`` (n_t, m) to the same node of the angles before and after;
    ``coupling`` (n_t, m, k): d residual / d (centre, slopes) (k = 2 or 4); ``force_rows`` (n_t, m, k):
    d (force, moment) / d phi. A fixed node's row is the identity (its residual 0).
    """
    pr = state[0]
    n_t, n_z = pr.shape
    j0 = grid.j0
    system = (residual, diag, west, east, coupling, force_rows)
    force = film_force(pr, grid)
    diag[:] = 0.0
    for i in range(n_t):
        for j in range(j0, n_z - 1):
            if grid.fixed[i, j]:
                _fixed_row(i, j - j0, n_unknowns, system)
            else:
                _node_row(i, j, state, films, history, c_time, grid, n_unknowns, system)
    return force


@njit(cache=True, fastmath=FAST, inline="always")
def _fixed_row(i, r, n_unknowns, system):
    """Row r of angle i of a node held fixed: the identity, its residual 0."""
    residual, diag, west, east, coupling, force_rows = system
    residual[i, r] = 0.0
    diag[i, r, r] = 1.0
    west[i, r] = 0.0
    east[i, r] = 0.0
    for k in range(n_unknowns):
        coupling[i, r, k] = 0.0
        force_rows[i, r, k] = 0.0


@njit(cache=True, fastmath=FAST, inline="always")
def _node_row(i, j, state, films, history, c_time, grid, n_unknowns, system):
    """Row of the free node (i, j): its content balance (the module's equation), its slopes against phi at the
    node and its neighbours, and (:func:`_film_columns`) against the centre and slopes through the film."""
    pr, dpr, fl, dfl = state
    h, dh, he, dhe, hn, dhn = films
    residual, diag, west, east, coupling, force_rows = system
    n_t, n_z = pr.shape
    j0 = grid.j0
    r = j - j0
    dt = grid.dtheta
    it2 = 1.0 / (dt * dt)
    couette = 6.0 / dt
    im = i - 1 if i > 0 else n_t - 1
    ip = i + 1 if i + 1 < n_t else 0
    p_p = pr[i, j]
    g_p = fl[i, j]
    he_p = he[i, j]
    he_w = he[im, j]
    hn_p = hn[i, j]
    width = grid.width[j]
    dz_n = grid.z[j + 1] - grid.z[j]
    a_e = he_p * he_p * he_p * it2
    a_w = he_w * he_w * he_w * it2
    a_n = hn_p * hn_p * hn_p / (dz_n * width)
    if j > 0:
        hn_s = hn[i, j - 1]
        dz_s = grid.z[j] - grid.z[j - 1]
        a_s = hn_s * hn_s * hn_s / (dz_s * width)
        p_s = pr[i, j - 1]
    else:  # the mid-plane of a half grid: no flux across it
        hn_s = 0.0
        dz_s = 1.0
        a_s = 0.0
        p_s = p_p
    p_e = pr[ip, j]
    p_w = pr[im, j]
    p_n = pr[i, j + 1]
    residual[i, r] = (a_e * (p_e - p_p) + a_w * (p_w - p_p) + a_n * (p_n - p_p) + a_s * (p_s - p_p)
                      - couette * (g_p * he_p - fl[im, j] * he_w) - c_time * g_p * h[i, j] + history[i, j])
    diag[i, r, r] = -(a_e + a_w + a_n + a_s) * dpr[i, j] - (couette * he_p + c_time * h[i, j]) * dfl[i, j]
    west[i, r] = a_w * dpr[im, j] + couette * he_w * dfl[im, j]
    east[i, r] = a_e * dpr[ip, j]
    if j + 1 < n_z - 1:
        diag[i, r, r + 1] = a_n * dpr[i, j + 1]
    if j - 1 >= j0:
        diag[i, r, r - 1] = a_s * dpr[i, j - 1]
    # d residual / d unknowns through the film: terms at the east and west faces, and at the node
    face_e = dhe[i, j] * (3.0 * he_p * he_p * (p_e - p_p) * it2 - couette * g_p)
    face_w = dhe[im, j] * (3.0 * he_w * he_w * (p_w - p_p) * it2 + couette * fl[im, j])
    north = 3.0 * hn_p * hn_p * dhn[i, j] * (p_n - p_p) / (dz_n * width)
    south = 3.0 * hn_s * hn_s * dhn[i, j - 1] * (p_s - p_p) / (dz_s * width) if j > 0 else 0.0
    node = -c_time * g_p * dh[i, j]
    weight = grid.weight[j] * dpr[i, j] * dt
    _film_columns(i, j, (face_e, face_w, north, south, node), weight, grid, n_unknowns, coupling, force_rows)


@njit(cache=True, fastmath=FAST, inline="always")
def _film_columns(i, j, terms, weight, grid, n_unknowns, coupling, force_rows):
    """The free node (i, j)'s row against the centre (k 0, 1) and slopes (k 2, 3): d residual / d unknown from the
    film's ``terms`` = (east face, west face, north face, south face, node), each d residual / d film there, and
    d (force, moment) / d phi from the node's force ``weight``."""
    face_e, face_w, north, south, node = terms
    n_t = grid.normal.shape[1]
    r = j - grid.j0
    im = i - 1 if i > 0 else n_t - 1
    for k in range(n_unknowns):
        axis = k % 2
        n_p = grid.normal[axis, i]
        if k < 2:
            coupling[i, r, k] = -(grid.normal_east[axis, i] * face_e + grid.normal_east[axis, im] * face_w
                                  + n_p * (north + south + node))
            force_rows[i, r, k] = weight * n_p
        else:
            z = grid.z[j]
            z_s = grid.z_north[j - 1] if j > 0 else 0.0
            coupling[i, r, k] = -((grid.normal_east[axis, i] * face_e + grid.normal_east[axis, im] * face_w
                                   + n_p * node) * z + n_p * (north * grid.z_north[j] + south * z_s))
            force_rows[i, r, k] = weight * n_p * z


@njit(cache=True, fastmath=FAST)
def _invert(a, out):
    """Inverse of the small square ``a`` into ``out`` by Gauss-Jordan with partial pivoting (``a`` destroyed);
    False if singular."""
    m = a.shape[0]
    out[:, :] = 0.0
    for r in range(m):
        out[r, r] = 1.0
    for c in range(m):
        best = c
        big = abs(a[c, c])
        for r in range(c + 1, m):
            if abs(a[r, c]) > big:
                big = abs(a[r, c])
                best = r
        if big == 0.0 or not math.isfinite(big):
            return False
        if best != c:
            for k in range(m):
                t = a[c, k]
                a[c, k] = a[best, k]
                a[best, k] = t
                t = out[c, k]
                out[c, k] = out[best, k]
                out[best, k] = t
        inv = 1.0 / a[c, c]
        for k in range(m):
            a[c, k] *= inv
            out[c, k] *= inv
        for r in range(m):
            if r != c:
                f = a[r, c]
                if f != 0.0:
                    for k in range(m):
                        a[r, k] -= f * a[c, k]
                        out[r, k] -= f * out[c, k]
    return True


@njit(cache=True, fastmath=FAST)
def factor(diag, west, east, inverse, ahead, last, below, bottom, scratch):
    """Factor the block cyclic tridiagonal matrix (blocks ``diag``, ``west``, ``east``) by block elimination.

    Angle i couples to i - 1 through diag(west[i]) and to i + 1 through diag(east[i]), cyclically. Eliminating
    angles 0 .. n - 2 in order leaves, per angle, the inverse of its pivot block P (``inverse``),
    ``ahead`` = P^-1 diag(east) and ``last`` = P^-1 (its coupling to angle n - 1, the wrap's fill-in);
    ``below`` (n, m, m) the last angle's row's coupling to angle i before it is eliminated; ``bottom`` the
    inverse of the last angle's block once the others are eliminated. False if a pivot block is singular.
    """
    n, m = west.shape
    row = below[n - 1]  # the last angle's coupling to the angle being eliminated (below[n - 1] is free)
    row[:, :] = 0.0
    for r in range(m):
        row[r, r] = east[n - 1, r]
    tail = np.empty((m, m))
    tail[:, :] = diag[n - 1]
    p = scratch
    for i in range(n - 1):
        wrap = last[i]
        if i == 0:
            p[:, :] = diag[0]
            wrap[:, :] = 0.0
            for r in range(m):
                wrap[r, r] = west[0, r]
        else:
            for r in range(m):
                w = west[i, r]
                for c in range(m):
                    p[r, c] = diag[i, r, c] - w * ahead[i - 1, r, c]
                    wrap[r, c] = -w * last[i - 1, r, c]
        if i == n - 2:
            for r in range(m):
                wrap[r, r] += east[i, r]
        pinv = inverse[i]
        if not _invert(p, pinv):
            return False
        # last = P^-1 wrap, ahead = P^-1 diag(east)
        for r in range(m):
            for c in range(m):
                s = 0.0
                for k in range(m):
                    s += pinv[r, k] * wrap[k, c]
                p[r, c] = s
        wrap[:, :] = p
        for r in range(m):
            for c in range(m):
                ahead[i, r, c] = pinv[r, c] * east[i, c] if i < n - 2 else 0.0
        below[i, :, :] = row
        # the last angle's row without angle i: its block and its coupling to angle i + 1
        for r in range(m):
            for c in range(m):
                s = 0.0
                t = 0.0
                for k in range(m):
                    s += row[r, k] * wrap[k, c]
                    t += row[r, k] * ahead[i, k, c]
                tail[r, c] -= s
                p[r, c] = -t
        row[:, :] = p
        if i + 1 == n - 2:
            for r in range(m):
                row[r, r] += west[n - 1, r]
    return _invert(tail, bottom)


@njit(cache=True, fastmath=FAST)
def solve(inverse, west, ahead, last, below, bottom, b):
    """Solve the factored system (:func:`factor`) for right-hand sides ``b`` (n, m, q) in place."""
    n, m, q = b.shape
    tail = b[n - 1].copy()
    v = np.empty((m, q))
    for i in range(n - 1):
        for r in range(m):
            for c in range(q):
                v[r, c] = b[i, r, c] - (west[i, r] * b[i - 1, r, c] if i > 0 else 0.0)
        for r in range(m):
            for c in range(q):
                s = 0.0
                for k in range(m):
                    s += inverse[i, r, k] * v[k, c]
                b[i, r, c] = s
        for r in range(m):
            for c in range(q):
                s = 0.0
                for k in range(m):
                    s += below[i, r, k] * b[i, k, c]
                tail[r, c] -= s
    for r in range(m):
        for c in range(q):
            s = 0.0
            for k in range(m):
                s += bottom[r, k] * tail[k, c]
            b[n - 1, r, c] = s
    for i in range(n - 2, -1, -1):
        for r in range(m):
            for c in range(q):
                s = 0.0
                for k in range(m):
                    s += ahead[i, r, k] * b[i + 1, k, c] + last[i, r, k] * b[n - 1, k, c]
                b[i, r, c] -= s


#: Work arrays of one bearing's march (allocated once per bearing by :func:`workspace`).
Work = namedtuple("Work", ("h", "dh", "he", "dhe", "hn", "dhn", "pressure", "d_pressure", "fill", "d_fill",
                           "residual", "diag", "west", "east", "coupling",
                           "force_rows", "inverse", "ahead", "last", "below", "bottom", "scratch", "rhs", "saved"))
#: What one time step balances: the film slope (2,) imposed, BDF2's history term H (n_t, n_z) and rate coefficient
#: c_time of the content (the module's equation), the load (2,) the film force must equal, and the force's scale
#: (the cycle's largest load: the unit of the force tolerance).
Balance = namedtuple("Balance", ("slope", "history", "c_time", "target", "scale"))
#: The unit of the force balance's tolerance is the cycle's largest load, at least this (per mu omega R^4 / c^2:
#: a journal without load is balanced to the tolerance of this force).
SMALLEST_SCALE = 1e-3
#: Most halvings of a Newton step whose residuals do not fall; Newton gives up after this many short steps in a
#: row (a tenth of the step or less).
LINE_SEARCH = 8
STALLED = 3
#: A leap (:func:`leap`): most steps on the centre, most trials of each (Levenberg-Marquardt: the damping raised
#: by LEAP_GROWTH after a trial that does not lower the force error, lowered by it after one that does; Newton:
#: the step halved, each search starting at LEAP_GROWTH times the last accepted length), and Levenberg-Marquardt's
#: damping at the start, relative to the diagonal of S'S.
LEAP_ITERATIONS = 40
LEAP_SEARCH = 12
LEAP_GROWTH = 4.0
LEAP_DAMPING = 1e-2
#: A leap that stalls (a step lowers the force error by less than LEAP_STALL) with the force balanced within
#: LEAP_FORCE of the cycle's largest load is taken as it is: where the film barely carries, the force error
#: lingers near that for dozens of steps, the time step was then halved and the leap redone, and on
#: rozhdestvensky-4's bearing 3 that cost more than the rest of the cycle.
LEAP_FORCE = 1e-3
LEAP_STALL = 0.5


def workspace(n_t, n_z, j0, k):
    """Work arrays for a grid of n_t x n_z nodes, free rows from j0, k balance unknowns."""
    m = n_z - 1 - j0
    return Work(*(np.empty((n_t, n_z)) for _ in range(10)), np.empty((n_t, m)), np.empty((n_t, m, m)),
                np.empty((n_t, m)), np.empty((n_t, m)), np.empty((n_t, m, k)), np.empty((n_t, m, k)),
                np.empty((n_t, m, m)), np.empty((n_t, m, m)), np.empty((n_t, m, m)), np.empty((n_t, m, m)),
                np.empty((m, m)), np.empty((m, m)), np.empty((n_t, m, 1 + k)), np.empty((n_t, m)))


@njit(cache=True, fastmath=FAST)
def _evaluate(phi, xi, balance, grid, smoothing, work, free=True):
    """Film, fields, residual and Jacobian at (phi, xi); returns (merit, force error 0, 1, largest node residual).

    Merit: half the sum of squares of the node residuals per c_time and (with the centre ``free``) of the force
    error per the balance's ``scale``.
    """
    c_time, target, scale = balance.c_time, balance.target, balance.scale
    film(xi, balance.slope, grid, work.h, work.dh, work.he, work.dhe, work.hn, work.dhn)
    fields(phi, grid, smoothing, work.pressure, work.d_pressure, work.fill, work.d_fill)
    force = assemble((work.pressure, work.d_pressure, work.fill, work.d_fill),
                     (work.h, work.dh, work.he, work.dhe, work.hn, work.dhn), balance.history, c_time, grid, 2,
                     work.residual, work.diag, work.west, work.east, work.coupling, work.force_rows)
    g0 = force[0] - target[0]
    g1 = force[1] - target[1]
    worst = 0.0
    merit = 0.0
    n_t, m = work.residual.shape
    for i in range(n_t):
        for r in range(m):
            v = work.residual[i, r]
            worst = max(worst, abs(v))
            merit += v * v
    merit = 0.5 * (merit / (c_time * c_time) + ((g0 * g0 + g1 * g1) / (scale * scale) if free else 0.0))
    return merit, g0, g1, worst


@njit(cache=True, fastmath=FAST)
def balance_step(phi, xi, balance, grid, tol, limit, work, free=True):
    """Solve one time step in place: the nodes' universal variable ``phi`` and the journal centre ``xi``.

    Semismooth Newton on the node balances bordered by the force balance F(phi) = target (``balance``:
    :data:`Balance`), from the ``phi`` and ``xi`` given (the previous step's field, a predicted centre), its
    direction by :func:`_newton_direction`, globalised by backtracking on the residuals' sum of squares
    (:func:`_line_search`: a full step can cycle between two sets of cavitated nodes). The film slope is
    imposed. With ``free`` False the centre is held where it is and only the nodes are solved (the force then
    is whatever the film gives). Returns the Newton iterations (>= 0), or -1 if Newton did not converge, -2 if
    the centre was held at the limit eccentricity (no film carries the load there).
    """
    held = False
    creeping = 0
    merit, g0, g1, worst = _evaluate(phi, xi, balance, grid, tol.smoothing, work, free)
    for it in range(tol.iterations):
        if (not free or abs(g0) + abs(g1) <= tol.force * balance.scale) and worst <= tol.balance * balance.c_time:
            return it
        if not factor(work.diag, work.west, work.east, work.inverse, work.ahead, work.last, work.below,
                      work.bottom, work.scratch):
            return -1
        solved, d0, d1 = _newton_direction(work, g0, g1, free)
        if not solved:
            return -1
        merit, g0, g1, worst, alpha, held = _line_search(phi, xi, d0, d1, merit, balance, grid, tol.smoothing,
                                                         limit, work, free)
        # short steps that barely lower the residuals: no solution near here (the caller leaps or halves the step)
        creeping = creeping + 1 if alpha < 0.1 else 0
        if creeping >= STALLED:
            return -2 if held else -1
    return -2 if held else -1


@njit(cache=True, fastmath=FAST, inline="always")
def _newton_direction(work, g0, g1, free):
    """Newton's step of the bordered system, the Jacobian factored in ``work`` (:func:`factor`): the centre's
    (d0, d1) from the force balance's Schur complement (F_phi X) d = G - F_phi y, where J y = R and J X = dR/dxi,
    and the field's -(y + X d) into ``work.rhs[:, :, 0]``. Returns (solved, d0, d1): not solved where the
    complement is singular (the centre ``free``; held, d = 0)."""
    rhs = work.rhs
    n_t, m = work.residual.shape
    for i in range(n_t):
        for r in range(m):
            rhs[i, r, 0] = work.residual[i, r]
            rhs[i, r, 1] = work.coupling[i, r, 0]
            rhs[i, r, 2] = work.coupling[i, r, 1]
    solve(work.inverse, work.west, work.ahead, work.last, work.below, work.bottom, rhs)
    s00 = s01 = s10 = s11 = 0.0
    b0 = g0
    b1 = g1
    for i in range(n_t):
        for r in range(m):
            f0 = work.force_rows[i, r, 0]
            f1 = work.force_rows[i, r, 1]
            if f0 == 0.0 and f1 == 0.0:
                continue
            s00 += f0 * rhs[i, r, 1]
            s01 += f0 * rhs[i, r, 2]
            s10 += f1 * rhs[i, r, 1]
            s11 += f1 * rhs[i, r, 2]
            b0 -= f0 * rhs[i, r, 0]
            b1 -= f1 * rhs[i, r, 0]
    det = s00 * s11 - s01 * s10
    if free and (det == 0.0 or not math.isfinite(det)):
        return False, 0.0, 0.0
    d0 = (b0 * s11 - b1 * s01) / det if free else 0.0
    d1 = (s00 * b1 - s10 * b0) / det if free else 0.0
    for i in range(n_t):
        for r in range(m):
            rhs[i, r, 0] = -(rhs[i, r, 0] + rhs[i, r, 1] * d0 + rhs[i, r, 2] * d1)  # the step of phi
    return True, d0, d1


@njit(cache=True, fastmath=FAST, inline="always")
def _line_search(phi, xi, d0, d1, merit, balance, grid, smoothing, limit, work, free):
    """Newton's step (the field's in ``work.rhs[:, :, 0]``, the centre's d) from (phi, xi), halved at most
    :data:`LINE_SEARCH` times until the merit falls by Armijo's share, in place; a centre past the ``limit`` is
    cut back onto it. Returns (merit, force error 0, 1, largest node residual, step length, whether the centre
    was cut back) at the last point tried."""
    n_t, m = work.residual.shape
    j0 = grid.j0
    rhs = work.rhs
    saved = work.saved
    for i in range(n_t):
        for r in range(m):
            saved[i, r] = phi[i, j0 + r]
    x0 = xi[0]
    x1 = xi[1]
    alpha = 1.0
    for _ in range(LINE_SEARCH):
        for i in range(n_t):
            for r in range(m):
                if not grid.fixed[i, j0 + r]:
                    phi[i, j0 + r] = saved[i, r] + alpha * rhs[i, r, 0]
        # the centre stays within the limit: a step past it is cut back onto it
        y0 = x0 + alpha * d0
        y1 = x1 + alpha * d1
        e = math.hypot(y0, y1)
        held = e > limit
        if held:
            y0 *= limit / e
            y1 *= limit / e
        xi[0] = y0
        xi[1] = y1
        trial, g0, g1, worst = _evaluate(phi, xi, balance, grid, smoothing, work, free)
        if trial <= (1.0 - 1e-4 * alpha) * merit:
            break
        alpha *= 0.5
    return trial, g0, g1, worst, alpha, held


@njit(cache=True, fastmath=FAST)
def film_force(pressure, grid):
    """Film force on the bearing (2,) of a pressure field (per unit of mu omega R^4 / c^2)."""
    n_t, n_z = pressure.shape
    out = np.zeros(2)
    for i in range(n_t):
        s = 0.0
        for j in range(n_z):
            s += grid.weight[j] * pressure[i, j]
        out[0] += s * grid.normal[0, i] * grid.dtheta
        out[1] += s * grid.normal[1, i] * grid.dtheta
    return out


@njit(cache=True, fastmath=FAST)
def _reduced_jacobian(work, n_t, m):
    """d(film force)/d(centre) of a field solved at a held centre: -F_phi J^-1 dR/dxi (the Schur complement).

    Reads the Jacobian the last (converged) evaluation left in ``work``; returns its negative, S (2 x 2).
    """
    rhs = work.rhs
    if not factor(work.diag, work.west, work.east, work.inverse, work.ahead, work.last, work.below, work.bottom,
                  work.scratch):
        return False, 0.0, 0.0, 0.0, 0.0
    for i in range(n_t):
        for r in range(m):
            rhs[i, r, 0] = 0.0
            rhs[i, r, 1] = work.coupling[i, r, 0]
            rhs[i, r, 2] = work.coupling[i, r, 1]
    solve(work.inverse, work.west, work.ahead, work.last, work.below, work.bottom, rhs)
    s00 = s01 = s10 = s11 = 0.0
    for i in range(n_t):
        for r in range(m):
            f0 = work.force_rows[i, r, 0]
            f1 = work.force_rows[i, r, 1]
            s00 += f0 * rhs[i, r, 1]
            s01 += f0 * rhs[i, r, 2]
            s10 += f1 * rhs[i, r, 1]
            s11 += f1 * rhs[i, r, 2]
    return True, s00, s01, s10, s11


@njit(cache=True, fastmath=FAST, inline="always")
def _force_error(work, grid, target):
    """The film force of the field in ``work`` less the load ``target``: (f0, f1)."""
    force = film_force(work.pressure, grid)
    return force[0] - target[0], force[1] - target[1]


@njit(cache=True, fastmath=FAST)
def leap(phi, xi, balance, grid, tol, limit, work, damped=True):
    """The step's balance far from the centre ``xi``, where no film near it carries the load, in place.

    A massless journal whose load turns onto a film short of oil crosses the clearance within a step, as far as
    the film there carries the load; the full Newton of :func:`balance_step` stalls on the way (its residuals
    mix the field's and the force's). Here Levenberg-Marquardt runs on the centre alone: each trial centre's
    field is solved with the centre held, the force's error f is the residual and the field's Schur complement
    S its Jacobian, the step d solves (S'S + lam diag S'S) d = S'f, and lam grows until the error falls (S is
    near singular along a film that barely carries: Newton's own step overshoots there). With ``damped`` False,
    Newton's step S d = f is halved until the error falls instead (the search starting near the last step's
    length); each finds crossings the other misses (:func:`_leap_search`). :func:`balance_step` polishes the
    result (:func:`_leap_end`). Returns as :func:`balance_step`.
    """
    n_t, n_z = phi.shape
    m = n_z - 1 - grid.j0
    trial = phi.copy()
    if balance_step(phi, xi, balance, grid, tol, limit, work, False) < 0:
        return -1
    f0, f1 = _force_error(work, grid, balance.target)
    size = math.hypot(f0, f1)
    y = np.empty(2)
    lam = LEAP_DAMPING
    alpha = 1.0 / LEAP_GROWTH
    for _ in range(LEAP_ITERATIONS):
        if size <= tol.force * balance.scale:
            break
        ok, s00, s01, s10, s11 = _reduced_jacobian(work, n_t, m)
        det = s00 * s11 - s01 * s10
        if not ok or det == 0.0 or not math.isfinite(det):
            return -1
        # Newton's step: where the film begins to carry it overshoots by orders of magnitude iteration after
        # iteration, so its search starts near the last accepted length
        alpha = min(1.0, LEAP_GROWTH * alpha)
        accepted, lam, alpha, f0, f1 = _leap_search(phi, xi, (s00, s01, s10, s11, det), (f0, f1, size),
                                                    (lam, alpha, damped), balance, grid, tol, limit, work, (trial, y))
        if not accepted:
            break
        phi[:, :] = trial
        xi[0] = y[0]
        xi[1] = y[1]
        before = size
        size = math.hypot(f0, f1)
        if size <= LEAP_FORCE * balance.scale and size > LEAP_STALL * before:
            break
    return _leap_end(phi, xi, size, balance, grid, tol, limit, work)


@njit(cache=True, fastmath=FAST, inline="always")
def _leap_search(phi, xi, jacobian, error, search, balance, grid, tol, limit, work, out):
    """One step of a leap: trial centres (held within ``limit``), each one's field solved from ``phi`` with the
    centre held, until the force error falls below ``error`` = (f0, f1, its size). ``search`` = (lam, alpha,
    damped): Levenberg-Marquardt's step, its damping lam raised after each failure (damped), or Newton's
    S d = f of length alpha, halved after each; ``jacobian`` = (s00, s01, s10, s11, det) the reduced Jacobian S
    (:func:`_reduced_jacobian`). The last trial's field and centre in ``out`` = (trial, y). Returns (accepted,
    lam, alpha, the accepted trial's force error 0, 1)."""
    s00, s01, s10, s11, det = jacobian
    f0, f1, size = error
    lam, alpha, damped = search
    trial, y = out
    # F(xi + d) ~ F(xi) - S d = target: Levenberg-Marquardt on the centre, (S'S + lam diag S'S) d = S' f
    a00 = s00 * s00 + s10 * s10
    a01 = s00 * s01 + s10 * s11
    a11 = s01 * s01 + s11 * s11
    r0 = s00 * f0 + s10 * f1
    r1 = s01 * f0 + s11 * f1
    n0 = (f0 * s11 - f1 * s01) / det
    n1 = (s00 * f1 - s10 * f0) / det
    for _ in range(LEAP_SEARCH):
        if damped:
            m00 = a00 * (1.0 + lam)
            m11 = a11 * (1.0 + lam)
            dm = m00 * m11 - a01 * a01
            y[0] = xi[0] + (r0 * m11 - r1 * a01) / dm
            y[1] = xi[1] + (m00 * r1 - a01 * r0) / dm
        else:
            y[0] = xi[0] + alpha * n0
            y[1] = xi[1] + alpha * n1
        e = math.hypot(y[0], y[1])
        if e > limit:
            y[0] *= limit / e
            y[1] *= limit / e
        trial[:, :] = phi
        if balance_step(trial, y, balance, grid, tol, limit, work, False) >= 0:
            g0, g1 = _force_error(work, grid, balance.target)
            if math.hypot(g0, g1) < (1.0 if damped else 1.0 - 1e-4 * alpha) * size:
                return True, max(lam / LEAP_GROWTH, 1e-12), alpha, g0, g1
        lam = max(lam, 1e-6) * LEAP_GROWTH
        alpha *= 0.5
    return False, lam, alpha, f0, f1


@njit(cache=True, fastmath=FAST, inline="always")
def _leap_end(phi, xi, size, balance, grid, tol, limit, work):
    """The outcome of a leap whose force error is ``size``: balanced within the tolerance, polished by
    :func:`balance_step`; a stalled leap within :data:`LEAP_FORCE` of the cycle's largest load taken with its
    field solved at the centre held; else failed (-2 if the centre is at the limit). Returns as
    :func:`balance_step`."""
    if size <= tol.force * balance.scale:
        return balance_step(phi, xi, balance, grid, tol, limit, work)
    if size > LEAP_FORCE * balance.scale:
        return -2 if math.hypot(xi[0], xi[1]) >= limit * (1.0 - 1e-9) else -1
    # balanced within LEAP_FORCE only: the field of this centre (work may hold a rejected trial's)
    return 0 if balance_step(phi, xi, balance, grid, tol, limit, work, False) >= 0 else -1


@njit(cache=True, fastmath=FAST)
def outputs(pressure, fill, h, grid):
    """Peak pressure, friction integral and side-flow integral of a field (dimensionless, as the reference tier).

    Friction: sum of (g / h + h dp/dtheta / 2) over the nodes; side flow: h^3 |dp/dz| at both ends (the slope of
    the quadratic through the end's three nodes; a half grid's one end counted twice).
    """
    n_t, n_z = pressure.shape
    peak = 0.0
    friction = 0.0
    flow = 0.0
    dt = grid.dtheta
    ends = 2.0 if grid.j0 == 0 else 1.0
    z = grid.z
    for i in range(n_t):
        im = i - 1 if i > 0 else n_t - 1
        ip = i + 1 if i + 1 < n_t else 0
        for j in range(n_z):
            peak = max(peak, pressure[i, j])
            dp = (pressure[ip, j] - pressure[im, j]) / (2.0 * dt)
            friction += grid.weight[j] * (fill[i, j] / h[i, j] + 0.5 * h[i, j] * dp) * dt
        last = n_z - 1
        flow += ends * h[i, last] ** 3 * abs(_end_slope(pressure[i, last], pressure[i, last - 1],
                                                        pressure[i, last - 2], z[last], z[last - 1], z[last - 2])) * dt
        if grid.j0 == 1:
            flow += h[i, 0] ** 3 * abs(_end_slope(pressure[i, 0], pressure[i, 1], pressure[i, 2], z[0], z[1],
                                                  z[2])) * dt
    return peak, friction, flow


@njit(cache=True, fastmath=FAST, inline="always")
def _end_slope(p0, p1, p2, z0, z1, z2):
    """dp/dz at z0 from the quadratic through three nodes (uneven spacing)."""
    d1 = z1 - z0
    d2 = z2 - z0
    return ((p1 - p0) * d2 * d2 - (p2 - p0) * d1 * d1) / (d1 * d2 * (d2 - d1))


#: Time steps (radians of shaft rotation, tau): the local error allowed per step (the change of the centre
#: from its prediction, per film left), the first step, the largest and the smallest (below it a step that
#: fails ends the orbit as failed), and the step at or below which a step without a balance near the prediction
#: leaps (:func:`leap`) rather than halving again.
Stepping = namedtuple("Stepping", ("tolerance", "first", "largest", "smallest", "leap"))
#: One bearing's cycle: the loads (n, 2) given at the times tau[:n] (tau (n + 1,), tau[n] the cycle's end), the
#: film slope (n, 2) at the same times (linear between them), and the guide (n, 2): the centres where a journal
#: that crosses the clearance is first sought (the mobility-finite orbit).
Cycle = namedtuple("Cycle", ("loads", "tau", "slope", "guide"))
#: How a march is controlled: Newton's stopping rule (:data:`Newton`), the time steps (:data:`Stepping`), the
#: limit eccentricity, the periodicity tolerance (a share of the thinnest film) and the most cycles.
Control = namedtuple("Control", ("newton", "stepping", "limit", "periodic", "max_cycles"))
#: What a march carries from step to step: the field phi, the field before the step being solved (``saved``) and
#: a step back (``old``), the film content g h now and a step back, and BDF2's history term, each (n_t, n_z); the
#: centre now and a step back, the step's predicted centre and its solution, its load and film slope, each (2,);
#: the outputs of :func:`outputs` now and a step back (3,); where a crossing journal is sought (n, 2): the guide,
#: then the last cycle's orbit; the counts (steps, Newton iterations, leaps); the force's scale (:data:`Balance`).
State = namedtuple("State", ("phi", "saved", "old", "content", "content_old", "history", "centre", "centre_old",
                             "guess", "trial", "target", "tilt", "outputs", "outputs_old", "track", "counts",
                             "scale"))


@njit(cache=True, fastmath=FAST, inline="always")
def _at(values, tau, t, out):
    """``values`` (n, 2) given at tau[:n], linear in between and periodic over tau[n], at time t, into ``out``."""
    n = values.shape[0]
    period = tau[n]
    t = t - period * math.floor(t / period)
    k = min(int(np.searchsorted(tau, t, side="right")) - 1, n - 1)
    u = (t - tau[k]) / (tau[k + 1] - tau[k])
    kn = k + 1 if k + 1 < n else 0
    out[0] = (1.0 - u) * values[k, 0] + u * values[kn, 0]
    out[1] = (1.0 - u) * values[k, 1] + u * values[kn, 1]


@njit(cache=True, fastmath=FAST)
def march(cycle, xi0, grid, control, work, out):
    """Periodic orbit of one bearing over its ``cycle`` (:data:`Cycle`) from the centre ``xi0``, in place.

    Adaptive BDF2 on the content (variable step, backward Euler at the first step), a cycle at a time
    (:func:`_lap`): each step by :func:`balance_step` from a field and a centre extrapolated from the last two
    (:func:`_predict`); the step grows or shrinks so that the balanced centre differs from its prediction by
    about ``stepping.tolerance`` of the film left (a step past three times that, or one whose Newton fails, is
    redone at half the size: :func:`_rejected`, :func:`_next_step`); a step whose Newton fails at
    ``stepping.leap`` or shorter seeks the journal on the guide (from the second cycle on, the last cycle's
    orbit), then leaps (:func:`_cross`). Loads and film slope are linear between the times given; every cycle
    ends on a step (:func:`_step_size`). Cycles are marched until the centre comes back within
    ``control.periodic`` of the thinnest film (``control``: :data:`Control`). ``out`` = (record (n, 2), outs
    (n, 3)): the centre and the outputs of :func:`outputs` at each time given, of the last cycle (linear between
    steps). Returns (status, cycles, steps, Newton iterations and leaps in all).
    """
    state = _march_start(cycle, xi0, grid, control.newton.smoothing, work)
    centre, counts = state.centre, state.counts
    h_prev = 0.0
    h = control.stepping.first
    status = NOT_PERIODIC
    for lap in range(1, control.max_cycles + 1):
        start0 = centre[0]
        start1 = centre[1]
        failed, collapsed, widest, h, h_prev = _lap(cycle, grid, control, work, state, h, h_prev, out)
        if failed:
            return FAILED, lap, counts[0], counts[1], counts[2]
        film_left = 1.0 - (control.limit if collapsed else widest)
        closure = math.hypot(centre[0] - start0, centre[1] - start1)
        state.track[:, :] = out[0]
        if lap > 1 and closure <= control.periodic * film_left:
            return (COLLAPSED if collapsed else PERIODIC), lap, counts[0], counts[1], counts[2]
        status = COLLAPSED if collapsed else NOT_PERIODIC
    return status, control.max_cycles, counts[0], counts[1], counts[2]


@njit(cache=True, fastmath=FAST, inline="always")
def _march_start(cycle, xi0, grid, smoothing, work):
    """The march's :data:`State` at time 0: the field empty of pressure but at the fixed nodes, the centre ``xi0``,
    the film, content and outputs there, the force's scale from the cycle's largest load."""
    n_t, n_z = grid.fixed.shape
    phi = np.zeros((n_t, n_z))
    for i in range(n_t):
        for j in range(n_z):
            if grid.fixed[i, j]:
                phi[i, j] = grid.p_fixed[i, j]
    scale = SMALLEST_SCALE
    for k in range(cycle.loads.shape[0]):
        scale = max(scale, abs(cycle.loads[k, 0]) + abs(cycle.loads[k, 1]))
    state = State(phi, phi.copy(), phi.copy(), np.empty((n_t, n_z)), np.empty((n_t, n_z)), np.empty((n_t, n_z)),
                  xi0.copy(), xi0.copy(), np.empty(2), np.empty(2), np.empty(2), np.empty(2), np.empty(3),
                  np.empty(3), cycle.guide.copy(), np.zeros(3, np.int64), scale)
    _at(cycle.slope, cycle.tau, 0.0, state.tilt)
    film(state.centre, state.tilt, grid, work.h, work.dh, work.he, work.dhe, work.hn, work.dhn)
    fields(phi, grid, smoothing, work.pressure, work.d_pressure, work.fill, work.d_fill)
    state.content[:, :] = work.fill * work.h
    state.outputs[0], state.outputs[1], state.outputs[2] = outputs(work.pressure, work.fill, work.h, grid)
    return state


@njit(cache=True, fastmath=FAST, inline="always")
def _lap(cycle, grid, control, work, state, h, h_prev, out):
    """One cycle of the march from time 0, step after step (:func:`_step`, the first one ``h`` after one of
    ``h_prev``), each taken (:func:`_take`) or redone shorter; records the centre and outputs of each time given
    into ``out`` (:func:`_record`). Returns (failed, collapsed, widest, h, h_prev): whether a step failed at the
    smallest size (the rest of the record NaN), whether the journal reached the limit, its largest eccentricity,
    the next step and the last."""
    record, outs = out
    n = cycle.loads.shape[0]
    period = cycle.tau[n]
    stepping = control.stepping
    centre = state.centre
    widest = math.hypot(centre[0], centre[1])
    collapsed = False
    record[0, 0] = centre[0]
    record[0, 1] = centre[1]
    outs[0, :] = state.outputs
    t = 0.0
    k_next = 1  # the next time given to record
    while t < period:
        h = _step_size(h, t, period, stepping.largest)
        done, jumped, error = _step(cycle, grid, control, work, state, t, h, h_prev, widest)
        if _rejected(done, jumped, state.counts[0] >= 1, error, h, stepping):
            state.phi[:, :] = state.saved
            if h <= stepping.smallest:
                record[k_next:, :] = np.nan
                outs[k_next:, :] = np.nan
                return True, collapsed, widest, h, h_prev
            h = max(0.5 * h, stepping.smallest)
            continue
        if done == -2 or math.hypot(state.trial[0], state.trial[1]) >= control.limit * (1.0 - 1e-12):
            collapsed = True
        _take(state, jumped, grid, work)
        widest = max(widest, math.hypot(centre[0], centre[1]))
        k_next = _record(cycle.tau, t, h, state, k_next, out)
        t = t + h
        h_prev = h
        state.counts[0] += 1
        if jumped:
            # after a crossing: no velocity to extrapolate, a short step to start again
            state.centre_old[0] = centre[0]
            state.centre_old[1] = centre[1]
            h = stepping.first
        else:
            h = _next_step(h, error, stepping.tolerance)
    return False, collapsed, widest, h, h_prev


@njit(cache=True, fastmath=FAST, inline="always")
def _step_size(h, t, period, largest):
    """The step from t: ``h`` at most ``largest``, and the cycle's end on a step."""
    h = min(h, largest)
    if t + h > period - 1e-9 * period:
        return period - t
    if t + 2.0 * h > period:
        return 0.5 * (period - t)  # two even steps rather than a sliver at the cycle's end
    return h


@njit(cache=True, fastmath=FAST, inline="always")
def _step(cycle, grid, control, work, state, t, h, h_prev, widest):
    """The time step h from t, in place: predicted (:func:`_predict`) and balanced by :func:`balance_step` from
    the prediction, or, where that finds no balance at a step of ``stepping.leap`` or shorter, by the crossing
    search (:func:`_cross`). Returns (balance_step's outcome, whether the journal crossed, the change of the
    centre from its prediction per film left (at least the limit's))."""
    tol, limit = control.newton, control.limit
    trial = state.trial
    c_time = _predict(state, grid, h, h_prev, limit)
    trial[0] = state.guess[0]
    trial[1] = state.guess[1]
    _at(cycle.loads, cycle.tau, t + h, state.target)
    _at(cycle.slope, cycle.tau, t + h, state.tilt)
    balance = Balance(state.tilt, state.history, c_time, state.target, state.scale)
    done = balance_step(state.phi, trial, balance, grid, tol, limit, work)
    state.counts[1] += done if done >= 0 else tol.iterations
    jumped = False
    if done == -1 and h <= control.stepping.leap:
        # no balance near the prediction at a short step: the journal crosses to where the film carries
        done = _cross(cycle.tau, t + h, balance, grid, control, work, state)
        jumped = done != -1
        state.counts[2] += 1
    film_left = max(1.0 - max(widest, math.hypot(trial[0], trial[1])), 1.0 - limit)
    error = math.hypot(trial[0] - state.guess[0], trial[1] - state.guess[1]) / film_left
    return done, jumped, error


@njit(cache=True, fastmath=FAST, inline="always")
def _predict(state, grid, h, h_prev, limit):
    """The predictor of a step h after one of h_prev, in ``state``: BDF2's history term of the content
    (backward Euler at the first step), the centre extrapolated from the last two (held within ``limit``) as
    ``guess``, and the field, saved first, extrapolated as the centre is (Newton then needs fewer iterations).
    Returns BDF2's rate coefficient c_time."""
    n_t, n_z = state.phi.shape
    xi, xi_old, guess = state.centre, state.centre_old, state.guess
    later = state.counts[0] >= 1
    r = h / h_prev if later else 0.0
    if later:
        a0 = (1.0 + 2.0 * r) / (1.0 + r)
        a1 = 1.0 + r
        a2 = r * r / (1.0 + r)
        c_time = 12.0 * a0 / h
        for i in range(n_t):
            for j in range(n_z):
                state.history[i, j] = 12.0 * (a1 * state.content[i, j] - a2 * state.content_old[i, j]) / h
        guess[0] = xi[0] + r * (xi[0] - xi_old[0])
        guess[1] = xi[1] + r * (xi[1] - xi_old[1])
    else:
        c_time = 12.0 / h
        for i in range(n_t):
            for j in range(n_z):
                state.history[i, j] = 12.0 * state.content[i, j] / h
        guess[0] = xi[0]
        guess[1] = xi[1]
    e = math.hypot(guess[0], guess[1])
    if e > limit:
        guess[0] *= limit / e
        guess[1] *= limit / e
    phi = state.phi
    state.saved[:, :] = phi
    if later:
        for i in range(n_t):
            for j in range(n_z):
                if not grid.fixed[i, j]:
                    phi[i, j] += r * (phi[i, j] - state.old[i, j])
    return c_time


@njit(cache=True, fastmath=FAST, inline="always")
def _cross(tau, t, balance, grid, control, work, state):
    """The balance at time t of a journal that crosses the clearance, in place: first where the track puts it at
    t (the guide, then the last cycle's orbit) if a field solved there with the centre held is balanced, and
    Newton from there then finds a balance, not a centre pushed onto the wall (the leap decides that); else
    leaps from the last centre, Levenberg-Marquardt's, then Newton's (:func:`leap`). Returns as
    :func:`balance_step`."""
    tol, limit = control.newton, control.limit
    phi, trial = state.phi, state.trial
    phi[:, :] = state.saved
    _at(state.track, tau, t, trial)
    done = -1
    if balance_step(phi, trial, balance, grid, tol, limit, work, False) >= 0:
        done = max(balance_step(phi, trial, balance, grid, tol, limit, work), -1)
    for damped in (True, False):
        if done != -1:
            break
        phi[:, :] = state.saved
        trial[0] = state.centre[0]
        trial[1] = state.centre[1]
        done = leap(phi, trial, balance, grid, tol, limit, work, damped)
    return done


@njit(cache=True, fastmath=FAST, inline="always")
def _rejected(done, jumped, later, error, h, stepping):
    """Whether a step is redone shorter: its Newton failed, or (but after a crossing, at the first step and at the
    smallest) its centre is further from its prediction than three times the tolerance."""
    return done == -1 or (not jumped and later and error > 3.0 * stepping.tolerance and h > stepping.smallest)


@njit(cache=True, fastmath=FAST, inline="always")
def _next_step(h, error, tolerance):
    """The step after one of h whose centre was ``error`` from its prediction: the error per step grows as h^2,
    the step by half to twice."""
    factor_h = 2.0 if error <= 0.0 else min(2.0, max(0.5, 0.9 * math.sqrt(tolerance / error)))
    return h * factor_h


@njit(cache=True, fastmath=FAST, inline="always")
def _take(state, jumped, grid, work):
    """The step is taken: its field (after a crossing, as solved: it does not extrapolate), content, centre and
    outputs become the march's (balance_step leaves the film at the centre)."""
    n_t, n_z = state.phi.shape
    state.old[:, :] = state.phi if jumped else state.saved
    state.content_old[:, :] = state.content
    for i in range(n_t):
        for j in range(n_z):
            state.content[i, j] = work.fill[i, j] * work.h[i, j]
    state.centre_old[0] = state.centre[0]
    state.centre_old[1] = state.centre[1]
    state.centre[0] = state.trial[0]
    state.centre[1] = state.trial[1]
    state.outputs_old[:] = state.outputs
    state.outputs[0], state.outputs[1], state.outputs[2] = outputs(work.pressure, work.fill, work.h, grid)


@njit(cache=True, fastmath=FAST, inline="always")
def _record(tau, t, h, state, k_next, out):
    """The centre and outputs at the times given within the step h from t (from ``k_next`` on), linear between
    the step's ends, into ``out`` = (record, outs). Returns the next time to record."""
    record, outs = out
    xi, xi_old = state.centre, state.centre_old
    n = record.shape[0]
    t_new = t + h
    while k_next < n and tau[k_next] <= t_new + 1e-12:
        u = (tau[k_next] - t) / h
        record[k_next, 0] = (1.0 - u) * xi_old[0] + u * xi[0]
        record[k_next, 1] = (1.0 - u) * xi_old[1] + u * xi[1]
        for q in range(3):
            outs[k_next, q] = (1.0 - u) * state.outputs_old[q] + u * state.outputs[q]
        k_next += 1
    return k_next
