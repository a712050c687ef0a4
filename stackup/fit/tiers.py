r"""Press fit of a shell pair in a housing bore: closed-form tiers in plain numpy.

These are the readable definitions (and the test oracle of the numba kernel
in :mod:`stackup._kernels.press_fit`). All lengths are radii or diameters in m
as named, stresses in Pa, temperatures in degC.

Model (Kopeliovich [1]_, with Lamé's thick rings [2]_)
------------------------------------------------------
The two half shells form a closed ring in hoop compression, pressed against
the housing bore. Both are linear-elastic rings in plane stress.

*Steel-equivalent wall.* A bi- or tri-metal shell is a steel back of
thickness :math:`t - t_L` with a lining of thickness :math:`t_L` and modulus
:math:`E_L`. Its hoop stiffness is that of a steel ring of the
steel-equivalent wall (Kopeliovich's :math:`A_{calc}` per unit width)

.. math:: t_e = t - t_L + t_L\,E_L/E_S,

which carries the mechanics below; the full wall :math:`t` sets the
geometry (the shell bore). Stresses are steel-equivalent, i.e. those of the
steel back: :math:`\sigma_S = N / t_e` for a hoop force :math:`N` per unit
width. Likewise the shell ring grows with temperature by the
stiffness-weighted expansion of its layers,

.. math:: \alpha_e = \frac{(t - t_L)\,\alpha_S + t_L (E_L/E_S)\,\alpha_L}{t_e},

the free hoop strain of bonded layers in a thin ring, while its wall
thickens by the layers' radial strains (each layer's own expansion plus the
Poisson effect of the hoop stress the mismatch sets up, plane stress),

.. math:: \alpha_t = \frac{(t - t_L)\,[\alpha_S + \nu_S(\alpha_S - \alpha_e)]
          + t_L\,[\alpha_L + \nu_L(\alpha_L - \alpha_e)]}{t}

(Kopeliovich [1]_,
sec. 6, calls the lining's effect negligible; it is not quite, for a
copper-lead or aluminium-tin lining of 0.3 mm over 100 K, see the tests).
Both simplifications are measured against the layered finite-element
reference (:mod:`stackup.fit.reference`).

*Free ring from the crush height.* The crush height :math:`h` of a half shell
is its excess outside peripheral length over half the checking-block bore
circumference :math:`\pi R_c`, read while the shell is loaded by the check
force :math:`F = \sigma_c A_{calc}` ([1]_, sec. 3; :math:`\sigma_c = 100` MPa).
A ring under external pressure :math:`q` carries the hoop force
:math:`q r_0`, so the check load is :math:`q = \sigma_c t_e / r_0`; the outer
fibre moves by :math:`-q\,C_S`, so the free outer radius is

.. math:: r_0 = R_c + \frac{h}{\pi} + \frac{\sigma_c\,t_e}{r_0}\,C_S(r_0)

(solved by fixed-point iteration; the checking block is rigid and the check is
made at the assembly temperature).

*Compatibility in the housing.* Radial interference :math:`\delta = r_0 - a`
at the operating temperature (housing, shell and journal grow freely by
:math:`\alpha\,\Delta T`) is shared by the housing bore and the shell ring:

.. math:: p = \frac{\max(\delta, 0)}{C_H + \frac{a}{r_0} C_S}, \qquad
          C_H = \frac{a}{E_H}\left(\frac{b^2 + a^2}{b^2 - a^2} + \nu_H\right)

with :math:`p` the pressure on the bore; the shell's outer face carries
:math:`p\,a/r_0`, so the contact force per radian balances.

*Shell compliance* :math:`C_S` at its outer fibre (steel ring of wall
:math:`t_e`), by tier:

- ``"lame"`` (thick ring): :math:`C_S = \frac{r_0}{E_S}\left(\frac{r_0^2 + c^2}{r_0^2 - c^2} - \nu_S\right)`,
  :math:`c = r_0 - t_e`; the inner fibre of that ring moves by
  :math:`u_S(c) = -\frac{2 p r_0^2 c}{E_S (r_0^2 - c^2)}`.
- ``"thin-ring"`` (uniform hoop stress, the classic shop formula):
  :math:`C_S = \frac{r_0^2}{t_e E_S}`; the wall keeps its thickness.

Outputs: contact pressure :math:`p`; mean steel-equivalent shell compression
:math:`\sigma_S = p a / t_e`; housing swell :math:`2 p C_H` (diametral,
elastic part only); bore in service :math:`2a + 2pC_H`; shell bore in service
:math:`2(a + p C_H - t_{loaded})` with :math:`t_{loaded}` the full wall plus
the thickening of the equivalent ring; operating clearance = shell bore -
journal at its own temperature (:func:`journal_in_service`). With
:math:`\delta \le 0` the fit is lost: :math:`p = 0` and the loose shells
follow the bore, which keeps every output continuous through the loss of
fit.

References
----------
.. [1] Kopeliovich, D., *Crush height of engine bearings*, Smooth Sliding /
   King Engine Bearings (secs. 2-6: press fit, crush check with
   :math:`F = 100\,\mathrm{MPa} \cdot A_{calc}`, housing material, rigidity and
   temperature).
.. [2] Timoshenko, S., Goodier, J. N., *Theory of Elasticity*, 3rd ed.,
   McGraw-Hill, 1970, sec. 28 (thick-walled cylinder, shrink fit).
.. [3] ISO 3548-3 / ISO 6864, Plain bearings - Thin-walled half bearings -
   checking of the peripheral length (crush height under a checking load).
"""

