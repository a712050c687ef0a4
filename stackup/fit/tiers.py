r"""Press fit of a shell pair in a housing bore: closed-form tiers in plain numpy.

These are the readable definitions (and the test oracle of the numba kernel
in :mod:`stackup._kernels.press_fit`). All lengths are radii or diameters in m
as named, stresses in Pa, temperatures in degC.

Model
-----
The two half shells form a closed ring in hoop compression, pressed against
the housing bore. Both are linear-elastic rings in plane stress.

*Free ring from the crush height.* The crush height :math:`h` of a half shell
is its excess outside peripheral length over half the checking-block bore
circumference :math:`\pi R_c`, read while the shell is loaded to a mean wall
compression :math:`\sigma_c`. A ring under external pressure :math:`q` has
mean hoop stress :math:`q r_0 / t` and outer-fibre displacement
:math:`-q\,C_S`, so its free outer radius is

.. math:: r_0 = R_c + \frac{h}{\pi} + \frac{\sigma_c\,t}{r_0}\,C_S(r_0)

(solved by fixed-point iteration; the checking block is rigid and the check is
made at the assembly temperature).

*Compatibility in the housing.* Radial interference :math:`\delta = r_0 - a`
at the operating temperature (housing, shell and journal grow freely by
:math:`\alpha\,\Delta T`) is shared by the housing bore and the shell ring:

.. math:: p = \frac{\max(\delta, 0)}{C_H + \frac{a}{r_0} C_S}, \qquad
          C_H = \frac{a}{E_H}\left(\frac{b^2 + a^2}{b^2 - a^2} + \nu_H\right)

with :math:`p` the pressure on the bore; the shell's outer face carries
:math:`p\,a/r_0`, so the contact force per radian balances.

*Shell compliance* :math:`C_S` at its outer fibre, by tier:

- ``"lame"`` (thick ring): :math:`C_S = \frac{r_0}{E_S}\left(\frac{r_0^2 + c^2}{r_0^2 - c^2} - \nu_S\right)`,
  :math:`c = r_0 - t`; the bore of the shell moves by
  :math:`u_S(c) = -\frac{2 p r_0^2 c}{E_S (r_0^2 - c^2)}`.
- ``"thin-ring"`` (uniform hoop stress, the classic shop formula):
  :math:`C_S = \frac{r_0^2}{t E_S}`; the wall keeps its thickness.

Outputs: contact pressure :math:`p`; mean shell compression
:math:`\sigma_S = p a / t`; housing swell :math:`2 p C_H` (diametral, elastic
part only); bore in service :math:`2a + 2pC_H`; shell bore in service
:math:`2(a + p C_H - t_S)` with :math:`t_S` the loaded wall; operating
clearance = shell bore - journal. With :math:`\delta \le 0` the fit is lost:
:math:`p = 0` and the loose shells follow the bore, which keeps every output
continuous through the loss of fit.

References
----------
.. [1] Timoshenko, S., Goodier, J. N., *Theory of Elasticity*, 3rd ed.,
   McGraw-Hill, 1970, sec. 28 (thick-walled cylinder, shrink fit).
.. [2] ISO 6864:2011, Plain bearings - Thin-walled half bearings - Checking of
   peripheral length (crush height under a checking load).
.. [3] Rozhdestvensky et al. 2018 and physics.md sec. 3 (press fit, housing
   swell and temperature in main bearings).
"""

from __future__ import annotations

import numpy as np

#: Fixed-point iterations for the free radius; the update is a contraction
#: with factor ~ sigma_c / E ~ 5e-4, so three steps reach 1e-15 relative.
FREE_RADIUS_ITERATIONS = 3


def housing_compliance(a, b, modulus, poisson):
    """Radial growth of a bore of radius ``a`` [m], outer radius ``b`` [m], per unit internal pressure [m/Pa]."""
    return a / modulus * ((b * b + a * a) / (b * b - a * a) + poisson)


def shell_compliance(r0, wall, modulus, poisson, thin):
    """Radial shrink of a ring's outer radius ``r0`` [m] per unit external pressure [m/Pa]."""
    if thin:
        return r0 * r0 / (wall * modulus)
    c = r0 - wall
    return r0 / modulus * ((r0 * r0 + c * c) / (r0 * r0 - c * c) - poisson)


def free_radius(check_radius, crush_height, wall, check_stress, modulus, poisson, thin):
    """Free outer radius [m] of the closed shell ring from its crush height [m] in a rigid checking block."""
    r0 = check_radius + crush_height / np.pi
    for _ in range(FREE_RADIUS_ITERATIONS):
        r0 = check_radius + crush_height / np.pi + check_stress * wall / r0 * shell_compliance(
            r0, wall, modulus, poisson, thin)
    return r0


def press_fit(housing_bore, housing_outer, shell_wall, crush_height, check_bore, check_stress,
              delta_t, housing, shell, journal_expansion, journal_d, thin):
    """Closed-form press fit; see the module docstring. Returns a dict of arrays.

    ``housing`` and ``shell`` are (modulus, poisson, expansion) tuples;
    ``delta_t`` = operating - assembly temperature [K].
    """
    e_h, nu_h, al_h = housing
    e_s, nu_s, al_s = shell
    r0 = free_radius(check_bore / 2, crush_height, shell_wall, check_stress, e_s, nu_s, thin)
    grow_h = 1.0 + al_h * delta_t
    grow_s = 1.0 + al_s * delta_t
    a = housing_bore / 2 * grow_h
    b = housing_outer / 2 * grow_h
    r0 = r0 * grow_s
    t = shell_wall * grow_s
    c_h = housing_compliance(a, b, e_h, nu_h)
    c_s = shell_compliance(r0, t, e_s, nu_s, thin)
    interference = r0 - a
    p = np.maximum(interference, 0.0) / (c_h + a / r0 * c_s)
    p_shell = p * a / r0
    u_h = p * c_h
    if thin:
        wall_loaded = t
    else:
        c = r0 - t
        u_outer = -p_shell * c_s
        u_inner = -2.0 * p_shell * r0 * r0 * c / (e_s * (r0 * r0 - c * c))
        wall_loaded = t + u_outer - u_inner
    shell_bore = 2.0 * (a + u_h - wall_loaded)
    out = {
        "contact_pressure": p,
        "shell_stress": p * a / t,
        "housing_swell": 2.0 * u_h,
        "bore_in_service": 2.0 * (a + u_h),
        "shell_bore": shell_bore,
        "loss_of_fit": interference <= 0.0,
    }
    if journal_d is not None:
        out["clearance"] = shell_bore - journal_d * (1.0 + journal_expansion * delta_t)
    return out
