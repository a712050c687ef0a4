"""Press fit of a shell pair in its housing bore: the public entry points, validated once, over the tiers.

:func:`press_fit` checks its arguments, runs the tier it is asked for
(the closed forms of :mod:`stackup.fit.tiers` through the numba kernel, or the
finite-element reference of :mod:`stackup.fit.reference`) and takes the
journal at its own temperature off the shell bore; :func:`press_fit_extremes`
runs it over the declared temperatures and keeps the highest shell stress and
the lowest contact pressure.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .. import materials
from .._validate import InRange, OneOf, OrNone, Positive, renamed, validated
from .._kernels import press_fit as _kernel
from . import reference, tiers

METHODS = ("lame", "thin-ring", "fe")
#: Each tier and its limits in one line, for reports; errors against the finite-element reference are measured
#: by ``python studies/press_fit_tiers.py`` (reports/press_fit_tiers.md).
TIER_NOTES = {
    "lame": "thick-ring (Lamé) tier, exact within linear plane-stress elasticity",
    "thin-ring": "thin-ring tier (a shop formula: ignores the shell's radial stress)",
    "fe": "finite-element reference tier",
}


@dataclass(frozen=True)
class PressFit:
    r"""Result of :func:`press_fit`; arrays broadcast over the inputs.

    Attributes
    ----------
    contact_pressure : numpy.ndarray
        Pressure between shell backs and housing bore [Pa]; 0 where the fit is lost.
    shell_stress : numpy.ndarray
        Mean compressive hoop stress of the shell's steel-equivalent wall [Pa],
        positive in compression (Kopeliovich's :math:`\sigma`: hoop force over
        :math:`A_{calc}`).
    housing_swell : numpy.ndarray
        Elastic growth of the bore diameter from the contact pressure [m].
    bore_in_service : numpy.ndarray
        Housing bore diameter at the operating temperature, swell included [m].
    shell_bore : numpy.ndarray
        Bore diameter of the fitted shell pair in service [m].
    clearance : numpy.ndarray or None
        Diametral operating clearance, shell bore minus journal at temperature [m]
        (None without ``journal_d``).
    loss_of_fit : numpy.ndarray of bool
        True where the shells have no interference left (pressure 0).
    """

    contact_pressure: np.ndarray
    shell_stress: np.ndarray
    housing_swell: np.ndarray
    bore_in_service: np.ndarray
    shell_bore: np.ndarray
    clearance: np.ndarray | None
    loss_of_fit: np.ndarray


#: An operating or assembly temperature the press-fit model is meant for [degC] (an engine file's too).
TEMPERATURE = InRange(-60.0, 300.0, unit=" degC")
#: The steel-equivalent wall compression of a crush check [Pa] (an engine file's too): the standard check is
#: 100 MPa (Kopeliovich, sec. 3); above 2 GPa no shell steel holds it.
CHECK_STRESS = InRange(0.0, 2e9, lo_open=True, unit=" Pa")

#: The checks of the arguments :func:`press_fit` and :func:`press_fit_extremes` share.
_CHECKS = dict(housing_bore=Positive(), housing_outer=Positive(), shell_wall=Positive(),
               crush_height=Positive(zero=True), bearing_width=Positive(), check_bore=Positive(),
               check_stress=CHECK_STRESS, lining_thickness=Positive(zero=True),
               assembly_temperature=TEMPERATURE, housing_material=materials.Known(),
               shell_material=materials.Known(), journal_material=materials.Known(),
               lining_material=OrNone(materials.Known()), method=OneOf(METHODS))


def _check_bore_given(args):
    if args["check_bore"] is None:
        raise ValueError("check_bore: missing; the crush height is defined in a checking block whose bore is the "
                         "nominal housing bore (ISO 3548-3), e.g. an engine file's press_fit.check_bore "
                         "(default: the lower drawing limit of the housing bore)")


def _lining_material_given(args):
    if args["lining_material"] is None and np.any(args["lining_thickness"] > 0):
        raise ValueError("lining_material: missing; a lining_thickness > 0 needs the lining's material")


def _inputs_broadcast(args):
    names = ("housing_bore", "housing_outer", "shell_wall", "lining_thickness", "crush_height", "check_bore",
             "check_stress", "temperature", "assembly_temperature", "journal_d", "journal_temperature")
    shapes = [np.shape(args[name]) for name in names if args.get(name) is not None]
    try:
        np.broadcast_shapes(*shapes)
    except ValueError:
        raise ValueError("press_fit: the array inputs do not broadcast together: shapes "
                         + ", ".join(map(str, shapes))) from None


def _rings_nest(args):
    """The housing ring around the bore, the shell wall inside half the bore, the lining inside the wall."""
    bore, outer = np.broadcast_arrays(args["housing_bore"], args["housing_outer"])
    if np.any(outer <= bore):
        i = np.argmax(outer <= bore)
        raise ValueError(f"housing_outer: {float(outer.flat[i])!r} m is not above housing_bore "
                         f"{float(bore.flat[i])!r} m; the outer diameter must exceed the bore")
    if np.any(2.0 * args["shell_wall"] >= args["housing_bore"]):
        raise ValueError(f"shell_wall: {float(np.max(args['shell_wall']))!r} m is not below half the housing bore")
    lining, wall = np.broadcast_arrays(args["lining_thickness"], args["shell_wall"])
    if np.any(lining >= wall):
        i = np.argmax(lining >= wall)
        raise ValueError(f"lining_thickness: {float(lining.flat[i])!r} m is not below the shell wall "
                         f"{float(wall.flat[i])!r} m; the steel back needs a thickness")


#: The checks across arguments, in the order they run.
_RELATIONS = (_check_bore_given, _lining_material_given, _inputs_broadcast, _rings_nest)


@renamed(length="bearing_width")
@validated(relations=_RELATIONS, temperature=TEMPERATURE, journal_d=Positive(),
           journal_temperature=OrNone(TEMPERATURE), **_CHECKS)
def press_fit(*, housing_bore, housing_outer, shell_wall, crush_height, bearing_width, check_bore=None,
              housing_material="steel", shell_material="steel", lining_thickness=0.0, lining_material=None,
              temperature=20.0, assembly_temperature=20.0, check_stress=100e6, journal_d=None,
              journal_material="steel", journal_temperature=None, method="lame"):
    r"""Contact pressure, shell stress, housing swell and operating clearance of a shell pair.

    Parameters
    ----------
    housing_bore : array_like
        Free housing bore diameter at the assembly temperature [m].
    housing_outer : array_like
        Equivalent outer diameter of the housing ring [m]; must exceed the bore.
    shell_wall : array_like
        Crown wall thickness of the shells, steel back plus lining [m].
    crush_height : array_like
        Crush height per half shell, measured in a checking block of bore
        ``check_bore`` under the check force :math:`F = \sigma_c A_{calc}` [m], >= 0.
    bearing_width : array_like
        Axial width of the shells [m] (``length`` before, deprecated); plane
        stress, so it scales forces only (the check force
        :math:`F = \sigma_c\,t_e\,L`) and is validated.
    check_bore : array_like
        Bore diameter of the checking block the crush height was measured in
        [m]: the standard's block (ISO 3548-3), whose bore is the nominal
        housing bore, not each housing's own bore. Required: a block of the
        bearing's own bore would make the swell independent of the bore size.
    housing_material, shell_material, journal_material : str or Material
        Names from :mod:`stackup.materials` (or Material objects);
        ``shell_material`` is the steel back.
    lining_thickness : array_like
        Thickness of the bearing lining within ``shell_wall`` [m], in
        [0, shell_wall); 0 for a plain steel shell.
    lining_material : str or Material, optional
        Lining material (needed when ``lining_thickness`` > 0); enters the
        steel-equivalent wall :math:`t_e = t - t_L + t_L E_L/E_S`.
    temperature : array_like
        Operating temperature of housing, shells and journal [degC].
    assembly_temperature : array_like
        Temperature at assembly and crush check [degC].
    check_stress : float
        Steel-equivalent wall compression of the crush check [Pa]
        (100 MPa: Kopeliovich, sec. 3).
    journal_d : array_like, optional
        Journal diameter at the assembly temperature [m]; gives ``clearance``.
    journal_temperature : array_like, optional
        The journal's own temperature in service [degC]; default
        ``temperature``. A journal runs hotter than the bulkhead around its
        bearing (often 10-20 K, physics.md sec. 3): each kelvin takes
        :math:`\alpha_J d_J` off the diametral clearance (0.53 um per K for
        a 46 mm steel journal).
    method : {"lame", "thin-ring", "fe"}
        Tier (see module docstring).

    Returns
    -------
    PressFit

    Notes
    -----
    Equations in :mod:`stackup.fit.tiers`; the operating clearance is the shell
    bore in service less the journal at its own temperature,
    :math:`C = D_{shell} - d_J\,(1 + \alpha_J (T_J - T_{assembly}))`
    (:func:`stackup.fit.tiers.journal_in_service`). Loss of fit (``loss_of_fit``) gives
    zero pressure and stress, never a negative pressure; the loose shells then
    follow the bore, so the clearance is continuous through the loss of fit.

    References
    ----------
    .. [1] Kopeliovich, D., *Crush height of engine bearings* (press fit,
       crush check on the steel-equivalent section :math:`A_{calc}`).
    """
    housing, shell, journal = (materials.get(m) for m in (housing_material, shell_material, journal_material))
    lining = shell if lining_material is None else materials.get(lining_material)
    bearings = dict(housing_bore=housing_bore, housing_outer=housing_outer, shell_wall=shell_wall,
                    lining_thickness=lining_thickness, crush_height=crush_height, check_bore=check_bore,
                    check_stress=check_stress, journal_d=housing_bore if journal_d is None else journal_d,
                    delta_t=temperature - assembly_temperature)
    shape = np.broadcast_shapes(*(np.shape(x) for x in bearings.values()), np.shape(journal_temperature))
    rings = _kernel.Materials(*(float(value) for m in (housing, shell, lining)
                                for value in (m.modulus, m.poisson, m.expansion)), float(journal.expansion))
    fit = (_by_elements(bearings, shape, rings) if method == "fe" else
           _by_kernel(bearings, shape, rings, thin=method == "thin-ring"))
    if journal_d is None:
        return fit
    journal_t = temperature if journal_temperature is None else journal_temperature
    hot = tiers.journal_in_service(np.asarray(journal_d, dtype=float), rings.journal_expansion,
                                   np.asarray(journal_t, dtype=float) - assembly_temperature)
    return replace(fit, clearance=np.broadcast_to(fit.shell_bore - hot, shape).copy())


def _by_kernel(bearings, shape, rings, *, thin):
    """The closed-form tiers through the numba kernel, without the journal; inputs as :func:`press_fit` forms them."""
    flat = _kernel.Bearings(**{name: _flat(x, shape) for name, x in bearings.items()})
    options = _kernel.Options(thin, False, tiers.FREE_RADIUS_ITERATIONS)
    p, sigma, swell, bore, shell_bore, _, loss = _kernel.press_fit(
        int(np.prod(shape, dtype=np.int64)), flat, rings, options)
    return PressFit(p.reshape(shape), sigma.reshape(shape), swell.reshape(shape), bore.reshape(shape),
                    shell_bore.reshape(shape), None, loss.reshape(shape))


def _by_elements(bearings, shape, rings):
    """The finite-element reference, bearing by bearing, without the journal; inputs as :func:`press_fit` forms them."""
    housing, back, lining = rings[0:3], rings[3:6], rings[6:9]
    names = ("housing_bore", "housing_outer", "shell_wall", "crush_height", "check_bore", "check_stress", "delta_t",
             "journal_d", "lining_thickness")
    columns = (np.broadcast_to(bearings[name], shape).ravel().tolist() for name in names)
    rows = [reference.press_fit_one(*args[:7], housing, back, rings.journal_expansion, None,
                                    lining_thickness=args[8], lining=lining)
            for args in zip(*columns)]
    out = {k: np.array([r[k] for r in rows]).reshape(shape) for k in rows[0]} if rows else {}
    return PressFit(out["contact_pressure"], out["shell_stress"], out["housing_swell"], out["bore_in_service"],
                    out["shell_bore"], None, out["loss_of_fit"].astype(bool))


@dataclass(frozen=True)
class PressFitExtremes:
    """Result of :func:`press_fit_extremes`; arrays broadcast over the inputs (temperatures reduced).

    Attributes
    ----------
    highest_shell_stress : numpy.ndarray
        Highest steel-equivalent shell compression over the temperatures [Pa]
        (to compare with the largest allowed stress).
    highest_stress_temperature : numpy.ndarray
        Temperature where it occurs [degC]: the coldest for a housing that
        expands more than the steel back (light alloys), the hottest for one
        that expands less (cast irons).
    lowest_contact_pressure : numpy.ndarray
        Lowest contact pressure over the temperatures [Pa] (to compare with the
        least allowed pressure); 0 where the fit is lost.
    lowest_pressure_temperature : numpy.ndarray
        Temperature where it occurs [degC].
    loss_of_fit : numpy.ndarray of bool
        True where the shells lose their interference at any of the temperatures.
    """

    highest_shell_stress: np.ndarray
    highest_stress_temperature: np.ndarray
    lowest_contact_pressure: np.ndarray
    lowest_pressure_temperature: np.ndarray
    loss_of_fit: np.ndarray


def _temperatures(field, value):
    """Temperatures to check: a non-empty 1-D sequence, each one the model is meant for [degC]."""
    temps = np.atleast_1d(TEMPERATURE(field, value))
    if temps.ndim != 1 or temps.size == 0:
        raise ValueError(f"{field}: {value!r} is not a non-empty sequence of temperatures")
    return temps


def _no_single_temperature(args):
    for name in ("temperature", "journal_d"):
        if name in args["not_arguments"]:
            raise ValueError(f"{name}: not an argument of press_fit_extremes (the temperatures come in "
                             "'temperatures'; the check needs no journal)")
    if args["not_arguments"]:
        raise TypeError(f"press_fit_extremes: unexpected keyword argument(s) {sorted(args['not_arguments'])}")


@renamed(length="bearing_width")
@validated(relations=(_no_single_temperature, *_RELATIONS), temperatures=_temperatures, **_CHECKS)
def press_fit_extremes(*, temperatures, housing_bore, housing_outer, shell_wall, crush_height, bearing_width,
                       check_bore=None, housing_material="steel", shell_material="steel", lining_thickness=0.0,
                       lining_material=None, assembly_temperature=20.0, check_stress=100e6,
                       journal_material="steel", method="lame", **not_arguments):
    r"""The press-fit check over declared temperatures: highest shell stress and lowest contact pressure.

    Contact pressure and shell stress are linear in the temperature change
    while the fit holds (:math:`\delta = r_0(1 + \alpha_S\Delta T) - a(1 +
    \alpha_H \Delta T)`), so their extremes over a temperature range lie at
    its ends; which end depends on the sign of :math:`\alpha_H - \alpha_S`.
    Checking every declared temperature (cold start, assembly, operating,
    hot) therefore finds the stress where it bites (cold for an aluminium
    housing, about 100 MPa above the hot value at 80 K: Kopeliovich, sec. 6)
    and the pressure where it bites (hot for aluminium, cold for cast iron).

    Parameters
    ----------
    temperatures : sequence of float
        Temperatures of housing, shells and journal to check [degC], e.g.
        ``(cold_start, assembly, operating, hot)``; at least one.
    housing_bore, housing_outer, shell_wall, crush_height, bearing_width, check_bore
        As in :func:`press_fit` (arrays per bearing broadcast as there).
    housing_material, shell_material, journal_material, lining_thickness, lining_material
        As in :func:`press_fit`.
    assembly_temperature, check_stress, method
        As in :func:`press_fit`, which also takes ``temperature`` and
        ``journal_d``; those are no arguments here.

    Returns
    -------
    PressFitExtremes
    """
    fit_args = dict(housing_bore=housing_bore, housing_outer=housing_outer, shell_wall=shell_wall,
                    crush_height=crush_height, bearing_width=bearing_width, check_bore=check_bore,
                    housing_material=housing_material, shell_material=shell_material,
                    lining_thickness=lining_thickness, lining_material=lining_material,
                    assembly_temperature=assembly_temperature, check_stress=check_stress,
                    journal_material=journal_material, method=method)
    best = None
    for t in np.atleast_1d(np.asarray(temperatures, dtype=float)):
        fit = press_fit(temperature=float(t), **fit_args)
        if best is None:
            best = [fit.shell_stress, np.full(fit.shell_stress.shape, t), fit.contact_pressure,
                    np.full(fit.contact_pressure.shape, t), fit.loss_of_fit]
            continue
        higher = fit.shell_stress > best[0]
        lower = fit.contact_pressure < best[2]
        best = [np.where(higher, fit.shell_stress, best[0]), np.where(higher, t, best[1]),
                np.where(lower, fit.contact_pressure, best[2]), np.where(lower, t, best[3]),
                best[4] | fit.loss_of_fit]
    return PressFitExtremes(*best)


def _flat(x, shape):
    """1-D float array for the kernel: length 1 for a scalar (read with stride 0), else the full size."""
    x = np.asarray(x, dtype=float)
    if x.size == 1:
        return x.reshape(1)
    return np.ascontiguousarray(np.broadcast_to(x, shape)).ravel()
