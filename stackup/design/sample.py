"""The design sample: one fixed set of parts, gauge errors and shell normals per scenario.

The designer compares every candidate scheme on the same random numbers
(common random numbers), so the search is reproducible and differences
between candidates are not sampling noise. Each declared scenario that
changes the clearance is drawn from the same generator state as the nominal
engine, so a scenario moves the same parts.

The operating clearance of a bearing is linear in the wall sum of its two
shells to within nanometres over the design window (press fit and swell
change by a fraction of a per cent of the wall change; measured in
``tests/design/test_design.py``), so each bearing is described by two numbers from
the operating clearance a study computes
(:func:`stackup.study.clearance.operating_clearance`):

.. math:: C_{op} = A - \\beta\\,(s_{upper} + s_{lower})

with :math:`A` and :math:`\\beta` from central differences around the wall
sum that would put the bearing in the middle of the window.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._random import lot_generator, seed_sequence
from ..parts import ShellNormals, draw_lot
from ..study.clearance import operating_clearance
from ..study.scenario import apply as apply_scenario

#: Spawn key of the design sample: apart from a study's lots (0, 1, ...) and its
#: pilot (2**63), so a study run with the same seed validates on other parts.
DESIGN_KEY = 2**63 + 1
#: Spawn key of the reading sample: housing and journal readings of many engines, whose distribution
#: weights the grid bins of the cell tables (:mod:`stackup.design.tables`).
READINGS_KEY = 2**63 + 4
#: Spawn key of the check sample (its sub-sample k under ``SeedSequence(seed, spawn_key=(k,))``): parts
#: no decision of the designer saw, for the figures it reports beside the design sample's.
CHECK_KEY = 2**63 + 3
#: Half step of the central difference of the operating clearance in the shell wall [m].
WALL_STEP = 2.5e-6


@dataclass(frozen=True)
class DesignSample:
    """The built bearings of one scenario's sample, flattened over engines and bearings.

    Attributes
    ----------
    label : str
        Scenario label ("nominal" for the engine as it is).
    engine : Engine
        The engine with the scenario applied.
    housing_reading, journal_reading : numpy.ndarray
        Gauge readings of the bores and journals [m].
    clearance_offset : numpy.ndarray
        :math:`A`, the operating clearance extrapolated to a zero wall sum [m].
    wall_factor : numpy.ndarray
        :math:`\\beta`, the drop of the operating clearance per metre of wall sum [-].
    shell_normals : ShellNormals
        Standard normals of the shells made for the sample.
    """

    label: str
    engine: object
    housing_reading: np.ndarray
    journal_reading: np.ndarray
    clearance_offset: np.ndarray
    wall_factor: np.ndarray
    shell_normals: ShellNormals

    @property
    def bearings(self):
        return self.housing_reading.size

    def ideal_wall_sum(self, clearance):
        """Wall sum [m] that gives each bearing the operating clearance ``clearance`` [m]."""
        return (self.clearance_offset - clearance) / self.wall_factor

    def operating_clearance(self, wall_sum):
        """Operating clearance [m] of each bearing with shells of wall sum ``wall_sum`` [m]."""
        return self.clearance_offset - self.wall_factor * wall_sum


@dataclass(frozen=True)
class Readings:
    """Gauge readings of the housing bores of the blocks kept and of the journals of the crankshafts kept [m].

    An engine is built when its block and its crankshaft are kept, two independent events, so the
    readings of one built bearing are distributed as the product of these two distributions.
    """

    housing: np.ndarray
    journal: np.ndarray


def draw_readings(engine, *, n_engines, seed, scenario=None, key=READINGS_KEY):
    """:class:`Readings` of ``n_engines`` engines of ``engine`` (with ``scenario`` applied), from the stream
    ``key`` under ``seed``."""
    engine = apply_scenario(engine, scenario or {})
    parts, _ = draw_lot(engine, lot_generator(seed_sequence(seed), key), n_engines)
    return Readings(parts.housing_reading[~parts.block_scrapped].ravel(),
                    parts.journal_reading[~parts.crank_scrapped].ravel())


def clearance_changes(engine, scenario):
    """True if ``scenario`` changes what the operating clearance depends on (parts, gauges, shells)."""
    other = apply_scenario(engine, scenario)
    return (other.housing_bore, other.journal_d, other.shell_wall) != (engine.housing_bore, engine.journal_d,
                                                                      engine.shell_wall)


def draw_sample(engine, *, n_engines, seed, window, scenario=None, label="nominal", key=DESIGN_KEY):
    """The design sample of ``engine`` (with ``scenario`` applied) for a clearance ``window`` [m].

    ``key`` is the spawn key of its random stream under ``seed``: :data:`DESIGN_KEY` (the search's sample),
    :data:`CHECK_KEY` (the check sample).
    """
    engine = apply_scenario(engine, scenario or {})
    parts, normals = draw_lot(engine, lot_generator(seed_sequence(seed), key), n_engines)
    built = np.broadcast_to(~(parts.block_scrapped | parts.crank_scrapped)[:, None], parts.housing_bore.shape)
    bore, journal = parts.housing_bore[built], parts.journal_d[built]
    # each bearing gets the crush heights of two shells of the sample within the crush limits
    crush_dim = engine.shell_wall.crush
    crush = crush_dim.process.from_normal(normals.crush)
    crush = crush[~crush_dim.outside(crush)]
    if crush.size < 2 * bore.size:
        raise ValueError(f"engine {engine.name}: too few shells within the crush limits for the design sample")
    crush = crush[:2 * bore.size].reshape(-1, 2)

    def clearance(wall):
        return clearance_at(engine, housing_bore=bore, journal_d=journal, crush=crush, wall_sum=2 * wall)

    middle = 0.5 * (window[0] + window[1])
    wall = 0.5 * (bore - journal - middle)  # nominal clearance in the middle of the window
    wall = wall + 0.5 * np.mean(clearance(wall) - middle)  # operating clearance near the middle
    low, high = clearance(wall - WALL_STEP), clearance(wall + WALL_STEP)
    factor = (low - high) / (4 * WALL_STEP)  # per metre of wall sum (two shells)
    offset = 0.5 * (low + high) + factor * 2 * wall
    return DesignSample(label, engine, parts.housing_reading[built], parts.journal_reading[built], offset, factor,
                        normals)


def clearance_at(engine, *, housing_bore, journal_d, crush, wall_sum):
    """Operating clearance [m] of bearings whose two shells have the wall sum ``wall_sum`` [m].

    ``crush`` (bearings, 2) holds the crush heights of each bearing's two
    shells [m]; each shell's wall is half the sum
    (:func:`stackup.study.clearance.operating_clearance`, the core a study's
    chain calls with the walls of the shells it took).
    """
    half = 0.5 * wall_sum
    return operating_clearance(engine, housing_bore=housing_bore, journal_d=journal_d, upper_wall=half,
                               lower_wall=half, upper_crush=crush[:, 0], lower_crush=crush[:, 1]).clearance
