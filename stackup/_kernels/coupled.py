r"""The crankshaft's support moments over the cycle, all main bearings together (numba).

The readable statement is in :mod:`stackup.film.coupled`; ``tests/film/test_coupled.py``
holds the numpy twins these kernels must match. Dimensionless as
:mod:`stackup._kernels.tilt`: journal centre :math:`\boldsymbol\xi` and edge offset
:math:`\mathbf e = \boldsymbol\gamma L/(2c)` in clearances, squeeze velocity in :math:`c\omega`,
time :math:`\tau = \omega t` (the crankshaft's angle, rad), force per :math:`\mu\omega R L^3/c^2`, moment per
:math:`\mu\omega R L^4/c^2`, pressure per :math:`\mu\omega L^2/c^2`.

Per bearing and solved crank angle the unknowns are the journal centre's move
:math:`\boldsymbol\delta` from the film tier's untilted orbit and the edge offset
:math:`\mathbf e`; the equations are the film's force (the orbit's load, :func:`bearing_load`
at no tilt) and the turn-back of every bearing by all the films' moments.

Asperity contact on the elastic layer (:func:`contact_moment`): the rigid film
:math:`\bar h_r(\theta, \zeta) = 1 - \boldsymbol\xi\cdot\mathbf n - \zeta\,\mathbf e\cdot\mathbf n`
becomes, through the layer's table (:func:`stackup.contact.layer_contact`), the film
:math:`\bar h` and the asperity pressure :math:`\bar p_c`; over the patch where the
rigid film is below the table's top,

.. math:: \bar{\mathbf F}_c = \tfrac12\oint\mathbf n\int\bar p_c\,d\zeta\,d\theta, \qquad
          \bar{\mathbf M}_c = \tfrac14\oint\mathbf n\int\bar p_c\,\zeta\,d\zeta\,d\theta

by Gauss-Legendre over the arc about the thinner edge and over the part of each
line below the top.
"""

import math
from collections import namedtuple

import numpy as np
from numba import njit, prange

from .mobility import Correction, bearing_table, table_lookup
from .tilt import Quadrature, squeeze_moment, wall_room  # noqa: F401 (Quadrature: the packed rule's layout)

#: The elastic layer's table in units of the composite roughness sigma: rigid film h_r/sigma on a uniform grid
#: (first value ``lo``, spacing ``step``) -> film h/sigma and asperity pressure [Pa].
Layer = namedtuple("Layer", ("lo", "step", "film", "pressure"))
#: Gauss-Legendre nodes and weights on [-1, 1] of the contact patch: around the bearing and along a line.
ContactRule = namedtuple("ContactRule", ("nodes", "weights", "nodes_axial", "weights_axial"))
#: The engines' mid-plane orbits without tilt: xi, v (E, B, n, 2); free edge offsets (E, B, n, 2); compliance
#: between the bearings per plane kappa (E, 2, B, B) (edge offset of j per unit film moment of i); per bearing
#: (E, B): sigma/c and the pressure unit c^2 / (mu omega L^2); L/D (E, B).
Engines = namedtuple("Engines", ("xi", "v", "free", "kappa", "roughness", "pressure_unit", "ld"))
#: Unknowns per bearing: the journal centre's move from the orbit (2) and the edge offset (2), in clearances.
UNKNOWNS = 4
#: The time march: the crankshaft's angle per crank-angle sample [rad], the stride, the most cycles, the Newton
#: tolerance (a share of the thinnest film), the most chord iterations, the eccentricity limit and the periodicity
#: tolerance (a share of the thinnest film).
March = namedtuple("March", ("dtau", "stride", "cycles", "tolerance", "chords", "limit", "periodic"))
#: States of a bearing's march: periodic, not periodic within the cycles, a step whose Newton failed.
PERIODIC, NOT_PERIODIC, FAILED = 0, 1, 2
#: Newton's tolerance is a share of the thinnest film but at least of this film [c]; a step also converges where
#: the residual (an edge offset too) is below RESIDUAL times that tolerance (the film's moment is smooth only to
#: its quadrature's accuracy: the residual stalls there, in deep asperity contact near 1e-4 c).
FILM_FLOOR = 0.05
RESIDUAL = 10.0
#: Halvings of a Newton step, and steps taken although they do not lower the residual.
HALVINGS = 8
UPHILL = 3
#: A Newton step's outcome: no root, the root within the tolerance, and a step shorter than the tolerance whose
#: full Newton step on a matrix differenced where it ends stayed longer than the tolerance after RETESTS such
#: short steps in all (the balance not resolved; near the wall, where the film's moment stops growing with the
#: tilt, Newton's matrix is nearly singular in the turn-back rows and the iterates wander by about a hundredth of
#: the clearance). A step that fails after a short one fails: the caller's fallbacks (from the last state, in
#: sub-steps) resolve more of those than keeping the short step's point does (it broke the mirror symmetry of
#: the heavy diesel's bearings 2 and 4 by 0.08 um).
FAILED_STEP, RESOLVED, UNRESOLVED = 0, 1, 2
RETESTS = 2


