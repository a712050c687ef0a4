"""The crankshaft as a continuous beam on its main bearings: support reactions, slopes and compliance.

Tiers (the ``law`` argument of :func:`reactions`):

- ``None``: rigid supports at the bearing offsets (three-moment equation);
- a number or array [N/m]: linear springs;
- a :class:`~stackup.crank.law.BellakhdharLaw`: the nonlinear law with
  clearance, oil film stiffening and anisotropic deformation stiffness,
  solved by Newton.

See :mod:`stackup.crank.beam` and :mod:`stackup.crank.law` for the equations.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._kernels import crank as _kernel
from .._validate import Finite, Positive, in_range, positive, validated
from .beam import condensed, rotational_compliance, slope_matrices
from .law import REST, BellakhdharLaw

#: Each support tier and its limits in one line, for reports (speed and error: reports/bench_crank.md).
TIER_NOTES = {
    "bearing-law": "continuous beam on the nonlinear bearing law of Bellakhdhar et al. (2013)",
    "linear": "continuous beam on linear springs (the bearing law's low stiffness)",
    "rigid": "continuous beam on rigid supports",
}
#: Status codes of a solve, stored with CF flag attributes (defined with the kernel that sets them).
STATUS = _kernel.STATUS
#: Newton stops when the residual is below this share of the load scale.
RTOL = 1e-10
MAX_ITERATIONS = 200  # a few per angle normally; a kinked (dx = 0) cold start takes many more


@dataclass(frozen=True)
class CrankReactions:
    """Result of :func:`reactions`.

    Attributes
    ----------
    reactions : numpy.ndarray (..., N+1, 2)
        Load each main bearing carries [N] (force of the journal on the bearing).
    displacements : numpy.ndarray (..., N+1, 2)
        Journal centre at each bearing off the straight reference line [m].
    converged : numpy.ndarray of bool (...)
    iterations : numpy.ndarray of int (...)
        Newton iterations (0 for rigid or linear supports).
    status : numpy.ndarray of int8 (...)
        Index into :data:`STATUS`.
    """

    reactions: np.ndarray
    displacements: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    status: np.ndarray


def _spans(field, value):
    """Constraint: one positive length per span (N,)."""
    spans = positive(field, value)
    if spans.ndim != 1:
        raise ValueError(f"{field}: shape {spans.shape} is not valid; give one length per span (N,)")
    return spans


def _beam(values):
    """Relation: EI (N,) or (N, 2) and the span loads inside their spans, for the N spans."""
    n = values["spans"].size
    ei = values["EI"]
    if ei.ndim != 0 and ei.shape != (n,) and ei.shape != (n, 2):
        raise ValueError(f"EI: shape {ei.shape} is not valid; give (N,) or (N, 2) with N = {n} spans")
    if values["load_positions"] is not None:
        in_range("load_positions", np.broadcast_to(values["load_positions"], (n,)), 0.0, 1.0, lo_open=True,
                 hi_open=True)


def _planes(spans, ei, load_positions):
    """(spans, EI per plane (N, 2), load positions (N,)) as tuples, the key of the cached beam matrices."""
    spans = np.asarray(spans, dtype=float)
    n = spans.size
    ei = np.asarray(ei, dtype=float)
    if ei.ndim == 0:
        ei = np.full(n, float(ei))
    if ei.shape == (n,):
        ei = np.stack([ei, ei], axis=-1)
    positions = np.full(n, 0.5) if load_positions is None else np.broadcast_to(
        np.asarray(load_positions, dtype=float), (n,))
    return tuple(spans), tuple(map(tuple, ei)), tuple(positions)


@lru_cache(maxsize=64)
def _condensed_planes(spans, ei, load_positions):
    ei = np.array(ei)
    planes = [condensed(np.array(spans), ei[:, c], np.array(load_positions)) for c in range(2)]
    kb = np.stack([p[0] for p in planes])
    transfer = np.stack([p[1] for p in planes])
    kb.flags.writeable = transfer.flags.writeable = False
    return kb, transfer


def _law(field, law):
    """Constraint: a bearing law, or linear springs' stiffness [N/m] (> 0)."""
    return law if isinstance(law, BellakhdharLaw) else positive(field, law)


