"""Press fit of shell pairs in housing bores, one bearing per loop step.

The numpy twin, and the definition of every term, is
:func:`stackup.fit.tiers.press_fit`. The caller packs the inputs once: the
bearings' arrays in :class:`Bearings`, the materials' constants in
:class:`Materials`, the tier and what to return in :class:`Options`.
"""

from collections import namedtuple

import numpy as np
from numba import njit, prange

#: Per-bearing inputs, 1-D float arrays of length n, or of length 1 for a value shared by all bearings [SI]:
#: ``shell_wall`` is the full wall, ``lining_thickness`` its lining, ``crush_height`` per half shell,
#: ``check_bore`` and ``check_stress`` those of the crush check, ``delta_t`` operating minus assembly
#: temperature [K], ``journal_d`` the journal at assembly (any value without a journal).
Bearings = namedtuple("Bearings", ["housing_bore", "housing_outer", "shell_wall", "lining_thickness", "crush_height",
                                   "check_bore", "check_stress", "journal_d", "delta_t"])

#: Modulus [Pa], Poisson's ratio [-] and expansion [1/K] of the housing, the shell's steel back and its
#: lining, and the journal's expansion [1/K].
Materials = namedtuple("Materials", ["housing_modulus", "housing_poisson", "housing_expansion", "back_modulus",
                                     "back_poisson", "back_expansion", "lining_modulus", "lining_poisson",
                                     "lining_expansion", "journal_expansion"])

#: ``thin``: the thin-ring tier (else Lamé's thick rings); ``with_journal``: return the clearance (else NaN);
#: ``free_radius_iterations``: fixed-point steps for the shell's free radius.
Options = namedtuple("Options", ["thin", "with_journal", "free_radius_iterations"])


@njit(cache=True, inline="always")
def _shell_compliance(r0, wall, modulus, poisson, thin):
    if thin:
        return r0 * r0 / (wall * modulus)
    c = r0 - wall
    return r0 / modulus * ((r0 * r0 + c * c) / (r0 * r0 - c * c) - poisson)


@njit(cache=True, inline="always")
def _at(values, i):
    # a length-1 array stands for a scalar broadcast over all bearings
    return values[0] if values.shape[0] == 1 else values[i]


@njit(cache=True, parallel=True)
def press_fit(n, bearings, materials, options):
    """Packed :class:`Bearings`, :class:`Materials`, :class:`Options` in (n bearings); arrays out:
    (p, stress, swell, bore, shell_bore, clearance, loss).

    The steel-equivalent wall, the lined ring's expansion and the wall's
    thermal thickening are formed per bearing as in the numpy twin
    (``equivalent_wall``, ``equivalent_expansion``, ``wall_expansion``).
    """
    e_h, nu_h, al_h, e_s, nu_s, al_s, e_l, nu_l, al_l, al_j = materials
    thin, with_journal, free_radius_iterations = options
    p_out = np.empty(n)
    stress = np.empty(n)
    swell = np.empty(n)
    bore = np.empty(n)
    shell_bore = np.empty(n)
    clearance = np.empty(n)
    loss = np.empty(n, np.bool_)
    for i in prange(n):
        t0 = _at(bearings.shell_wall, i)
        t_l = _at(bearings.lining_thickness, i)
        back = t0 - t_l
        lining = t_l * (e_l / e_s)
        te0 = back + lining
        al_e = (back * al_s + lining * al_l) / te0
        al_t = (back * (al_s + nu_s * (al_s - al_e)) + t_l * (al_l + nu_l * (al_l - al_e))) / t0
        sigma_c = _at(bearings.check_stress, i)
        base = 0.5 * _at(bearings.check_bore, i) + _at(bearings.crush_height, i) / np.pi
        r0 = base
        for _ in range(free_radius_iterations):
            r0 = base + sigma_c * te0 / r0 * _shell_compliance(r0, te0, e_s, nu_s, thin)
        dt = _at(bearings.delta_t, i)
        grow_h = 1.0 + al_h * dt
        grow_s = 1.0 + al_e * dt
        a = 0.5 * _at(bearings.housing_bore, i) * grow_h
        b = 0.5 * _at(bearings.housing_outer, i) * grow_h
        r0 *= grow_s
        t = t0 * (1.0 + al_t * dt)
        te = te0 * grow_s
        c_h = a / e_h * ((b * b + a * a) / (b * b - a * a) + nu_h)
        c_s = _shell_compliance(r0, te, e_s, nu_s, thin)
        interference = r0 - a
        p = max(interference, 0.0) / (c_h + a / r0 * c_s)
        p_shell = p * a / r0
        u_h = p * c_h
        if thin:
            wall_loaded = t
        else:
            c = r0 - te
            wall_loaded = t - p_shell * c_s + 2.0 * p_shell * r0 * r0 * c / (e_s * (r0 * r0 - c * c))
        p_out[i] = p
        stress[i] = p * a / te
        swell[i] = 2.0 * u_h
        bore[i] = 2.0 * (a + u_h)
        sb = 2.0 * (a + u_h - wall_loaded)
        shell_bore[i] = sb
        clearance[i] = sb - _at(bearings.journal_d, i) * (1.0 + al_j * dt) if with_journal else np.nan
        loss[i] = interference <= 0.0
    return p_out, stress, swell, bore, shell_bore, clearance, loss