@njit(cache=True, inline="always")
def layer_lookup(rigid, layer):
    """(film, pressure) of the layer's table at the rigid film ``rigid`` [sigma]: linear between its points,
    the last segment's slope beyond the bottom, no contact above the top."""
    lo, step, film, pressure = layer
    n = film.shape[0]
    t = (rigid - lo) / step
    if t >= n - 1:
        return rigid, 0.0
    if t < 0.0:
        i = 0
    else:
        i = int(t)
    w = t - i
    return film[i] + w * (film[i + 1] - film[i]), pressure[i] + w * (pressure[i + 1] - pressure[i])


@njit(cache=True)
def contact_moment(x0, x1, e0, e1, roughness, pressure_unit, layer, rule):
    """Asperity force and moment (F0, F1, M0, M1) on the bearing, dimensionless (module docstring).

    ``roughness``: sigma / c; ``pressure_unit``: c^2 / (mu omega L^2) [1/Pa]; ``layer``: :data:`Layer`;
    ``rule``: :data:`ContactRule`.
    """
    top = (layer.lo + layer.step * (layer.film.shape[0] - 1)) * roughness  # the table's top [c]
    rp = math.hypot(x0 + e0, x1 + e1)
    rm = math.hypot(x0 - e0, x1 - e1)
    r = max(rp, rm)
    if 1.0 - r >= top or r == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    c0, c1 = (x0 + e0, x1 + e1) if rp >= rm else (x0 - e0, x1 - e1)
    centre = math.atan2(c1, c0)
    span = math.acos(min(1.0, max(-1.0, (1.0 - top) / r)))
    f0 = f1 = m0 = m1 = 0.0
    for i in range(rule.nodes.shape[0]):
        theta = centre + span * rule.nodes[i]
        n0 = math.cos(theta)
        n1 = math.sin(theta)
        h0 = 1.0 - x0 * n0 - x1 * n1
        g = e0 * n0 + e1 * n1
        # the part of the line [-1, 1] whose rigid film h0 - g zeta is below the top
        if g > 0.0:
            za, zb = max(-1.0, (h0 - top) / g), 1.0
        elif g < 0.0:
            za, zb = -1.0, min(1.0, (h0 - top) / g)
        elif h0 < top:
            za, zb = -1.0, 1.0
        else:
            continue
        if zb <= za:
            continue
        half = 0.5 * (zb - za)
        mid = 0.5 * (zb + za)
        p0 = p1 = 0.0
        for j in range(rule.nodes_axial.shape[0]):
            zeta = mid + half * rule.nodes_axial[j]
            _, p = layer_lookup((h0 - g * zeta) / roughness, layer)
            w = rule.weights_axial[j] * half * p
            p0 += w
            p1 += w * zeta
        w = span * rule.weights[i] * pressure_unit
        f0 += w * p0 * n0
        f1 += w * p0 * n1
        m0 += w * p1 * n0
        m1 += w * p1 * n1
    return 0.5 * f0, 0.5 * f1, 0.25 * m0, 0.25 * m1


