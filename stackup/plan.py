r"""Grade-quantity planning for shells (and graded housings and journals).

For a scheme and the engine's processes, :func:`plan` estimates from a sample
of engines, per grade:

- the expected demand per 1000 engines with its 95 % interval (per-engine
  demands are independent; the bearings of one engine are not, through the
  shared block and crankshaft components, so the interval uses the variance of
  the per-engine demand, not a multinomial per bearing);
- the share of the shell production that falls into the grade when sorted by
  the measured wall (the engine's supply: made to order, with spill into
  neighbouring grades, or one process sorted);
- for ``volume`` engines, the shells made, demanded and the surplus or
  shortfall;
- the stock of each grade to hold at the start of a production lot of
  ``lot_engines`` engines so that the lot's demand for the grade is covered
  with probability ``service_level`` (a cycle service level [1]_): the
  ``service_level`` quantile of the lot's demand, a sum of ``lot_engines``
  independent per-engine demands, whose distribution is the
  ``lot_engines``-fold convolution of the sampled per-engine demand. The
  normal approximation :math:`L\mu_g + z_{SL}\,\sigma_g\sqrt{L}` covers
  too few lots (the per-engine demand is skewed, and the skew fades only
  slowly with the lot), so it is used only past :data:`EXACT_LOT_SUPPORT`.
  The safety stock is that stock less the lot's expected demand. The tests
  check the service level by simulating lots.

:func:`planner_table` turns a plan into the table a production planner uses:
whole parts (rounded up where stock must cover demand), units in the column
names, and a plain title saying what it answers.

References
----------
.. [1] Silver, E. A., Pyke, D. F., Thomas, D. J., *Inventory and Production
   Management in Supply Chains*, 4th ed., CRC Press, 2017, ch. 6 (safety stock
   for a cycle service level).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pandas as pd
import xarray as xr
from scipy import signal, stats

from ._validate import InRange, Integer, OneOf, OrNone, Positive, renamed, validated
from ._module import callable_module
from ._random import lot_generator, seed_sequence
from .assembly import shell_demand_per_engine
from .engines import load_engine
from .parts import draw_lot
from .patterns import laid_on
from .stats import mean_half_width
from .study.inputs import load_inputs
from .study.pilot import pilot_parts, shell_plan

#: Service level of the shell stock when none is given: share of lots whose demand for a grade is covered [-].
SERVICE_LEVEL = 0.99
#: Largest support of the lot-demand distribution computed exactly by convolution [shells]; past it (lots of
#: about 100 000 engines) the normal approximation, whose skewness error falls as one over the root of the lot.
EXACT_LOT_SUPPORT = 2**20
#: Fewest engines whose sample variance gives a demand interval.
MIN_ENGINES = 2


def _stock_of_shells_only(values):
    """``service_level`` and ``lot_engines`` plan a shell stock: refused for graded housings and journals."""
    if values["part"] != "shell":
        for name in ("service_level", "lot_engines"):
            if values[name] is not None:
                what = "housing bores" if values["part"] == "housing" else "journals"
                raise ValueError(f"{name}: applies to the shell stock only; {what} are graded, not stocked: "
                                 "leave it out, or plan the shells")


def _lot_within_volume(values):
    """A lot of shells given is at most the volume: the whole volume as one lot."""
    lot, volume = values["lot_engines"], values["volume"]
    if lot is not None and lot > volume:
        raise ValueError(f"lot_engines: a lot of {lot:,} engines is more than the volume of {volume:,} engines; "
                         f"give a lot of at most {volume:,} engines (the whole volume as one lot)")


@renamed(processes="engine")
@validated(volume=Integer(minimum=1), part=OneOf(("shell", "housing", "journal")),
           service_level=OrNone(InRange(0.0, 1.0, lo_open=True, hi_open=True)), lot_engines=OrNone(Integer(minimum=1)),
           sample_engines=Integer(minimum=100), relations=(_stock_of_shells_only, _lot_within_volume))
def plan(scheme, engine="iso-example", *, volume, service_level=None, lot_engines=None, sample_engines=20_000,
         seed=0, part="shell"):
    """Quantities per grade for a scheme: shells (demand, production share, surplus, stock per lot), or graded parts.

    ``scheme`` may also be a study dataset (:class:`stackup.Study` result):
    then every scheme of it is planned from the study's own engines and shell
    lots (rows indexed by scheme and grade).

    Parameters
    ----------
    scheme : str, path, Scheme or xarray.Dataset
        One of ISO 13778's schemes named by its name is laid on ``engine``'s
        drawing as a comparison lays it (:func:`stackup.patterns.laid_on`); a
        scheme file or Scheme is planned as it is.
    engine : str, path or Engine
        The engine whose part processes, gauges and shell supply are planned
        for (``processes=``, its old name, is deprecated).
    volume : int
        Engines to build, > 0.
    service_level : float, optional
        Shells only: probability in (0, 1) that a lot's demand for a grade is
        covered by the stock per lot; default :data:`SERVICE_LEVEL`.
    lot_engines : int, optional
        Shells only: engines per production lot of shells, at most
        ``volume``; default the engine's lot, or ``volume`` when the volume is
        smaller than one lot (said in the attribute ``lot_note``).
    sample_engines : int
        Engines sampled to estimate the demand, >= 100.
    seed : int
    part : {"shell", "housing", "journal"}
        Shells, or the housing bores or journals the scheme grades: their
        share per grade (read by the gauge) and count per 1000 engines and
        for ``volume`` engines, with 95 % intervals. Housing bores and
        journals are graded, not stocked: ``service_level`` and
        ``lot_engines`` are refused with them.

    Returns
    -------
    pandas.DataFrame
        One row per grade. Shells, all counts in shells (fractional where
        they are expectations):

        - ``demand_per_1000`` with ``demand_per_1000_lo`` and
          ``demand_per_1000_hi``: expected demand per 1000 engines and its
          95 % interval;
        - ``demand_share``: share of the demand; ``aim_share``: share of the
          shells made that is aimed at the grade (made to order; NaN for a
          sorted process); ``production_share``: share of the shells made
          that is read into the grade [-];
        - ``made``, ``demanded``, ``surplus``: expected shells read into the
          grade, asked for and left over (negative: short) for ``volume``
          engines;
        - ``lot_demand_mean``: expected demand of a lot; ``order_up_to``: the
          stock per lot that covers the lot's demand with probability
          ``service_level`` (whole shells); ``safety_stock``: the order-up-to
          level less the expected lot demand.

        Graded parts: ``share`` [-], ``per_1000`` with ``per_1000_lo`` and
        ``per_1000_hi`` (95 % interval) and ``for_volume``, expected parts.
        The attributes hold the plan's parameters.
    """
    service_level = float(SERVICE_LEVEL if service_level is None else service_level)
    if isinstance(scheme, xr.Dataset):
        if part != "shell":
            raise ValueError(f"part: a study dataset plans shells only, not {part}s")
        return _from_dataset(scheme, volume=volume, service_level=service_level, lot_engines=lot_engines)
    engine = load_engine(engine)
    scheme = laid_on(scheme, engine)  # ISO 13778's by name on the engine's drawing, as a comparison runs them
    parts = pilot_parts(engine, seed, sample_engines)
    laid = {"laid_on": engine.name if scheme.notes else None}  # adapt() notes how a pattern was laid, a file has none
    if part != "shell":
        frame = _graded_parts(scheme, engine, parts, part, volume, sample_engines, seed)
        frame.attrs.update(laid)
        return frame
    lot, note = _lot(volume, lot_engines, engine.shell_wall.lot_engines)
    frame = _shell_plan(scheme, engine, parts, volume=volume, lot=lot, service_level=service_level)
    frame.attrs = {"part": "shell", "scheme": scheme.name, "engine": engine.name, "volume": volume,
                   "service_level": service_level, "lot_engines": lot, "lot_note": note,
                   "sample_engines": sample_engines, "seed": seed, **laid, **frame.attrs}
    return frame


def _shell_plan(scheme, engine, parts, *, volume, lot, service_level):
    """The shell rows of :func:`plan` from the sampled ``parts``, with the engine's shell supply in the attributes."""
    shells = shell_plan(engine, scheme, parts)
    per_engine = shells.demand_per_engine
    mean = per_engine.mean(axis=0)
    half = mean_half_width(per_engine, axis=0)
    supply = engine.shell_wall
    landing = shells.landing  # share of production read into each grade (the rest is scrap)
    aim = shells.aim if shells.aim is not None else np.full(mean.shape, np.nan)
    made = _shells_made(supply, volume, lot, engine.main_bearings)
    per_lot = supply.shells_per_lot(lot * engine.main_bearings)
    stock = np.array([lot_demand_quantile(per_engine[:, g], lot, service_level) for g in range(mean.size)])
    frame = pd.DataFrame({
        "grade": list(scheme.shell.labels),
        "demand_per_1000": 1000 * mean,
        "demand_per_1000_lo": 1000 * (mean - half),
        "demand_per_1000_hi": 1000 * (mean + half),
        "demand_share": mean / mean.sum(),
        "aim_share": aim,
        "production_share": landing,
        "ordered_per_lot": per_lot * aim,
        "made": made * landing,
        "demanded": volume * mean,
        "surplus": made * landing - volume * mean,
        "lot_demand_mean": lot * mean,
        "safety_stock": stock - lot * mean,
        "order_up_to": stock,
    }).set_index("grade")
    frame.attrs.update({"supply": supply.mode, "shells_made": made, "shells_per_lot": per_lot,
                        "shell_surplus": supply.surplus, "main_bearings": engine.main_bearings,
                        "scrap_share": float(1 - landing.sum()), "unasked": unasked(scheme, frame)})
    return frame


