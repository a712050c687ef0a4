"""V engines: two side-by-side rods on each crank pin, against an independent calculation.

The reference here is written from the geometry alone (vectors in a plane, the
piston's travel differentiated numerically, each firing placed by walking the
firing order), not from :mod:`stackup.loads`: it shares only the pressure
trace, the input both take.
"""

from pathlib import Path

import numpy as np
import pytest

from stackup.engines import load_engine
from stackup.loads import (
    ATMOSPHERE,
    Combustion,
    Kinematics,
    cylinder_throw_angles,
    firing_offsets,
    pin_loads,
    v_cylinders,
)

BORE, STROKE, ROD = 0.10325, 0.092, 0.1549
REC, ROT, SHARE = 0.85, 0.42, 0.5
SPEED = 5900 * 2 * np.pi / 60
ANGLE = np.arange(0.0, 720.0, 2.5)
# a synthetic cylinder pressure: a peak of 8 MPa 12 deg after firing TDC, atmospheric elsewhere
TRACE_ANGLE = np.arange(0.0, 720.0, 1.0)
TRACE_P = ATMOSPHERE + 7.9e6 * np.exp(-(((TRACE_ANGLE + 360.0) % 720.0 - 360.0 - 12.0) / 18.0) ** 2)

#: A 90 deg cross-plane V8 in GM's numbering (1-3-5-7 left bank, 2-4-6-8 right) and firing order.
V8 = {"cylinders": 8, "bank_angle": 90.0, "numbering": "alternate", "first_bank": "left",
      "throw_angles": [0, 90, 270, 180], "firing_order": [1, 8, 7, 2, 6, 5, 4, 3]}
#: A plain 60 deg V6 with three common pins 120 deg apart (no split pins), numbered bank by bank (1-2-3 right);
#: it fires unevenly, 60 and 180 deg apart, as a common-pin 60 deg V6 does.
V6 = {"cylinders": 6, "bank_angle": 60.0, "numbering": "bank-by-bank", "first_bank": "right",
      "throw_angles": [0, 120, 240], "firing_order": [1, 4, 2, 5, 3, 6]}


def kinematics(*, reciprocating=REC, rotating=ROT, conrod=ROD):
    return Kinematics(cylinder_bore=BORE, stroke=STROKE, conrod=conrod, reciprocating_mass=reciprocating,
                      rotating_mass=rotating, counterweight_unbalance=SHARE * rotating * STROKE / 2)


def library(engine, kin, trace=(TRACE_ANGLE, TRACE_P)):
    throw, axis = v_cylinders(engine["cylinders"], bank_angle=engine["bank_angle"], numbering=engine["numbering"],
                              first_bank=engine["first_bank"])
    return pin_loads(ANGLE, kinematics=kin, combustion=Combustion(), throw_angles=engine["throw_angles"],
                     firing_order=engine["firing_order"], speed=SPEED, pressure_trace=trace, cylinder_throw=throw,
                     cylinder_axis=axis)


