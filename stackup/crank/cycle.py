"""One stage of a study: each sampled engine's bearing loads over the engine cycle."""

from __future__ import annotations

import numpy as np

from .shaft import STATUS, reactions

#: Crank status in a dataset: the solver's codes, then engines the stage did not run on.
CYCLE_STATUS = (*STATUS, "not_computed")
NOT_COMPUTED = len(STATUS)


METHODS = ("bearing-law", "linear", "rigid")


def engine_cycles(spec, *, bore_offset, journal_eccentricity, clearance, crank_angle, method="bearing-law",
                  law=None):
    """Bearing reactions of engines over a crank-angle grid.

    Parameters
    ----------
    spec : CrankSpec
        The engine's crank train, loads and bearing law.
    bore_offset, journal_eccentricity : array_like (engines, N+1, 2)
        Misalignment of the bores and the journals [m] (see :meth:`CrankSpec.offsets`).
    clearance : array_like (engines, N+1)
        Diametral operating clearance of each bearing [m] (the law's J scales with it).
    crank_angle : array_like (angles,)
        Crank angles [deg].
    method : {"bearing-law", "linear", "rigid"}
        Support tier: the engine's nonlinear bearing law, linear springs of
        its low stiffness k_lv, or rigid supports.
    law : BellakhdharLaw, optional
        With ``"bearing-law"``: this law (parameters broadcast to (engines, 1,
        N+1), e.g. fitted to each bearing's film) instead of the engine's.

    Returns
    -------
    CrankReactions with leading shape (engines, angles).
    """
    loads = spec.pin_loads(crank_angle)[None]  # (1, angles, N, 2), shared by all engines
    offsets = spec.offsets(np.asarray(bore_offset), np.asarray(journal_eccentricity), crank_angle)
    if method == "bearing-law":
        law = spec.law(np.asarray(clearance)[:, None, :]) if law is None else law
    elif method == "linear":
        law = spec.law_parameters["k_lv"]
    else:
        law = None
    return reactions(loads, spans=spec.spans, EI=spec.ei, offsets=offsets, law=law)


def worst_status(status):
    """Worst solver status over the angle axis (the last), per engine."""
    return np.max(status, axis=-1).astype(np.int8)