def _loads_on_the_beam(values):
    """Relation: span loads (..., N, 2) and support offsets (..., N+1, 2) of the N spans, their leading shapes
    broadcasting together; a bearing law's parameters constant along the sequence axis."""
    n_spans = values["spans"].size
    loads, offsets, law = values["pin_loads"], values["offsets"], values["law"]
    if loads.ndim < 2 or loads.shape[-2:] != (n_spans, 2):
        raise ValueError(f"pin_loads: shape {loads.shape} is not valid; expected (..., {n_spans}, 2)")
    lead = loads.shape[:-2]
    if offsets is not None:
        if offsets.ndim < 2 or offsets.shape[-2:] != (n_spans + 1, 2):
            raise ValueError(f"offsets: shape {offsets.shape} is not valid; expected (..., {n_spans + 1}, 2)")
        try:
            lead = np.broadcast_shapes(lead, offsets.shape[:-2])
        except ValueError:
            raise ValueError(f"offsets: leading shape {offsets.shape[:-2]} does not broadcast with pin_loads "
                             f"{loads.shape[:-2]}") from None
    if isinstance(law, BellakhdharLaw):
        per_sequence = _per_sequence(lead, n_spans)
        try:
            np.stack(law.arrays(per_sequence), axis=-2)
        except ValueError:
            raise ValueError(f"law: parameters must broadcast to {per_sequence}, constant along the sequence "
                             f"axis of pin_loads {loads.shape}") from None


def _per_sequence(lead, n_spans):
    """Shape a bearing law's parameters take: the loads' leading shape with one step along the sequence axis."""
    return (*lead[:-1], 1, n_spans + 1) if lead else (1, n_spans + 1)


@validated(pin_loads=Finite(), spans=_spans, EI=Positive(), offsets=Finite(), law=_law,
           relations=(_beam, _loads_on_the_beam))
def reactions(pin_loads, *, spans, EI, load_positions=None, offsets=None, law=None):  # noqa: N803 (EI is the domain's name)
    """Support reactions of a crankshaft beam on N+1 main bearings.

    Parameters
    ----------
    pin_loads : array_like (..., N, 2)
        Load on each span (crank pin) [N]: component 0 towards the bearing
        caps, component 1 transverse (engine-fixed frame).
    spans : array_like (N,)
        Span lengths between bearing centres [m].
    EI : array_like (N,) or (N, 2)
        Bending stiffness of each span [N m^2], per load component if (N, 2).
    load_positions : array_like (N,), optional
        Position of each load as a fraction of its span, in (0, 1); default 0.5.
    offsets : array_like (..., N+1, 2), optional
        Bearing centres off the straight reference line [m] (misalignment),
        same axes as the loads; default 0.
    law : None, float or array_like, or BellakhdharLaw
        Rigid supports, linear springs [N/m] (per bearing if an array), or the
        nonlinear bearing law (parameters may be arrays per bearing, broadcast
        against ``(..., N+1)`` but constant along the sequence axis, e.g.
        shape ``(engines, 1, N+1)`` for loads ``(engines, angles, N, 2)``).

    Returns
    -------
    CrankReactions

    Notes
    -----
    With the law, each sequence along the axis before ``N`` (e.g. crank
    angle) is solved in order, each step warm-started from the previous two;
    Newton uses the analytic Jacobian, a backtracking line search and, where
    the law has no stiffness (journals at rest in their clearance), a
    stiffness floor on the Newton matrix only, so the solution is unchanged.
    A case that does not converge is marked in ``status``, never silently.
    """
    loads = np.asarray(pin_loads, dtype=float)
    kb, transfer = _condensed_planes(*_planes(spans, EI, load_positions))
    n_spans = kb.shape[1] - 1
    offsets = np.zeros((n_spans + 1, 2)) if offsets is None else np.asarray(offsets, dtype=float)
    lead = np.broadcast_shapes(loads.shape[:-2], offsets.shape[:-2])
    loads = np.broadcast_to(loads, (*lead, n_spans, 2))
    offsets = np.broadcast_to(offsets, (*lead, n_spans + 1, 2))
    if isinstance(law, BellakhdharLaw):
        return _on_the_law(kb, transfer, loads, offsets, law)
    return _on_springs(kb, transfer, loads, offsets, law)


