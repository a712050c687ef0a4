"""Methods and assumptions, limits of validity and the parameters of a comparison, filled from its facts.

What each stage's tier solves is the stage's own sentence (``TIER_NOTES`` of
:mod:`stackup.fit` and :mod:`stackup.crank`, the film tier's record in :mod:`stackup.film.registry`).
"""

from __future__ import annotations

import re

from dataclasses import fields

import pandas as pd

from ..crank import TIER_NOTES as CRANK_TIERS
from ..film.registry import find as film_tier
from ..fit import TIER_NOTES as FIT_TIERS
from ..study import Study
from . import format as fmt
from . import templates as words


def _dimension(label, d):
    """One sampled dimension of the engine's processes, in words."""
    lo, hi = d.limits_m
    text = words.DIMENSION_PART.format(label=label, lo=lo * 1e3, hi=hi * 1e3, distribution=d.distribution.lower(),
                                       cpk=d.cpk, std=fmt.um(d.std_m, 2))
    if d.shared:
        text += words.SHARED_PART.format(shared=100 * d.shared)
    if d.gauge_repeatability_m or d.gauge_resolution_m:
        text += words.GAUGE_PART.format(repeatability=d.gauge_repeatability_m * fmt.UM)
        if d.gauge_resolution_m:
            text += words.READ_OUT_PART.format(resolution=d.gauge_resolution_m * fmt.UM)
    return text


def _shells(facts):
    shell, crush = facts.processes.shell_wall, facts.processes.crush_height
    if shell.supply != "to-order":
        return words.SHELLS_SORTED.format(supply=shell.supply, lot=shell.lot_engines, surplus=100 * shell.surplus)
    return words.SHELLS_TO_ORDER.format(
        lot=shell.lot_engines, surplus=100 * shell.surplus, sigma=fmt.um(shell.sigma_m, 2),
        repeatability=fmt.um(shell.gauge_repeatability_m, 2), pilot=fmt.count(facts.about.pilot_engines),
        lo=crush.limits_m[0] * 1e3, hi=crush.limits_m[1] * 1e3, cpk=crush.cpk)


def _clearance_side(facts):
    """The bullets of the clearance stages: parts, shells, press fit, temperatures, clearance."""
    press, crank, study = facts.press_fit, facts.processes.crank, facts.study
    oil = ("." if crank is None else
           words.OIL_PART.format(oil=crank.oil, supply=crank.oil_supply_temperature_degC))
    return [
        words.PARTS.format(housing=_dimension("housing bore", facts.processes.housing_bore),
                           journal=_dimension("journal", facts.processes.journal_d)),
        _shells(facts),
        words.PRESS_FIT.format(housing=press.housing_material, outer=press.housing_outer * 1e3,
                               shell=press.shell_material, width=press.length * 1e3, bore=press.check_bore * 1e3,
                               stress=press.check_stress / 1e6, tier=FIT_TIERS.get(study.fit_method, study.fit_method)),
        words.TEMPERATURES.format(assembly=press.assembly_temperature, running=press.temperature,
                                  journal=press.temperature + press.journal_temperature_excess, oil=oil),
        words.CLEARANCE.format(n_engines=fmt.count(study.n_engines), bearings=facts.about.bearings),
    ]


def _mechanics_side(facts):
    """The bullets of the mechanical chain: crankshaft and loads, oil film, life."""
    crank, study = facts.processes.crank, facts.study
    return [
        words.CRANKSHAFT.format(tier=CRANK_TIERS.get(study.crank_method, study.crank_method), speed=crank.speed_rpm,
                                step=study.crank_angle_step, coaxiality=fmt.um(crank.coaxiality_m, 0),
                                runout=fmt.um(crank.journal_runout_m, 0),
                                engines=fmt.count(facts.about.mechanics_engines)),
        _film_method(facts),
        _life_method(facts),
    ]


def methods(facts):
    """Methods and assumptions, in one place: processes, gauges, press fit, temperatures, tiers, sample sizes."""
    lines = _clearance_side(facts) + iso_lines(*facts.iso)
    if facts.about.mechanics_engines:
        lines += _mechanics_side(facts)
    lines.append(words.STATISTICS)
    if facts.about.summaries:
        lines.append(words.SUMMARIES)
    return lines