@njit(cache=True, inline="always")
def surface_film(x0, x1, e0, e1, roughness, layer):
    """Thinnest film over the bearing surface [c]: the layer's film at the thinnest rigid film (an edge)."""
    rigid = 1.0 - max(math.hypot(x0 + e0, x1 + e1), math.hypot(x0 - e0, x1 - e1))
    film, _ = layer_lookup(rigid / roughness, layer)
    return film * roughness


@njit(cache=True)
def bearing_load(x0, x1, v0, v1, e0, e1, u0, u1, correction, roughness, pressure_unit, layer, quadrature, rule,
                 limit):
    """Force and moment (F0, F1, M0, M1) of the film and the asperities on one bearing, dimensionless.

    The film's (:func:`stackup._kernels.tilt.squeeze_moment`, tilt squeeze ``u``) with the centre held
    inside the eccentricity ``limit`` and the edge offset whose thinnest edge film is the rigid one where
    that is above the limit film :math:`f = 1 - \text{limit}`, and :math:`f/(2 - h_r/f)` below it
    (continuous with its slope, as the transient tier closes its film: the film's force and moment keep
    growing, slowly, where the asperities on the layer carry the rest), scaled and turned by ``correction``
    (ratio, cosine, sine of the turn); plus the asperities' on the layer at the unheld centre and tilt.
    """
    floor = 1.0 - limit
    r = math.hypot(x0, x1)
    y0, y1 = x0, x1
    if r > limit:
        y0, y1 = x0 * limit / r, x1 * limit / r
    rigid = 1.0 - max(math.hypot(y0 + e0, y1 + e1), math.hypot(y0 - e0, y1 - e1))
    held = 1.0
    if rigid < floor:
        film = floor / (2.0 - rigid / floor)
        held = min(1.0, wall_room(y0, y1, 0.0, 0.0, e0, e1, 1.0 - film))
    f0, f1, m0, m1 = squeeze_moment(y0, y1, v0, v1, held * e0, held * e1, u0, u1, quadrature)
    ratio, ct, st = correction
    a0, a1, c0, c1 = contact_moment(x0, x1, e0, e1, roughness, pressure_unit, layer, rule)
    return (ratio * (ct * f0 - st * f1) + a0, ratio * (st * f0 + ct * f1) + a1,
            ratio * (ct * m0 - st * m1) + c0, ratio * (st * m0 + ct * m1) + c1)


@njit(cache=True)
def _all_loads(g, k, z, before, dtau, quasi, corrections, layer, quadrature, rule, limit, out):
    """Force and moment (B, 4) into ``out`` of engine ``g`` at angle ``k`` with unknowns ``z`` (B, 4): centre move
    and edge offset; their squeeze from ``before`` over ``dtau`` (``quasi``: both held, only turning with the
    film's mean speed). The centre's squeeze velocity is the orbit's plus its move's."""
    xi, v, roughness, unit = g.xi, g.v, g.roughness, g.pressure_unit
    for j in range(z.shape[0]):
        d0, d1, e0, e1 = z[j, 0], z[j, 1], z[j, 2], z[j, 3]
        w0 = v[j, k, 0] + 0.5 * d1
        w1 = v[j, k, 1] - 0.5 * d0
        u0 = 0.5 * e1
        u1 = -0.5 * e0
        if not quasi:
            w0 += (d0 - before[j, 0]) / dtau
            w1 += (d1 - before[j, 1]) / dtau
            u0 += (e0 - before[j, 2]) / dtau
            u1 += (e1 - before[j, 3]) / dtau
        out[j, 0], out[j, 1], out[j, 2], out[j, 3] = bearing_load(
            xi[j, k, 0] + d0, xi[j, k, 1] + d1, w0, w1, e0, e1, u0, u1,
            (corrections[j, k, 0], corrections[j, k, 1], corrections[j, k, 2]), roughness[j], unit[j], layer,
            quadrature, rule, limit)