def unasked(scheme, frame):
    """The shells made in grades no preferred pair asks for, and the allowed pairs that could fit them.

    A wall process aimed at the asked grades (or one process sorted into
    every grade) puts shells into grades the preferred pairs never take: ISO
    scheme 2 pairs B+B and allows A+C, so its A and C shells are fitted only
    where B runs short. Returns plain data for the plan's attributes:
    ``grades`` (labels), ``shells`` (expected for the volume), ``share`` of
    the shells made [-], ``alternatives`` (the allowed pairs that use them,
    as "A+C for B+B"), ``pairs``: bearings those alternatives could fit in
    place of the preferred pair (at most its demand, with the shells left
    over in each grade) if fitted before it, and ``used``: the unasked
    shells those bearings take.
    """
    labels = list(frame.index)
    made, demanded = frame.made.to_numpy(), frame.demanded.to_numpy()
    idle = [g for g in range(len(labels)) if demanded[g] < 0.5 <= made[g]]
    if not idle:
        return {}
    spare = np.maximum(made - demanded, 0.0)
    pairs, used, uses = 0, 0, []
    for (pu, pl), options in scheme.alternatives.items():
        # bearings of the preferred pair the volume asks for (each takes one shell of each of its grades)
        wanted = demanded[pu] / 2 if pu == pl else min(demanded[pu], demanded[pl])
        for u, l in options:
            if u not in idle and l not in idle:
                continue
            uses.append(f"{labels[u]}+{labels[l]} for {labels[pu]}+{labels[pl]}")
            k = math.floor(max(min(wanted, spare[u] / 2 if u == l else min(spare[u], spare[l])), 0.0))
            spare[u] -= k
            spare[l] -= k
            wanted -= k
            pairs += k
            used += k * ((u in idle) + (l in idle))
    total = float(made.sum())
    return {"grades": [labels[g] for g in idle], "shells": float(made[idle].sum()),
            "share": float(made[idle].sum() / total) if total else 0.0, "alternatives": uses, "pairs": int(pairs),
            "used": int(used)}


