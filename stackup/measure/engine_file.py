"""Writing measured entries into a copy of an engine file, keeping its comments.

An engine file is the user's: measured values go into a copy (never over the
file itself unless asked), each replaced key marked with a comment saying
where the new value comes from; every other line, comments included, stays
as it was. The copy is loaded strictly (:func:`stackup.engines.load_engine`)
before it is written.
"""

from __future__ import annotations

import math
import os
import re
import tomllib
from pathlib import Path

from ..engines import engine_files, engine_path, load_engine

_HEADER = re.compile(r"^\s*\[\s*([A-Za-z0-9_.\-\s]+?)\s*\]\s*(#.*)?$")


def number(value):
    """A float as TOML text: enough digits for a nanometre in mm, no trailing noise."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{value!r} is not a finite number")
    text = f"{float(value):.8g}"
    return text if any(c in text for c in ".en") else text + ".0"


def inline(value):
    """A value (number, text, list, dict) as TOML inline text."""
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {inline(v)}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(inline(v) for v in value) + "]"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return number(float(value))


def _sections(lines):
    """(name, start, end) of the top level ("" , 0, first header) and of every [table] (header line to next)."""
    heads = [(i, m.group(1).replace(" ", "")) for i, line in enumerate(lines) if (m := _HEADER.match(line))]
    bounds = [("", 0, heads[0][0] if heads else len(lines))]
    for k, (i, name) in enumerate(heads):
        bounds.append((name, i, heads[k + 1][0] if k + 1 < len(heads) else len(lines)))
    return bounds


def set_key(text, table, key, value, comment):
    """``text`` with ``key = value`` set in ``[table]`` ("" for the top level), a ``# comment`` line above it.

    An existing ``key = ...`` line is replaced (its own comment lines above it
    stay); a ``[table.key]`` sub-table is removed; otherwise the line is added
    at the end of the table's lines (before trailing blank lines).
    """
    lines = text.splitlines()
    bounds = {name: (start, end) for name, start, end in _sections(lines)}
    if table not in bounds:
        raise ValueError(f"engine file: no [{table}] table to write {key} into")
    sub = bounds.get(f"{table}.{key}")
    if sub is not None:
        del lines[sub[0]:sub[1]]
        bounds = {name: (start, end) for name, start, end in _sections(lines)}
    start, end = bounds[table]
    new = [f"# {line}" if line else "#" for line in comment.splitlines()] + [f"{key} = {value}"]
    pattern = re.compile(rf"^\s*{re.escape(key)}\s*=")
    first = start + (1 if table else 0)
    at = next((i for i in range(first, end) if pattern.match(lines[i])), None)
    if at is None:
        at = end
        while at > first and not lines[at - 1].strip():
            at -= 1
        lines[at:at] = new
    else:
        lines[at:at + 1] = new
    return "\n".join(lines) + "\n"


def file_units(engine):
    """The length unit an engine file (a built-in name or a path) declares ("mm", "um" or "m")."""
    return tomllib.loads(Path(engine_path(engine)).read_text(encoding="utf-8")).get("units", "m")


def write_engine(engine, out, changes, *, name=None, force=False):
    """Write a copy of ``engine``'s file to ``out`` with ``changes`` set; return the path written.

    Parameters
    ----------
    engine : str or path
        Built-in engine name or engine file.
    out : str or path
        File to write; refused if it exists (or is the engine's own file)
        unless ``force``.
    changes : sequence of (table, key, value, comment)
        Entries to set (:func:`set_key`); ``value`` a Python value or TOML text
        (a str starting with ``{`` or a digit is taken as TOML).
    name : str, optional
        The copy's engine name (its ``name`` key).
    """
    source = Path(engine_path(engine))
    out = Path(out)
    if out.is_dir():
        raise ValueError(f"out: {str(out)!r} is a folder; give a file name")
    if out.exists() and not force:
        same = out.resolve() == source.resolve()
        raise ValueError(f"out: {str(out)!r} {'is the engine file itself' if same else 'exists'}; pass force=True "
                         "(--force) to replace it, or give another file name")
    files = engine_files(source)
    text = files["text"]
    for table, key, value, comment in changes:
        rendered = value if isinstance(value, str) and value[:1] in "{[-0123456789" else inline(value)
        text = set_key(text, table, key, rendered, comment)
    if name is not None:
        text = set_key(text, "", "name", inline(name), "engine name of this copy")
    tomllib.loads(text)
    load_engine(None, files={**files, "name": out.stem, "text": text})
    out.parent.mkdir(parents=True, exist_ok=True)
    for extra, content in files["extra"].items():  # a measured pressure trace the engine file names
        target = out.parent / extra
        if not target.exists():
            target.write_text(content)
    tmp = out.with_name(f".{out.name}.partial-{os.getpid()}")
    tmp.write_text(text)
    os.replace(tmp, out)
    return out
