"""The elastic layer under the film: column stiffness, and the film the asperities open on it."""

import numpy as np
import pytest
from scipy import optimize

from stackup.contact import column_stiffness, greenwood_tripp, layer_contact

SIGMA, MODULUS = 0.32e-6, 6e10


def test_one_column_is_its_constrained_modulus_over_its_thickness():
    # uniaxial strain: E' = E (1 - nu) / ((1 + nu)(1 - 2 nu)); steel 210 GPa, 0.3 -> 282.7 GPa
    k = column_stiffness([2e-3], [210e9], [0.3])
    assert k == pytest.approx(210e9 * 0.7 / (1.3 * 0.4) / 2e-3, rel=1e-12)


def test_columns_in_series_add_their_compliances():
    k1, k2 = column_stiffness([0.3e-3], [70e9], [0.33]), column_stiffness([1.5e-3], [210e9], [0.3])
    assert column_stiffness([0.3e-3, 1.5e-3], [70e9, 210e9], [0.33, 0.3]) == pytest.approx(1 / (1 / k1 + 1 / k2))


@pytest.mark.parametrize("rigid", [3.0, 1.0, 0.0, -1.0, -5.0])
def test_layer_film_is_the_root_of_the_deflection_balance(rigid):
    k = 1e14
    out = layer_contact(rigid * SIGMA, roughness=SIGMA, contact_modulus=MODULUS, stiffness=k)

    def gap(h):
        return h - rigid * SIGMA - greenwood_tripp(h, roughness=SIGMA, contact_modulus=MODULUS) / k

    root = optimize.brentq(gap, rigid * SIGMA - 1e-9, rigid * SIGMA + 1e-5, xtol=1e-16)
    assert float(out.film) == pytest.approx(root, rel=1e-9, abs=1e-15)
    assert float(out.pressure) == pytest.approx(float(greenwood_tripp(root, roughness=SIGMA, contact_modulus=MODULUS)),
                                                rel=1e-6)


def test_hard_cases_far_film_and_deep_overlap():
    far = layer_contact(30 * SIGMA, roughness=SIGMA, contact_modulus=MODULUS, stiffness=1e14)
    assert float(far.film) == pytest.approx(30 * SIGMA) and float(far.pressure) < 1e-3
    # the rigid surfaces overlap by 20 roughnesses: the layer takes nearly all of it, p -> k (-h_r)
    deep = layer_contact(-20 * SIGMA, roughness=SIGMA, contact_modulus=MODULUS, stiffness=1e13)
    assert float(deep.pressure) == pytest.approx(1e13 * 20 * SIGMA, rel=0.2)
    assert -20 * SIGMA < float(deep.film) < 0
    # a stiffer layer leaves a thinner film
    stiff = layer_contact(-20 * SIGMA, roughness=SIGMA, contact_modulus=MODULUS, stiffness=1e15)
    assert float(stiff.film) < float(deep.film)


@pytest.mark.parametrize("call, message", [
    (lambda: column_stiffness([-1e-3], [2e11], [0.3]), "thickness: -0.001 is not valid; must be > 0"),
    (lambda: column_stiffness([1e-3], [2e11], [0.5]), r"poisson: 0.5 is outside the valid range"),
    (lambda: layer_contact(0.0, roughness=SIGMA, contact_modulus=MODULUS, stiffness=0.0),
     "stiffness: 0.0 is not valid; must be > 0"),
    (lambda: layer_contact(np.nan, roughness=SIGMA, contact_modulus=MODULUS, stiffness=1e14),
     "rigid_film: nan is not a finite"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