@njit(cache=True)
def _residual(g, k, z, loads, target, out):
    """Per bearing (B, 4) into ``out``: the force's excess over the orbit's ``target`` (B, n, 2), per
    1 + |target|; then e - free + kappa M per plane."""
    kappa, free = g.kappa, g.free
    b_n = z.shape[0]
    for j in range(b_n):
        size = 1.0 + math.hypot(target[j, k, 0], target[j, k, 1])
        for c in range(2):
            out[j, c] = (loads[j, c] - target[j, k, c]) / size
            s = z[j, 2 + c] - free[j, k, c]
            for i in range(b_n):
                s += kappa[c, j, i] * loads[i, 2 + c]
            out[j, 2 + c] = s


@njit(cache=True, inline="always")
def _rigid_film(g, k, z, j):
    """Thinnest rigid film over bearing j's width at angle k [c]."""
    x0 = g.xi[j, k, 0] + z[j, 0]
    x1 = g.xi[j, k, 1] + z[j, 1]
    return 1.0 - max(math.hypot(x0 + z[j, 2], x1 + z[j, 3]), math.hypot(x0 - z[j, 2], x1 - z[j, 3]))


@njit(cache=True)
def _jacobian(g, k, z, before, dtau, quasi, corrections, layer, quadrature, rule, limit, target, loads, jac):
    """Newton matrix (4B, 4B) into ``jac``, each bearing's own derivatives by forward differences: the force rows
    dF_j/dz_j per 1 + |target|, the turn-back rows I + kappa dM/dz."""
    b_n = z.shape[0]
    trial = z.copy()
    shifted = np.empty((b_n, UNKNOWNS))
    local = np.empty((b_n, UNKNOWNS, UNKNOWNS))
    for d in range(UNKNOWNS):
        for j in range(b_n):
            trial[j, d] = z[j, d] + 1e-6 + 1e-4 * abs(_rigid_film(g, k, z, j))
        _all_loads(g, k, trial, before, dtau, quasi, corrections, layer, quadrature, rule, limit, shifted)
        for j in range(b_n):
            h = trial[j, d] - z[j, d]
            for c in range(UNKNOWNS):
                local[j, c, d] = (shifted[j, c] - loads[j, c]) / h
            trial[j, d] = z[j, d]
    jac[:] = 0.0
    for j in range(b_n):
        size = 1.0 + math.hypot(target[j, k, 0], target[j, k, 1])
        for c in range(2):
            for d in range(UNKNOWNS):
                jac[UNKNOWNS * j + c, UNKNOWNS * j + d] = local[j, c, d] / size
            jac[UNKNOWNS * j + 2 + c, UNKNOWNS * j + 2 + c] = 1.0
            for i in range(b_n):
                for d in range(UNKNOWNS):
                    jac[UNKNOWNS * j + 2 + c, UNKNOWNS * i + d] += g.kappa[c, j, i] * local[i, 2 + c, d]


@njit(cache=True)
def _thinnest(g, k, z):
    """Thinnest rigid film over the bearings at angle k [c] (the Newton tolerance's scale)."""
    out = 1.0
    for j in range(z.shape[0]):
        out = min(out, _rigid_film(g, k, z, j))
    return out


