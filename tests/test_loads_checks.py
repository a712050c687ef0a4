"""Loads: the checks pin_loads and firing_offsets declare, and the same loads for a trusted caller."""

import numpy as np
import pytest

from stackup._validate import trusted
from stackup.loads import Combustion, Kinematics, firing_offsets, pin_loads

K = Kinematics(cylinder_bore=0.076, stroke=0.0805, conrod=0.136, reciprocating_mass=0.75, rotating_mass=0.6,
               counterweight_unbalance=0.0)
FOUR = {"kinematics": K, "combustion": Combustion(), "throw_angles": [0, 180, 180, 0], "firing_order": [1, 3, 4, 2]}


@pytest.mark.parametrize("kw, message", [
    ({"speed": 0.0}, r"speed: 0.0 is not valid; must be > 0"),
    ({"speed": 400.0, "firing_order": [1, 2, 2, 4]}, r"firing_order: \[1, 2, 2, 4\] is not a permutation of cylinders"),
    ({"speed": 400.0, "throw_angles": [0, 180, np.nan, 0]}, r"throw_angles: nan is not a finite number"),
    ({"speed": 400.0, "pressure_trace": ([0.0, 360.0], [1e5, np.inf])}, r"pressure_trace: inf is not a finite number"),
])
def test_pin_loads_name_bad_input(kw, message):
    with pytest.raises(ValueError, match=message):
        pin_loads(np.arange(0.0, 720.0, 10.0), **{**FOUR, **kw})
    with pytest.raises(ValueError, match=r"crank_angle: nan is not a finite number"):
        pin_loads([0.0, np.nan], **FOUR, speed=400.0)


def test_two_cylinders_fired_at_once_are_found_by_placing_them():
    with pytest.raises(ValueError, match=r"firing_order: \[1, 2, 3, 4\] fires two cylinders at once"):
        firing_offsets([0, 180, 180, 0], [1, 2, 3, 4])


def test_trusted_callers_get_the_same_loads():
    angle = np.arange(0.0, 720.0, 5.0)
    checked = pin_loads(angle, **FOUR, speed=400.0)
    with trusted():
        np.testing.assert_array_equal(pin_loads(angle, **FOUR, speed=400.0), checked)


@pytest.mark.parametrize("kw, message", [
    ({"cylinder_throw": [0, 0, 1, 1]}, r"cylinder_throw, cylinder_axis: give both \(a V engine\) or neither"),
    ({"cylinder_throw": [0, 0, 0, 1], "cylinder_axis": [45, -45, 45, -45]},
     r"cylinder_throw: \[0, 0, 0, 1\] does not put the same number of cylinders on each of throws 0\.\.1"),
    ({"cylinder_throw": [0, 0, 1, 1], "cylinder_axis": [45, -45, 45]}, r"cylinder_axis: shape \(3,\); give one per"),
    ({"cylinder_throw": [0, 0, 1, 1], "cylinder_axis": [45, -45, np.nan, -45]}, r"cylinder_axis: nan is not a finite"),
])
def test_a_v_layout_that_does_not_fit_its_throws_is_named(kw, message):
    v4 = {"kinematics": K, "combustion": Combustion(), "throw_angles": [0, 180], "firing_order": [1, 3, 2, 4], "speed": 400.0}
    with pytest.raises(ValueError, match=message):
        pin_loads(np.arange(0.0, 720.0, 10.0), **{**v4, **kw})
