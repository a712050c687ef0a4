"""Broken input files never change a result silently (issue 21, item 5).

Valid engine files (the built-in ones) and scheme files (the six ISO 13778
schemes) are mutated one key at a time: a key dropped, a key misspelt, a
value of the wrong type, a length scaled by 1000 (a file in mm written in
um). Each mutated file must either be refused with a ValueError naming the
file and the key (or its section), or be read to the result its intent gives:
a dropped optional key reads as its documented default, a length of zero
scaled stays zero. A misspelt key, a value of the wrong type and a length
scaled by 1000 are never accepted.
"""

from __future__ import annotations

import dataclasses
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from stackup import engines, schemes

ENGINE_FILES = sorted(Path(engines.builtin_folder()).glob("*.toml"))
SCHEME_FILES = sorted(Path(schemes.builtin_folder()).glob("*.toml"))


# --- writing a table back as TOML --------------------------------------------------------------------------

def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a JSON string is a TOML basic string
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{json.dumps(k)} = {_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(v)


def to_toml(data):
    """TOML text of a table: scalars and lists as values, sub-tables as [sections] (inline inside lists)."""
    lines = []

    def section(table, path):
        if path:
            lines.append("[" + ".".join(json.dumps(p) for p in path) + "]")
        for k, v in table.items():
            if not isinstance(v, dict):
                lines.append(f"{json.dumps(k)} = {_value(v)}")
        for k, v in table.items():
            if isinstance(v, dict):
                section(v, (*path, k))

    section(data, ())
    return "\n".join(lines) + "\n"


# --- mutations ---------------------------------------------------------------------------------------------

def paths(table, prefix=()):
    """Every key path of a table (not into lists)."""
    for k, v in table.items():
        yield (*prefix, k)
        if isinstance(v, dict):
            yield from paths(v, (*prefix, k))


def lookup(table, path):
    for p in path:
        table = table[p]
    return table


def with_change(data, path, *, drop=False, rename=None, value=None):
    out = json.loads(json.dumps(data))  # a deep copy (TOML values are JSON values here)
    parent = lookup(out, path[:-1])
    key = path[-1]
    if drop:
        del parent[key]
    elif rename is not None:
        parent[rename] = parent.pop(key)
    else:
        parent[key] = value
    return out


def misspellings(key):
    """A few typos of a key, none of them the key itself."""
    out = [key + key[-1], key[:-1] if len(key) > 1 else key + "x", key[0] + key + "_"]
    if len(key) > 2:
        out.append(key[0] + key[2] + key[1] + key[3:])
    return [m for m in dict.fromkeys(out) if m != key]


def retyped(value):
    """Values of another type than ``value``: a number as text, true/false, a table where a value was, ..."""
    if isinstance(value, bool):
        return ["true", 1]
    if isinstance(value, (int, float)):
        return [str(value), True, [value]]
    if isinstance(value, str):
        return [123, True, [value]]
    if isinstance(value, list):
        return [json.dumps(value), 1.0, {"a": 1}] + ([[str(x) for x in value]] if value and not isinstance(value[0], (str, dict)) else [])
    if isinstance(value, dict):
        return [1.0, "table", [1.0]]
    raise TypeError(value)


#: Keys holding lengths in the file's units (mm in every built-in file), by the last part of their path.
ENGINE_LENGTHS = {"limits", "sigma", "bolt_scatter", "ovality", "taper", "repeatability", "bias", "mean", "lo", "hi",
                  "start", "end", "housing_outer", "length", "check_bore", "lining_thickness", "cylinder_bore",
                  "stroke", "conrod", "spans", "bearing_width", "coaxiality", "journal_runout", "dx", "journal_rz",
                  "journal_rq", "shell_rz", "shell_rq", "critical_film", "wear_limit", "groove_width", "hole_diameter",
                  "operating_clearance", "target_offset"}
SCHEME_DATA = ("grades", "table", "letters", "alternatives")  # tables whose keys are labels (data), not names


def scheme_length(path):
    return (path[-1] in ("limits", "resolution", "stated_clearance", "start", "stop", "step")
            or (len(path) == 3 and path[1] == "grades"))


def _is_number_or_numbers(v):
    if isinstance(v, bool):
        return False
    if isinstance(v, (int, float)):
        return True
    return isinstance(v, list) and v != [] and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)