def _lot(volume, lot_engines, default):
    """(engines per lot, note): the lot given, or the default shrunk to the volume where it is larger."""
    if lot_engines is not None:
        return lot_engines, ""
    if default > volume:
        return volume, (f"the volume of {volume:,} engines is less than the engine's lot of {default:,}: "
                        f"planned as one lot of {volume:,} engines")
    return default, ""


def _shells_made(supply, volume, lot, bearings):
    """Shells made for ``volume`` engines in lots of ``lot``: each lot rounds its shells up (the last lot may be short)."""
    full, rest = divmod(volume, lot)
    return full * supply.shells_per_lot(lot * bearings) + (supply.shells_per_lot(rest * bearings) if rest else 0)


def lot_demand_quantile(per_engine, lot, level):
    """Smallest stock that covers the demand of ``lot`` engines with probability ``level`` [parts].

    The lot's demand is the sum of ``lot`` independent per-engine demands,
    each distributed as the sample ``per_engine`` (whole parts per engine);
    its distribution is the ``lot``-fold convolution of the sample's
    (computed by repeated squaring with FFT convolution), and the stock is
    its ``level`` quantile. Past :data:`EXACT_LOT_SUPPORT` the normal
    approximation :math:`L\\mu + z\\,\\sigma\\sqrt{L}`, rounded up.

    Parameters
    ----------
    per_engine : array_like of int (engines,)
        Parts of one kind each sampled engine asks for.
    lot : int
        Engines per lot.
    level : float
        Service level in (0, 1).

    Returns
    -------
    int
    """
    counts = np.asarray(per_engine).astype(np.int64)
    pmf = np.bincount(counts) / counts.size
    if (pmf.size - 1) * lot >= EXACT_LOT_SUPPORT:
        mean, sd = counts.mean(), counts.std(ddof=1)
        return int(math.ceil(lot * mean + stats.norm.ppf(level) * sd * math.sqrt(lot) - 1e-9))
    total, power, k = np.ones(1), pmf, lot
    while k:
        if k & 1:
            total = _convolve(total, power)
        k >>= 1
        if k:
            power = _convolve(power, power)
    # the smallest stock whose cumulative probability reaches the level (FFT rounding is ~1e-15)
    return int(np.searchsorted(np.cumsum(total), level - 1e-12))


def _convolve(a, b):
    """Distribution of the sum of two independent whole-number variables with distributions ``a`` and ``b``."""
    c = signal.fftconvolve(a, b) if min(a.size, b.size) > 64 else np.convolve(a, b)
    c = np.clip(c, 0.0, None)
    return c / c.sum()


