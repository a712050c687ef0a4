r"""Reference tier: shell ring and housing ring as plane-stress rings in contact, by finite elements.

Shares no formula with the closed forms of :mod:`stackup.fit.tiers`: each
ring is meshed radially with quadratic axisymmetric elements (plane stress,
displacement :math:`u(r)`, strains :math:`\varepsilon_r = u'`,
:math:`\varepsilon_\theta = u/r`), thermal growth enters as an eigenstrain
:math:`\alpha\,\Delta T` and contact as a Lagrange multiplier closing the gap
between the shell's outer node and the housing's bore node. A lined shell is
two bonded layers, the lining inside the steel back, each with its own
modulus, Poisson's ratio and expansion (no steel-equivalent section, no
neglected lining expansion: the yardstick of those simplifications). The
crush check is solved the same way: the free shell radius is found so that the
ring, loaded by the external pressure whose hoop force equals the check force
:math:`\sigma_c A_{calc}` per unit width, has an outer periphery
:math:`2\pi R_c + 2h`. Stresses are reported steel-equivalent (hoop force over
the steel-equivalent wall), as the closed forms report them.

Slow (a small linear solve per bearing): the yardstick the fast tiers are
measured against, not a production tier.

References
----------
.. [1] Zienkiewicz, O. C., Taylor, R. L., *The Finite Element Method*, Vol. 1,
   5th ed., Butterworth-Heinemann, 2000, ch. 5 (axisymmetric stress analysis).
"""

from __future__ import annotations

import numpy as np

#: Quadratic elements per ring: enough for a converged contact pressure (the
#: tests double them; the reference's discretisation error is stated in
#: ``reports/press_fit_tiers.md``).
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


def _rings(bounds, layers, elements):
    """Stiffness (per radian, per unit length) and eigenstrain load of bonded rings.

    ``bounds`` are the radii from the inside out, one more than ``layers``,
    each layer a (modulus, poisson, eigenstrain) tuple meshed with
    ``elements`` quadratic elements; neighbouring layers share their
    interface node. Returns (nodes, k, f).
    """
    nodes = np.concatenate([np.linspace(lo, hi, 2 * elements + 1)[(1 if i else 0):]
                            for i, (lo, hi) in enumerate(zip(bounds[:-1], bounds[1:]))])
    k = np.zeros((nodes.size, nodes.size))
    f = np.zeros(nodes.size)
    for e, (idx, shape, dshape, r, weight) in enumerate(_quadrature(nodes, elements * len(layers))):
        modulus, poisson, eigenstrain = layers[e // (3 * elements)]
        d = _plane_stress(modulus, poisson)
        b = np.vstack([dshape, shape / r])
        k[np.ix_(idx, idx)] += weight * b.T @ d @ b
        f[idx] += weight * b.T @ d @ np.array([eigenstrain, eigenstrain])
    return nodes, k, f


def _hoop_force(nodes, u, layers, elements):
    """Integral of hoop stress over the wall [N/m per unit length] from the nodal displacements."""
    total = 0.0
    for e, (idx, shape, dshape, r, weight) in enumerate(_quadrature(nodes, elements * len(layers))):
        modulus, poisson, eigenstrain = layers[e // (3 * elements)]
        strain = np.array([dshape @ u[idx], shape @ u[idx] / r]) - eigenstrain
        total += weight / r * (_plane_stress(modulus, poisson) @ strain)[1]
    return total


def _shell(r0, wall, lining_thickness, back, lining, delta_t):
    """Radii and layers of the shell ring (lining inside the back): ``back``/``lining`` are (E, nu, alpha)."""
    def layer(m):
        return (m[0], m[1], m[2] * delta_t)

    if lining_thickness > 0.0:
        return [r0 - wall, r0 - wall + lining_thickness, r0], [layer(lining), layer(back)]
    return [r0 - wall, r0], [layer(back)]


def _shell_under_pressure(r0, wall, lining_thickness, back, lining, elements):
    """Outer displacement and hoop force of the shell ring under unit external pressure."""
    bounds, layers = _shell(r0, wall, lining_thickness, back, lining, 0.0)
    nodes, k, _ = _rings(bounds, layers, elements)
    f = np.zeros(nodes.size)
    f[-1] = -r0  # unit pressure on the outer face, per radian
    u = np.linalg.solve(k, f)
    return u[-1], _hoop_force(nodes, u, layers, elements)


def free_radius(check_radius, crush_height, wall, check_force, back, lining_thickness=0.0, lining=None,
                elements=ELEMENTS):
    r"""Free outer radius [m] of the shell ring from its crush height, by the FE check model.

    ``check_force`` is the hoop force of the check per unit width [N/m]
    (:math:`\sigma_c A_{calc} / L`); ``back``, ``lining`` are (E, nu, alpha).
    """
    r0 = check_radius + crush_height / np.pi
    for _ in range(4):
        u_unit, hoop_unit = _shell_under_pressure(r0, wall, lining_thickness, back, lining, elements)
        q = check_force / -hoop_unit  # pressure giving the check's hoop force
        r0 = check_radius + crush_height / np.pi - q * u_unit
    return r0


def press_fit_one(housing_bore, housing_outer, shell_wall, crush_height, check_bore, check_stress, delta_t,
                  housing, shell, journal_expansion, journal_d, lining_thickness=0.0, lining=None,
                  elements=ELEMENTS):
    """One bearing by FE; same outputs as :func:`stackup.fit.tiers.press_fit` (scalars).

    ``housing``, ``shell`` (its steel back) and ``lining`` are (modulus,
    poisson, expansion) tuples; ``lining_thickness`` [m] of ``shell_wall`` is
    lining.
    """
    e_h, nu_h, al_h = housing
    e_s = shell[0]
    equivalent = shell_wall - lining_thickness + (lining_thickness * lining[0] / e_s if lining_thickness else 0.0)
    r0 = free_radius(check_bore / 2, crush_height, shell_wall, check_stress * equivalent, shell,
                     lining_thickness, lining, elements)
    a, b = housing_bore / 2, housing_outer / 2
    eig_h = al_h * delta_t
    bounds, layers = _shell(r0, shell_wall, lining_thickness, shell, lining, delta_t)
    ns, ks, fs = _rings(bounds, layers, elements)
    nh, kh, fh = _rings([a, b], [(e_h, nu_h, eig_h)], elements)
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
    hoop = _hoop_force(ns, us, layers, elements)
    if contact:
        shell_bore = 2.0 * (ns[0] + us[0])
    else:  # loose shells follow the bore with their own (thermally grown, unloaded) wall
        shell_bore = 2.0 * (a + uh[0] - (ns[-1] + us[-1] - ns[0] - us[0]))
    out = {
        "contact_pressure": p,
        "shell_stress": -hoop / (equivalent * (1.0 + shell[2] * delta_t)),
        "housing_swell": 2.0 * (uh[0] - eig_h * a),
        "bore_in_service": 2.0 * (a + uh[0]),
        "shell_bore": shell_bore,
        "loss_of_fit": not contact,
    }
    if journal_d is not None:
        out["clearance"] = shell_bore - journal_d * (1.0 + journal_expansion * delta_t)
    return out