def scaled(value, factor=1000):
    return [x * factor for x in value] if isinstance(value, list) else value * factor


# --- comparing results -------------------------------------------------------------------------------------

def same(a, b, skip=("path",)):
    """Equal results: dataclasses field by field, arrays element by element, floats exactly."""
    if dataclasses.is_dataclass(a) and not isinstance(a, type):
        return type(a) is type(b) and all(same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a)
                                          if f.name not in skip)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(np.asarray(a), np.asarray(b))
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, (list, tuple)):
        return isinstance(b, (list, tuple)) and len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a):
        return math.isnan(b)
    if hasattr(a, "__dict__") and not callable(a):
        return type(a) is type(b) and same(vars(a), vars(b))
    return a == b


# --- the readers and what a dropped key means --------------------------------------------------------------

def read_engine(data, name):
    return engines.load_engine(name, files={"name": name, "text": to_toml(data), "extra": {}})


def read_scheme(data, name, folder):
    path = Path(folder) / f"{name}.toml"
    path.write_text(to_toml(data))
    return schemes.load(path)


_ANY = object()  # an optional key whose absence is itself the documented meaning (checked by a predicate)

ENGINE_DEFAULTS = {
    ("title",): "", ("source",): "", ("name",): lambda e, d: e.name == d,
    ("*", "process", "distribution"): "normal",
    ("*", "gauge", "repeatability"): 0.0, ("*", "gauge", "readings"): 1, ("*", "gauge", "combine"): "mean",
    ("*", "form", "ovality"): 0.0, ("*", "form", "taper"): 0.0, ("*", "form", "planes"): [0.5],
    ("*", "form", "directions"): 1,
    ("press_fit", "check_bore"): lambda e, d: e.press_fit.check_bore == e.housing_bore.lo,
    ("shell_wall",): {}, ("targets",): {}, ("bearing_law",): {}, ("oil",): {},
    ("shell_wall", "supply"): "to-order", ("shell_wall", "process"): {"distribution": "normal", "cpk": 1.33},
    ("shell_wall", "sigma"): 0.001, ("shell_wall", "target_offset"): 0.0, ("shell_wall", "gauge"): {},
    ("shell_wall", "lot_engines"): 1000, ("shell_wall", "surplus"): 0.1,
    ("*", "gauge"): {}, ("*", "shared"): 0.0, ("*", "bolt_scatter"): 0.0, ("*", "source"): "",
    ("*", "form"): lambda e, d: d.form is None,
    ("press_fit", "lining_thickness"): 0.0, ("press_fit", "housing_material"): "steel",
    ("press_fit", "shell_material"): "steel", ("press_fit", "journal_material"): "steel",
    ("press_fit", "check_stress"): 100e6, ("press_fit", "assembly_temperature"): 20.0,
    ("press_fit", "temperature"): 20.0, ("press_fit", "crush_height_source"): "",
    # the journal at the housing's temperature unless the file says how much hotter, and from where
    ("press_fit", "journal_temperature_excess"): 0.0, ("press_fit", "journal_temperature_source"): "",
    ("press_fit", "housing_outer_interval"): lambda e, d: e.press_fit.housing_outer_interval is None,
    ("press_fit", "cold_temperature"): lambda e, d: e.press_fit.cold_temperature is None,
    ("press_fit", "hot_temperature"): lambda e, d: e.press_fit.hot_temperature is None,
    ("press_fit", "limits"): lambda e, d: e.press_fit.limits == engines.KOPELIOVICH_LIMITS,
    ("wear",): lambda e, d: e.wear == engines.DEFAULT_WEAR,
    ("wear", "critical_film"): lambda e, d: e.wear.critical_film == e.wear.journal_rz + e.wear.shell_rz,
    ("wear", "lining_material"): "aluminium",
    # Levanov's method-1 scale (1e8 s, stackup.life.METHOD1_SCALE) at the file's wear speed
    ("wear", "method1_wear_limit"): lambda e, d: abs(e.wear.method1_wear_limit - 1e8 * e.wear.wear_rate) < 1e-12,
    ("oil_feed",): lambda e, d: e.oil_feed.source.startswith("default:"),
    # no [supports]: the bearing law's own stiffness, the bulkhead's web rigid against tilt and the bore ring's
    # turn from the law (docs/engine-file.md, "What the sections hold")
    ("supports",): lambda e, d: (not e.crank.supports.angular.any() and e.crank.supports.ring.all()
                                 and "bearing law" in e.crank.supports.source),
    ("supports", "source"): lambda e, d: e.crank.supports.source == "",
    ("oil_feed", "groove_arc"): [90.0, 270.0], ("oil_feed", "hole_angle"): 180.0,
    ("targets", "operating_clearance"): lambda e, d: e.clearance_window == (0.0, np.inf),
    ("targets", "relative_clearance"): lambda e, d: e.clearance_window == (0.0, np.inf),
    ("targets", "clearance_source"): "", ("targets", "life_hours"): 1000.0,
    ("crank", "counterweight_share"): 0.0, ("crank", "compression_ratio"): 16.0, ("crank", "peak_pressure"): 13e6,
    ("crank", "crank_material"): "steel", ("crank", "coaxiality"): 0.0, ("crank", "journal_runout"): 0.0,
    # no source for the section inertias: assumed (a declared model uncertainty of the comparison)
    ("crank", "section_inertia_source"): "",
    # one width per bearing: the shells' (press_fit.length); a V's two rods side by side on each pin
    ("crank", "bearing_width"): lambda e, d: e.crank.bearing_width == e.press_fit.bearing_width,
    ("crank", "rods"): "side-by-side",
    ("bearing_law", "dx"): 0.00965, ("bearing_law", "k_lv"): 0.98e9, ("bearing_law", "k_hv"): 1.72e9,
    ("bearing_law", "theta0"): 97.0, ("bearing_law", "dtheta"): 15.0, ("bearing_law", "clearance_ratio"): 37.0 / 30.0,
    ("oil", "grade"): "SAE-5W-30", ("oil", "supply_temperature"): 90.0,
}