def _from_dataset(ds, *, volume, service_level, lot_engines):
    """Shell plan per scheme and grade from a study's assembled engines and shell lots."""
    lot, note = _lot(volume, lot_engines, int(ds.attrs["lot_engines"]))
    engine, schemes = _stored_inputs(ds)
    supply, bearings = engine.shell_wall, engine.main_bearings
    made_for_volume = _shells_made(supply, volume, lot, bearings)
    rows, scrap, idle = [], {}, {}
    for name in ds.scheme.values:
        d = ds.sel(scheme=name)
        built = np.all(d.status.values == 0, axis=1)
        if built.sum() < MIN_ENGINES:
            raise ValueError(f"scheme {name}: {int(built.sum())} engine(s) of the study were built; a plan needs "
                             f"at least {MIN_ENGINES}")
        labels = [g for g, has in zip(d.shell_grade.values, d.grade_in_scheme.values) if has]
        made_total = float(d.shells_made.sum() + d.shells_scrapped)
        scrap[str(name)] = float(d.shells_scrapped) / made_total
        first = len(rows)
        for g in labels:
            per_engine = (np.sum(d.shell_upper_grade.values[built] == g, axis=1)
                          + np.sum(d.shell_lower_grade.values[built] == g, axis=1))
            mean = per_engine.mean()
            half = mean_half_width(per_engine)
            share = float(d.shells_made.sel(shell_grade=g)) / made_total
            made = made_for_volume * share
            stock = lot_demand_quantile(per_engine, lot, service_level)
            rows.append({"scheme": str(name), "grade": str(g), "demand_per_1000": 1000 * mean,
                         "demand_per_1000_lo": 1000 * (mean - half), "demand_per_1000_hi": 1000 * (mean + half),
                         "production_share": share, "made": made, "demanded": volume * mean,
                         "surplus": made - volume * mean, "lot_demand_mean": lot * mean,
                         "safety_stock": stock - lot * mean, "order_up_to": stock})
        idle[str(name)] = unasked(schemes[str(name)], pd.DataFrame(rows[first:]).set_index("grade"))
    frame = pd.DataFrame(rows).set_index(["scheme", "grade"])
    frame.attrs.update({"part": "shell", "volume": volume, "service_level": service_level, "lot_engines": lot,
                        "lot_note": note, "source": "study dataset", "engine": ds.attrs.get("engine", ""),
                        "engines": int(ds.sizes["engine"]), "supply": supply.mode, "shells_made": made_for_volume,
                        "shells_per_lot": supply.shells_per_lot(lot * bearings), "shell_surplus": supply.surplus,
                        "main_bearings": bearings, "scrap_share": scrap, "unasked": idle})
    return frame


def _stored_inputs(ds):
    """The engine and ``{name: Scheme}`` of a study dataset, read from the texts it stores."""
    files = json.loads(ds.attrs["input_files"])
    labels = list(files["schemes"])
    engine, schemes = load_inputs(files, labels)
    return engine, {s.name: s for s in schemes}


def _graded_parts(scheme, engine, parts, part, volume, n, seed):
    """Share and counts of housing bores or journals read into each of the scheme's grades."""
    index = scheme.grade_indices(parts.housing_reading, parts.journal_reading)[0 if part == "housing" else 1]
    grades = scheme.housing if part == "housing" else scheme.journal
    if not grades.graded:
        raise ValueError(f"part: scheme {scheme.name} does not grade the {part}")
    per_engine = np.stack([np.sum(index == g, axis=1) for g in range(len(grades.labels))], axis=1).astype(float)
    b = index.shape[1]
    mean = per_engine.mean(axis=0)
    half = mean_half_width(per_engine, axis=0)
    frame = pd.DataFrame({
        "grade": list(grades.labels),
        "share": mean / b,
        "per_1000": 1000 * mean,
        "per_1000_lo": 1000 * (mean - half),
        "per_1000_hi": 1000 * (mean + half),
        "for_volume": volume * mean,
    }).set_index("grade")
    frame.attrs.update({"scheme": scheme.name, "engine": engine.name, "volume": volume, "part": part,
                        "main_bearings": b, "sample_engines": n, "seed": seed,
                        "ungradable_share": float(np.mean(index < 0))})
    return frame