def reference(engine, *, reciprocating=REC, rotating=ROT, conrod=ROD, trace=(TRACE_ANGLE, TRACE_P)):
    """Each pin's force over the cycle (angles, pins, 2) from the geometry alone.

    Plane x (across the engine, the way the top of a pin moves) and y (up, the
    V's bisector). A pin at angle theta from the top (in the sense of rotation)
    sits at r (sin theta, cos theta); a cylinder whose axis leans gamma from
    the bisector has its axis u = (sin gamma, cos gamma). The piston lies at s u
    with s = P.u + sqrt(l^2 - (P.w)^2) (w across the axis). The rod, compressed
    by C, balances the gas force and the piston's d'Alembert force along u:
    C (d.u) = (p - p_atm) A + m s'' with d the rod's direction from pin to piston;
    the pin takes -C d, and the big ends their centrifugal force less the
    counterweights'. Returned as the library's components: (towards the caps,
    across in the sense of rotation) = (-y, x).
    """
    n = engine["cylinders"]
    r, area = STROKE / 2, np.pi * BORE**2 / 4
    pins = np.array(engine["throw_angles"], float)
    # numbering and banks written out, not taken from v_cylinders: cylinder -> (pin, leans which way)
    if engine["numbering"] == "alternate":
        pin_of = [c // 2 for c in range(n)]
        first_bank = [c % 2 == 0 for c in range(n)]
    else:
        pin_of = [c % (n // 2) for c in range(n)]
        first_bank = [c < n // 2 for c in range(n)]
    # seen from the flywheel end with the standard rotation the top of a pin moves towards the left bank:
    # the right bank's axis leans against the rotation (it leads)
    right = [fb == (engine["first_bank"] == "right") for fb in first_bank]
    gamma = np.radians([-engine["bank_angle"] / 2 if on_right else engine["bank_angle"] / 2 for on_right in right])

    def travel(theta, g):
        p = r * np.stack([np.sin(theta), np.cos(theta)], -1)
        u = np.array([np.sin(g), np.cos(g)])
        w = np.array([np.cos(g), -np.sin(g)])
        return p @ u + np.sqrt(conrod**2 - (p @ w) ** 2), p, u

    # crank angle 0: the first-fired cylinder at the top of its stroke
    first = engine["firing_order"][0] - 1
    shift = gamma[first] - np.radians(pins[pin_of[first]])
    # firings: walk the order, each cylinder at its first TDC after the one before
    tdc = np.mod(np.degrees(gamma - np.radians(pins[pin_of]) - shift), 360.0)
    fire, last = {}, None
    for c in (k - 1 for k in engine["firing_order"]):
        if last is None:
            fire[c] = 0.0
        else:
            fire[c] = min(t for t in (tdc[c], tdc[c] + 360.0, tdc[c] + 720.0) if t > last)
        last = fire[c]
    assert last < 720.0  # the order fits in one cycle

    out = np.zeros((ANGLE.size, pins.size, 2))
    h = 1e-4
    for c in range(n):
        theta = np.radians(ANGLE + pins[pin_of[c]]) + shift
        s, p, u = travel(theta, gamma[c])
        s_dd = (travel(theta + h, gamma[c])[0] - 2 * s + travel(theta - h, gamma[c])[0]) / h**2 * SPEED**2
        pressure = np.interp(np.mod(ANGLE - fire[c], 720.0), *trace, period=720.0)
        d = (s[:, None] * u - p) / conrod
        compression = ((pressure - ATMOSPHERE) * area + reciprocating * s_dd) / (d @ u)
        force = -compression[:, None] * d + (1 - SHARE) * rotating * SPEED**2 * p
        out[:, pin_of[c]] += np.stack([-force[:, 1], force[:, 0]], -1)
    return out


@pytest.mark.parametrize("engine", [V8, V6], ids=["V8-90-cross-plane", "V6-60-common-pin"])
def test_pin_loads_of_a_v_engine_match_an_independent_calculation(engine):
    expected = reference(engine)
    got = library(engine, kinematics())
    scale = np.abs(expected).max()
    assert scale > 20e3  # gas and inertia of two cylinders: tens of kN
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-6 * scale)


def test_the_independent_calculation_tells_the_banks_apart():
    """The reference is not blind to the bank convention: the other first bank gives other loads."""
    swapped = {**V6, "first_bank": "left", "firing_order": [1, 6, 5, 4, 3, 2]}
    assert np.abs(reference(swapped) - library(V6, kinematics())).max() > 1e3


def test_a_90_degree_v_has_a_constant_primary_inertia_force_turning_with_its_pin():
    """Taylor (1985), vol. 2, ch. 8: on a 90 deg V the primary reciprocating forces of the two banks add up to
    m_rec r w^2, constant in size, along the crank throw; with a very long rod the secondary forces vanish."""
    long_rod = 1e4 * STROKE
    kin = kinematics(rotating=0.0, conrod=long_rod)
    atmosphere = (TRACE_ANGLE, np.full(TRACE_ANGLE.shape, ATMOSPHERE))
    loads = library(V8, kin, trace=atmosphere)
    size = REC * STROKE / 2 * SPEED**2
    np.testing.assert_allclose(np.hypot(loads[..., 0], loads[..., 1]), size, rtol=1e-3)
    # along each throw, outwards: at the pin's angle theta from the top, (towards the caps, across) = (-cos, sin)
    throw, axis = v_cylinders(8, bank_angle=90.0, numbering="alternate", first_bank="left")
    own = cylinder_throw_angles(V8["throw_angles"], throw, axis)
    theta = np.radians(ANGLE[:, None] + np.array(V8["throw_angles"]) - own[0])
    np.testing.assert_allclose(loads / size, np.stack([-np.cos(theta), np.sin(theta)], -1), atol=2e-3)


def test_builtin_v8_fires_every_90_degrees_and_loads_four_pins():
    crank = load_engine("gm-ls3-v8").crank
    own = cylinder_throw_angles(crank.throw_angles, crank.cylinder_throw, crank.cylinder_axis)
    fire = firing_offsets(own, crank.firing_order)
    np.testing.assert_array_equal(np.sort(fire), np.arange(0.0, 720.0, 90.0))
    assert crank.pin_loads(ANGLE).shape == (ANGLE.size, 4, 2)
    assert crank.spans.shape == (4,) and crank.layout == "V"


def test_inline_engines_take_the_one_cylinder_a_pin_path_unchanged():
    """Every built-in inline engine's loads are those of one cylinder per pin on the engine's axis, to the bit."""
    from stackup.engines import available_engines
    from stackup.loads import cylinder_pressure, pin_load

    for name in available_engines():
        crank = load_engine(name).crank
        if crank is None or crank.layout != "inline":
            continue
        fire = firing_offsets(crank.throw_angles, crank.firing_order)
        pressure = cylinder_pressure(np.mod(ANGLE[:, None] - fire[None, :], 720.0), crank.kinematics,
                                     crank.combustion)
        pin_angle = ANGLE[:, None] + np.asarray(crank.throw_angles, float)[None, :]
        expected = pin_load(pin_angle, pressure, crank.kinematics, crank.speed)
        assert crank.pin_loads(ANGLE).tobytes() == expected.tobytes(), name


def _v8_text():
    from stackup.engines import engine_path

    return engine_path("gm-ls3-v8").read_text()


@pytest.mark.parametrize("old, new, message", [
    ('layout = "V"', 'layout = "boxer"', (r"engine file 'v8\.toml', key crank\.layout: 'boxer' is not covered "
                                          r"\(opposed cylinders each on its own throw\); valid: 'inline', 'V'")),
    ('layout = "V"', 'layout = "W"', r"key crank\.layout: 'W' is not covered \(three or four banks\)"),
    ('layout = "V"', 'layout = "radial"', r"key crank\.layout: 'radial' is not covered"),
    ('layout = "V"', 'layout = "v"', r"key crank\.layout: 'v' is not one of 'inline', 'V'"),
    ('rods = "side-by-side"', 'rods = "fork-and-blade"', (r"key crank\.rods: 'fork-and-blade' is not covered .*"
                                                         r"valid: 'side-by-side'")),
    ('rods = "side-by-side"', 'rods = "split-pin"', r"key crank\.rods: 'split-pin' is not covered"),
    ("bank_angle = 90.0 ", "bank_angle = 1.5708 ", (r"key crank\.bank_angle: 1\.5708 deg is outside the valid range "
                                                    r"\[10, 180\] deg")),
    ("bank_angle = 90.0 ", "bank_angle = 200.0 ", r"key crank\.bank_angle: 200 deg is outside the valid range"),
    ('first_bank = "left"', 'first_bank = "right"', (r"key crank\.firing_order: .* check throw_angles \(a V "
                                                     r"engine's also numbering and first_bank\)")),
    ('\nnumbering = "alternate"', '\nnumbering = "gm"', (r"key crank\.numbering: 'gm' is not one of 'alternate', "
                                                     r"'bank-by-bank'")),
    ('numbering = "alternate"\n', '', r"key crank\.numbering: missing"),
    ("cylinders = 8", "cylinders = 7", r"key crank\.cylinders: 7 is odd; a V engine has two cylinders on each throw"),
    ("main_bearings = 5", "main_bearings = 9", (r"key crank\.cylinders: 8 cylinders in a V \(two a throw, 4 throws\) "
                                                r"need 5 main bearings, main_bearings is 9")),
    ('layout = "V"\n', '', r"key crank\.bank_angle: 90\.0 is for a V engine; add layout = \"V\" or remove bank_angle"),
    ("throw_angles = [0, 90, 270, 180]", "throw_angles = [0, 90, 270, 180, 0, 90, 270, 180]",
     r"key crank\.throw_angles: 8 entries; give 4, one per throw"),
])
def test_a_v_engine_file_is_refused_in_one_line_naming_file_key_and_value(tmp_path, old, new, message):
    text = _v8_text()
    assert old in text
    path = tmp_path / "v8.toml"
    path.write_text(text.replace(old, new, 1))
    with pytest.raises(ValueError, match=message) as refusal:
        load_engine(path)
    assert "\n" not in str(refusal.value)


def test_an_inline_engine_with_a_v_engines_bearings_is_told_about_the_v_layout(tmp_path):
    from stackup.engines import engine_path

    text = engine_path("nef-6").read_text().replace("main_bearings = 7", "main_bearings = 4")
    (tmp_path / "six.toml").write_text(text)
    with pytest.raises(ValueError, match=r"key crank\.cylinders: 6 cylinders in line \(one a throw\) need 7 main "
                                         r"bearings, main_bearings is 4; a V engine: crank\.layout = \"V\""):
        load_engine(tmp_path / "six.toml")


def test_fords_numbering_of_the_same_crank_fires_evenly_as_the_docs_say():
    """docs/engine-file.md: Ford's numbering (1-4 right bank, 5-8 left) with the 5.0 L HO firing order."""
    throw, axis = v_cylinders(8, bank_angle=90.0, numbering="bank-by-bank", first_bank="right")
    fire = firing_offsets(cylinder_throw_angles([0, 90, 270, 180], throw, axis), [1, 3, 7, 2, 6, 5, 4, 8])
    np.testing.assert_array_equal(np.sort(fire), np.arange(0.0, 720.0, 90.0))


USER_V8 = Path(__file__).parents[1] / "data" / "v8_user.toml"


def test_a_users_v8_file_written_from_the_docs_loads_with_fords_numbering():
    crank = load_engine(USER_V8).crank
    assert crank.cylinder_throw == (0, 1, 2, 3, 0, 1, 2, 3)
    assert crank.cylinder_axis == (-45.0, -45.0, -45.0, -45.0, 45.0, 45.0, 45.0, 45.0)  # 1-4 right: leading
    assert crank.pin_loads(ANGLE).shape == (ANGLE.size, 4, 2)


@pytest.mark.integration
def test_a_study_runs_the_builtin_v8_through_the_mechanics():
    """The chain takes four pins' loads on five main bearings: every film periodic, lives of hundreds of hours and
    more (a 4 deg crank step: at 12 deg the films of a 90 deg V8 at 5900 rpm do not become periodic)."""
    from stackup import Study

    ds = Study(engine="gm-ls3-v8", schemes=("iso13778-4",), n_engines=200, pilot_engines=2000, mechanics_engines=4,
               crank_angle_step=4.0, progress=False).run()
    assert ds.sizes["bearing"] == 5
    done = ds.crank_status.values[0, :4] == 0
    assert done.all()
    # two cylinders' gas and inertia on each pin, shared between two supports: tens of kN, the end bearings least
    reaction = ds.reaction_max.values[0]
    assert np.all((reaction > 15e3) & (reaction < 60e3))
    assert np.all(reaction[:, [0, 4]] < reaction[:, 1:4].min(axis=1, keepdims=True))
    h_min = ds.h_min.values[0, :4]
    assert np.all((h_min > 0.05e-6) & (h_min < 20e-6))
    assert np.nanmedian(ds.life.values[0, :4]) > 100 * 3600
