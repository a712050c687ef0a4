"""Press fit, housing swell and temperature: the operating clearance of a main bearing.

Public entry point :func:`press_fit`, with tiers

- ``"lame"`` (default): closed-form thick rings, exact within linear plane-stress
  elasticity (agrees with ``"fe"`` to 1e-9 relative); numba kernel.
- ``"thin-ring"``: the shell as a thin ring (uniform hoop stress, wall
  unchanged), the classic shop formula; cheaper, a few per cent off in
  contact pressure for thick walls (see ``reports/press_fit_tiers.md``).
- ``"fe"``: the reference, radial finite elements of both rings with contact;
  slow, for validation.

The model and its equations: :mod:`stackup.fit.tiers`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import _validate as check
from .. import materials
from .._kernels import press_fit as _kernel
from . import reference, tiers

METHODS = ("lame", "thin-ring", "fe")

#: Press-fit design limits (physics.md sec. 3): the bearing must not spin or
#: fret below this contact pressure [Pa]; joint faces protrude above this
#: shell compression [Pa].
CONTACT_PRESSURE_MIN = 8e6
SHELL_STRESS_MAX = 450e6


@dataclass(frozen=True)
class PressFit:
    """Result of :func:`press_fit`; arrays broadcast over the inputs.

    Attributes
    ----------
    contact_pressure : numpy.ndarray
        Pressure between shell backs and housing bore [Pa]; 0 where the fit is lost.
    shell_stress : numpy.ndarray
        Mean compressive hoop stress of the shell wall [Pa], positive in compression.
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


def press_fit(*, housing_bore, housing_outer, shell_wall, crush_height, length, housing_material="steel",
              shell_material="steel", temperature=20.0, assembly_temperature=20.0, check_bore=None,
              check_stress=100e6, journal_d=None, journal_material="steel", method="lame"):
    r"""Contact pressure, shell stress, housing swell and operating clearance of a shell pair.

    Parameters
    ----------
    housing_bore : array_like
        Free housing bore diameter at the assembly temperature [m].
    housing_outer : array_like
        Equivalent outer diameter of the housing ring [m]; must exceed the bore.
    shell_wall : array_like
        Crown wall thickness of the shells (steel-equivalent) [m].
    crush_height : array_like
        Crush height per half shell, measured in a checking block of bore
        ``check_bore`` under ``check_stress`` [m], >= 0.
    length : array_like
        Shell width [m]; plane stress, so it scales forces only (kept for the
        check force :math:`F = \sigma_c\,t\,L`) and is validated.
    housing_material, shell_material, journal_material : str or Material
        Names from :mod:`stackup.materials` (or Material objects).
    temperature : array_like
        Operating temperature of housing, shells and journal [degC].
    assembly_temperature : array_like
        Temperature at assembly and crush check [degC].
    check_bore : array_like, optional
        Bore diameter of the checking block [m]; default ``housing_bore``
        (the bearing measured against a block of its own bore).
    check_stress : float
        Mean wall compression of the crush check [Pa] (100 MPa in ISO 6864 practice).
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
    """
    check.one_of("method", method, METHODS)
    housing_bore = check.positive("housing_bore", housing_bore)
    housing_outer = check.positive("housing_outer", housing_outer)
    shell_wall = check.positive("shell_wall", shell_wall)
    crush_height = check.positive("crush_height", crush_height, allow_zero=True)
    check.positive("length", length)
    temperature = check.in_range("temperature", temperature, -60.0, 300.0, unit=" degC")
    assembly_temperature = check.in_range("assembly_temperature", assembly_temperature, -60.0, 300.0, unit=" degC")
    check_bore = housing_bore if check_bore is None else check.positive("check_bore", check_bore)
    check_stress = check.in_range("check_stress", check_stress, 0.0, 2e9, lo_open=True, unit=" Pa")
    if journal_d is not None:
        journal_d = check.positive("journal_d", journal_d)
    housing, shell, journal = (materials.get(m) for m in (housing_material, shell_material, journal_material))

    arrays = [housing_bore, housing_outer, shell_wall, crush_height, check_bore, check_stress,
              temperature - assembly_temperature, housing_bore if journal_d is None else journal_d]
    try:
        (bore, outer, wall, crush, block, stress, delta_t, journal_d_b) = np.broadcast_arrays(*arrays)
    except ValueError:
        raise ValueError("press_fit: the array inputs do not broadcast together: shapes "
                         + ", ".join(str(np.shape(a)) for a in arrays)) from None
    if np.any(outer <= bore):
        i = np.argmax(outer <= bore)
        raise ValueError(f"housing_outer: {float(outer.flat[i])!r} m is not above housing_bore "
                         f"{float(bore.flat[i])!r} m; the outer diameter must exceed the bore")
    if np.any(2.0 * wall >= bore):
        raise ValueError(f"shell_wall: {float(wall.max())!r} m is not below half the housing bore")

    props = {"housing": (housing.modulus, housing.poisson, housing.expansion),
             "shell": (shell.modulus, shell.poisson, shell.expansion)}
    if method == "fe":
        shape = bore.shape
        rows = [reference.press_fit_one(*args[:7], props["housing"], props["shell"], journal.expansion,
                                        None if journal_d is None else args[7])
                for args in zip(*(x.ravel().tolist() for x in (bore, outer, wall, crush, block, stress, delta_t, journal_d_b)))]
        out = {k: np.array([r[k] for r in rows]).reshape(shape) for k in rows[0]} if rows else {}
        return PressFit(out["contact_pressure"], out["shell_stress"], out["housing_swell"], out["bore_in_service"],
                        out["shell_bore"], out.get("clearance"), out["loss_of_fit"].astype(bool))

    shape = bore.shape
    originals = (housing_bore, housing_outer, shell_wall, crush_height, check_bore, check_stress,
                 temperature - assembly_temperature, housing_bore if journal_d is None else journal_d)
    flat = [_flat(x, shape) for x in (originals[0], *originals[1:6], originals[7], originals[6])]
    p, sigma, swell, bore_s, shell_bore, clearance, loss = _kernel.press_fit(
        bore.size, *flat, *props["housing"], *props["shell"], journal.expansion, method == "thin-ring",
        journal_d is not None, tiers.FREE_RADIUS_ITERATIONS)
    return PressFit(p.reshape(shape), sigma.reshape(shape), swell.reshape(shape), bore_s.reshape(shape),
                    shell_bore.reshape(shape), None if journal_d is None else clearance.reshape(shape),
                    loss.reshape(shape))


def _flat(x, shape):
    """1-D float array for the kernel: length 1 for a scalar (read with stride 0), else the full size."""
    x = np.asarray(x, dtype=float)
    if x.size == 1:
        return x.reshape(1)
    return np.ascontiguousarray(np.broadcast_to(x, shape)).ravel()


__all__ = ["METHODS", "PressFit", "press_fit", "tiers", "reference"]