def planner_table(frame):
    """The table a production planner uses, from a :func:`plan` result: whole parts, units in the column names.

    Counts a stock must cover (demand, parts needed, stock per lot) are
    rounded up, the lower bound of an interval down; shells ordered and made
    are apportioned to the grades so that they add up to the shells ordered
    per lot and made for the volume. Column names carry the unit
    ("[shells]", "[bores]", "[journals]", "[%]") and the quantity they are
    for ("per 1000 engines", "10000 engines", "per lot of 1000 engines"), so
    the table reads the same pasted into a spreadsheet. Shells have a row
    "scrapped" (read outside every grade: made, never fitted) and a row "all
    shells" that adds up every row above (empty where a sum means nothing),
    so the made column adds up to the shells made the title states; graded
    parts have a row "not gradable".

    The title says which quantity a buyer orders: the shells per lot
    (``ordered per lot``, aimed at each grade where shells are made to
    order), whose sum over the volume is the ``made`` column; the stock per
    lot is the level each grade must have at the start of a lot, a check on
    that order rather than a second one.

    Returns
    -------
    pandas.DataFrame
        Indexed by grade (scheme and grade for a plan from a study dataset),
        whole numbers as nullable integers, with the lines that say what the
        table answers in ``attrs["title"]`` (a list of str) and, among them, those
        that say what the order does not cover in ``attrs["warnings"]``.
    """
    a = frame.attrs
    if a.get("part", "shell") != "shell":
        return _graded_table(frame)
    if isinstance(frame.index, pd.MultiIndex):
        schemes = list(frame.index.get_level_values("scheme").unique())
        table = pd.concat({scheme: _shell_table(frame.xs(scheme, level="scheme"), a, a["scrap_share"][scheme])
                           for scheme in schemes}, names=["scheme", "grade"])
        totals = {scheme: table.loc[(scheme, "all shells")] for scheme in schemes}
        idle = {scheme: a["unasked"].get(scheme, {}) for scheme in schemes}  # the schemes of this frame only
    else:
        table = _shell_table(frame, a, a["scrap_share"])
        totals, idle = {None: table.loc["all shells"]}, {None: a["unasked"]}
    several = len(totals) > 1  # a line names the scheme it is about where the table holds several
    title = [_shell_title(a, frame), _order_line(a, table)]
    title += [_made_line(scheme if several else None, total, table.columns, a["volume"])
              for scheme, total in totals.items()]
    if a.get("lot_note"):
        title.append(a["lot_note"][0].upper() + a["lot_note"][1:] + ".")
    title.append(_stock_line(a))
    warnings = []
    stock = int(frame.order_up_to.groupby(level="scheme").sum().max() if isinstance(frame.index, pd.MultiIndex)
                else frame.order_up_to.sum())
    lot, level = a["lot_engines"], a["service_level"]
    if stock > a["shells_per_lot"]:
        warnings.append(f"Note: that stock ({stock:,} shells of all grades) is more than the {a['shells_per_lot']:,} "
                     f"shells made per lot: the surplus of {100 * a['shell_surplus']:.3g} % does not cover the mix of "
                     f"a lot of {lot:,} engines at {100 * level:.4g} %.")
    warnings += [_idle_line(scheme if several else None, record) for scheme, record in idle.items() if record]
    parts = ({s: frame.xs(s, level="scheme") for s in totals} if isinstance(frame.index, pd.MultiIndex)
             else {None: frame})
    warnings += [line for scheme, rows in parts.items() if (line := _short_line(scheme if several else None, rows, a))]
    table.attrs["title"] = [*title, *warnings, _estimated_from(a) + "."]
    table.attrs["warnings"] = warnings  # what the order does not cover (a short report keeps these lines whole)
    return table


def _shell_table(frame, a, scrap):
    """Planner rows of one scheme's shells, with the rows "scrapped" and "all shells"."""
    volume, per_lot = a["volume"], f"per lot of {a['lot_engines']} engines"
    share = frame.production_share.to_numpy()
    made = _apportion(np.append(frame.made.to_numpy(), a["shells_made"] * scrap) if np.isfinite(scrap) else
                      frame.made.to_numpy())
    needed = _up(frame.demanded)
    stock = np.rint(frame.order_up_to.to_numpy()).astype(int)
    columns = {
        "demand per 1000 engines [shells]": _up(frame.demand_per_1000),
        "demand per 1000 engines, 95 % low [shells]": _down(frame.demand_per_1000_lo.clip(lower=0)),
        "demand per 1000 engines, 95 % high [shells]": _up(frame.demand_per_1000_hi),
        "share of shells made [%]": 100 * share,
    }
    if "ordered_per_lot" in frame and frame.ordered_per_lot.notna().all():
        columns[f"ordered {per_lot}, aimed at the grade [shells]"] = _apportion(frame.ordered_per_lot.to_numpy())
    columns.update({
        f"made, {volume} engines [shells]": made[:len(frame)],
        f"needed, {volume} engines [shells]": needed,
        f"surplus, {volume} engines [shells]": made[:len(frame)] - needed,
        f"stock {per_lot} [shells]": stock,
        f"safety stock {per_lot} [shells]": stock - _up(frame.lot_demand_mean),
    })
    table = pd.DataFrame(columns, index=pd.Index(frame.index, name="grade")).astype(float)
    table.loc["scrapped"] = np.nan
    table.loc["scrapped", ["share of shells made [%]", f"made, {volume} engines [shells]"]] = [100 * scrap, made[-1]]
    table.loc["all shells"] = table.sum()
    table.loc["all shells", [c for c in table.columns if "95 %" in c]] = np.nan
    table.index.name = "grade"
    return _nullable(table)


