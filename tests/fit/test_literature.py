"""Press fit against Kopeliovich, *Crush height of engine bearings* (reference values from his text).

The paper states neither the checking-block bore nor the bore its curves are
drawn for. The block is taken at the lower limit of the housing bore (ISO
3548-3: the nominal housing bore); the bore is named per test. His shells are
tri-metal, crush-checked on the steel-equivalent section A_calc; the lining's
thickness is not stated, so each test runs plain steel shells and a 0.3 mm
copper-lead lining (the usual 0.30-0.38 mm intermediate layer of tri-metal
shells), the lining with the steel back's expansion as he assumes (sec. 6).
Tolerances cover reading his figures (about +-0.5 MPa, +-0.005 mm) and those
unstated inputs; they are wider than the differences between the two linings.
"""

import numpy as np
import pytest

from stackup import materials
from stackup.fit import press_fit, press_fit_extremes

#: Kopeliovich assumes the lining expands as the steel back (sec. 6).
LINING = materials.Material("copper-lead, steel expansion", 72e9, 0.34, 12.2e-6)
LININGS = {"plain": 0.0, "copper-lead 0.3 mm": 0.3e-3}


def kopeliovich(bore, wall, crush, block, lining, **kw):
    """A Kopeliovich bearing: OD/ID 1.5, 15 mm wide, tri-metal on a steel back."""
    return press_fit(housing_bore=bore, housing_outer=1.5 * bore, shell_wall=wall, crush_height=crush, bearing_width=15e-3,
                     check_bore=block, shell_material="steel-back", lining_thickness=lining,
                     lining_material=LINING, **kw)


# Table 2: aluminium housing, bore 50.135-50.155 mm (1.6 mm wall) or 52.935-52.955 mm (3 mm wall),
# wall 1.588-1.600 / 2.988-3.000 mm, crush height 0.100-0.137 mm. The least contact pressure: least
# crush, thinnest wall, bore at mid-tolerance.
TABLE2 = {1.6e-3: 50.135e-3, 3.0e-3: 52.935e-3}


def table2_least_pressure(wall, temperature, lining):
    lo = TABLE2[wall]
    return kopeliovich(lo + 10e-6, wall - 12e-6, 0.100e-3, lo, lining, housing_material="aluminium",
                       temperature=temperature).contact_pressure


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_thin_shell_in_aluminium_loses_its_fit_when_heated(lining):
    # sec. 6, Fig. 12: 13.5 MPa at room temperature, down to 7 MPa at 100 degC (1.6 mm wall)
    assert table2_least_pressure(1.6e-3, 20.0, lining) == pytest.approx(13.5e6, abs=1.5e6)
    assert table2_least_pressure(1.6e-3, 100.0, lining) == pytest.approx(7.0e6, abs=1.0e6)


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_thick_shell_keeps_about_10_mpa_hot(lining):
    # sec. 6, Fig. 12: the 3 mm wall "has minimum contact pressure 10 MPa" at 100 degC
    assert table2_least_pressure(3.0e-3, 100.0, lining) == pytest.approx(10e6, abs=1.5e6)


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_heating_to_100_degc_lowers_the_stress_by_about_100_mpa(lining):
    # sec. 6, Fig. 11: "decreases by ~100 MPa" from room temperature to 100 degC (1.6 mm wall, aluminium)
    lo = TABLE2[1.6e-3]
    ext = press_fit_extremes(temperatures=[20.0, 100.0], housing_bore=np.array([lo, lo + 20e-6]),
                             housing_outer=1.5 * lo, shell_wall=np.array([1.600e-3, 1.588e-3]),
                             crush_height=np.array([0.137e-3, 0.100e-3]), bearing_width=15e-3, check_bore=lo,
                             housing_material="aluminium", shell_material="steel-back", lining_thickness=lining,
                             lining_material=LINING)
    hot = kopeliovich(np.array([lo, lo + 20e-6]), np.array([1.600e-3, 1.588e-3]), np.array([0.137e-3, 0.100e-3]),
                      lo, lining, housing_material="aluminium", temperature=100.0)
    np.testing.assert_array_equal(ext.highest_stress_temperature, 20.0)  # cold is where the stress bites
    np.testing.assert_allclose(ext.highest_shell_stress - hot.shell_stress, 100e6, atol=15e6)


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_crush_height_for_10_mpa_steel_and_aluminium(lining):
    # sec. 4, Fig. 6 (Table 1: bore 50.180-50.200, wall 1.588-1.600 mm, 20 degC): 10 MPa is reached at
    # 0.060 mm crush in a steel housing and 0.082 mm in an aluminium one; the least pressure (largest
    # bore, thinnest wall)
    crush = np.linspace(0.0, 0.15e-3, 3001)
    needed = {}
    for housing in ("steel", "aluminium"):
        p = kopeliovich(50.200e-3, 1.588e-3, crush, 50.180e-3, lining, housing_material=housing).contact_pressure
        needed[housing] = crush[np.argmax(p >= 10e6)]
    assert needed["steel"] == pytest.approx(0.060e-3, abs=0.015e-3)
    assert needed["aluminium"] == pytest.approx(0.082e-3, abs=0.015e-3)
    assert needed["aluminium"] - needed["steel"] == pytest.approx(0.022e-3, abs=0.004e-3)


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_aluminium_housing_stress_is_a_fifth_below_steel(lining):
    # sec. 4, Fig. 5: at 0.1 mm crush 350 MPa in aluminium against 450 MPa in steel. His absolute stresses
    # are about 40 % above this model's (a smaller A_calc than here?); their ratio is tested.
    kw = dict(bore=50.190e-3, wall=1.594e-3, crush=0.1e-3, block=50.180e-3, lining=lining)
    ratio = (kopeliovich(housing_material="aluminium", **kw).shell_stress
             / kopeliovich(housing_material="steel", **kw).shell_stress)
    assert ratio == pytest.approx(350 / 450, abs=0.03)


@pytest.mark.parametrize("lining", LININGS.values(), ids=LININGS)
def test_kopeliovich_aluminium_housing_opens_the_clearance(lining):
    # sec. 4, Fig. 7: the clearance difference between aluminium and steel housings "reaches 20 um" at
    # 0.1 mm crush; the model gives 15-16 um at mid-tolerance (his maximum over the tolerances is not stated)
    kw = dict(bore=50.190e-3, wall=1.594e-3, crush=0.1e-3, block=50.180e-3, lining=lining, journal_d=46.964e-3)
    diff = (kopeliovich(housing_material="aluminium", **kw).clearance
            - kopeliovich(housing_material="steel", **kw).clearance)
    assert diff == pytest.approx(20e-6, abs=6e-6)
