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
  diameter, hence the housing swell), the shells' crush height process, how
  much hotter the journal runs than its bulkhead, and, where the engine file
  assumes them, the crankshaft's bending stiffness and (where the journals'
  tilt is turned back at the supports) the supports' angular compliance.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

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
#: Scenario keys that change a model input rather than a process.
MODEL_KEYS = ("housing_outer", "crush_shift", "journal_temperature_excess", "crank_stiffness_scale",
              "support_angular_scale")
#: Scenario keys that disturb the crankshaft, film and life stages (a comparison runs them on some engines).
MECHANICS_KEYS = ("misalignment_scale", "crank_stiffness_scale", "support_angular_scale")

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
#: Lower end of an assumed crankshaft's section inertias, a factor on the engine file's [-]: throw inertias taken
#: from another engine's identification (Bellakhdhar et al. 2013, Table 2, scaled) may be off by a factor of two,
#: as the bulkhead model's; the upper end is the plain journal's section (no throw bends less than a straight
#: shaft of its journal).
CRANK_STIFFNESS_LOW = 0.5
#: Factor either way on an angular support compliance derived from a bulkhead web
#: (:func:`stackup.crank.housing.bulkhead_compliance`'s stated uncertainty).
BULKHEAD_FACTOR = 2.0


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
        return is_assumed(self.source)


def is_assumed(source):
    """Whether a source (an engine file's or a declared range's) says it is an assumption: it begins with
    "assumed", in any case."""
    return source.lower().startswith("assumed")


def _mm(value):
    return f"{value * 1e3:.0f} mm"


def housing_stiffness(engine, tilt_method="equilibrium"):
    """The :class:`Uncertainty` of the housing's equivalent outer diameter: measured interval, else assumed range."""
    spec, bore = engine.press_fit, engine.housing_bore.lo
    measure = "the housing swell (`stackup measure swell`)"
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
                  "(a bolted bulkhead is no ring, physics.md sec. 3)")
    return Uncertainty("housing stiffness (equivalent outer diameter)",
                       {f"housing OD {_mm(lo)}": {"housing_outer": lo}, f"housing OD {_mm(hi)}": {"housing_outer": hi}},
                       source, measure)


def crush_height(engine, tilt_method="equilibrium"):
    """The :class:`Uncertainty` of the shells' crush height process: its mean shifted by :data:`CRUSH_SHIFT` σ."""
    k = CRUSH_SHIFT
    return Uncertainty("crush height process (mean)",
                       {f"crush mean +{k:g}σ": {"crush_shift": k}, f"crush mean −{k:g}σ": {"crush_shift": -k}},
                       f"assumed: the engine file's crush mean ±{k:g}σ",
                       "crush heights (checking block, ISO 3548-3; `stackup measure fit`)")


def _hotter(kelvin):
    """A journal-temperature scenario's label: "journal 20 K hotter", or "journal as hot as housing" at 0 K."""
    if kelvin == 0:
        return "journal as hot as housing"
    return f"journal {abs(kelvin):g} K {'hotter' if kelvin > 0 else 'cooler'}"


def journal_temperature(engine, tilt_method="equilibrium"):
    """The :class:`Uncertainty` of the journal's temperature above its housing: :data:`JOURNAL_EXCESS_RANGE`."""
    nominal = engine.press_fit.journal_temperature_excess
    lo, hi = min(JOURNAL_EXCESS_RANGE[0], nominal), max(JOURNAL_EXCESS_RANGE[1], nominal)
    return Uncertainty("journal–housing temperature difference",
                       {_hotter(lo): {"journal_temperature_excess": lo},
                        _hotter(hi): {"journal_temperature_excess": hi}},
                       "assumed: journals often run 10-20 K above their bulkheads (physics.md sec. 3); 0 K: the "
                       "standard's",
                       "journal and bulkhead temperatures in a running engine")


def _journal_d(engine):
    """The main journal's mean diameter [m]."""
    return 0.5 * (engine.journal_d.lo + engine.journal_d.hi)