@njit(cache=True)
def step(g, k, guess, before, dtau, quasi, corrections, target, layer, quadrature, rule, march, jac, fresh):
    """Unknowns (B, 4) of engine ``g``'s bearings at angle ``k``: Newton on the force and the turn-back.

    Chord iterations on the Newton matrix ``jac`` (kept from the last step where ``fresh``), the matrix
    differenced again where an iteration lowers the residual by less than a factor of four. Each iteration:
    Newton's step (:func:`_newton_step`), taken whole where it is within the tolerance on a matrix differenced
    where it starts, else halved until the residual falls (:func:`_backtrack`). Returns (z, outcome,
    evaluations), the outcome one of FAILED_STEP, RESOLVED, UNRESOLVED.
    """
    b_n = guess.shape[0]
    z = guess.copy()
    model = (before, dtau, quasi, corrections, layer, quadrature, rule, march.limit)  # the film loads' inputs
    loads = np.empty((b_n, UNKNOWNS))
    r = np.empty((b_n, UNKNOWNS))
    _all_loads(g, k, z, *model, loads)
    _residual(g, k, z, loads, target, r)
    evaluations = 1
    differenced = False
    if not fresh:
        _jacobian(g, k, z, *model, target, loads, jac)
        evaluations += UNKNOWNS
        differenced = True
    trial = np.empty((b_n, UNKNOWNS))
    r_new = np.empty((b_n, UNKNOWNS))
    uphill = 0
    short = 0
    for _ in range(march.chords):
        found, delta, size = _newton_step(jac, r)
        if not found:
            return z, FAILED_STEP, evaluations  # no Newton step: the caller's fallbacks (the last state, sub-steps)
        scale = march.tolerance * max(abs(_thinnest(g, k, z)), FILM_FLOOR)
        if differenced and size <= scale:
            # the full Newton step on a matrix differenced here is within the tolerance: the root is that near
            # (the residual itself stalls at the film moment's quadrature accuracy in deep asperity contact)
            z[:] = z + delta
            return z, RESOLVED, evaluations
        merit = (r * r).sum()
        accepted, t, used = _backtrack(g, k, z, delta, (size, scale, merit), target, model, (trial, loads, r_new))
        evaluations += used
        if accepted:
            z[:] = trial
            r[:] = r_new
            if np.abs(r_new).max() <= RESIDUAL * scale:
                return z, RESOLVED, evaluations
            # a short step, halved or on an old matrix, says nothing of the root: the test is the next full step on
            # a matrix differenced where it ends (the residual in the unknowns' units, Newton's decrement), which
            # near the wall, where the force rows are too stiff for the residual itself to pass at the film
            # quadrature's accuracy, still resolves the films
            if size * t <= scale:
                short += 1
                if short > RETESTS:
                    return z, UNRESOLVED, evaluations
            elif (r_new * r_new).sum() <= 0.0625 * merit:
                differenced = False
                continue  # the chord converges fast enough
        elif differenced:
            # no step along Newton's direction lowers the residual: the film's moment is not monotone in the tilt,
            # so the residual can have a minimum that is not a root; the shortest step is taken all the same
            # (at most UPHILL times), which leaves it
            if uphill == UPHILL:
                return z, FAILED_STEP, evaluations
            uphill += 1
            z[:] = trial
            r[:] = r_new
        else:
            _all_loads(g, k, z, *model, loads)
            evaluations += 1
        # Newton's matrix again, at the point reached (its loads in ``loads``)
        _jacobian(g, k, z, *model, target, loads, jac)
        evaluations += UNKNOWNS
        differenced = True
    return z, (UNRESOLVED if short else FAILED_STEP), evaluations


@njit(cache=True)
def _newton_step(jac, r):
    """Newton's step -jac^-1 r (B, 4) for the residual r (B, 4) and its largest component: (found, step, size).
    Not found where the matrix or the residual is not a number (a film force not a number), or the matrix is
    singular (a bearing whose film neither moves nor turns with its unknowns) or nearly so (a step not finite)."""
    b_n = r.shape[0]
    if not (np.isfinite(jac).all() and np.isfinite(r).all()):
        return False, r, 0.0
    solved = True
    try:
        delta = np.linalg.solve(jac, -r.reshape(UNKNOWNS * b_n)).reshape(b_n, UNKNOWNS)
    except Exception:  # noqa: BLE001 (numba catches no narrower class)
        solved = False
    if not solved:
        return False, r, 0.0
    size = np.abs(delta).max()
    return np.isfinite(size), delta, size


@njit(cache=True)
def _backtrack(g, k, z, delta, reach, target, model, out):
    """Newton's step ``delta`` from ``z`` halved at most :data:`HALVINGS` times until the residual's sum of squares
    falls by Armijo's share below the merit, or the step is within the tolerance: ``reach`` = (the step's size, the
    tolerance, the merit); ``model``: the film loads' inputs after the unknowns (:func:`_all_loads`). Writes the
    last point tried, its loads and residual into ``out`` = (trial, loads, r_new). Returns (accepted, the step's
    share taken, film loads computed)."""
    size, scale, merit = reach
    trial, loads, r_new = out
    t = 1.0
    used = 0
    for _ in range(HALVINGS):
        trial[:] = z + t * delta
        _all_loads(g, k, trial, *model, loads)
        used += 1
        _residual(g, k, trial, loads, target, r_new)
        if (r_new * r_new).sum() <= (1.0 - 1e-4 * t) * merit or size * t <= scale:
            return True, t, used
        t *= 0.5
    return False, t, used


