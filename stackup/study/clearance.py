"""A bearing's operating clearance from its parts: the one core every sampler of the package calls.

The study's chain (assembled bearings of sampled lots), the root-input model
of tails and Sobol indices (:mod:`stackup.study.roots`: one engine from its
independent inputs) and the designer's sample (:mod:`stackup.design.sample`:
the clearance at a given wall sum) all ask the same question, so they ask it
here: which shell pair a bearing's readings call for (:func:`preferred_pairs`)
and what press fit and operating clearance its housing bore, journal and two
shells give (:func:`operating_clearance`, :func:`press_fit_checks`). A change
to the press fit, to how a shell pair enters it or to grading is made here
once.
"""

from __future__ import annotations

from ..fit import press_fit, press_fit_extremes


def preferred_pairs(scheme, housing_reading, journal_reading):
    """Preferred (upper, lower) shell grade indices of bearings with these gauge readings [m]; -1 where ungraded.

    The readings are read out at the scheme's steps and classified
    (:meth:`~stackup.schemes.Scheme.grade_indices`), then paired by the
    scheme's table (:meth:`~stackup.schemes.Scheme.pair_indices`).
    """
    return scheme.pair_indices(*scheme.grade_indices(housing_reading, journal_reading))


def _shell_pair(upper_wall, lower_wall, upper_crush, lower_crush):
    """The press fit's shell of a pair: the mean crown wall and the mean crush height of its two halves."""
    return {"shell_wall": 0.5 * (upper_wall + lower_wall), "crush_height": 0.5 * (upper_crush + lower_crush)}


def operating_clearance(engine, *, housing_bore, journal_d, upper_wall, lower_wall, upper_crush, lower_crush,
                        method="lame"):
    """Press fit and operating clearance of bearings at ``engine``'s operating temperatures.

    Parameters
    ----------
    engine : Engine
        Its press-fit data (housing, materials, checking block, temperatures).
    housing_bore, journal_d : array_like
        Free housing bore and journal diameters at the assembly temperature [m].
    upper_wall, lower_wall : array_like
        Crown wall of the upper and the lower shell [m].
    upper_crush, lower_crush : array_like
        Crush height of the upper and the lower shell [m].
    method : str
        Press-fit tier (:data:`stackup.fit.METHODS`).

    Returns
    -------
    stackup.fit.PressFit
        ``clearance`` is the diametral operating clearance [m]: housing and
        shells at the engine's operating temperature, the journal at its own
        (``engine.press_fit.journal_temperature``, the operating temperature
        plus the engine file's ``journal_temperature_excess``).
    """
    return press_fit(housing_bore=housing_bore, journal_d=journal_d,
                     **_shell_pair(upper_wall, lower_wall, upper_crush, lower_crush), method=method,
                     **engine.press_fit.kwargs())


def soaked_clearances(engine, *, housing_bore, journal_d, upper_wall, lower_wall, upper_crush, lower_crush,
                      method="lame"):
    """Diametral clearance of the same bearings at assembly and at the cold start (parameters as
    :func:`operating_clearance`), housing, shells and journal all at one temperature [m].

    The press fit's model at the engine's ``assembly_temperature`` and its
    :attr:`~stackup.engines.PressFitSpec.cold_start_temperature`: an
    aluminium housing shrinks about twice as much as the steel journal, so its
    bearings close cold (physics.md sec. 4b). Returns ``(assembly, cold)``.
    """
    spec = engine.press_fit
    shells = _shell_pair(upper_wall, lower_wall, upper_crush, lower_crush)
    return tuple(press_fit(housing_bore=housing_bore, journal_d=journal_d, **shells, method=method,
                           **spec.soaked_kwargs(t)).clearance
                 for t in (spec.assembly_temperature, spec.cold_start_temperature))


def press_fit_checks(engine, *, housing_bore, upper_wall, lower_wall, upper_crush, lower_crush, method="lame"):
    """The press fit of the same bearings over every temperature ``engine`` declares (parameters as
    :func:`operating_clearance`): a :class:`stackup.fit.PressFitExtremes`."""
    return press_fit_extremes(housing_bore=housing_bore,
                              **_shell_pair(upper_wall, lower_wall, upper_crush, lower_crush), method=method,
                              **engine.press_fit.extremes_kwargs())


__all__ = ["operating_clearance", "preferred_pairs", "press_fit_checks", "soaked_clearances"]
