r"""Engine loads over the 720 degree cycle: cylinder pressure and crank-pin forces.

Cylinder pressure (one cylinder, cycle angle :math:`\psi`, 0 = firing TDC):
closed cycle from IVC (:math:`\psi = -180°`) to EVO (:math:`+180°`) as a
polytrope of exponent :math:`n` with a Wiebe heat release,

.. math:: x_b(\psi) = 1 - \exp\left[-a\left(\frac{\psi - \psi_0}{\Delta\psi}\right)^{m+1}\right],
          \qquad d(pV^n) = (n - 1)\,V^{n-1}\,dQ

integrated exactly (:math:`pV^n` is the integral of the heat-release term),
with the heat :math:`Q` scaled so the peak pressure is the given one;
exhaust and intake strokes at constant pressure.

Slider-crank kinematics (crank radius :math:`r`, con-rod :math:`l`,
:math:`\lambda = r/l`, pin angle :math:`\varphi` from TDC):

.. math:: \ddot x = -r\omega^2\left[\cos\varphi + \lambda\,\frac{\cos 2\varphi + \lambda^2\sin^4\varphi}
          {(1 - \lambda^2\sin^2\varphi)^{3/2}}\right], \qquad \sin\beta = \lambda\sin\varphi

Force on the crank pin, engine-fixed frame (component 0 along the cylinder
axis towards the crank and the bearing caps, component 1 transverse in the
direction of rotation at TDC):

.. math:: \mathbf F = F_p\,(1, \tan\beta) + (m_{rot} r - u_{cw})\,\omega^2\,(-\cos\varphi, \sin\varphi),
          \qquad F_p = (p - p_{case}) A + m_{rec}\,\ddot x

with :math:`u_{cw}` the counterweight unbalance of the throw [kg m], applied
at the pin's span (a beam-model simplification).

V engines (two rods side by side on one pin, :func:`v_cylinders`): each
cylinder's axis lies at :math:`\gamma = \mp\alpha/2` from the V's bisector
(bank angle :math:`\alpha`; the leading bank, the one a pin passes first, at
:math:`-\alpha/2`). A cylinder's force is the expression above in its own
bank's frame, at its own pin angle :math:`\varphi - \gamma` and firing
angle, turned by :math:`\gamma` into the engine frame (component 0 then
along the bisector towards the caps); the pin carries the sum over its
cylinders, so the rotating masses of both big ends,

.. math:: \mathbf F_{pin} = \sum_{c \in pin} R(\gamma_c)\,\mathbf F_c(\varphi - \gamma_c),
          \qquad R(\gamma) = \begin{pmatrix}\cos\gamma & \sin\gamma\\ -\sin\gamma & \cos\gamma\end{pmatrix}

Both rods act at the middle of the pin: the axial offset of side-by-side
rods (about half a big end's width) is not modelled.

References
----------
.. [1] Heywood, J. B., *Internal Combustion Engine Fundamentals*, McGraw-Hill,
   1988, sec. 2.2 (kinematics), 9.2 (Wiebe function).
.. [2] Bellakhdhar et al. 2013, sec. 6.1 (four-cylinder loads at 4000 rpm).
.. [3] Taylor, C. F., *The Internal-Combustion Engine in Theory and Practice*,
   vol. 2, rev. ed., MIT Press, 1985, ch. 8 (balance of V engines: two rods
   on one pin, the forces of each bank along its own axis).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import integrate, optimize

from . import _validate as check
from ._validate import Finite, Positive, finite, validated

ATMOSPHERE = 1.0e5  # crankcase pressure [Pa]
#: How a V engine's maker numbers its cylinders (:func:`v_cylinders`).
NUMBERINGS = ("alternate", "bank-by-bank")
#: The bank of cylinder 1, seen from the flywheel end (:func:`v_cylinders`).
BANKS = ("left", "right")
_STEP = 0.1  # integration step of the closed cycle [deg]


@dataclass(frozen=True)
class Combustion:
    """Closed-cycle parameters of the built-in pressure model (SI, angles in degrees)."""

    compression_ratio: float = 16.0
    peak_pressure: float = 13.0e6
    intake_pressure: float = 1.0e5
    exhaust_pressure: float = 1.1e5
    polytropic_exponent: float = 1.35
    start: float = -12.0
    duration: float = 50.0
    wiebe_a: float = 5.0
    wiebe_m: float = 2.0

    def __post_init__(self):
        check.fields(self, {"compression_ratio": check.InRange(1.0, 40.0, lo_open=True),
                            "peak_pressure": check.Positive(), "intake_pressure": check.Positive(),
                            "exhaust_pressure": check.Positive(),
                            "polytropic_exponent": check.InRange(1.0, 1.7, lo_open=True),
                            "start": ("combustion start", check.InRange(-90.0, 90.0)),
                            "duration": ("combustion duration", check.Positive())})


@dataclass(frozen=True)
class Kinematics:
    """Slider-crank geometry and masses of one cylinder (SI)."""

    cylinder_bore: float
    stroke: float
    conrod: float
    reciprocating_mass: float
    rotating_mass: float
    counterweight_unbalance: float

    def __post_init__(self):
        check.fields(self, {"cylinder_bore": check.Positive(), "stroke": check.Positive(),
                            "reciprocating_mass": check.Positive(zero=True), "rotating_mass": check.Positive(zero=True),
                            "counterweight_unbalance": check.Positive(zero=True)})
        if self.conrod <= self.stroke / 2:
            raise ValueError(f"conrod: {self.conrod!r} m is not longer than the crank radius {self.stroke / 2!r} m")

    @property
    def crank_radius(self):
        return self.stroke / 2

    @property
    def piston_area(self):
        return np.pi * self.cylinder_bore**2 / 4

    def volume(self, angle_deg, compression_ratio):
        """Cylinder volume [m^3] at pin angle ``angle_deg`` from TDC."""
        r, lam = self.crank_radius, self.crank_radius / self.conrod
        phi = np.radians(angle_deg)
        travel = r * (1 - np.cos(phi)) + self.conrod * (1 - np.sqrt(1 - (lam * np.sin(phi)) ** 2))
        swept = self.piston_area * self.stroke
        return swept / (compression_ratio - 1) + self.piston_area * travel

    def piston_acceleration(self, angle_deg, omega):
        """Piston acceleration along the cylinder axis, away from the crank positive [m/s^2]."""
        r, lam = self.crank_radius, self.crank_radius / self.conrod
        phi = np.radians(angle_deg)
        s2 = np.sin(phi) ** 2
        return -r * omega**2 * (np.cos(phi) + lam * (np.cos(2 * phi) + lam**2 * s2**2) / (1 - lam**2 * s2) ** 1.5)


def cylinder_pressure(cycle_angle, kinematics, combustion):
    """Cylinder pressure [Pa] at cycle angles [deg] (0 = firing TDC, period 720)."""
    c = combustion
    psi = np.arange(-180.0, 180.0 + _STEP / 2, _STEP)
    volume = kinematics.volume(psi, c.compression_ratio)
    n = c.polytropic_exponent
    burn = np.clip((psi - c.start) / c.duration, 0.0, None)
    fraction = 1.0 - np.exp(-c.wiebe_a * burn ** (c.wiebe_m + 1))
    # pV^n = p_ivc V_ivc^n + (n - 1) Q_total * integral of V^(n-1) dx_b
    motored = c.intake_pressure * volume[0] ** n
    heat_term = (n - 1) * integrate.cumulative_trapezoid(volume ** (n - 1), fraction, initial=0.0)

    def peak(q_total):
        return np.max((motored + q_total * heat_term) / volume**n)

    p_motored = peak(0.0)
    if c.peak_pressure <= p_motored:
        raise ValueError(f"peak_pressure: {c.peak_pressure!r} Pa is below the motored peak {p_motored:.4g} Pa "
                         f"of compression ratio {c.compression_ratio}")
    q_total = optimize.brentq(lambda q: peak(q) - c.peak_pressure, 0.0, 1.0e3 * c.peak_pressure * volume[0])
    closed = (motored + q_total * heat_term) / volume**n

    a = np.mod(np.asarray(cycle_angle, dtype=float) + 180.0, 720.0) - 180.0  # in [-180, 540)
    pressure = np.interp(a, psi, closed)
    pressure = np.where((a > 180.0) & (a <= 360.0), c.exhaust_pressure, pressure)
    return np.where(a > 360.0, c.intake_pressure, pressure)


def pin_load(pin_angle, pressure, kinematics, omega):
    """Force on one crank pin (..., 2) [N] from pin angle [deg], cylinder pressure [Pa], speed [rad/s]."""
    k = kinematics
    lam = k.crank_radius / k.conrod
    phi = np.radians(pin_angle)
    s = np.sin(phi)
    tan_beta = lam * s / np.sqrt(1 - (lam * s) ** 2)
    # acceleration is positive away from the crank, so the d'Alembert force towards the crank is +m*a
    f_piston = (pressure - ATMOSPHERE) * k.piston_area + k.reciprocating_mass * k.piston_acceleration(pin_angle, omega)
    unbalance = (k.rotating_mass * k.crank_radius - k.counterweight_unbalance) * omega**2
    return np.stack([f_piston - unbalance * np.cos(phi), f_piston * tan_beta + unbalance * s], axis=-1)


def check_firing_order(throw_angles, firing_order):
    """Refuse a firing order that does not name each cylinder (one per throw angle) once."""
    n = np.size(throw_angles)
    if sorted(int(c) - 1 for c in firing_order) != list(range(n)):
        raise ValueError(f"firing_order: {list(firing_order)!r} is not a permutation of cylinders 1..{n}")


def _cylinders_fire_once(args):
    check_firing_order(args["throw_angles"], args["firing_order"])


@validated(relations=(_cylinders_fire_once,), throw_angles=Finite())
def firing_offsets(throw_angles, firing_order):
    """Cycle angle [deg] at which each cylinder fires, from its throw angle and the firing order.

    Cylinder ``i`` is at TDC when ``crank_angle + throw_angle_i`` is a multiple
    of 360; the firing order picks which of its two TDCs in 720 deg fires.
    ``throw_angles`` are one per cylinder, each seen from its own cylinder's
    axis (a V engine's: :func:`cylinder_throw_angles`).
    """
    throw = np.mod(np.asarray(throw_angles, dtype=float), 360.0)
    order = [int(c) - 1 for c in firing_order]
    n = throw.size
    fire = np.empty(n)
    last = None
    for cyl in order:
        tdc = np.mod(-throw[cyl], 360.0)
        candidates = np.array([tdc, tdc + 360.0])
        if last is None:
            fire[cyl] = tdc
        else:
            gaps = np.mod(candidates - last, 720.0)
            gaps[gaps == 0] = 720.0
            fire[cyl] = candidates[np.argmin(gaps)]
        last = fire[cyl]
    spacing = np.sort(np.mod(fire - fire[order[0]], 720.0))
    shown = [float(a) for a in throw]
    if len(set(np.round(spacing, 6))) != n:  # only placing the firings shows it, so the body checks
        raise ValueError(f"firing_order: {list(firing_order)!r} fires two cylinders at once with throws {shown}; "
                         "check throw_angles (a V engine's also numbering and first_bank)")
    in_order = np.mod(fire[order] - fire[order[0]], 720.0)
    if n > 1 and np.any(np.diff(in_order) <= 0):
        # each next TDC taken, the order ran past 720 deg: the throws fire the cylinders in another order
        raise ValueError(f"firing_order: {list(firing_order)!r} is not the order throws {shown} fire in within "
                         "720 deg; check throw_angles (a V engine's also numbering and first_bank)")
    return np.mod(fire - fire[order[0]], 720.0)


def v_cylinders(cylinders, *, bank_angle, numbering, first_bank):
    r"""Where a V engine's cylinders sit: each one's throw (0-based) and its axis from the bisector [deg].

    Parameters
    ----------
    cylinders : int
        Number of cylinders, even: two side-by-side rods on each throw.
    bank_angle : float
        Angle between the banks' cylinder axes [deg], in (0, 180].
    numbering : {"alternate", "bank-by-bank"}
        The maker's numbering, throws counted from the front (timing end):
        ``"alternate"`` puts cylinders 1, 3, 5, ... on one bank and 2, 4, 6,
        ... on the other, cylinders 2k-1 and 2k on throw k (General Motors,
        Chrysler); ``"bank-by-bank"`` numbers one bank front to back, then
        the other, cylinders k and k + n/2 on throw k (Ford, Audi, BMW,
        Mercedes-Benz, Toyota's V6).
    first_bank : {"left", "right"}
        The bank of cylinder 1, seen from the flywheel end looking to the
        front (from the driver's seat of a front-engined car), the crankshaft
        turning in the standard sense (SAE J824: counter-clockwise seen from
        the flywheel end). A pin then passes the right bank first: the right
        bank leads, at :math:`-\alpha/2`. For an engine turning the other way,
        name the other bank.

    Returns
    -------
    (numpy.ndarray of int, numpy.ndarray)
        Each cylinder's throw (0-based) and its axis's angle from the V's
        bisector [deg], counted in the sense of rotation, in cylinder-number
        order: the ``cylinder_throw`` and ``cylinder_axis`` of :func:`pin_loads`.
    """
    number = np.arange(cylinders)
    if numbering == "alternate":
        throw, on_first = number // 2, number % 2 == 0
    else:
        half = cylinders // 2
        throw, on_first = number % half, number < half
    leads = on_first == (first_bank == "right")
    return throw, np.where(leads, -bank_angle / 2, bank_angle / 2)


def cylinder_throw_angles(throw_angles, cylinder_throw=None, cylinder_axis=None):
    """Each cylinder's throw angle seen from its own axis [deg]: its throw's angle less its axis's angle."""
    throws = np.asarray(throw_angles, dtype=float)
    if cylinder_throw is None:
        return throws
    return throws[np.asarray(cylinder_throw, dtype=int)] - np.asarray(cylinder_axis, dtype=float)


def _trace(field, value):
    """A pressure trace (cycle angles [deg], pressures [Pa]): two arrays of finite numbers."""
    if len(value) != 2:
        raise ValueError(f"{field}: {len(value)} arrays; give (cycle angles [deg], pressures [Pa])")
    return tuple(finite(field, v) for v in value)


def _layout_fits(args):
    """The cylinders' throws and axes agree with the throws and the firing order."""
    throws, on, axis = args["throw_angles"], args["cylinder_throw"], args["cylinder_axis"]
    if (on is None) != (axis is None):
        raise ValueError("cylinder_throw, cylinder_axis: give both (a V engine) or neither (inline)")
    if on is None:
        check_firing_order(throws, args["firing_order"])
        return
    on = np.asarray(on)
    n_throws = np.size(throws)
    if on.ndim != 1 or np.asarray(axis).shape != on.shape:
        raise ValueError(f"cylinder_axis: shape {np.asarray(axis).shape}; give one per cylinder {on.shape}")
    counts = np.bincount(on.astype(int), minlength=n_throws) if on.size and on.min() >= 0 else None
    if (counts is None or counts.size != n_throws or not np.all(on == on.astype(int))
            or np.any(counts != counts[0])):
        raise ValueError(f"cylinder_throw: {on.tolist()!r} does not put the same number of cylinders on each of "
                         f"throws 0..{n_throws - 1}")
    check_firing_order(on, args["firing_order"])


@validated(relations=(_layout_fits,), crank_angle=Finite(), throw_angles=Finite(), speed=Positive(),
           pressure_trace=_trace, cylinder_axis=Finite())
def pin_loads(crank_angle, *, kinematics, combustion, throw_angles, firing_order, speed, pressure_trace=None,
              cylinder_throw=None, cylinder_axis=None):
    """Crank-pin loads (angles, throws, 2) [N] over crank angles [deg] (0 = firing TDC of the first cylinder fired).

    ``speed`` is the crankshaft speed [rad/s]. ``pressure_trace`` (cycle
    angles [deg], pressures [Pa]) replaces the built-in pressure model.
    ``throw_angles`` are one per throw (crank pin), ``firing_order`` names
    every cylinder. An inline engine has one cylinder per throw, cylinder
    ``i`` on throw ``i``; a V engine gives ``cylinder_throw`` (each
    cylinder's throw, 0-based) and ``cylinder_axis`` (each cylinder's axis
    from the V's bisector [deg], in the sense of rotation), from
    :func:`v_cylinders`: each pin carries the sum of its cylinders' forces,
    each along its own bank's axis at its own firing angle.
    """
    angle = np.asarray(crank_angle, dtype=float)
    omega = float(speed)
    own = cylinder_throw_angles(throw_angles, cylinder_throw, cylinder_axis)
    fire = firing_offsets(own, firing_order)
    cycle = np.mod(angle[:, None] - fire[None, :], 720.0)
    if pressure_trace is None:
        pressure = cylinder_pressure(cycle, kinematics, combustion)
    else:
        trace_angle, trace_p = pressure_trace
        pressure = np.interp(cycle, trace_angle, trace_p, period=720.0)
    # crank angle 0 is the first cylinder's firing TDC: its pin on its own axis there
    first = int(firing_order[0]) - 1
    pin_angle = angle[:, None] + (own - own[first])[None, :]
    loads = pin_load(pin_angle, pressure, kinematics, omega)  # each cylinder in its own bank's frame
    if cylinder_throw is None:
        return loads
    loads = turned(loads, cylinder_axis)
    per_throw = np.argsort(np.asarray(cylinder_throw), kind="stable").reshape(np.size(throw_angles), -1)
    return loads[:, per_throw].sum(axis=2)


def turned(force, angle):
    r"""Forces (..., 2) of a cylinder's frame in the engine's frame, its axis at ``angle`` [deg] from the reference.

    Component 0 along the axis towards the crank, 1 across it in the sense
    of rotation; the frame turned by ``angle`` in the sense of rotation,
    :math:`R(\gamma)` of the module's notes.
    """
    gamma = np.radians(np.asarray(angle, dtype=float))
    c, s = np.cos(gamma), np.sin(gamma)
    f0, f1 = force[..., 0], force[..., 1]
    return np.stack([c * f0 + s * f1, c * f1 - s * f0], axis=-1)


def read_pressure_trace(path, *, name=None):
    """A measured cylinder pressure trace from CSV: columns ``crank_angle_deg`` and ``pressure_pa``.

    Angles are cycle angles [deg] from firing TDC over 720 deg (one row per
    angle, any spacing, in increasing order); pressures absolute [Pa].
    ``path`` may also be an open text buffer (``name`` then names it in
    messages). Returns (angles, pressures) for :func:`pin_loads`.
    """
    import pandas as pd

    frame = pd.read_csv(path)
    path = path if name is None else name
    missing = {"crank_angle_deg", "pressure_pa"} - set(frame.columns)
    if missing:
        raise ValueError(f"pressure trace {str(path)!r}: missing column(s) {sorted(missing)}; "
                         "needs crank_angle_deg and pressure_pa")
    angle = check.finite(f"pressure trace {str(path)!r} crank_angle_deg", frame["crank_angle_deg"].to_numpy(float))
    pressure = check.positive(f"pressure trace {str(path)!r} pressure_pa", frame["pressure_pa"].to_numpy(float))
    if angle.size < 2 or np.any(np.diff(angle) <= 0) or angle[-1] - angle[0] >= 720.0:
        raise ValueError(f"pressure trace {str(path)!r}: crank_angle_deg must increase and span less than 720 deg")
    return angle, pressure
