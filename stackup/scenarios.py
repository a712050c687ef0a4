"""Robustness scenarios: the declared sets a comparison runs beside its study.

A scenario is plain data (a dict of the keys :data:`KEYS`, explained in
:mod:`stackup.study.scenario`), applied to an engine by :func:`apply`. Two
kinds:

- **process** scenarios (:data:`DECLARED`): what a plant would see, the same
  for every engine: process means shifted, a worse gauge, more misalignment;
- **model-uncertainty** scenarios (:func:`model_uncertainties`): the ends of
  the declared range of each model input the engine file assumes and a
  verdict may rest on, each range with its source or marked as assumed, and
  what to measure to narrow it: the housing's stiffness (its equivalent outer
  diameter, hence the housing swell), the shells' crush height process, and
  how much hotter the journal runs than its bulkhead.
"""

from __future__ import annotations

from dataclasses import dataclass

from .study.scenario import KEYS, apply

#: The declared process scenarios of the comparison report: process mean shift +-1 sigma,
#: gauge error up to 2 um, doubled misalignment.
DECLARED = {
    "bore mean +1σ": {"housing_shift": 1.0},
    "bore mean −1σ": {"housing_shift": -1.0},
    "journal mean +1σ": {"journal_shift": 1.0},
    "journal mean −1σ": {"journal_shift": -1.0},
    "gauge repeatability 2 µm": {"gauge_repeatability": 2e-6},
    "misalignment ×2": {"misalignment_scale": 2.0},
}
#: Scenario keys that change a model input rather than a process (the supports' compliance joins them).
MODEL_KEYS = ("housing_outer", "crush_shift", "journal_temperature_excess")
#: Scenario keys that disturb the crankshaft, film and life stages (a comparison runs them on some engines).
MECHANICS_KEYS = ("misalignment_scale",)

#: Assumed range of the housing's equivalent outer diameter over its bore's lower limit [-] where no fitting
#: test measured it. A bolted bulkhead and cap are no ring, so its equivalent ring is an assumption
#: (physics.md sec. 3); below OD/ID 1.5 the housing's own compliance dominates the fit, at 3.0 Lamé's factor
#: (b^2 + a^2)/(b^2 - a^2) is within 25 % of a rigid ring's.
HOUSING_RATIO_RANGE = (1.5, 3.0)
#: OD/ID standing for the upper end "as stiff as a rigid ring" of a measured interval (Lamé's factor 1.02).
RIGID_RATIO = 10.0
#: Assumed range of the journal's temperature above its housing's in service [K]: journals often run 10-20 K
#: above their bulkheads (physics.md sec. 3); 0 is the standard's one temperature for both.
JOURNAL_EXCESS_RANGE = (0.0, 20.0)
#: Assumed shift of the crush height process mean [standard deviations], as the parts' process scenarios.
CRUSH_SHIFT = 1.0


@dataclass(frozen=True)
class Uncertainty:
    """A model input the verdict rests on, over a declared range.

    Attributes
    ----------
    input : str
        The input in words ("housing stiffness (equivalent outer diameter)").
    scenarios : dict of str -> dict
        Label -> scenario (:mod:`stackup.study.scenario`): the ends of the range.
    source : str
        Where the range comes from; it begins with "assumed" where nobody measured it.
    measure : str
        What to measure to narrow the range, in words a user can act on.
    """

    input: str
    scenarios: dict
    source: str
    measure: str

    @property
    def assumed(self):
        """The range is an assumption, not a measurement."""
        return self.source.startswith("assumed")


def _mm(value):
    return f"{value * 1e3:.0f} mm"