@njit(cache=True)
def _corrections(g, correction, ld, limit, out):
    """Finite correction (ratio, cosine, sine of the turn) per bearing and angle into ``out`` (B, n, 3)."""
    tables, ld_nodes, stretched, finite = correction
    for j in range(g.xi.shape[0]):
        table = bearing_table(Correction(tables, ld_nodes, stretched, finite), ld[j])
        for k in range(g.xi.shape[1]):
            out[j, k, 0] = 1.0
            out[j, k, 1] = 1.0
            out[j, k, 2] = 0.0
            if finite:
                x0, x1 = g.xi[j, k, 0], g.xi[j, k, 1]
                alpha = math.atan2(g.v[j, k, 1], g.v[j, k, 0]) - math.atan2(x1, x0)
                alpha = math.atan2(math.sin(alpha), math.cos(alpha))
                log_ratio, turn, _, _, _ = table_lookup(table, stretched, min(math.hypot(x0, x1), limit), alpha)
                out[j, k, 0] = math.exp(log_ratio)
                out[j, k, 1] = math.cos(turn)
                out[j, k, 2] = math.sin(turn)


@njit(cache=True)
def _targets(g, corrections, layer, quadrature, rule, limit, out):
    """The force (B, n, 2) of the film on the orbit without tilt or centre move: the load the tilted journal's
    film must carry (the same film model on both sides, so that no tilt leaves the orbit where it is)."""
    for j in range(g.xi.shape[0]):
        for k in range(g.xi.shape[1]):
            f0, f1, _, _ = bearing_load(g.xi[j, k, 0], g.xi[j, k, 1], g.v[j, k, 0], g.v[j, k, 1], 0.0, 0.0, 0.0, 0.0,
                                        (corrections[j, k, 0], corrections[j, k, 1], corrections[j, k, 2]),
                                        g.roughness[j], g.pressure_unit[j], layer, quadrature, rule, limit)
            out[j, k, 0] = f0
            out[j, k, 1] = f1


#: Sub-steps tried, in turn, where Newton fails over a whole step (the tilt moving fast as an edge closes in).
SUBSTEPS = (4, 16, 64)


@njit(cache=True)
def _mix(a, kp, k, w):
    """``a[:, kp]`` and ``a[:, k]`` mixed, (1 - w) and w, as one angle: (B, 1, ...)."""
    out = np.empty((a.shape[0], 1, a.shape[2]))
    for j in range(a.shape[0]):
        for c in range(a.shape[2]):
            out[j, 0, c] = (1.0 - w) * a[j, kp, c] + w * a[j, k, c]
    return out


@njit(cache=True, inline="always")
def _guess(g, k, kp, z, out):
    """Unknowns at angle k from those ``z`` at kp: the centre's move kept, the turn-back (free minus tilt) kept."""
    for j in range(z.shape[0]):
        out[j, 0] = z[j, 0]
        out[j, 1] = z[j, 1]
        for c in range(2):
            out[j, 2 + c] = g.free[j, k, c] - (g.free[j, kp, c] - z[j, 2 + c])