def _shell_title(a, frame):
    scheme = a["scheme"] if "scheme" in a else ", ".join(frame.index.get_level_values("scheme").unique())
    return (f"How many shells of each grade to make and stock for {a['volume']:,} engines of {a['engine']} "
            f"with scheme {scheme}?")


def _order_line(a, table):
    """Which quantity a buyer orders, and how it is split into grades."""
    aimed = ("as the column \"ordered per lot\" says" if any(c.startswith("ordered per lot") for c in table.columns)
             else "so that the sorted shells hold the mix of the planned demand")
    how = (f"made to order: each grade aimed at {aimed}, the wall process then spilling some into the neighbouring "
           "grades" if a["supply"] == "to-order" else
           "made by one wall process and sorted into the grades by the gauge")
    return (f"To order: {a['shells_per_lot']:,} shells per lot of {a['lot_engines']:,} engines "
            f"({_lots(a['volume'], a['lot_engines'])}), {a['shells_made']:,} for the volume: two per bearing and "
            f"{100 * a['shell_surplus']:.3g} % more, {how}. This is the quantity a buyer orders; the other columns "
            "say what it gives.")


def _made_line(scheme, total, columns, volume):
    """The made, needed and surplus columns added up, in words (one scheme)."""
    made = int(total[f"made, {volume} engines [shells]"])
    needed = int(total[f"needed, {volume} engines [shells]"])
    surplus = int(total[f"surplus, {volume} engines [shells]"])
    scrap = made - needed - surplus
    of = f"Scheme {scheme}: of" if scheme is not None else "Of"
    return (f"{of} the {made:,} shells made for the volume the gauge sorts {made - scrap:,} into the grades "
            f"(\"made\") and scraps {scrap:,} ({100 * scrap / made:.2g} %, read outside every grade); the volume's "
            f"preferred pairs need {needed:,} (\"needed\") and {surplus:,} are left over (\"surplus\"; a "
            "negative one is a shortfall).")


def _stock_line(a):
    lot, level = a["lot_engines"], a["service_level"]
    return (f"Stock per lot: the shells of each grade a lot of {lot:,} engines must have at its start for its demand "
            f"for the grade to be covered in {100 * level:.4g} % of lots; what the shells ordered per lot must give "
            "each grade (a check of the order, not a second order). The safety stock is the part above the lot's "
            "expected demand.")


def _idle_line(scheme, record):
    """Shells made in grades no preferred pair asks for, and what the scheme's alternatives could do with them."""
    grades = " and ".join(record["grades"])
    text = (f"{'Scheme ' + scheme + ': g' if scheme is not None else 'G'}rade{'s' if len(record['grades']) > 1 else ''} "
            f"{grades}: {record['shells']:,.0f} shells ({100 * record['share']:.2g} % of those made) land where no "
            "preferred pair asks for them")
    if not record["alternatives"]:
        return text + "; no allowed pair uses them, so they are left over (in the surplus)."
    return (text + f"; the scheme allows {', '.join(record['alternatives'])}, which the assembly fits only where "
            f"the preferred grade runs short, so they are left over (in the surplus). Fitted first, {record['pairs']:,} "
            f"such pairs would use {record['used']:,} of them in place of as many shells of the preferred grades.")


def _short_line(scheme, rows, a):
    """The grades whose shells made per lot fall below their stock per lot (the order does not pass the check)."""
    per_lot = rows.made * a["lot_engines"] / a["volume"]
    short = [(g, per_lot[g], rows.order_up_to[g]) for g in rows.index if per_lot[g] < rows.order_up_to[g] - 0.5]
    if not short:
        return ""
    listed = ", ".join(f"{g} ({math.floor(m):,} made against {int(s):,})" for g, m, s in short)
    return (f"{'Scheme ' + scheme + ': t' if scheme is not None else 'T'}he order falls short of the stock "
            f"per lot in {listed}: over {100 * (1 - a['service_level']):.2g} % of lots run short of them unless "
            "shells are left from earlier lots or an allowed alternative pair fits; aim more of the order at them.")


def _estimated_from(a):
    if a.get("source") == "study dataset":
        return f"Estimated from the {a['engines']:,} engines of the study dataset"
    laid = (f"; scheme {a['scheme']} is ISO 13778's pattern laid on {a['laid_on']}'s drawing as `stackup compare` "
            "runs it (`stackup schemes --engine` with this engine shows its grades)" if a.get("laid_on") else "")
    return f"Estimated from {a['sample_engines']:,} sampled engines (seed {a['seed']}){laid}"


def _lots(volume, lot):
    full, rest = divmod(volume, lot)
    lots = f"the volume is {full:,} lot{'s' if full > 1 else ''} of {lot:,} engines"
    return f"{lots} and one of {rest:,}" if rest else lots


