"""One way to turn a user's seed into random generators.

A study spawns one child :class:`numpy.random.SeedSequence` per production
lot from its root seed, so the numbers of lot ``k`` are the same whatever the
chunking, the number of workers or the order in which lots finish.
"""

from __future__ import annotations

import numpy as np


def seed_sequence(seed) -> np.random.SeedSequence:
    """Root seed sequence from None, an int or a SeedSequence."""
    if isinstance(seed, np.random.SeedSequence):
        return seed
    if seed is None or (isinstance(seed, (int, np.integer)) and not isinstance(seed, bool) and seed >= 0):
        return np.random.SeedSequence(seed)
    raise ValueError(f"seed: {seed!r} is not valid; use None, a non-negative int or a numpy SeedSequence")


def lot_generator(root: np.random.SeedSequence, lot: int) -> np.random.Generator:
    """Generator of production lot ``lot``: child ``lot`` of ``root``, built directly.

    ``SeedSequence(entropy, spawn_key=(lot,))`` is exactly what
    ``root.spawn(...)[lot]`` returns, without spawning the ``lot`` siblings.
    """
    child = np.random.SeedSequence(root.entropy, spawn_key=(*root.spawn_key, lot), pool_size=root.pool_size)
    return np.random.Generator(np.random.PCG64(child))


#: Spawn key of the pilot sample a study plans its shell quantities from;
#: beyond any lot index, so the pilot never shares numbers with a lot.
PILOT_KEY = 2**63


def as_generator(rng) -> np.random.Generator:
    """A Generator from None, an int, a SeedSequence or a Generator."""
    if isinstance(rng, np.random.Generator):
        return rng
    return np.random.Generator(np.random.PCG64(seed_sequence(rng)))
