"""Engine loads: pressure model, slider-crank kinematics, firing order."""

import numpy as np
import pytest

from stackup.loads import (
    ATMOSPHERE,
    Combustion,
    Kinematics,
    cylinder_pressure,
    firing_offsets,
    pin_load,
    pin_loads,
)

K = Kinematics(cylinder_bore=0.076, stroke=0.0805, conrod=0.136, reciprocating_mass=0.75, rotating_mass=0.6,
               counterweight_unbalance=0.0)


def test_peak_pressure_is_the_parameter_and_lies_after_tdc():
    angle = np.arange(0, 720, 0.5)
    p = cylinder_pressure(angle, K, Combustion(peak_pressure=12e6))
    assert p.max() == pytest.approx(12e6, rel=2e-3)
    assert 5 < angle[p.argmax()] < 30


def test_motored_compression_is_a_polytrope():
    c = Combustion(peak_pressure=20e6, start=60.0)  # burns after TDC: compression is motored
    v_ivc, v_tdc = K.volume(-180.0, c.compression_ratio), K.volume(0.0, c.compression_ratio)
    assert cylinder_pressure(0.0, K, c) == pytest.approx(c.intake_pressure * (v_ivc / v_tdc) ** 1.35, rel=1e-9)
    assert v_ivc / v_tdc == pytest.approx(c.compression_ratio)


def test_exhaust_and_intake_strokes_at_their_pressures():
    c = Combustion()
    assert cylinder_pressure(270.0, K, c) == c.exhaust_pressure
    assert cylinder_pressure(450.0, K, c) == c.intake_pressure


def test_piston_acceleration_matches_numerical_derivative():
    omega = 400.0
    phi = np.linspace(0, 360, 73)
    x = lambda a: K.crank_radius * np.cos(np.radians(a)) + K.conrod * np.sqrt(1 - (K.crank_radius / K.conrod * np.sin(np.radians(a))) ** 2)
    h = 1e-3
    numeric = (x(phi + h) - 2 * x(phi) + x(phi - h)) / np.radians(h) ** 2 * omega**2
    np.testing.assert_allclose(K.piston_acceleration(phi, omega), numeric, rtol=1e-5, atol=1e-3 * K.crank_radius * omega**2)


def test_pin_load_at_tdc_is_gas_minus_inertia():
    omega = 400.0
    lam = K.crank_radius / K.conrod
    f = pin_load(0.0, 10e6, K, omega)
    gas = (10e6 - ATMOSPHERE) * K.piston_area
    inertia = (K.reciprocating_mass * (1 + lam) + K.rotating_mass) * K.crank_radius * omega**2
    assert f[0] == pytest.approx(gas - inertia)
    assert f[1] == pytest.approx(0.0, abs=1e-9)


def test_side_force_follows_the_rod_angle():
    f = pin_load(90.0, ATMOSPHERE, Kinematics(0.076, 0.0805, 0.136, 0.0, 0.0, 0.0), 0.0)
    assert f[0] == 0 and f[1] == 0
    f = pin_load(90.0, 5e6, Kinematics(0.076, 0.0805, 0.136, 0.0, 0.0, 0.0), 0.0)
    lam = 0.0805 / 2 / 0.136
    assert f[1] / f[0] == pytest.approx(lam / np.sqrt(1 - lam**2))


def test_firing_offsets_inline_four_and_six():
    np.testing.assert_array_equal(firing_offsets([0, 180, 180, 0], [1, 3, 4, 2]), [0, 540, 180, 360])
    np.testing.assert_array_equal(firing_offsets([0, 240, 120, 120, 240, 0], [1, 5, 3, 6, 2, 4]),
                                  [0, 480, 240, 600, 120, 360])
    with pytest.raises(ValueError, match="firing_order: \\[1, 2, 2, 4\\] is not a permutation"):
        firing_offsets([0, 180, 180, 0], [1, 2, 2, 4])


def test_each_cylinder_peaks_at_its_firing_angle():
    angle = np.arange(720.0)
    loads = pin_loads(angle, kinematics=K, combustion=Combustion(), throw_angles=[0, 180, 180, 0],
                      firing_order=[1, 3, 4, 2], speed=400.0)
    peaks = angle[loads[:, :, 0].argmax(axis=0)]
    np.testing.assert_allclose(np.mod(peaks - [0, 540, 180, 360], 720), peaks[0], atol=1)


def test_user_pressure_trace_replaces_the_model():
    angle = np.arange(720.0)
    trace = (np.array([0.0, 360.0, 719.0]), np.array([5e6, 1e5, 5e6]))
    massless = Kinematics(0.076, 0.0805, 0.136, 0.0, 0.0, 0.0)
    loads = pin_loads(angle, kinematics=massless, combustion=Combustion(), throw_angles=[0], firing_order=[1], speed=1.0,
                      pressure_trace=trace)
    assert loads[0, 0, 0] == pytest.approx((5e6 - ATMOSPHERE) * K.piston_area, rel=1e-6)


def test_bad_kinematics():
    with pytest.raises(ValueError, match="conrod: 0.03 m is not longer than the crank radius"):
        Kinematics(0.076, 0.08, 0.03, 0.5, 0.5, 0.0)
    with pytest.raises(ValueError, match="peak_pressure: .* is below the motored peak"):
        cylinder_pressure(0.0, K, Combustion(peak_pressure=2e6))


def test_engine_with_a_csv_pressure_trace(tmp_path):
    from importlib import resources

    from stackup.engines import load_engine

    angle = np.arange(0.0, 720.0, 2.0)
    pressure = 1e5 + 9e6 * np.exp(-(((angle + 360) % 720 - 360 - 12) / 20) ** 2)
    (tmp_path / "trace.csv").write_text("crank_angle_deg,pressure_pa\n" + "\n".join(f"{a},{p}" for a, p in zip(angle, pressure)))
    text = (resources.files("stackup") / "data" / "engines" / "iso-example.toml").read_text()
    engine_file = tmp_path / "traced.toml"
    engine_file.write_text(text.replace("peak_pressure = 13.0e6            # [Pa]", 'pressure_trace = "trace.csv"'))
    crank = load_engine(engine_file).crank
    loads = crank.pin_loads(np.arange(720.0))
    modelled = load_engine("iso-example").crank.pin_loads(np.arange(720.0))
    assert crank.pressure_trace is not None
    # the trace peaks at 9.1 MPa, the model at 13 MPa: gas loads scale accordingly
    assert 0.6 < loads[:, 0, 0].max() / modelled[:, 0, 0].max() < 0.8
    (tmp_path / "bad.csv").write_text("angle,p\n0,1\n")
    engine_file.write_text(text.replace("peak_pressure = 13.0e6            # [Pa]", 'pressure_trace = "bad.csv"'))
    with pytest.raises(ValueError, match="missing column"):
        load_engine(engine_file)


def test_crank_angle_zero_is_the_first_fired_cylinders_tdc_whatever_its_throw_angle():
    """Throws written from another reference ([180, 0, 0, 180] for [0, 180, 180, 0]) are the same crank: the same
    loads, cylinder 1 firing at crank angle 0 (before, its pressure peaked with its pin at the bottom)."""
    angle = np.arange(0.0, 720.0, 2.0)
    four = {"kinematics": K, "combustion": Combustion(), "firing_order": [1, 3, 4, 2], "speed": 400.0}
    np.testing.assert_allclose(pin_loads(angle, throw_angles=[180, 0, 0, 180], **four),
                               pin_loads(angle, throw_angles=[0, 180, 180, 0], **four), rtol=1e-9, atol=1e-6)