def _graded_table(frame):
    """Planner rows of housing bores or journals per grade, with the row "not gradable"."""
    a = frame.attrs
    unit = "bores" if a["part"] == "housing" else "journals"
    volume, bearings, lost = a["volume"], a["main_bearings"], a["ungradable_share"]
    table = pd.DataFrame({
        f"share of {unit} [%]": (100 * frame.share.to_numpy()).round(2),
        f"per 1000 engines [{unit}]": np.rint(frame.per_1000.to_numpy()).astype(int),
        f"per 1000 engines, 95 % low [{unit}]": _down(frame.per_1000_lo.clip(lower=0)),
        f"per 1000 engines, 95 % high [{unit}]": _up(frame.per_1000_hi),
        f"expected, {volume} engines [{unit}]": np.rint(frame.for_volume.to_numpy()).astype(int),
    }, index=frame.index)
    table.loc["not gradable"] = [round(100 * lost, 2), round(1000 * bearings * lost), np.nan, np.nan,
                                 round(volume * bearings * lost)]
    table = _nullable(table)
    what = "housing bores" if a["part"] == "housing" else "crankshaft main journals"
    table.attrs["title"] = [
        f"How many {what} of each grade will {volume:,} engines of {a['engine']} give, graded by scheme "
        f"{a['scheme']}?",
        f"Graded on the gauge reading, {bearings} per engine; \"not gradable\": read outside every grade.",
        _estimated_from(a) + "; counts per 1000 engines with their 95 % interval, and expected for the volume.",
    ]
    return table


def _nullable(table):
    """Whole-number columns as nullable integers (empty where a value means nothing), shares to 0.01 %."""
    table = table.astype({c: "Int64" for c in table.columns if "[%]" not in c})
    for c in table.columns:
        if "[%]" in c:
            table[c] = table[c].astype(float).round(2)
    return table


def planner_text(table):
    """The planner table as text: its title, then the table with column names wrapped over a few lines."""
    import textwrap

    index = [" / ".join(map(str, k)) if isinstance(k, tuple) else str(k) for k in table.index]
    cells = {c: ["" if pd.isna(v) else f"{v:,.2f}" if "[%]" in c else f"{v:,}" for v in table[c]]
             for c in table.columns}
    widths = {c: max(10, *(len(v) for v in cells[c])) for c in table.columns}
    heads = {c: textwrap.wrap(c, widths[c]) for c in table.columns}
    widths = {c: max(widths[c], *(len(line) for line in heads[c])) for c in table.columns}
    depth = max(len(h) for h in heads.values())
    first = max(len(table.index.name or ""), *(len(i) for i in index))
    lines = []
    for k in range(depth):
        name = (table.index.name or "") if k == depth - 1 else ""
        row = [name.ljust(first)]
        for c in table.columns:
            head = heads[c]
            row.append((head[k - (depth - len(head))] if k >= depth - len(head) else "").rjust(widths[c]))
        lines.append("  ".join(row).rstrip())
    for i, label in enumerate(index):
        lines.append("  ".join([label.ljust(first), *(cells[c][i].rjust(widths[c]) for c in table.columns)]))
    return "\n".join([*table.attrs.get("title", []), "", *lines])


def _up(values):
    """Whole parts, rounded up (values within 1e-9 of a whole number are that number)."""
    return np.ceil(np.asarray(values, dtype=float) - 1e-9).astype(int)


def _down(values):
    return np.floor(np.asarray(values, dtype=float) + 1e-9).astype(int)


def _apportion(values):
    """Expected parts per grade as whole parts that add up to their rounded sum (largest remainder)."""
    floor = np.floor(values)
    short = int(round(values.sum() - floor.sum()))
    floor[np.argsort(floor - values, kind="stable")[:short]] += 1
    return floor.astype(int)


@renamed(processes="engine")
def simulate_lot_coverage(scheme, engine="iso-example", *, order_up_to, lot_engines, lots=400, seed=1):
    """Share of simulated lots whose demand for each grade is at most ``order_up_to`` (grades,).

    ``engine`` (``processes=``, its old name, is deprecated) is a built-in name, a file or an Engine.
    """
    engine = load_engine(engine)
    scheme = laid_on(scheme, engine)
    root = seed_sequence(seed)
    covered = np.zeros(len(scheme.shell.labels))
    for k in range(lots):
        parts, _ = draw_lot(engine, lot_generator(root, k), lot_engines)
        covered += shell_demand_per_engine(scheme, parts).astype(float).sum(axis=0) <= np.asarray(order_up_to)
    return covered / lots


def _preferred_pair_demand(scheme, parts):
    """Bearings per preferred pair code (n_grades**2,), over gradable built bearings."""
    code = scheme.pair_code(*scheme.grade_indices(parts.housing_reading, parts.journal_reading))
    built = ~(parts.block_scrapped | parts.crank_scrapped)[:, None] & (code >= 0)
    return np.bincount(code[built], minlength=len(scheme.shell.labels) ** 2)


