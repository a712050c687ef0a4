r"""The crankshaft as a continuous Euler-Bernoulli beam on N+1 supports, condensed to the supports.

Spans :math:`l_i` with bending stiffness :math:`EI_i` per plane carry a point
load each at a fraction :math:`a_i` of the span. With two cubic beam elements
per span (exact for point loads) and the support deflections :math:`w` kept,
static condensation of every rotation and load-point deflection gives

.. math:: K_b\,w = T\,P + S

with :math:`K_b` the (N+1)x(N+1) stiffness of the free beam against its
support deflections, :math:`T` the (N+1)xN transfer of the span loads to the
supports and :math:`S` the support forces on the beam. :math:`K_b` has the two
rigid-body modes of a free beam (translation, rotation) in its null space, so
the support forces always balance the loads in force and moment. This is the
relation Bellakhdhar et al. write as :math:`A R + B U + C P = 0` (their eqs.
1-3) in condensed stiffness form.

References
----------
.. [1] Bellakhdhar, B., Dogui, A., Ligier, J.-L., C. R. Mecanique 341 (2013) 743-754, sec. 2.
.. [2] Przemieniecki, J. S., *Theory of Matrix Structural Analysis*, McGraw-Hill, 1968 (beam element, condensation).
"""

from __future__ import annotations

import numpy as np


def element_stiffness(length, ei):
    """Cubic Euler-Bernoulli element on (w1, phi1, w2, phi2) [N/m, N, N*m]."""
    l = length
    return ei / l**3 * np.array([
        [12.0, 6.0 * l, -12.0, 6.0 * l],
        [6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l],
        [-12.0, -6.0 * l, 12.0, -6.0 * l],
        [6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l],
    ])


def _assembled(spans, ei, load_positions):
    """Stiffness (2 n_nodes, 2 n_nodes) of one bending plane, nodes support 0, load 0, support 1, ..., and the
    kept (support deflection), load-point deflection and eliminated degrees of freedom."""
    spans = np.asarray(spans, dtype=float)
    n = spans.size
    n_nodes = 2 * n + 1
    k = np.zeros((2 * n_nodes, 2 * n_nodes))
    for i in range(n):
        a = load_positions[i] * spans[i]
        for j, length in enumerate((a, spans[i] - a)):
            first = 2 * i + j
            dofs = [2 * first, 2 * first + 1, 2 * first + 2, 2 * first + 3]
            k[np.ix_(dofs, dofs)] += element_stiffness(length, ei[i])
    kept = np.array([2 * (2 * j) for j in range(n + 1)])  # support deflections
    loads = np.array([2 * (2 * i + 1) for i in range(n)])  # load-point deflections
    gone = np.setdiff1d(np.arange(2 * n_nodes), kept)
    return k, kept, loads, gone


def condensed(spans, ei, load_positions):
    """Support stiffness K_b (N+1, N+1) [N/m] and load transfer T (N+1, N) [-] of one bending plane.

    Nodes: support 0, load 0, support 1, load 1, ..., support N.
    """
    k, kept, loads, gone = _assembled(spans, ei, load_positions)
    k_ee = k[np.ix_(gone, gone)]
    k_re = k[np.ix_(kept, gone)]
    k_b = k[np.ix_(kept, kept)] - k_re @ np.linalg.solve(k_ee, k_re.T)
    select = (gone[:, None] == loads[None, :]).astype(float)
    transfer = -k_re @ np.linalg.solve(k_ee, select)
    return 0.5 * (k_b + k_b.T), transfer


def slope_matrices(spans, ei, load_positions):
    """Support slopes of one bending plane from support deflections and span loads.

    Returns (S_w (N+1, N+1) [1/m], S_p (N+1, N) [1/N]) with the beam's slope
    :math:`dw/dz` at each support :math:`= S_w\\,w + S_p\\,P`: the rotations the
    static condensation of :func:`condensed` eliminated,
    :math:`u_e = K_{ee}^{-1}(F_e - K_{er}\\,w)`, at the support nodes.
    """
    k, kept, loads, gone = _assembled(spans, ei, load_positions)
    n = len(kept) - 1
    k_ee = k[np.ix_(gone, gone)]
    k_er = k[np.ix_(gone, kept)]
    select = (gone[:, None] == loads[None, :]).astype(float)
    rotations = np.searchsorted(gone, [2 * (2 * j) + 1 for j in range(n + 1)])  # support rotation DOFs
    s_w = -np.linalg.solve(k_ee, k_er)[rotations]
    s_p = np.linalg.solve(k_ee, select)[rotations]
    return s_w, s_p


def rotational_compliance(spans, ei, load_positions):
    """Rotation of the beam at each support per unit moment applied at a support, deflections held.

    Returns C (N+1, N+1) [rad/(N m)] of one bending plane: a moment :math:`M_j`
    (conjugate to the slope :math:`dw/dz`) at support j turns support i by
    :math:`C_{ij} M_j` with every support deflection held and no other moment
    applied: the block of :math:`K_{ee}^{-1}` (the degrees of freedom the
    condensation of :func:`condensed` eliminates) at the support rotations.
    Its diagonal is the compliance a bearing's film moment meets; an end
    support of equal spans :math:`l` with uniform :math:`EI` is near
    :math:`l/(3EI)` (the far supports turn freely).
    """
    k, kept, _, gone = _assembled(spans, ei, load_positions)
    k_ee = k[np.ix_(gone, gone)]
    rotations = np.searchsorted(gone, [2 * (2 * j) + 1 for j in range(len(kept))])
    select = np.zeros((gone.size, rotations.size))
    select[rotations, np.arange(rotations.size)] = 1.0
    c = np.linalg.solve(k_ee, select)[rotations]
    return 0.5 * (c + c.T)