def iso_parts(caveats, anchor):
    """The anchor of the re-centring (None where no scheme was re-centred) and the caveats of the standard's
    schemes on this drawing, as sentence parts (the report's bullets, and `stackup schemes --engine`)."""
    where = None if anchor is None else words.ISO_ANCHOR_PART.format(
        clearance=fmt.um(anchor.clearance_min, 1), operating=fmt.um(anchor.operating_min, 1), engine=anchor.engine,
        outer=anchor.housing_outer * 1e3, place=_place(anchor.place), lo=fmt.um_edge(anchor.window[0]),
        hi=fmt.um_edge(anchor.window[1]))
    narrow = {}  # parts of one scheme alike (fine housing and journal classes) in one item
    for c in caveats:
        for n in c.narrow:
            narrow.setdefault((c.scheme, n.of, fmt.um(n.width, 1), fmt.um(n.sigma, 1)), []).append(n.part)
    items = [words.ISO_NARROW_PART.format(scheme=scheme, parts=" and ".join(parts), width=width, of=of, sigma=sigma)
             for (scheme, of, width, sigma), parts in narrow.items()]
    held = [c for c in caveats if c.held]
    if held:  # the same floor for every scheme of the standard (its one smallest clearance)
        items.append(words.ISO_HELD_PART.format(schemes=", ".join(c.scheme for c in held),
                                                target=fmt.um(held[0].window_target, 1),
                                                floor=fmt.um(held[0].floor, 1)))
    return where, items


def _place(share):
    """Where in a window a share of its width lies from its lower edge, in words."""
    side = "below" if share < 0 else "above" if share > 1 else "in"
    return words.ISO_PLACE[side].format(share=100 * (-share if side == "below" else share - 1 if side == "above"
                                                     else share))


def iso_lines(caveats, anchor):
    """The methods' bullets on the standard's schemes laid on this drawing (none where the study has none)."""
    where, items = iso_parts(caveats, anchor)
    return ([words.ISO_ANCHOR.format(anchor=where)] if where else []) + (
        [words.ISO_CAVEATS.format(items="; ".join(items))] if items else [])


def _film_method(facts):
    """The film tier, what it solves and its measured error against the transient reference, in one bullet."""
    method = facts.about.film_method
    record = film_tier(method)  # by a deprecated name in a dataset from before the tiers' one name
    tier = method if record is None else record.notes
    e, checked = facts.film_errors, facts.corrected
    errors = ("" if e is None else
              words.FILM_ERRORS_PART.format(h_min=100 * e.h_min, h_min_mean=100 * e.h_min_mean,
                                            milliseconds=1e3 * e.seconds))
    if len(checked):  # this engine's own error, as the check measured it, in place of the built-in engines'

        def thick(column):
            return 100 * max(cheap / q[0] - 1 for cheap, q in zip(checked[f"{column}_cheap"],
                                                                   checked[f"{column}_corrected"]))

        errors = words.CHECKED_ERRORS_PART.format(h_min=thick("h_min"), h_min_mean=thick("h_min_mean"))
    return words.OIL_FILM.format(method=method, tier=tier, errors=errors)


def _life_method(facts):
    """The life methods, their film and constants with sources, in one bullet."""
    wear, film = facts.wear, facts.study.life_film
    return words.LIFE.format(
        film=film.replace("-", " "), why=words.CYCLE_MEAN_PART if film == "cycle-mean" else words.NOT_CYCLE_MEAN_PART,
        critical=fmt.um(wear.critical_film_m, 2), journal_rz=fmt.um(wear.journal_rz_m, 2),
        shell_rz=fmt.um(wear.shell_rz_m, 2),
        wear_limit=fmt.um(wear.wear_limit_m, 0), wear_rate=wear.wear_rate_m_per_s,
        method1_limit=fmt.um(wear.method1_limit_m, 0), method1_scale=wear.method1_limit_m / wear.wear_rate_m_per_s,
        wear_source=fmt.cited(wear.wear_source))