@njit(cache=True)
def substeps(g, kp, k, z, dtau, corrections, layer, quadrature, rule, march, parts):
    """Unknowns at angle ``k`` from those ``z`` at ``kp``, in ``parts`` backward-Euler sub-steps over the orbit,
    free tilt and correction interpolated linearly between the two angles, the target the film's force on
    that orbit. Returns (z, outcome, evaluations): the worst sub-step's outcome."""
    b_n = z.shape[0]
    jac = np.eye(UNKNOWNS * b_n)
    count = 0
    worst = RESOLVED
    guess = np.empty((b_n, UNKNOWNS))
    for m in range(1, parts + 1):
        w = m / parts
        one = Engines(_mix(g.xi, kp, k, w), _mix(g.v, kp, k, w), _mix(g.free, kp, k, w), g.kappa, g.roughness,
                      g.pressure_unit, g.ld)
        mixed = _mix(corrections, kp, k, w)
        aim = np.empty((b_n, 1, 2))
        _targets(one, mixed, layer, quadrature, rule, march.limit, aim)  # the film's force at the mixed orbit
        before_free = _mix(g.free, kp, k, (m - 1) / parts)
        for j in range(b_n):
            guess[j, 0] = z[j, 0]
            guess[j, 1] = z[j, 1]
            for c in range(2):
                guess[j, 2 + c] = one.free[j, 0, c] - (before_free[j, 0, c] - z[j, 2 + c])
        new, ok, used = step(one, 0, guess, z, dtau / parts, False, mixed, aim, layer, quadrature, rule, march, jac,
                             False)
        count += used
        if not ok:
            new, ok, used = step(one, 0, z, z, dtau / parts, False, mixed, aim, layer, quadrature, rule, march, jac,
                                 False)
            count += used
        if not ok:
            return z, FAILED_STEP, count
        worst = max(worst, ok)
        z = new
    return z, worst, count


@njit(cache=True)
def _advance(g, kp, k, z, dtau, corrections, target, layer, quadrature, rule, march, jac, fresh):
    """Unknowns at solved angle ``k`` from those ``z`` at ``kp``: Newton from the guess, from ``z``, then
    in sub-steps. Returns (z, outcome, evaluations)."""
    guess = np.empty_like(z)
    _guess(g, k, kp, z, guess)
    new, ok, count = step(g, k, guess, z, dtau, False, corrections, target, layer, quadrature, rule, march, jac,
                          fresh)
    if not ok:
        # the residual is not monotone (the film's squeeze moment peaks where the edge film runs out): from the
        # last state, which the squeeze holds the journal near, Newton reaches the root
        new, ok, used = step(g, k, z, z, dtau, False, corrections, target, layer, quadrature, rule, march, jac,
                             False)
        count += used
    for parts in SUBSTEPS:
        if ok:
            break
        new, ok, used = substeps(g, kp, k, z, dtau, corrections, layer, quadrature, rule, march, parts)
        count += used
    return new, ok, count


