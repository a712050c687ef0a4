"""The bearings the film studies run on: a built-in engine's loads, tilt, geometry and oil over its cycle."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from stackup.crank import reactions, support_slopes
from stackup.engines import load_engine
from stackup.film.cycle import HEAT_STEP
from stackup.film.heat import heat_balance


@dataclass(frozen=True)
class Case:
    """Main bearings of one engine over its cycle (bearing axis first)."""

    engine: str
    crank_angle: np.ndarray  # (angles,) [deg]
    loads: np.ndarray  # (bearings, angles, 2) [N]
    tilt: np.ndarray  # (bearings, angles, 2) [rad], journal axis against the bearing axis
    diameter: float  # [m]
    length: float  # [m]
    clearance: float  # diametral [m]
    viscosity: np.ndarray  # (bearings,) effective [Pa s]
    temperature: np.ndarray  # (bearings,) effective [degC]
    speed: float  # [rad/s]
    feed: object  # the engine's stackup.film.heat.OilFeed

    def geometry(self, bearings=slice(None)):
        """Keyword arguments of stackup.film.orbit.orbit for the chosen bearings."""
        return dict(journal_d=self.diameter, bearing_width=self.length, clearance=self.clearance,
                    viscosity=self.viscosity[bearings], speed=self.speed)


def engine_case(name, *, clearance=None, bore_offset=None, journal_eccentricity=None, step=1.0):
    """The engine's main bearings on the bearing law at one clearance, optionally misaligned.

    clearance: diametral operating clearance [m], default the middle of the engine's window;
    bore_offset, journal_eccentricity: (bearings, 2) [m]. Effective viscosity from the
    heat balance of the study chain (stackup.film.heat, finite tier, feed and side
    flow), as the study chain does.
    """
    engine = load_engine(name)
    spec = engine.crank
    n = engine.main_bearings
    if clearance is None:
        clearance = float(np.mean(engine.clearance_window))
    angle = np.arange(0.0, 720.0, step)
    pins = spec.pin_loads(angle)
    bore = np.zeros((n, 2)) if bore_offset is None else np.asarray(bore_offset, float)
    journal = np.zeros((n, 2)) if journal_eccentricity is None else np.asarray(journal_eccentricity, float)
    offsets = spec.offsets(bore, journal, angle)
    r = reactions(pins, spans=spec.spans, EI=spec.ei, offsets=offsets, law=spec.law(np.full(n, clearance)))
    if not r.converged.all():
        raise RuntimeError(f"{name}: crank solve did not converge")
    # the journals tilt with the beam; the bores of a line-bored block keep the line's direction
    slopes = support_slopes(pins, r.displacements, spans=spec.spans, EI=spec.ei)
    loads = np.moveaxis(r.reactions, 0, 1)
    diameter = 0.5 * (engine.journal_d.lo + engine.journal_d.hi)
    # the study chain's quasi-static heat balance (feed and side flow) on a 4 deg subsample
    heat = heat_balance(loads[:, ::max(1, int(round(HEAT_STEP / step)))], journal_d=diameter,
                        bearing_width=spec.bearing_width, clearance=clearance, speed=spec.speed, oil=spec.oil,
                        supply_temperature=spec.oil_supply_temperature, feed=engine.oil_feed, method="finite")
    return Case(name, angle, loads, np.moveaxis(slopes, 0, 1), diameter, spec.bearing_width, clearance,
                heat.viscosity, heat.temperature, spec.speed, engine.oil_feed)