from __future__ import annotations

import numpy as np

#: Fixed-point iterations for the free radius; the update is a contraction
#: with factor ~ sigma_c / E ~ 5e-4, so three steps reach 1e-15 relative.
FREE_RADIUS_ITERATIONS = 3


def equivalent_wall(wall, lining_thickness, lining_modulus, back_modulus):
    r"""Steel-equivalent wall :math:`t - t_L + t_L E_L / E_S` [m] of a lined shell (Kopeliovich's :math:`A_{calc}` per width)."""
    return wall - lining_thickness + lining_thickness * (lining_modulus / back_modulus)


def equivalent_expansion(wall, lining_thickness, lining_modulus, back_modulus, lining_expansion, back_expansion):
    r"""Thermal expansion [1/K] of a lined shell ring: its layers' expansions weighted by hoop stiffness (thin ring)."""
    back = wall - lining_thickness
    lining = lining_thickness * (lining_modulus / back_modulus)
    return (back * back_expansion + lining * lining_expansion) / (back + lining)


def wall_expansion(wall, lining_thickness, ring_expansion, back_poisson, lining_poisson, back_expansion,
                   lining_expansion):
    r"""Thermal thickening [1/K] of a lined shell wall (its layers' radial strains, plane stress); see the module."""
    back = wall - lining_thickness
    return (back * (back_expansion + back_poisson * (back_expansion - ring_expansion))
            + lining_thickness * (lining_expansion + lining_poisson * (lining_expansion - ring_expansion))) / wall


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
    """Free outer radius [m] of the closed shell ring (steel wall ``wall``) from its crush height [m] in a rigid block."""
    r0 = check_radius + crush_height / np.pi
    for _ in range(FREE_RADIUS_ITERATIONS):
        r0 = check_radius + crush_height / np.pi + check_stress * wall / r0 * shell_compliance(
            r0, wall, modulus, poisson, thin)
    return r0


def journal_in_service(journal_d, journal_expansion, delta_t):
    r"""Journal diameter [m] at its own temperature: :math:`d_J (1 + \alpha_J \Delta T_J)`, free thermal growth.

    ``journal_d`` at the assembly temperature [m], ``journal_expansion`` [1/K], ``delta_t`` the journal's
    temperature less the assembly temperature [K]. In service the journal runs hotter than the bulkhead around
    its bearing (physics.md sec. 3: often 10-20 K), so its ``delta_t`` may exceed the housing's.
    """
    return journal_d * (1.0 + journal_expansion * delta_t)


def press_fit(housing_bore, housing_outer, shell_wall, equivalent_wall, crush_height, check_bore, check_stress,
              delta_t, housing, shell, journal_expansion, journal_d, thin, wall_growth=None, journal_delta_t=None):
    """Closed-form press fit; see the module docstring. Returns a dict of arrays.

    ``shell_wall`` is the full wall, ``equivalent_wall`` its steel-equivalent
    wall [m]; ``housing`` and ``shell`` are (modulus, poisson, expansion)
    tuples, the shell's with the modulus and Poisson's ratio of its steel back
    and the expansion of the lined ring (:func:`equivalent_expansion`, may be
    an array); ``wall_growth`` the wall's thermal thickening [1/K]
    (:func:`wall_expansion`; default the ring's expansion, exact for an
    unlined shell); ``delta_t`` = operating - assembly temperature [K] of housing and shells,
    ``journal_delta_t`` the journal's (default ``delta_t``).
    """
    e_h, nu_h, al_h = housing
    e_s, nu_s, al_s = shell
    r0 = free_radius(check_bore / 2, crush_height, equivalent_wall, check_stress, e_s, nu_s, thin)
    grow_h = 1.0 + al_h * delta_t
    grow_s = 1.0 + al_s * delta_t
    a = housing_bore / 2 * grow_h
    b = housing_outer / 2 * grow_h
    r0 = r0 * grow_s
    t = shell_wall * (1.0 + (al_s if wall_growth is None else wall_growth) * delta_t)
    te = equivalent_wall * grow_s
    c_h = housing_compliance(a, b, e_h, nu_h)
    c_s = shell_compliance(r0, te, e_s, nu_s, thin)
    interference = r0 - a
    p = np.maximum(interference, 0.0) / (c_h + a / r0 * c_s)
    p_shell = p * a / r0
    u_h = p * c_h
    if thin:
        wall_loaded = t
    else:
        c = r0 - te
        u_outer = -p_shell * c_s
        u_inner = -2.0 * p_shell * r0 * r0 * c / (e_s * (r0 * r0 - c * c))
        wall_loaded = t + u_outer - u_inner
    shell_bore = 2.0 * (a + u_h - wall_loaded)
    out = {
        "contact_pressure": p,
        "shell_stress": p * a / te,
        "housing_swell": 2.0 * u_h,
        "bore_in_service": 2.0 * (a + u_h),
        "shell_bore": shell_bore,
        "loss_of_fit": interference <= 0.0,
    }
    if journal_d is not None:
        out["clearance"] = shell_bore - journal_in_service(journal_d, journal_expansion,
                                                           delta_t if journal_delta_t is None else journal_delta_t)
    return out
