"""What changed between two saved comparisons: the verdict, the shares, the lives, and the inputs that differ.

:func:`between` reads two comparisons ``stackup compare`` saved (their
folders or their ``compare.nc``) and nothing else: the verdict, ranking and
lives of each are the facts its report states (:func:`stackup.facts.facts`,
:func:`stackup.rank.ranked`), and its inputs are what the dataset stores
of itself (the study's parameters, the text of every file it read, the
scenarios, the package version). :func:`lines` says it in words for
``stackup diff``.

A change of a share or a life is said to lie beyond the runs' noise only
where the two 95 % intervals do not overlap; two runs on other seeds or
other inputs are independent samples, so overlapping intervals say the
difference is not shown, not that there is none.
"""

from __future__ import annotations

import json
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from .facts import facts
from .io import open_comparison
from .output import DATASET, describe
from .patterns import ISO_SCHEMES
from .rank import ranked
from .report.verdict import verdict
from .schemes import from_dict

#: Study parameters that say nothing about the inputs (how the work was split or shown).
NOT_INPUTS = ("chunk_lots", "history")


@dataclass(frozen=True)
class Run:
    """One saved comparison as :func:`between` reads it.

    Attributes
    ----------
    path : pathlib.Path
        Its dataset.
    about : str
        The run in a few words (engines, engine, schemes, seed, ...).
    verdict : str
        The report's first verdict paragraph, without Markdown.
    ranking : pandas.DataFrame
        :func:`stackup.rank.ranked` of its facts: one row per scheme, in rank order.
    b10 : dict
        Scheme -> (value, lower, upper) engine life B10 [h] (empty where the film did not run).
    inputs : dict
        Flat ``{what: value}`` of everything it was run from (:func:`inputs`).
    """

    path: Path
    about: str
    verdict: str
    ranking: pd.DataFrame
    b10: dict
    inputs: dict


@dataclass(frozen=True)
class Difference:
    """Two runs and what differs between them.

    Attributes
    ----------
    a, b : Run
    schemes : pandas.DataFrame
        Per scheme of either run (A's rank order, then B's new ones): the share outside the window [ppm], the
        share of bearings below the life target at the worst position [%], the median and B10 engine life [h],
        each with its 95 % interval in A and B, and whether the intervals of A and B are apart (``*_apart``).
    inputs : list of (str, object, object)
        ``(what, value in A, value in B)`` for each input that differs (None: not given in that run).
    """

    a: Run
    b: Run
    schemes: pd.DataFrame
    inputs: list

    @property
    def same_choice(self):
        """Both runs' verdicts choose the same scheme."""
        return self.a.ranking.index[0] == self.b.ranking.index[0]


def _dataset(path):
    path = Path(path)
    if path.is_dir():
        path = path / DATASET
    if not path.is_file():
        raise ValueError(f"run: {str(path)!r} is not a file; give a folder `stackup compare` wrote or its {DATASET}")
    return path


def _flat(table, prefix=""):
    """A nested TOML table as ``{"a.b.c": value}``."""
    out = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(_flat(value, f"{name}."))
        else:
            out[name] = value
    return out


def _toml_keys(text, what):
    """A stored file's keys (``what`` + key), or its whole text where it is not TOML (a pressure trace, a CSV)."""
    try:
        return {f"{what} {key}": value for key, value in _flat(tomllib.loads(text)).items()}
    except tomllib.TOMLDecodeError:
        return {what: text}


def _scheme_keys(text, what):
    """A stored scheme's keys as :meth:`~stackup.schemes.Scheme.to_toml_text` writes them (one form whatever file
    it was read from, so a difference is one of grades, pairs or source, not of layout)."""
    return _toml_keys(from_dict(tomllib.loads(text)).to_toml_text(), what)


def inputs(ds, scenarios):
    """Everything a saved comparison was run from, flat: ``{what: value}``.

    The study's parameters (``study <name>``), every key of the engine file
    and of each scheme file as stored (``engine file <key>``, ``scheme <label> <key>``), the other files the
    engine file names, the scenarios, the share that does not separate schemes and the package version.
    """
    study = json.loads(ds.attrs["study"])
    files = json.loads(ds.attrs.get("input_files", "{}"))
    out = {f"study {k}": v for k, v in study.items() if k not in NOT_INPUTS}
    engine = files.get("engine", {})
    out.update(_toml_keys(engine.get("text", ""), "engine file"))
    for name, text in engine.get("extra", {}).items():
        out.update(_toml_keys(text, f"engine's file {name}"))
    for label, text in files.get("schemes", {}).items():
        out.update(_scheme_keys(text, f"scheme {label}"))
    out["scenarios"] = list(scenarios)
    out["negligible share [ppm]"] = ds.attrs.get("negligible_ppm")
    out["stackup version"] = ds.attrs.get("stackup_version")
    return out


def read(path):
    """A saved comparison (its folder or its dataset) as a :class:`Run`."""
    path = _dataset(path)
    try:
        saved = open_comparison(path)
    except (OSError, KeyError) as error:
        raise ValueError(f"run: {str(path)!r} is not a comparison `stackup compare` saved ({error})") from None
    ds = saved.dataset
    if "study" not in ds.attrs:
        raise ValueError(f"run: {str(path)!r} is not a comparison `stackup compare` saved (no study attribute)")
    known = facts(ds, scenarios=saved.scenarios, sensitivity=saved.sensitivity, tails=saved.tails)
    ranking = ranked(known.ranking)
    scenario_rankings = {label: ranked(rows) for label, rows in known.scenario_rankings.items()}
    said = [line for line in verdict(known, ranking, scenario_rankings) if line and not line.startswith("<!--")]
    b10 = dict(known.film.engine_life_b10_h) if len(known.film) else {}
    identity = {**json.loads(ds.attrs["study"]), "scenarios": list(saved.scenarios),
                "design": "designed_scheme" in ds.attrs}
    return Run(path, describe(identity), said[0].replace("**", "").replace("`", ""), ranking, b10,
               inputs(ds, saved.scenarios))