def allocate(scheme, pair_demand, supply, *, shortage_cost=10.0):
    """Least-cost use of the scheme's allowed pairs for given demand and shell supply (LP, HiGHS).

    Variables: bearings of each preferred pair served by each allowed option
    (``scheme.option_table``), and surplus and shortfall of each grade.
    Minimises ``sum(surplus) + shortage_cost * sum(shortfall)`` subject to
    every bearing being served and shells used = supply - surplus + shortfall.
    Returns (objective, allocation {(preferred, option): bearings}, surplus (grades,), shortfall (grades,)).
    """
    from scipy.optimize import linprog

    labels = scheme.shell.labels
    n = len(labels)
    options = scheme.option_table
    columns = [(p, k) for p in np.flatnonzero(pair_demand) for k in range(options.shape[1]) if options[p, k, 0] >= 0]
    n_y = len(columns)
    cost = np.concatenate([np.zeros(n_y), np.ones(n), np.full(n, shortage_cost)])
    a_eq, b_eq = [], []
    for p in np.flatnonzero(pair_demand):
        a_eq.append([1.0 if c[0] == p else 0.0 for c in columns] + [0.0] * 2 * n)
        b_eq.append(pair_demand[p])
    for g in range(n):
        row = [float(np.sum(options[p, k] == g)) for p, k in columns]
        row += [1.0 if j == g else 0.0 for j in range(n)] + [-1.0 if j == g else 0.0 for j in range(n)]
        a_eq.append(row)
        b_eq.append(supply[g])
    result = linprog(cost, A_eq=np.array(a_eq), b_eq=np.array(b_eq), bounds=(0, None), method="highs")
    if not result.success:
        raise ValueError(f"allocate: the LP failed ({result.message})")
    y = result.x[:n_y]
    allocation = {(labels[options[p, k, 0]] + "+" + labels[options[p, k, 1]] if k else "preferred",
                   labels[p // n] + "+" + labels[p % n]): v for (p, k), v in zip(columns, y) if v > 1e-9}
    return float(result.fun), allocation, result.x[n_y:n_y + n], result.x[n_y + n:]


@renamed(processes="engine")
@validated(volume=Integer(minimum=1), shortage_cost=Positive(), sample_engines=Integer(minimum=100))
def optimise_supply(scheme, engine="iso-example", *, volume, shortage_cost=10.0, sample_engines=20_000, seed=0):
    """Process mean of one shell process sorted into grades, and use of alternatives, that minimise surplus and shortfall.

    The shell process is the engine's sorted process (``shell_wall.process``,
    stated over the scheme's shell range) with its mean moved; shells made are
    two per bearing plus the engine's surplus (``engine``: a built-in name,
    a file or an Engine; ``processes=``, its old name, is deprecated). For
    each mean the allocation is the LP of :func:`allocate` on expected
    supply; the mean is found by a bounded scalar search over the scheme's
    shell range.

    Returns a dict: ``mean`` [m], ``objective``, ``centred_objective`` (the
    process centred on the shell range), ``allocation``, ``surplus`` and
    ``shortfall`` per grade.
    """
    from scipy.optimize import minimize_scalar

    engine = load_engine(engine)
    scheme = laid_on(scheme, engine)  # ISO 13778's by name on the engine's drawing, as a comparison runs them
    parts = pilot_parts(engine, seed, sample_engines)
    demand = _preferred_pair_demand(scheme, parts) * volume / parts.housing_bore.shape[0]
    supply_spec = engine.shell_wall
    dim = supply_spec.dimension(scheme)
    made = supply_spec.shells_per_lot(volume * engine.main_bearings)
    lo_bins, hi_bins = scheme.shell.bins()
    spread = np.hypot(dim.process.std, supply_spec.gauge.repeatability)

    def supply(mean):
        return made * (stats.norm.cdf(hi_bins, mean, spread) - stats.norm.cdf(lo_bins, mean, spread))

    def objective(mean):
        return allocate(scheme, demand, supply(mean), shortage_cost=shortage_cost)[0]

    lo, hi = scheme.shell.limits
    best = minimize_scalar(objective, bounds=(lo, hi), method="bounded", options={"xatol": 1e-9})
    value, allocation, surplus, shortfall = allocate(scheme, demand, supply(best.x), shortage_cost=shortage_cost)
    return {"mean": float(best.x), "objective": value, "centred_objective": objective(0.5 * (lo + hi)),
            "allocation": allocation, "surplus": dict(zip(scheme.shell.labels, surplus)),
            "shortfall": dict(zip(scheme.shell.labels, shortfall)), "demand": demand, "supply": supply}


callable_module(__name__, plan)