SCHEME_DEFAULTS = {
    ("title",): "", ("source",): "", ("name",): lambda s, d: s.name == d,
    ("stated_clearance",): lambda s, d: s.stated_clearance is None,
    ("*", "resolution"): 0.0, ("*", "overlap"): False,
    # limits beside grades or classes: the grades' span, or start to stop
    ("*", "limits"): lambda s, d: np.allclose(d.limits, (d.lo.min(), d.hi.max()) if not d.fine
                                              else (d._edges[0] * 1e-9, d._edges[-1] * 1e-9), rtol=0, atol=1e-12),
    ("pairing", "alternatives"): lambda s, d: s.alternatives == {},
}


def default_for(defaults, path):
    for key in (path, ("*", *path[1:])):
        if key in defaults:
            return defaults[key]
    return None


# --- one mutation, judged ----------------------------------------------------------------------------------

def mutations(kind, data):
    """Every (path, operation, argument) of a file: drop, misspell, retype, scale a length by 1000."""
    out = []
    for path in paths(data):
        value = lookup(data, path)
        out.append((path, "drop", None))
        out += [(path, "misspell", m) for m in misspellings(path[-1])]
        out += [(path, "retype", v) for v in retyped(value)]
        is_length = (path[-1] in ENGINE_LENGTHS) if kind == "engine" else scheme_length(path)
        if is_length and _is_number_or_numbers(value):
            out.append((path, "scale", None))
    return out


class Judged:
    counts = {"tried": 0, "refused": 0, "accepted": 0}