def _life_bias(bias):
    """What the film tier's error on the cycle-mean film does to method 1's life, or '' (no such error)."""
    if bias is None:
        return ""
    thinner = bias.film / (1 + bias.error)
    return words.LIFE_BIAS_PART.format(error=100 * bias.error, film=fmt.um(bias.film), ratio=bias.life_h /
                                       bias.thinner_life_h, life=fmt.hours(bias.life_h),
                                       thinner_life=fmt.hours(bias.thinner_life_h), thinner_film=fmt.um(thinner),
                                       cap=fmt.whole(bias.cap_h))


def limits_of_validity(facts):
    """What the models leave out, said plainly."""
    # with the mass-conserving check the lives carry its scale: the cheap tier's bias is corrected, not a limit
    bias = words.LIFE_CHECKED_PART if len(facts.corrected) else _life_bias(facts.life_bias)
    before = list(words.LIMITS_BEFORE_LIFE)
    before.insert(-1, words.CRANK_LIMIT.format(block=_block(facts)))
    return [*before, words.LIFE_LIMIT.format(bias=bias), *words.LIMITS_AFTER_LIFE]


def _block(facts):
    """How the study's crankshaft meets the block against tilt, from its tilt method (and, for a study saved when
    the default read the mid-plane, its data: no film over the width, no block turned)."""
    method = facts.study.tilt_method
    if method == "coupled":
        return words.BLOCK_COUPLED
    if method == "free":
        return words.BLOCK_HELD
    return words.BLOCK_OWN_SUPPORT if facts.edge is None or facts.edge.counted else words.BLOCK_RIGID


#: Study parameters the parameters list gives even at their defaults.
ALWAYS = ("engine", "schemes", "n_engines", "seed")


def _text(value):
    """A parameter's value as the parameters list writes it."""
    return ", ".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)


def _standard(source):
    """A standard's source cited by its designation ('ISO 13778:2017'; its title is in the scheme files)."""
    designation = re.match(r"(ISO|DIN|EN|SAE|JIS|GB)[ /][^,]*", source)
    return designation.group(0) if designation else source


def parameters_table(facts):
    """The study's parameters and the data it used, as rows of (parameter, value) for a readable table.

    Schemes that share a source (the six ISO schemes) share one row; a designed scheme's is the Designed
    scheme section's, and the engine's is in its file (the dataset's ``input_files``). The study's parameters at their
    :class:`~stackup.study.Study` defaults or unset are left out (:data:`ALWAYS` aside): the dataset's ``study``
    attribute holds them all; the version is the report's header's.
    """
    defaults = {f.name: _text(f.default) for f in fields(Study)}
    rows = [(key, _text(value)) for key, value in facts.study.items
            if value is not None and (key in ALWAYS or _text(value) != defaults.get(key))]
    rows += [("negligible share outside the window [ppm]", fmt.general(facts.ranking.negligible))]
    by_source = {}
    designed = facts.design.name if facts.design is not None else None  # its source is its own section's
    for name, source in facts.sources.schemes.items():
        if name == designed:
            continue
        # one document's numbered schemes (laid on the engine's drawing or not): one row
        numbered = re.fullmatch(r"(.*?), scheme (\d+)(;.*)?", " ".join(source.split()))
        key = (_standard(numbered.group(1)), numbered.group(3) or "") if numbered else (source, "")
        by_source.setdefault(key, []).append((name, numbered.group(2) if numbered else None))
    for (source, after), named in by_source.items():
        numbers = [n for _, n in named if n is not None]
        run = len(numbers) > 2 and [int(n) for n in numbers] == list(range(int(numbers[0]), int(numbers[-1]) + 1))
        listed = f"{numbers[0]}–{numbers[-1]}" if run else ", ".join(numbers)
        text = f"{source}, scheme{'s' if len(numbers) > 1 else ''} {listed}{after}" if numbers else source
        rows.append((f"source of {', '.join(name for name, _ in named)}", text))
    return pd.DataFrame(rows, columns=["parameter", "value"])


def parameters_text(table):
    """The parameters as one paragraph, ``name: value`` separated by semicolons (a table of two columns)."""
    return "; ".join(words.PARAMETER.format(name=name, value=str(value).rstrip(". "))
                     for name, value in table.itertuples(index=False)) + "."