@njit(cache=True)
def march_engine(g, correction, layer, quadrature, rule, march, tilt, shift, film, state, evaluations, unresolved):
    """One engine's centres and support moments over the cycle: backward Euler in the centre's move and the tilt
    (their squeeze) from the quasi-static balance at the first angle, every ``stride``-th angle, cycle after
    cycle until the state returns within the periodicity tolerance; the angles between take the film's
    turn-back (free minus tilt) and the centre's move interpolated.

    Writes the edge offset (B, n, 2) and the centre's move (B, n, 2) [c], the thinnest film over the surface
    (B, n) [c], the state per bearing, the film loads computed (the cost) and the share of the last cycle's solved
    angles whose balance was not resolved (the same for every bearing: they are one system).
    """
    b_n, n = g.xi.shape[0], g.xi.shape[1]
    corrections = np.empty((b_n, n, 3))
    _corrections(g, correction, g.ld, march.limit, corrections)
    target = np.empty((b_n, n, 2))
    _targets(g, corrections, layer, quadrature, rule, march.limit, target)
    stride = march.stride
    solved = np.arange(0, n, stride)
    dtau = march.dtau * stride
    jac = np.eye(UNKNOWNS * b_n)
    z = np.zeros((b_n, UNKNOWNS))
    z, ok, count = step(g, 0, z, z, dtau, True, corrections, target, layer, quadrature, rule, march, jac, False)
    if not np.isfinite(z).all():
        z[:] = 0.0  # a quasi-static start that is not a number: the march starts from the orbit, aligned
    fresh = ok != FAILED_STEP
    status = NOT_PERIODIC
    failed = False
    states = np.zeros((b_n, n, UNKNOWNS))
    loose = 0
    for cycle in range(march.cycles):
        failed = False  # the state of the last cycle, whose tilt is returned
        loose = 0
        first = z.copy()
        states[:, 0, :] = z
        for s in range(1, solved.shape[0]):
            z, ok, used = _advance(g, solved[s - 1], solved[s], z, dtau, corrections, target, layer, quadrature, rule,
                                   march, jac, fresh)
            count += used
            failed = failed or not ok
            loose += ok == UNRESOLVED
            fresh = ok != FAILED_STEP
            states[:, solved[s], :] = z
        # periodic: the state after a cycle against the state a cycle before, within a share of the thinnest film;
        # the closing step spans the angles from the last solved one round to the first
        last = solved[solved.shape[0] - 1]
        z, ok, used = _advance(g, last, 0, z, march.dtau * (n - last), corrections, target, layer, quadrature,
                               rule, march, jac, fresh)
        count += used
        failed = failed or not ok
        loose += ok == UNRESOLVED
        fresh = ok != FAILED_STEP
        gap = np.abs(z - first).max()
        states[:, 0, :] = z
        if gap <= march.periodic * max(abs(_thinnest(g, 0, z)), FILM_FLOOR):
            status = PERIODIC
            break
    # the angles between the solved ones: the turn-back and the centre's move interpolated
    for s in range(solved.shape[0]):
        k = solved[s]
        kn = solved[s + 1] if s + 1 < solved.shape[0] else n
        kk = kn if kn < n else 0
        for m in range(k + 1, kn):
            w = (m - k) / (kn - k)
            for j in range(b_n):
                for c in range(2):
                    states[j, m, c] = (1.0 - w) * states[j, k, c] + w * states[j, kk, c]
                    back = (1.0 - w) * (g.free[j, k, c] - states[j, k, 2 + c]) + w * (
                        g.free[j, kk, c] - states[j, kk, 2 + c])
                    states[j, m, 2 + c] = g.free[j, m, c] - back
    for j in range(b_n):
        state[j] = FAILED if failed else status
        evaluations[j] = count
        unresolved[j] = loose / solved.shape[0]
        for k in range(n):
            shift[j, k, 0] = states[j, k, 0]
            shift[j, k, 1] = states[j, k, 1]
            tilt[j, k, 0] = states[j, k, 2]
            tilt[j, k, 1] = states[j, k, 3]
            film[j, k] = surface_film(g.xi[j, k, 0] + states[j, k, 0], g.xi[j, k, 1] + states[j, k, 1],
                                      states[j, k, 2], states[j, k, 3], g.roughness[j], layer)


@njit(cache=True, parallel=True)
def march_engines(engines, correction, layer, quadrature, rule, march, tilt, shift, film, state, evaluations,
                  unresolved):
    """:func:`march_engine` for every engine (prange over engines): tilt and shift (E, B, n, 2), film (E, B, n),
    state, evaluations and unresolved (E, B)."""
    # numba's parallel loop takes arrays and numbers, not tuples holding arrays: the packed inputs are taken apart
    # here and put together again in the loop
    xi, v, free, kappa, roughness, unit, ld = engines
    tables, ld_nodes, stretched, finite = correction
    lo, step_, table_film, table_pressure = layer
    nodes, weights, nodes_dry, weights_dry, cap = quadrature
    c_nodes, c_weights, a_nodes, a_weights = rule
    dtau, stride, cycles, tolerance, chords, limit, periodic = march
    for g in prange(xi.shape[0]):
        one = Engines(xi[g], v[g], free[g], kappa[g], roughness[g], unit[g], ld[g])
        march_engine(one, Correction(tables, ld_nodes, stretched, finite), Layer(lo, step_, table_film, table_pressure),
                     Quadrature(nodes, weights, nodes_dry, weights_dry, cap),
                     ContactRule(c_nodes, c_weights, a_nodes, a_weights),
                     March(dtau, stride, cycles, tolerance, chords, limit, periodic), tilt[g], shift[g], film[g],
                     state[g], evaluations[g], unresolved[g])
