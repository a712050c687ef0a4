"""Press fit: limits, monotonicity, continuity, the FE reference, kernel twin and bad input."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from stackup import materials
from stackup._kernels import press_fit as kernel
from stackup.fit import press_fit, press_fit_extremes, tiers

BASE = dict(housing_bore=50.009e-3, housing_outer=80e-3, shell_wall=1.98e-3, crush_height=0.08e-3, bearing_width=22e-3,
            check_bore=50.000e-3, journal_d=46.009e-3, shell_material="steel-back")


def fit(**kw):
    return press_fit(**{**BASE, **kw})


def test_zero_crush_at_the_check_state_gives_the_check_stress():
    # A rigid housing (steel, enormous outer diameter is not rigid enough: use a material 1e6 times stiffer)
    rigid = materials.Material("rigid", 210e15, 0.3, 0.0)
    r = fit(housing_bore=50.0e-3, check_bore=50.0e-3, crush_height=0.0, housing_material=rigid)
    assert r.shell_stress == pytest.approx(100e6, rel=1e-6)
    r = fit(housing_bore=50.0e-3, check_bore=50.0e-3, crush_height=0.0, housing_material=rigid, check_stress=80e6)
    assert r.shell_stress == pytest.approx(80e6, rel=1e-6)


def test_infinitely_stiff_housing_takes_no_interference():
    rigid = materials.Material("rigid", 210e15, 0.3, 0.0)
    r = fit(housing_material=rigid)
    assert r.housing_swell < 1e-10  # 0.1 nm
    # all interference in the shell: its extra compression over the check state is E * crush / (pi * R) (thin limit)
    stiff = fit(housing_material=rigid, housing_bore=50.0e-3)
    extra = (stiff.shell_stress - 100e6)
    thin_estimate = 205e9 * 0.08e-3 / (np.pi * 25e-3)
    assert extra == pytest.approx(thin_estimate, rel=0.08)


def test_more_crush_gives_more_pressure_stress_and_swell():
    crush = np.linspace(0.0, 0.15e-3, 16)
    r = fit(crush_height=crush)
    for field in (r.contact_pressure, r.shell_stress, r.housing_swell, r.clearance):
        assert np.all(np.diff(field) > 0)


def test_heating_an_aluminium_housing_loosens_the_fit():
    t = np.linspace(20.0, 150.0, 14)
    r = fit(housing_material="aluminium", temperature=t, crush_height=0.05e-3)
    assert np.all(np.diff(r.contact_pressure) <= 0)
    assert np.all(np.diff(r.clearance) > 0)
    assert r.loss_of_fit[-1] and not r.loss_of_fit[0]


def test_steel_housing_is_almost_insensitive_to_temperature():
    al = fit(housing_material="aluminium", temperature=[20.0, 120.0])
    steel = fit(housing_material="steel", temperature=[20.0, 120.0])
    change_steel = abs(steel.contact_pressure[1] - steel.contact_pressure[0]) / steel.contact_pressure[0]
    change_al = abs(al.contact_pressure[1] - al.contact_pressure[0]) / al.contact_pressure[0]
    assert change_steel < 0.1 and change_al > 0.5
    assert abs(steel.clearance[1] - steel.clearance[0]) < 2e-6 < abs(al.clearance[1] - al.clearance[0])


def test_aluminium_housing_gives_less_stress_and_more_swell_than_steel():
    al, steel = fit(housing_material="aluminium"), fit(housing_material="steel")
    assert al.shell_stress < steel.shell_stress
    assert al.housing_swell > 1.5 * steel.housing_swell


def test_thicker_housing_wall_gives_less_swell():
    r = fit(housing_outer=np.array([1.25, 1.5, 2.0, 3.0]) * 50.009e-3)
    assert np.all(np.diff(r.housing_swell) < 0)
    assert np.all(np.diff(r.contact_pressure) > 0)


def test_loss_of_fit_is_continuous_and_never_negative():
    # sweep the crush through the point where the fit is lost in a hot aluminium housing
    crush = np.linspace(0.0, 0.06e-3, 601)
    r = fit(housing_material="aluminium", temperature=120.0, crush_height=crush)
    assert r.loss_of_fit.any() and not r.loss_of_fit.all()
    assert np.all(r.contact_pressure >= 0) and np.all(r.contact_pressure[r.loss_of_fit] == 0)
    step = np.max(np.abs(np.diff(r.clearance)))
    typical = np.median(np.abs(np.diff(r.clearance[~r.loss_of_fit])))
    assert step < 3 * typical  # no jump at the loss of fit


@pytest.mark.parametrize("housing", ["steel", "aluminium", "grey-cast-iron"])
@pytest.mark.parametrize("ratio", [1.25, 2.0])
@pytest.mark.parametrize("temperature", [20.0, 150.0])
def test_lame_tier_agrees_with_fe_reference(housing, ratio, temperature):
    kw = dict(housing_material=housing, housing_outer=ratio * 50.009e-3, temperature=temperature,
              crush_height=np.array([0.0, 0.05e-3, 0.15e-3]), shell_wall=np.array([1.6e-3, 1.98e-3, 3.0e-3]))
    fast, ref = fit(**kw), fit(**kw, method="fe")
    np.testing.assert_array_equal(fast.loss_of_fit, ref.loss_of_fit)
    # the FE with 24 quadratic elements per ring is converged to ~1e-8 (test below)
    np.testing.assert_allclose(fast.contact_pressure, ref.contact_pressure, rtol=1e-7, atol=1.0)
    np.testing.assert_allclose(fast.shell_stress, ref.shell_stress, rtol=1e-7, atol=1.0)
    np.testing.assert_allclose(fast.clearance, ref.clearance, rtol=0, atol=1e-11)
    np.testing.assert_allclose(fast.housing_swell, ref.housing_swell, rtol=1e-7, atol=1e-13)


def test_fe_reference_is_grid_converged():
    from stackup.fit import reference

    args = (50.009e-3, 60e-3, 3.0e-3, 0.1e-3, 50e-3, 100e6, 80.0, (71e9, 0.33, 21e-6), (205e9, 0.29, 12.2e-6), 11.5e-6, 46e-3)
    coarse = reference.press_fit_one(*args, elements=12)
    fine = reference.press_fit_one(*args, elements=48)
    assert coarse["contact_pressure"] == pytest.approx(fine["contact_pressure"], rel=1e-7)


def test_thin_ring_tier_error_is_a_few_percent_for_thick_walls():
    thick = fit(shell_wall=3.0e-3, crush_height=0.1e-3)
    thin = fit(shell_wall=3.0e-3, crush_height=0.1e-3, method="thin-ring")
    err = abs(thin.contact_pressure / thick.contact_pressure - 1)
    assert 0.001 < err < 0.1


def test_shell_stress_balances_contact_pressure():
    # equilibrium of a half ring: hoop force t * sigma = p * bore radius
    r = fit(temperature=20.0)
    assert r.shell_stress * 1.98e-3 == pytest.approx(r.contact_pressure * 50.009e-3 / 2, rel=1e-12)


def test_broadcasts_over_all_array_inputs():
    r = fit(housing_bore=np.full((4, 1), 50.009e-3), crush_height=np.linspace(0.05e-3, 0.1e-3, 3), temperature=[[[20.0]], [[90.0]]])
    assert r.contact_pressure.shape == (2, 4, 3)
    assert r.clearance.shape == (2, 4, 3)
    assert fit(journal_d=None).clearance is None


case = st.fixed_dictionaries({
    "bore": st.floats(40e-3, 120e-3), "ratio": st.floats(1.1, 3.0), "wall": st.floats(1.0e-3, 4.0e-3),
    "lining": st.floats(0.0, 0.4), "crush": st.floats(0.0, 0.2e-3), "block": st.floats(-20e-6, 20e-6),
    "stress": st.floats(20e6, 200e6), "dt": st.floats(-40.0, 200.0),
})


@given(st.lists(case, min_size=1, max_size=8))
def test_kernel_matches_numpy_twin(cases):
    cols = {k: np.array([c[k] for c in cases]) for k in cases[0]}
    housing, back, lining = (71e9, 0.33, 21e-6), (205e9, 0.29, 12.2e-6), (72e9, 0.34, 18.5e-6)
    bore, wall = cols["bore"], cols["wall"]
    t_lining = cols["lining"] * wall
    te = tiers.equivalent_wall(wall, t_lining, lining[0], back[0])
    alpha = tiers.equivalent_expansion(wall, t_lining, lining[0], back[0], lining[2], back[2])
    growth = tiers.wall_expansion(wall, t_lining, alpha, back[1], lining[1], back[2], lining[2])
    journal = bore - 2 * wall - 40e-6
    for thin in (False, True):
        want = tiers.press_fit(bore, bore * cols["ratio"], wall, te, cols["crush"], bore + cols["block"],
                               cols["stress"], cols["dt"], housing, (back[0], back[1], alpha), 11.5e-6, journal, thin,
                               wall_growth=growth)
        got = kernel.press_fit(bore.size, kernel.Bearings(bore, bore * cols["ratio"], wall, t_lining, cols["crush"],
                                                         bore + cols["block"], cols["stress"], journal, cols["dt"]),
                               kernel.Materials(*housing, *back, *lining, 11.5e-6),
                               kernel.Options(thin, True, tiers.FREE_RADIUS_ITERATIONS))
        names = ["contact_pressure", "shell_stress", "housing_swell", "bore_in_service", "shell_bore", "clearance", "loss_of_fit"]
        for name, g in zip(names, got):
            np.testing.assert_allclose(g, want[name], rtol=1e-12, atol=1e-18, err_msg=name)


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"shell_wall": -1e-3}, r"shell_wall: -0.001 is not valid; must be > 0"),
        ({"housing_outer": 50.0e-3}, r"housing_outer: 0.05 m is not above housing_bore 0.050009 m"),
        ({"housing_material": "unobtainium"}, r"material: 'unobtainium' is not a known material"),
        ({"crush_height": np.nan}, r"crush_height: nan is not a finite number"),
        ({"crush_height": -0.01e-3}, r"crush_height: -1e-05 is not valid; must be >= 0"),
        ({"temperature": 400.0}, r"temperature: 400.0 degC is outside the valid range \[-60.0, 300.0\]"),
        ({"method": "reynold"}, r"method: 'reynold' is not one of 'lame', 'thin-ring', 'fe'"),
        ({"shell_wall": 30e-3}, r"shell_wall: 0.03 m is not below half the housing bore"),
    ],
)
def test_bad_input_is_named(kw, message):
    with pytest.raises(ValueError, match=message):
        fit(**kw)


def test_user_material_file_adds_entries(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text('[magnesium]\nmodulus = 45e9\npoisson = 0.35\nexpansion = 26e-6\nsource = "test"\n')
    assert materials.load(path) == ["magnesium"]
    assert fit(housing_material="magnesium").housing_swell > fit(housing_material="aluminium").housing_swell


def test_crush_check_force_acts_on_the_steel_equivalent_section():
    # Kopeliovich, sec. 3: F = 100 MPa * A_calc, A_calc the section of a steel-only shell of equal stiffness.
    # A lined shell at its check state (rigid housing of the block's bore, zero crush) carries exactly the
    # check's steel-equivalent stress, and behaves as a steel shell of the equivalent wall.
    rigid = materials.Material("rigid", 210e15, 0.3, 0.0)
    lining = materials.get("copper-lead")
    lined = fit(housing_bore=50.0e-3, crush_height=0.0, housing_material=rigid, lining_thickness=0.4e-3,
                lining_material=lining)
    assert lined.shell_stress == pytest.approx(100e6, rel=1e-6)
    equivalent = 1.98e-3 - 0.4e-3 + 0.4e-3 * lining.modulus / materials.get("steel-back").modulus
    kw = dict(housing_material="nodular-cast-iron", crush_height=0.06e-3, journal_d=None)
    a = fit(**kw, lining_thickness=0.4e-3, lining_material=lining)
    b = fit(**kw, shell_wall=equivalent)
    assert a.contact_pressure == pytest.approx(b.contact_pressure, rel=1e-12)
    assert a.shell_stress == pytest.approx(b.shell_stress, rel=1e-12)
    # the check force on the full wall would overstate the shell's stiffness and the pressure
    assert a.contact_pressure < fit(**kw).contact_pressure


@pytest.mark.parametrize("lining, thickness", [("copper-lead", 0.3e-3), ("aluminium-tin", 0.3e-3),
                                               ("copper-lead", 0.6e-3)])
@pytest.mark.parametrize("housing", ["nodular-cast-iron", "aluminium"])
def test_steel_equivalent_ring_against_layered_fe(lining, thickness, housing):
    # the FE reference meshes steel back and lining as bonded layers with their own modulus, Poisson's
    # ratio and expansion; the closed form's steel-equivalent ring is within 0.3 % in pressure and stress
    # (0.05 MPa, 1 MPa near the loss of fit) and 0.5 um in clearance (the lining's Poisson thickening), from -30 to 130 degC
    kw = dict(housing_material=housing, lining_thickness=thickness, lining_material=lining,
              crush_height=np.array([0.03e-3, 0.08e-3, 0.12e-3]), temperature=np.array([[-30.0], [20.0], [130.0]]))
    fast, ref = fit(**kw), fit(**kw, method="fe")
    np.testing.assert_array_equal(fast.loss_of_fit, ref.loss_of_fit)
    np.testing.assert_allclose(fast.contact_pressure, ref.contact_pressure, rtol=3e-3, atol=0.05e6)
    np.testing.assert_allclose(fast.shell_stress, ref.shell_stress, rtol=3e-3, atol=1e6)
    np.testing.assert_allclose(fast.housing_swell, ref.housing_swell, atol=0.05e-6)
    np.testing.assert_allclose(fast.clearance, ref.clearance, atol=0.5e-6)


def test_check_bore_is_the_standard_block_and_must_be_given():
    with pytest.raises(ValueError, match=r"check_bore: missing; the crush height is defined in a checking block"):
        press_fit(**{k: v for k, v in BASE.items() if k != "check_bore"})


def test_a_smaller_bore_in_the_same_block_gives_more_swell():
    # the crush height is checked in one block (the standard's); a housing bored to the small end of its
    # tolerance takes more interference: the swell follows the bore
    r = fit(housing_bore=np.linspace(50.000e-3, 50.018e-3, 7), housing_material="nodular-cast-iron")
    assert np.all(np.diff(r.housing_swell) < 0) and np.all(np.diff(r.contact_pressure) < 0)
    # 18 um more bore takes 9 um of radial interference away: dp = 9 um / (C_H + a/r0 C_S), within 2 %
    a, b = 25.0e-3, 40e-3
    nodular, back = materials.get("nodular-cast-iron"), materials.get("steel-back")
    c_h = tiers.housing_compliance(a, b, nodular.modulus, nodular.poisson)
    c_s = tiers.shell_compliance(a, 1.98e-3, back.modulus, back.poisson, False)
    assert r.contact_pressure[0] - r.contact_pressure[-1] == pytest.approx(9e-6 / (c_h + c_s), rel=0.02)


def test_lining_input_is_checked():
    with pytest.raises(ValueError, match=r"lining_material: missing"):
        fit(lining_thickness=0.3e-3)
    with pytest.raises(ValueError, match=r"lining_thickness: 0.002 m is not below the shell wall"):
        fit(lining_thickness=2e-3, lining_material="copper-lead")


EXTREME = {k: v for k, v in BASE.items() if k != "journal_d"}


@pytest.mark.parametrize("housing, cold_bites", [("aluminium", True), ("nodular-cast-iron", False),
                                                 ("grey-cast-iron", False)])
def test_extremes_find_the_stress_and_pressure_where_they_bite(housing, cold_bites):
    # a housing expanding more than the steel back (aluminium) is tightest cold, loosest hot; cast irons
    # (alpha below the steel back's) the other way round
    temps = [-30.0, 20.0, 100.0, 130.0]
    crush = np.array([0.06e-3, 0.12e-3])
    ext = press_fit_extremes(temperatures=temps, **{**EXTREME, "crush_height": crush, "housing_material": housing})
    each = [fit(**{**EXTREME, "crush_height": crush, "housing_material": housing}, temperature=t) for t in temps]
    stress = np.array([r.shell_stress for r in each])
    pressure = np.array([r.contact_pressure for r in each])
    np.testing.assert_array_equal(ext.highest_shell_stress, stress.max(axis=0))
    np.testing.assert_array_equal(ext.lowest_contact_pressure, pressure.min(axis=0))
    np.testing.assert_array_equal(ext.highest_stress_temperature, -30.0 if cold_bites else 130.0)
    np.testing.assert_array_equal(ext.lowest_pressure_temperature, 130.0 if cold_bites else -30.0)
    assert not ext.loss_of_fit.any()


def test_extremes_report_a_fit_lost_at_any_temperature():
    ext = press_fit_extremes(temperatures=[20.0, 150.0], **{**EXTREME, "crush_height": 0.01e-3,
                                                           "housing_material": "aluminium"})
    assert ext.loss_of_fit and ext.lowest_contact_pressure == 0.0 and ext.lowest_pressure_temperature == 150.0


def test_extremes_refuse_a_single_temperature_argument():
    with pytest.raises(ValueError, match=r"temperature: not an argument of press_fit_extremes"):
        press_fit_extremes(temperatures=[20.0], temperature=20.0, **EXTREME)
    with pytest.raises(ValueError, match=r"temperatures: 400.0 degC is outside the valid range"):
        press_fit_extremes(temperatures=[20.0, 400.0], **EXTREME)


def test_old_name_length_still_gives_the_bearing_width_with_a_warning():
    new = fit()
    kw = {k: v for k, v in BASE.items() if k != "bearing_width"}
    with pytest.warns(DeprecationWarning, match=r"length= is deprecated; use bearing_width="):
        old = press_fit(**kw, length=22e-3)
    for name in ("contact_pressure", "shell_stress", "clearance"):
        np.testing.assert_array_equal(getattr(old, name), getattr(new, name))
    with pytest.warns(DeprecationWarning, match=r"press_fit_extremes: length= is deprecated"):
        old = press_fit_extremes(temperatures=[20.0], **{k: v for k, v in kw.items() if k != "journal_d"},
                                 length=22e-3)
    np.testing.assert_array_equal(old.highest_shell_stress, new.shell_stress)
    with pytest.raises(TypeError, match=r"give bearing_width= \(the old name length= is deprecated\), not both"):
        press_fit(**BASE, length=22e-3)


def test_trusted_callers_get_the_same_numbers_without_the_checks():
    # the study's chain may run in trusted(): the body then sees the caller's values, not the checked arrays
    from stackup._validate import trusted

    kw = dict(BASE, housing_bore=np.array([50.004e-3, 50.012e-3]), crush_height=[0.07e-3, 0.09e-3],
              lining_thickness=0.3e-3, lining_material="aluminium-tin", temperature=95.0)
    checked = fit(**kw)
    extremes = press_fit_extremes(temperatures=(-20.0, 20.0, 130.0), **{k: v for k, v in kw.items()
                                                                          if k not in ("journal_d", "temperature")})
    with trusted():
        raw = fit(**kw)
        raw_extremes = press_fit_extremes(temperatures=(-20.0, 20.0, 130.0),
                                          **{k: v for k, v in kw.items() if k not in ("journal_d", "temperature")})
    for name in ("contact_pressure", "shell_stress", "housing_swell", "shell_bore", "clearance", "loss_of_fit"):
        np.testing.assert_array_equal(getattr(raw, name), getattr(checked, name))
    for name in ("highest_shell_stress", "highest_stress_temperature", "lowest_contact_pressure",
                 "lowest_pressure_temperature", "loss_of_fit"):
        np.testing.assert_array_equal(getattr(raw_extremes, name), getattr(extremes, name))


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"bearing_width": 0.0}, r"bearing_width: 0.0 is not valid; must be > 0"),
        ({"housing_bore": np.full(3, 50e-3), "crush_height": np.full(2, 0.1e-3)},
         r"press_fit: the array inputs do not broadcast together: shapes \(3,\), \(\), \(\), \(\), \(2,\)"),
        ({"journal_material": "unobtainium"}, r"journal_material: 'unobtainium' is not a known material"),
        ({"lining_thickness": 0.3e-3, "lining_material": "unobtainium"},
         r"lining_material: 'unobtainium' is not a known material"),
    ],
)
def test_declared_checks_name_the_argument(kw, message):
    with pytest.raises(ValueError, match=message):
        fit(**kw)


def test_extremes_refuse_a_journal_and_unknown_arguments():
    with pytest.raises(ValueError, match=r"journal_d: not an argument of press_fit_extremes"):
        press_fit_extremes(temperatures=[20.0], journal_d=46e-3, **EXTREME)
    with pytest.raises(TypeError, match=r"unexpected keyword argument\(s\) \['colour'\]"):
        press_fit_extremes(temperatures=[20.0], colour="red", **EXTREME)
    with pytest.raises(ValueError, match=r"temperatures: \[\] is not a non-empty sequence of temperatures"):
        press_fit_extremes(temperatures=[], **EXTREME)


def test_a_hotter_journal_takes_its_own_thermal_growth_off_the_clearance():
    # closed form: d_J * alpha_J * dT_J; a steel journal of 46.009 mm, 10 K hotter than its housing
    alpha = materials.get("steel").expansion
    base, hot = fit(temperature=100.0), fit(temperature=100.0, journal_temperature=110.0)
    assert base.clearance - hot.clearance == pytest.approx(46.009e-3 * alpha * 10.0, rel=1e-9)
    assert 5.0e-6 < base.clearance - hot.clearance < 5.6e-6  # "a journal 10 K hotter takes about 5 um off"
    # the journal's temperature changes nothing else, and by default it is the housing's
    for field in ("contact_pressure", "shell_stress", "housing_swell", "shell_bore"):
        assert getattr(hot, field) == pytest.approx(getattr(base, field), rel=1e-12)
    assert fit(temperature=100.0, journal_temperature=100.0).clearance == pytest.approx(base.clearance, rel=1e-12)


def test_the_journal_temperature_broadcasts_and_the_reference_tier_agrees():
    t = np.array([100.0, 110.0, 120.0])
    lame = fit(temperature=100.0, journal_temperature=t)
    fe = fit(temperature=100.0, journal_temperature=t, method="fe")
    assert lame.clearance.shape == (3,) and np.all(np.diff(lame.clearance) < 0)
    np.testing.assert_allclose(np.diff(fe.clearance), np.diff(lame.clearance), rtol=1e-9)  # same journal growth
    # numpy twin: the same clearance with the journal's own temperature change
    twin = tiers.journal_in_service(46.009e-3, materials.get("steel").expansion, t - 20.0)
    np.testing.assert_allclose(lame.shell_bore - twin, lame.clearance, rtol=0, atol=1e-15)


def test_a_journal_temperature_outside_the_models_range_is_named():
    with pytest.raises(ValueError, match="journal_temperature"):
        fit(journal_temperature=400.0)
    with pytest.raises(ValueError, match="journal_temperature"):
        fit(journal_temperature=float("nan"))
