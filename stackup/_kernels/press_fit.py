"""Press fit of shell pairs in housing bores, one bearing per loop step.

The numpy twin, and the definition of every term, is
:func:`stackup.fit.tiers.press_fit`.
"""

import numpy as np
from numba import njit, prange


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
def press_fit(n, housing_bore, housing_outer, shell_wall, equivalent_wall, crush_height, check_bore, check_stress,
              journal_d, delta_t, shell_expansion, wall_growth, e_h, nu_h, al_h, e_s, nu_s, al_j, thin, with_journal,
              free_radius_iterations):
    """1-D arrays of length n (or 1, broadcast) in; (p, stress, swell, bore, shell_bore, clearance, loss) out.

    ``shell_wall`` is the full wall, ``equivalent_wall`` the steel-equivalent
    wall that carries the mechanics [m]; ``shell_expansion`` the lined
    ring's expansion and ``wall_growth`` its wall's thermal thickening
    [1/K]; ``free_radius_iterations``:
    fixed-point steps for the shell's free radius (see the numpy twin).
    """
    p_out = np.empty(n)
    stress = np.empty(n)
    swell = np.empty(n)
    bore = np.empty(n)
    shell_bore = np.empty(n)
    clearance = np.empty(n)
    loss = np.empty(n, np.bool_)
    for i in prange(n):
        t0 = _at(shell_wall, i)
        te0 = _at(equivalent_wall, i)
        sigma_c = _at(check_stress, i)
        base = 0.5 * _at(check_bore, i) + _at(crush_height, i) / np.pi
        r0 = base
        for _ in range(free_radius_iterations):
            r0 = base + sigma_c * te0 / r0 * _shell_compliance(r0, te0, e_s, nu_s, thin)
        dt = _at(delta_t, i)
        grow_h = 1.0 + al_h * dt
        grow_s = 1.0 + _at(shell_expansion, i) * dt
        a = 0.5 * _at(housing_bore, i) * grow_h
        b = 0.5 * _at(housing_outer, i) * grow_h
        r0 *= grow_s
        t = t0 * (1.0 + _at(wall_growth, i) * dt)
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
        clearance[i] = sb - _at(journal_d, i) * (1.0 + al_j * dt) if with_journal else np.nan
        loss[i] = interference <= 0.0
    return p_out, stress, swell, bore, shell_bore, clearance, loss