def _on_springs(kb, transfer, loads, offsets, law):
    """Rigid supports (``law`` None) or linear springs [N/m]: one linear solve per bending plane."""
    lead, n = loads.shape[:-2], kb.shape[1]
    f_ext = np.einsum("cpi,...ic->...pc", transfer, loads)
    if law is None:
        w = offsets
        support = np.einsum("cpq,...qc->...pc", kb, w) - f_ext
        result = -support
    else:
        k = np.broadcast_to(np.asarray(law, dtype=float), (*lead, n))
        eye = np.eye(n)
        w = np.empty(offsets.shape)
        for c in range(2):
            matrix = kb[c] + k[..., :, None] * eye
            rhs = f_ext[..., c] + k * offsets[..., c]
            w[..., c] = np.linalg.solve(matrix, rhs[..., None])[..., 0]
        result = k[..., None] * (w - offsets)
    ok = np.ones(lead, bool)
    return CrankReactions(result, np.array(w), ok, np.zeros(lead, np.int32), np.zeros(lead, np.int8))


def _on_the_law(kb, transfer, loads, offsets, law):
    """The bearing law: Newton on each sequence of load cases in the kernel, sequences in parallel."""
    lead, n_spans = loads.shape[:-2], kb.shape[1] - 1
    seq = lead[-1] if lead else 1
    batch = int(np.prod(lead[:-1])) if len(lead) > 1 else 1
    params = np.stack(law.arrays(_per_sequence(lead, n_spans)), axis=-2)  # (..., 1, 6, N+1)
    kernel = _kernel.solve if batch > 1 else _kernel.solve_serial
    r, w, status, iterations = kernel(
        kb, transfer,
        np.ascontiguousarray(loads).reshape(batch, seq, n_spans, 2),
        np.ascontiguousarray(offsets).reshape(batch, seq, n_spans + 1, 2),
        np.ascontiguousarray(params).reshape(batch, 6, n_spans + 1),
        _kernel.Newton(RTOL, MAX_ITERATIONS, REST),
    )
    return CrankReactions(r.reshape(*lead, n_spans + 1, 2), w.reshape(*lead, n_spans + 1, 2),
                          (status == 0).reshape(lead), iterations.reshape(lead), status.reshape(lead))


def _loads_and_deflections(values):
    n = values["spans"].size
    loads, w = values["pin_loads"], values["displacements"]
    if loads.shape[-2:] != (n, 2) or w.shape[-2:] != (n + 1, 2):
        raise ValueError(f"pin_loads {loads.shape} and displacements {w.shape} must end in ({n}, 2) and ({n + 1}, 2)")


@validated(pin_loads=Finite(), displacements=Finite(), spans=Positive(), EI=Positive(),
           relations=(_loads_and_deflections,))
