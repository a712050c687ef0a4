r"""Reference tier: shell ring and housing ring as two plane-stress rings in contact, by finite elements.

Shares no formula with the closed forms of :mod:`stackup.fit.tiers`: each
ring is meshed radially with quadratic axisymmetric elements (plane stress,
displacement :math:`u(r)`, strains :math:`\varepsilon_r = u'`,
:math:`\varepsilon_\theta = u/r`), thermal growth enters as an eigenstrain
:math:`\alpha\,\Delta T` and contact as a Lagrange multiplier closing the gap
between the shell's outer node and the housing's bore node. The crush check is
solved the same way: the free shell radius is found so that the ring, loaded
by the external pressure that gives the check stress as its mean wall
compression, has an outer periphery :math:`2\pi R_c + 2h`.

Slow (a small linear solve per bearing): the yardstick the fast tiers are
measured against, not a production tier.

References
----------
.. [1] Zienkiewicz, O. C., Taylor, R. L., *The Finite Element Method*, Vol. 1,
   5th ed., Butterworth-Heinemann, 2000, ch. 5 (axisymmetric stress analysis).
"""

from __future__ import annotations

import numpy as np

#: Quadratic elements per ring; 24 keep the contact pressure within 1e-7
#: relative of the converged value (checked in the tests by doubling).
ELEMENTS = 24
_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(3)


def _quadrature(nodes, elements):
    """Gauss points of the quadratic elements: (element dofs, N, dN/dr, r, weight r dr)."""
    for e in range(elements):
        idx = np.arange(2 * e, 2 * e + 3)
        half = 0.5 * (nodes[idx[2]] - nodes[idx[0]])
        for xi, w in zip(_GAUSS_X, _GAUSS_W):
            shape = np.array([0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)])
            dshape = np.array([xi - 0.5, -2.0 * xi, xi + 0.5]) / half
            r = shape @ nodes[idx]
            yield idx, shape, dshape, r, w * half * r


def _plane_stress(modulus, poisson):
    return modulus / (1.0 - poisson**2) * np.array([[1.0, poisson], [poisson, 1.0]])


def _ring(r_in, r_out, modulus, poisson, eigenstrain, elements):
    """Stiffness (per radian, per unit length) and eigenstrain load of a ring; nodes r_in..r_out."""
    nodes = np.linspace(r_in, r_out, 2 * elements + 1)
    k = np.zeros((nodes.size, nodes.size))
    f = np.zeros(nodes.size)
    d = _plane_stress(modulus, poisson)
    for idx, shape, dshape, r, weight in _quadrature(nodes, elements):
        b = np.vstack([dshape, shape / r])
        k[np.ix_(idx, idx)] += weight * b.T @ d @ b
        f[idx] += weight * b.T @ d @ np.array([eigenstrain, eigenstrain])
    return nodes, k, f


def _stresses(nodes, u, modulus, poisson, eigenstrain, elements):
    """Integral of hoop stress over the wall [N/m per unit length] from the nodal displacements."""
    d = _plane_stress(modulus, poisson)
    total = 0.0
    for idx, shape, dshape, r, weight in _quadrature(nodes, elements):
        strain = np.array([dshape @ u[idx], shape @ u[idx] / r]) - eigenstrain
        total += weight / r * (d @ strain)[1]
    return total


def _shell_under_pressure(r0, wall, modulus, poisson, elements):
    """Outer displacement and wall-integrated hoop stress of the shell ring under unit external pressure."""
    nodes, k, _ = _ring(r0 - wall, r0, modulus, poisson, 0.0, elements)
    f = np.zeros(nodes.size)
    f[-1] = -r0  # unit pressure on the outer face, per radian
    u = np.linalg.solve(k, f)
    return u[-1], _stresses(nodes, u, modulus, poisson, 0.0, elements)


def free_radius(check_radius, crush_height, wall, check_stress, modulus, poisson, elements=ELEMENTS):
    """Free outer radius [m] of the shell ring from its crush height, by the FE check model."""
    r0 = check_radius + crush_height / np.pi
    for _ in range(4):
        u_unit, hoop_unit = _shell_under_pressure(r0, wall, modulus, poisson, elements)
        q = check_stress * wall / -hoop_unit  # pressure giving mean compression check_stress
        r0 = check_radius + crush_height / np.pi - q * u_unit
    return r0


def press_fit_one(housing_bore, housing_outer, shell_wall, crush_height, check_bore, check_stress, delta_t,
                  housing, shell, journal_expansion, journal_d, elements=ELEMENTS):
    """One bearing by FE; same arguments and outputs as :func:`stackup.fit.tiers.press_fit` (scalars)."""
    e_h, nu_h, al_h = housing
    e_s, nu_s, al_s = shell
    r0 = free_radius(check_bore / 2, crush_height, shell_wall, check_stress, e_s, nu_s, elements)
    a, b = housing_bore / 2, housing_outer / 2
    eig_h, eig_s = al_h * delta_t, al_s * delta_t
    ns, ks, fs = _ring(r0 - shell_wall, r0, e_s, nu_s, eig_s, elements)
    nh, kh, fh = _ring(a, b, e_h, nu_h, eig_h, elements)
    m, n = ns.size, nh.size

    def solve(contact):
        size = m + n + (1 if contact else 0)
        k = np.zeros((size, size))
        f = np.zeros(size)
        k[:m, :m], k[m:m + n, m:m + n] = ks, kh
        f[:m], f[m:m + n] = fs, fh
        if contact:
            # u_shell(r0) - u_housing(a) = a - r0; the multiplier is the contact force per radian
            k[-1, m - 1], k[-1, m] = 1.0, -1.0
            k[m - 1, -1], k[m, -1] = 1.0, -1.0
            f[-1] = a - r0
        return np.linalg.solve(k, f)

    x = solve(True)
    force = x[-1]  # the shell node feels -force: compressive contact force per radian
    contact = force > 0.0
    if not contact:
        x = solve(False)
    us, uh = x[:m], x[m:m + n]
    p = force / (a * (1.0 + eig_h)) if contact else 0.0  # per unit area of the thermally grown bore
    hoop = _stresses(ns, us, e_s, nu_s, eig_s, elements)
    grown_wall = shell_wall * (1.0 + eig_s)
    if contact:
        shell_bore = 2.0 * (ns[0] + us[0])
    else:  # loose shells follow the bore with their own (thermally grown) wall
        shell_bore = 2.0 * (a + uh[0] - grown_wall)
    out = {
        "contact_pressure": p,
        "shell_stress": -hoop / grown_wall,
        "housing_swell": 2.0 * (uh[0] - eig_h * a),
        "bore_in_service": 2.0 * (a + uh[0]),
        "shell_bore": shell_bore,
        "loss_of_fit": not contact,
    }
    if journal_d is not None:
        out["clearance"] = shell_bore - journal_d * (1.0 + journal_expansion * delta_t)
    return out
