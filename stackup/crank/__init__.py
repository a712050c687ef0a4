"""The crankshaft as a continuous beam on its main bearings: support reactions.

Tiers (the ``law`` argument of :func:`reactions`): rigid supports, linear
springs, or the nonlinear bearing law of Bellakhdhar et al. (2013).

- :mod:`~stackup.crank.shaft`: the reactions, the slopes and the rotational
  compliance at the bearings, per tier;
- :mod:`~stackup.crank.beam`: the continuous beam condensed to its supports;
- :mod:`~stackup.crank.law`: the bearing law;
- :mod:`~stackup.crank.housing`: the supports' compliance in the block;
- :mod:`~stackup.crank.cycle`: a study's stage, the bearing loads over the engine cycle.
"""

from .law import BellakhdharLaw
from .shaft import (MAX_ITERATIONS, RTOL, STATUS, TIER_NOTES, CrankReactions, reactions, support_compliance,
                    support_slopes)

__all__ = ["BellakhdharLaw", "CrankReactions", "MAX_ITERATIONS", "RTOL", "STATUS", "TIER_NOTES", "reactions",
           "support_compliance", "support_slopes"]