def housing_stiffness(engine):
    """The :class:`Uncertainty` of the housing's equivalent outer diameter: measured interval, else assumed range."""
    spec, bore = engine.press_fit, engine.housing_bore.lo
    measure = "the housing swell (fitting tests, `stackup measure swell`)"
    if spec.housing_outer_interval is not None:
        lo, hi = spec.housing_outer_interval
        rigid = hi == float("inf")
        hi = RIGID_RATIO * bore if rigid else hi
        source = ("measured: the engine file's housing_outer_interval (fitting tests)"
                  + (f", upper end unbounded, run as a rigid ring (OD/ID {RIGID_RATIO:g})" if rigid else ""))
    else:
        lo = min(HOUSING_RATIO_RANGE[0] * bore, spec.housing_outer)
        hi = max(HOUSING_RATIO_RANGE[1] * bore, spec.housing_outer)
        source = (f"assumed: OD/ID {lo / bore:.2g}-{hi / bore:.2g} around the file's {_mm(spec.housing_outer)} "
                  "(a bolted bulkhead is no ring, physics.md sec. 3; ISO 13778 clause 4: swell 'of the order of a "
                  "few micrometres', measure it)")
    return Uncertainty("housing stiffness (equivalent outer diameter)",
                       {f"housing OD {_mm(lo)}": {"housing_outer": lo}, f"housing OD {_mm(hi)}": {"housing_outer": hi}},
                       source, measure)


def crush_height(engine):
    """The :class:`Uncertainty` of the shells' crush height process: its mean shifted by :data:`CRUSH_SHIFT` σ."""
    k = CRUSH_SHIFT
    return Uncertainty("crush height process (mean)",
                       {f"crush mean +{k:g}σ": {"crush_shift": k}, f"crush mean −{k:g}σ": {"crush_shift": -k}},
                       f"assumed: the engine file's crush process, its mean ±{k:g}σ as the parts' process scenarios",
                       "the shells' crush heights (checking block, ISO 3548-3; `stackup measure fit`)")


def _hotter(kelvin):
    """A journal-temperature scenario's label: "journal 20 K hotter", or "journal as hot as housing" at 0 K."""
    if kelvin == 0:
        return "journal as hot as housing"
    return f"journal {abs(kelvin):g} K {'hotter' if kelvin > 0 else 'cooler'}"


def journal_temperature(engine):
    """The :class:`Uncertainty` of the journal's temperature above its housing: :data:`JOURNAL_EXCESS_RANGE`."""
    nominal = engine.press_fit.journal_temperature_excess
    lo, hi = min(JOURNAL_EXCESS_RANGE[0], nominal), max(JOURNAL_EXCESS_RANGE[1], nominal)
    return Uncertainty("journal–housing temperature difference",
                       {_hotter(lo): {"journal_temperature_excess": lo},
                        _hotter(hi): {"journal_temperature_excess": hi}},
                       "assumed: journals often run 10-20 K above their bulkheads (physics.md sec. 3); 0 K is the "
                       "standard's one temperature",
                       "journal and bulkhead temperatures in a running engine")


#: The model inputs a comparison declares, each a function of the engine giving its :class:`Uncertainty`.
#: The supports' compliance joins them once the crankshaft's supports carry one (its key in MODEL_KEYS and
#: MECHANICS_KEYS, its change in :func:`stackup.study.scenario.apply`).
MODEL_INPUTS = (housing_stiffness, crush_height, journal_temperature)


def model_uncertainties(engine):
    """The declared model-uncertainty scenarios of an engine (an :class:`~stackup.engines.Engine`): a list of
    :class:`Uncertainty`, one per input of :data:`MODEL_INPUTS`."""
    return [declared(engine) for declared in MODEL_INPUTS]


def kind(scenario):
    """"model" where a scenario changes a model input (:data:`MODEL_KEYS`), else "process"."""
    return "model" if any(key in MODEL_KEYS for key in (scenario or {})) else "process"


__all__ = ["DECLARED", "KEYS", "MECHANICS_KEYS", "MODEL_INPUTS", "MODEL_KEYS", "Uncertainty", "apply",
           "crush_height", "housing_stiffness", "journal_temperature", "kind", "model_uncertainties"]