def support_slopes(pin_loads, displacements, *, spans, EI, load_positions=None):  # noqa: N803
    """Slope of the crankshaft at each main bearing [rad] from the beam solution.

    Parameters
    ----------
    pin_loads : array_like (..., N, 2)
        Span loads [N], as given to :func:`reactions`.
    displacements : array_like (..., N+1, 2)
        Journal centres at the bearings [m] (``CrankReactions.displacements``).
    spans, EI, load_positions :
        As :func:`reactions`.

    Returns
    -------
    numpy.ndarray (..., N+1, 2)
        :math:`dw/dz` per load component at each support, z along the crank
        axis from bearing 1 towards bearing N+1: the tilt of the journal axis
        against the straight reference line (and against the bore axes, which
        the line-boring leaves parallel to it), the film's ``tilt``.

    Notes
    -----
    The rotations eliminated by the static condensation of
    :func:`stackup.crank.beam.condensed`, recovered from the deflections and the
    loads (:func:`stackup.crank.beam.slope_matrices`), per bending plane.
    """
    loads = np.asarray(pin_loads, dtype=float)
    w = np.asarray(displacements, dtype=float)
    spans_arr = np.asarray(spans, dtype=float)
    n = spans_arr.size
    ei = np.asarray(EI, dtype=float)
    ei = np.broadcast_to(ei if ei.ndim < 2 else ei, (n,) if ei.ndim < 2 else (n, 2))
    ei = np.stack([ei, ei], axis=-1) if ei.ndim == 1 else ei
    positions = np.full(n, 0.5) if load_positions is None else np.broadcast_to(load_positions, (n,))
    s_w, s_p = _slope_planes(tuple(spans_arr), tuple(map(tuple, ei)), tuple(positions))
    # plane c: s_w[c] w[..., c] + s_p[c] P[..., c], as matrix products (einsum's path search cost more than them)
    return np.stack([w[..., c] @ s_w[c].T + loads[..., c] @ s_p[c].T for c in range(2)], axis=-1)


@lru_cache(maxsize=64)
def _slope_planes(spans, ei, load_positions):
    """:func:`stackup.crank.beam.slope_matrices` of both bending planes, stacked (2, ...); kept for the next call."""
    ei = np.array(ei)
    planes = [slope_matrices(np.array(spans), ei[:, c], np.array(load_positions)) for c in range(2)]
    s_w, s_p = np.stack([p[0] for p in planes]), np.stack([p[1] for p in planes])
    s_w.flags.writeable = s_p.flags.writeable = False
    return s_w, s_p


@validated(spans=_spans, EI=Positive(), relations=(_beam,))
def support_compliance(*, spans, EI, load_positions=None, coupled=False):  # noqa: N803
    r"""Rotational compliance of the crankshaft at its main bearings [rad/(N m)].

    The slope a unit moment applied at a support gives there, per bending plane,
    with every support deflection held (the bearings carry the journal's
    position; the moment of a bearing's film only turns the journal): the
    compliance the film's restoring moment meets in the tilt equilibrium
    :math:`\boldsymbol\gamma = \boldsymbol\gamma_{free} - C\,\mathbf M_{film}`
    (:func:`stackup.film.orbit.orbit`, ``tilt_compliance``).

    Parameters
    ----------
    spans, EI, load_positions :
        As :func:`reactions`.
    coupled : bool
        Return the whole matrix (a moment at one support turns the others
        too) instead of its diagonal.

    Returns
    -------
    numpy.ndarray
        (N+1, 2): the diagonal per load component; with ``coupled``
        (2, N+1, N+1): :math:`C_{ij}`, the slope at support i per unit moment at j.

    Notes
    -----
    :func:`stackup.crank.beam.rotational_compliance`: the support-rotation
    block of the inverse of the stiffness the static condensation eliminates.
    On the built-in engines the neighbour of a loaded support turns by about
    a quarter of its rotation, the other way.
    """
    matrices = _compliance_planes(*_planes(spans, EI, load_positions))
    if coupled:
        return matrices.copy()
    return np.stack([np.diag(m) for m in matrices], axis=-1)


@lru_cache(maxsize=64)
def _compliance_planes(spans, ei, load_positions):
    """:func:`stackup.crank.beam.rotational_compliance` of both bending planes (2, N+1, N+1); kept for the next call."""
    ei = np.array(ei)
    matrices = np.stack([rotational_compliance(np.array(spans), ei[:, c], np.array(load_positions)) for c in range(2)])
    matrices.flags.writeable = False
    return matrices