def judge(kind, file, path, op, arg, tmp):
    data = tomllib.loads(file.read_text())
    name = file.stem
    read = (lambda d: read_engine(d, name)) if kind == "engine" else (lambda d: read_scheme(d, name, tmp))
    original = read(data)
    if op == "drop":
        changed = with_change(data, path, drop=True)
    elif op == "misspell":
        changed = with_change(data, path, rename=arg)
    elif op == "retype":
        changed = with_change(data, path, value=arg)
    else:
        changed = with_change(data, path, value=scaled(lookup(data, path)))
    Judged.counts["tried"] += 1
    what = f"{kind} {name}: {op} {'.'.join(path)} ({arg!r})"
    try:
        result = read(changed)
    except ValueError as error:
        Judged.counts["refused"] += 1
        message = str(error)
        assert f"'{name}.toml'" in message, f"{what}: the message does not name the file: {message}"
        named = (arg, path[-1], path[0]) if op == "misspell" else (path[-1], path[0])
        assert any(n in message for n in named), f"{what}: the message names neither key nor section: {message}"
        return "refused"
    Judged.counts["accepted"] += 1
    data_key = kind == "scheme" and any(p in SCHEME_DATA for p in path[:-1])
    if op == "scale":
        assert not np.any(np.asarray(lookup(data, path), dtype=float)), f"{what}: a length x1000 was accepted"
        assert same(result, original), f"{what}: a zero length x1000 changed the result"
    elif op == "drop" and data_key:
        pass  # a label dropped from a table of labels (a grade, a pairing alternative) is a smaller valid scheme
    elif op == "drop":
        default = default_for(ENGINE_DEFAULTS if kind == "engine" else SCHEME_DEFAULTS, path)
        assert default is not None, f"{what}: dropping the key was accepted, but it has no documented default"
        if callable(default) and path == ("name",):
            assert default(result, name), f"{what}: a file without a name is not named after the file"
        elif callable(default):
            part = result
            if len(path) == 2 and kind == "scheme" and path[0] in ("housing", "journal", "shell"):
                part = getattr(result, path[0])
            elif len(path) == 2 and kind == "engine" and path[0] in ("housing_bore", "journal_d", "crush_height"):
                part = {"housing_bore": result.housing_bore, "journal_d": result.journal_d,
                        "crush_height": result.shell_wall.crush}[path[0]]
            assert default(result, part), f"{what}: dropping the key did not give its documented default"
        else:
            expected = read(with_change(data, path, value=default))
            assert same(result, expected), f"{what}: dropping the key is not the same as its default {default!r}"
    elif op == "misspell" and data_key:
        pass  # a relabelled grade nobody refers to is a valid scheme
    else:
        raise AssertionError(f"{what}: accepted")
    return "accepted"


def all_mutations():
    out = []
    for file in ENGINE_FILES:
        out += [("engine", file, *m) for m in mutations("engine", tomllib.loads(file.read_text()))]
    for file in SCHEME_FILES:
        out += [("scheme", file, *m) for m in mutations("scheme", tomllib.loads(file.read_text()))]
    return out


ALL = all_mutations()


def test_the_mutations_cover_every_file_and_operation():
    assert {m[1] for m in ALL} == {*ENGINE_FILES, *SCHEME_FILES}
    assert {m[3] for m in ALL} == {"drop", "misspell", "retype", "scale"}
    assert len(ENGINE_FILES) >= 3 and len(SCHEME_FILES) >= 6


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(mutation=st.sampled_from(ALL))
def test_a_mutated_file_is_refused_by_key_or_read_as_intended(mutation, tmp_path):
    judge(*mutation, tmp_path)


@pytest.mark.slow
def test_every_mutation_is_refused_by_key_or_read_as_intended(tmp_path):
    failures = []
    for mutation in ALL:
        try:
            judge(*mutation, tmp_path)
        except Exception as error:  # noqa: BLE001 - a crash other than ValueError is a defect to list too
            kind, file, path, op, arg = mutation
            failures.append(f"{kind} {file.stem}: {op} {'.'.join(path)} ({arg!r}): "
                            f"{type(error).__name__}: {str(error).splitlines()[0][:300]}")
    print(Judged.counts)
    assert not failures, f"{len(failures)} of {len(ALL)} mutations:\n" + "\n".join(failures)