#: The per-scheme numbers compared: (column of the table, ranking column or "b10", unit).
COMPARED = (("outside_window", "outside_window_ppm", "ppm"),
            ("life_below_target_worst_position", "life_below_target_pct", "%"),
            ("engine_life_median", "engine_life_median_h", "h"),
            ("engine_life_b10", "b10", "h"))


def _number(run, scheme, column):
    """(value, lower, upper) of a scheme's number in a run; NaNs where the run lacks the scheme or the number."""
    if scheme not in run.ranking.index:
        return (np.nan, np.nan, np.nan)
    if column == "b10":
        return tuple(run.b10.get(scheme, (np.nan, np.nan, np.nan)))
    row = run.ranking.loc[scheme]
    if column not in row or row[column] is None or not np.isfinite(row[column]):
        return (np.nan, np.nan, np.nan)
    ci = row.get(f"{column}_ci")
    return (float(row[column]), *(ci if isinstance(ci, tuple) else (np.nan, np.nan)))


def between(a, b):
    """What differs between the saved comparisons ``a`` and ``b`` (folders or ``compare.nc`` files, or runs
    :func:`read` already read): a :class:`Difference`."""
    first, second = (run if isinstance(run, Run) else read(run) for run in (a, b))
    schemes = [*first.ranking.index, *(s for s in second.ranking.index if s not in first.ranking.index)]
    rows = []
    for scheme in schemes:
        row = {"scheme": scheme}
        for name, column, _ in COMPARED:
            x, y = _number(first, scheme, column), _number(second, scheme, column)
            row.update({f"{name}_a": x[0], f"{name}_a_ci": x[1:], f"{name}_b": y[0], f"{name}_b_ci": y[1:],
                        f"{name}_apart": bool(x[2] < y[1] or y[2] < x[1])})
        rows.append(row)
    keys = [*first.inputs, *(k for k in second.inputs if k not in first.inputs)]
    differ = [(k, first.inputs.get(k), second.inputs.get(k)) for k in keys
              if first.inputs.get(k) != second.inputs.get(k)]
    return Difference(first, second, pd.DataFrame(rows).set_index("scheme"), differ)


def _value(x, ci, digits):
    if not np.isfinite(x):
        return "—"
    text = f"{x:,.{digits}f}"
    return text + (f" [{ci[0]:,.{digits}f}, {ci[1]:,.{digits}f}]" if np.all(np.isfinite(ci)) else "")


def _shown(value, width=60):
    text = json.dumps(value, ensure_ascii=False) if not isinstance(value, str) else value
    text = " ".join(text.split())
    return text if len(text) <= width else text[: width - 1] + "…"


def lines(difference):
    """:class:`Difference` in words, as ``stackup diff`` prints it."""
    a, b = difference.a, difference.b
    out = [f"A: {a.path} ({a.about})", f"B: {b.path} ({b.about})", ""]
    chosen = a.ranking.index[0], b.ranking.index[0]
    out.append(f"Verdict: both choose {chosen[0]}." if difference.same_choice else
               f"Verdict: changed, A chooses {chosen[0]}, B chooses {chosen[1]}.")
    out += [f"  A: {a.verdict}", f"  B: {b.verdict}", ""]
    for name, _, unit in COMPARED:
        table = difference.schemes
        if table[[f"{name}_a", f"{name}_b"]].isna().all().all():
            continue
        digits = 1 if unit == "%" else 0
        frame = pd.DataFrame({
            "A": [_value(x, ci, digits) for x, ci in zip(table[f"{name}_a"], table[f"{name}_a_ci"])],
            "B": [_value(x, ci, digits) for x, ci in zip(table[f"{name}_b"], table[f"{name}_b_ci"])],
            "B - A": [f"{y - x:+,.{digits}f}" if np.isfinite(y - x) else "—"
                      for x, y in zip(table[f"{name}_a"], table[f"{name}_b"])],
            "": ["intervals apart" if apart else "" for apart in table[f"{name}_apart"]],
        }, index=table.index)
        out += [f"{name.replace('_', ' ')} [{unit}] (95 % intervals):", frame.to_string(), ""]
    if not difference.inputs:
        out.append("Inputs: the same (the same study parameters, files, scenarios and version).")
        return out
    said, laid = [], {}  # an ISO scheme by name is laid on the engine's drawing: its changes follow the engine's
    for what, x, y in difference.inputs:
        label = what.split(" ")[1] if what.startswith("scheme ") else None
        if label in ISO_SCHEMES:
            laid.setdefault(label, []).append(what.split(" ", 2)[2])
        else:
            said.append(f"  {what}: {_shown(x)} -> {_shown(y)}")
    said += [f"  scheme {label}: laid on the engine's drawing anew ({len(keys)} key{'s' if len(keys) > 1 else ''}: "
             f"{_shown(', '.join(keys), 70)}), as the engine file's changes move it" for label, keys in laid.items()]
    return [*out, f"Inputs that differ ({len(said)}):", *said]