def crank_stiffness(engine, tilt_method="equilibrium"):
    r"""The :class:`Uncertainty` of the crankshaft's section inertias where the engine file assumes them
    (``section_inertia_source`` empty or beginning "assumed"), else None: from :data:`CRANK_STIFFNESS_LOW` times
    the file's up to the plain journal's :math:`\pi D^4/64` for the stiffest throw."""
    spec = engine.crank
    if spec is None:
        return None
    source = " ".join(spec.section_inertia_source.split())
    if source and not is_assumed(source):
        return None
    d = _journal_d(engine)
    high = float(f"{spec.crank_modulus * np.pi * d**4 / 64 / spec.ei.max():.2g}")  # as its label says it
    low = CRANK_STIFFNESS_LOW
    given = source[len("assumed"):].lstrip(":; ") if is_assumed(source) else source
    given = given or "the engine file gives no source"
    return Uncertainty("crankshaft bending stiffness (section inertias)",
                       {f"crank inertia ×{low:g}": {"crank_stiffness_scale": low},
                        f"crank inertia ×{high:.2g} (plain journal)": {"crank_stiffness_scale": high}},
                       f"assumed: {given}; ×{low:g} (scaled throws may be off by two) to the plain {1e3 * d:.0f} mm "
                       "journal's section (no throw is stiffer)",
                       "the crankshaft's bending compliance (a finite-element model, or a bending test on its end journals)")


def support_tilt_compliance(engine, tilt_method="equilibrium"):
    """The :class:`Uncertainty` of the supports' angular compliance where any of it is derived, from a bulkhead
    web (:func:`stackup.crank.housing.bulkhead_compliance`) or, for the bore ring's own turn, from the bearing
    law's plane-strain deformation stiffness (:func:`stackup.crank.housing.ring_tilt_compliance`), and the study
    turns the journals back with it (``tilt_method`` "equilibrium" at each support, "coupled" with all support
    moments; "free" holds the beam's slope), else None: :data:`BULKHEAD_FACTOR` either way."""
    supports = engine.crank.supports if engine.crank is not None else None
    if supports is None or tilt_method == "free":
        return None
    ring = supports.ring is not None and bool(np.any(supports.ring))
    if not (supports.angular_derived or ring):
        return None
    derived = []
    if supports.angular_derived:
        derived.append("the bulkhead web's (bulkhead_compliance)")
    if ring:
        derived.append("the bore ring's, an upper end (ring_tilt_compliance)")
    k = BULKHEAD_FACTOR
    return Uncertainty("supports' angular compliance (bulkhead and bore ring)",
                       {f"support tilt compliance ×{1 / k:g}": {"support_angular_scale": 1 / k},
                        f"support tilt compliance ×{k:g}": {"support_angular_scale": k}},
                       f"assumed: {' and '.join(derived)}, ×{k:g} either way, not checked against finite elements",
                       "a bearing cap's tilt under a couple (finite elements, or on a mandrel)")


#: The model inputs a comparison declares, each called as ``f(engine, tilt_method)`` (the study's tilt method:
#: whether the study reads the input) and giving its :class:`Uncertainty`, or None where the engine file sources
#: the input or the study does not read it.
MODEL_INPUTS = (housing_stiffness, crush_height, journal_temperature, crank_stiffness, support_tilt_compliance)


def model_uncertainties(engine, tilt_method="equilibrium"):
    """The declared model-uncertainty scenarios of an engine (an :class:`~stackup.engines.Engine`) for a study
    with ``tilt_method``: a list of :class:`Uncertainty`, one per input of :data:`MODEL_INPUTS` that declares
    one."""
    out = []
    for declared in MODEL_INPUTS:
        u = declared(engine, tilt_method)
        if u is not None:
            out.append(u)
    return out


def kind(scenario):
    """"model" where a scenario changes a model input (:data:`MODEL_KEYS`), else "process"."""
    return "model" if any(key in MODEL_KEYS for key in (scenario or {})) else "process"


__all__ = ["DECLARED", "KEYS", "MECHANICS_KEYS", "MODEL_INPUTS", "MODEL_KEYS", "Uncertainty", "apply",
           "crank_stiffness", "crush_height", "housing_stiffness", "is_assumed", "journal_temperature", "kind",
           "model_uncertainties", "support_tilt_compliance"]
