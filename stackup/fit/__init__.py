"""Press fit, housing swell and temperature: the operating clearance of a main bearing.

Public entry points :func:`press_fit` (one temperature) and
:func:`press_fit_extremes` (the check over the declared temperatures: highest
shell stress, lowest contact pressure), with tiers

- ``"lame"`` (default): closed-form thick rings of steel-equivalent wall,
  exact within linear plane-stress elasticity for unlined shells (agrees with
  ``"fe"`` to 1e-7 relative); numba kernel.
- ``"thin-ring"``: the shell as a thin ring (uniform hoop stress, wall
  unchanged), the classic shop formula; cheaper, a few per cent off in
  contact pressure for thick walls (see ``reports/press_fit_tiers.md``).
- ``"fe"``: the reference, radial finite elements of both rings (the shell
  as bonded steel back and lining) with contact; slow, for validation.

The model (Kopeliovich, *Crush height of engine bearings*) and its
equations: :mod:`stackup.fit.tiers`. The design limits (least contact
pressure, largest shell stress) and the temperatures to check are engine
data with their source (``[press_fit]`` and ``[press_fit.limits]`` of an
engine file, :class:`stackup.engines.PressFitLimits`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate as check
from .. import materials
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


def press_fit(*, housing_bore, housing_outer, shell_wall, crush_height, length, check_bore=None,
              housing_material="steel", shell_material="steel", lining_thickness=0.0, lining_material=None,
              temperature=20.0, assembly_temperature=20.0, check_stress=100e6, journal_d=None,
              journal_material="steel", method="lame"):
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
    length : array_like
        Shell width [m]; plane stress, so it scales forces only (the check
        force :math:`F = \sigma_c\,t_e\,L`) and is validated.
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
    method : {"lame", "thin-ring", "fe"}
        Tier (see module docstring).

    Returns
    -------
    PressFit

    Notes
    -----
    Equations in :mod:`stackup.fit.tiers`. Loss of fit (``loss_of_fit``) gives
    zero pressure and stress, never a negative pressure; the loose shells then
    follow the bore, so the clearance is continuous through the loss of fit.

    References
    ----------
    .. [1] Kopeliovich, D., *Crush height of engine bearings* (press fit,
       crush check on the steel-equivalent section :math:`A_{calc}`).
    """
    check.one_of("method", method, METHODS)
    if check_bore is None:
        raise ValueError("check_bore: missing; the crush height is defined in a checking block whose bore is the "
                         "nominal housing bore (ISO 3548-3), e.g. an engine file's press_fit.check_bore "
                         "(default: the lower drawing limit of the housing bore)")
    housing_bore = check.positive("housing_bore", housing_bore)
    housing_outer = check.positive("housing_outer", housing_outer)
    shell_wall = check.positive("shell_wall", shell_wall)
    crush_height = check.positive("crush_height", crush_height, allow_zero=True)
    check.positive("length", length)
    temperature = check.in_range("temperature", temperature, -60.0, 300.0, unit=" degC")
    assembly_temperature = check.in_range("assembly_temperature", assembly_temperature, -60.0, 300.0, unit=" degC")
    check_bore = check.positive("check_bore", check_bore)
    check_stress = check.in_range("check_stress", check_stress, 0.0, 2e9, lo_open=True, unit=" Pa")
    lining_thickness = check.positive("lining_thickness", lining_thickness, allow_zero=True)
    if journal_d is not None:
        journal_d = check.positive("journal_d", journal_d)
    housing, shell, journal = (materials.get(m) for m in (housing_material, shell_material, journal_material))
    if lining_material is None:
        if np.any(lining_thickness > 0):
            raise ValueError("lining_material: missing; a lining_thickness > 0 needs the lining's material")
        lining = shell
    else:
        lining = materials.get(lining_material)

    arrays = [housing_bore, housing_outer, shell_wall, lining_thickness, crush_height, check_bore, check_stress,
              temperature - assembly_temperature, housing_bore if journal_d is None else journal_d]
    try:
        (bore, outer, wall, lining_t, crush, block, stress, delta_t, journal_d_b) = np.broadcast_arrays(*arrays)
    except ValueError:
        raise ValueError("press_fit: the array inputs do not broadcast together: shapes "
                         + ", ".join(str(np.shape(a)) for a in arrays)) from None
    if np.any(outer <= bore):
        i = np.argmax(outer <= bore)
        raise ValueError(f"housing_outer: {float(outer.flat[i])!r} m is not above housing_bore "
                         f"{float(bore.flat[i])!r} m; the outer diameter must exceed the bore")
    if np.any(2.0 * wall >= bore):
        raise ValueError(f"shell_wall: {float(wall.max())!r} m is not below half the housing bore")
    if np.any(lining_t >= wall):
        i = np.argmax(lining_t >= wall)
        raise ValueError(f"lining_thickness: {float(lining_t.flat[i])!r} m is not below the shell wall "
                         f"{float(wall.flat[i])!r} m; the steel back needs a thickness")

    props = {"housing": (housing.modulus, housing.poisson, housing.expansion),
             "shell": (shell.modulus, shell.poisson, shell.expansion),
             "lining": (lining.modulus, lining.poisson, lining.expansion)}
    shape = bore.shape
    if method == "fe":
        rows = [reference.press_fit_one(*args[:7], props["housing"], props["shell"], journal.expansion,
                                        None if journal_d is None else args[7], lining_thickness=args[8],
                                        lining=props["lining"])
                for args in zip(*(x.ravel().tolist()
                                  for x in (bore, outer, wall, crush, block, stress, delta_t, journal_d_b, lining_t)))]
        out = {k: np.array([r[k] for r in rows]).reshape(shape) for k in rows[0]} if rows else {}
        return PressFit(out["contact_pressure"], out["shell_stress"], out["housing_swell"], out["bore_in_service"],
                        out["shell_bore"], out.get("clearance"), out["loss_of_fit"].astype(bool))

    flat = [_flat(x, shape) for x in (housing_bore, housing_outer, shell_wall, lining_thickness, crush_height,
                                      check_bore, check_stress, housing_bore if journal_d is None else journal_d,
                                      temperature - assembly_temperature)]
    p, sigma, swell, bore_s, shell_bore, clearance, loss = _kernel.press_fit(
        bore.size, *flat, *props["housing"], *props["shell"], *props["lining"], journal.expansion, method == "thin-ring",
        journal_d is not None, tiers.FREE_RADIUS_ITERATIONS)
    return PressFit(p.reshape(shape), sigma.reshape(shape), swell.reshape(shape), bore_s.reshape(shape),
                    shell_bore.reshape(shape), None if journal_d is None else clearance.reshape(shape),
                    loss.reshape(shape))


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


def press_fit_extremes(*, temperatures, **press_fit_kwargs):
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
    **press_fit_kwargs
        Keyword arguments of :func:`press_fit` except ``temperature`` and
        ``journal_d`` (arrays per bearing broadcast as there).

    Returns
    -------
    PressFitExtremes
    """
    for name in ("temperature", "journal_d"):
        if name in press_fit_kwargs:
            raise ValueError(f"{name}: not an argument of press_fit_extremes (the temperatures come in "
                             "'temperatures'; the check needs no journal)")
    temps = np.atleast_1d(check.in_range("temperatures", temperatures, -60.0, 300.0, unit=" degC"))
    if temps.ndim != 1 or temps.size == 0:
        raise ValueError(f"temperatures: {temperatures!r} is not a non-empty sequence of temperatures")
    best = None
    for t in temps:
        fit = press_fit(temperature=float(t), **press_fit_kwargs)
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


__all__ = ["METHODS", "PressFit", "PressFitExtremes", "press_fit", "press_fit_extremes", "tiers", "reference"]
