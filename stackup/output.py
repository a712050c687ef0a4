"""Where a run writes: checked before anything is computed, then written whole or not at all.

A run's files are written into a staging folder (hidden, beside or inside
the output folder) and moved into place only when every file is written, so
an error or Ctrl-C leaves the output folder as it was. Before anything is
computed, :func:`prepare_folder` refuses an output folder that is a file,
cannot be written, holds files that are not a run, or holds another run
(unless ``force``); :func:`prepare_file` does the same for one output file.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import tempfile
from dataclasses import dataclass
from pathlib import Path

#: The dataset of a comparison; a folder holding it (or a report) holds a run.
DATASET = "compare.nc"
#: Files a comparison writes (globs), replaced together when a run replaces another.
RUN_FILES = (DATASET, "report.md", "report.html", "*.png")
#: Study parameters that tell two comparisons apart.
IDENTITY = ("engine", "schemes", "n_engines", "seed", "window")
_STAGING = ".stackup-partial-"


class OutputRefused(ValueError):
    """An output location that a run must not write to, with the reason and what to do instead."""


@dataclass
class Staged:
    """A run's output on its way: written into ``staging``, moved to ``target`` by :meth:`commit`."""

    target: Path
    staging: Path

    def commit(self):
        """Move the staged files into the target folder (replacing a previous run's files); return the target."""
        with _no_interrupt():
            if self.target.is_dir():
                for pattern in RUN_FILES:
                    for old in self.target.glob(pattern):
                        old.unlink()
                for new in self.staging.iterdir():
                    os.replace(new, self.target / new.name)
                self.staging.rmdir()
            else:
                self.target.parent.mkdir(parents=True, exist_ok=True)
                os.replace(self.staging, self.target)
        return self.target

    def discard(self):
        """Remove the staged files: the target stays as it was."""
        with _no_interrupt():
            shutil.rmtree(self.staging, ignore_errors=True)


class _no_interrupt:
    """Ctrl-C waits until the block is done (moving or removing files is quick)."""

    def __enter__(self):
        try:
            self.previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
        except ValueError:  # not the main thread: signals go elsewhere anyway
            self.previous = None

    def __exit__(self, *exc):
        if self.previous is not None:
            signal.signal(signal.SIGINT, self.previous)


def prepare_folder(folder, *, identity=None, force=False, option="--out"):
    """Check that ``folder`` can take a comparison's files and open its staging folder; nothing else is written.

    Parameters
    ----------
    folder : str or path
    identity : dict, optional
        The run's :data:`IDENTITY` parameters (and ``scenarios``, their
        labels): a folder holding a run with the same ones is replaced (it is
        the same run again); another run is refused unless ``force``.
    force : bool
        Replace another run's files.
    option : str
        How the user named the folder, for the messages.

    Returns
    -------
    Staged

    Raises
    ------
    OutputRefused
        The folder is a file, cannot be written, holds files that are not a
        run, or holds another run and ``force`` is false.
    """
    folder = Path(folder)
    where = f"{option} {str(folder)!r}"
    if folder.exists() and not folder.is_dir():
        raise OutputRefused(f"{where} is a file, not a folder; give a folder for the dataset and the report")
    if folder.is_dir():
        _check_contents(folder, where, identity, force)
        parent = folder
    else:
        parent = _existing_ancestor(folder, where)
    return Staged(folder, _staging(parent, where))


def _check_contents(folder, where, identity, force):
    entries = [p for p in folder.iterdir() if not p.name.startswith(_STAGING)]
    if not entries:
        return
    if not any((folder / name).is_file() for name in (DATASET, "report.md")):
        raise OutputRefused(f"{where} is not empty and holds no stackup run (it holds {entries[0].name!r}); give a "
                            "new or empty folder")
    saved = saved_run(folder)
    if force or (saved is not None and identity is not None and saved == _normalised(identity)):
        return
    raise OutputRefused(f"{where} holds another run ({describe(saved)}); pass --force to replace it, or give "
                        "another folder")


def _existing_ancestor(path, where):
    for parent in path.absolute().parents:
        if parent.exists():
            if not parent.is_dir():
                raise OutputRefused(f"{where}: {str(parent)!r} is a file, not a folder")
            return parent
    raise OutputRefused(f"{where}: no folder of this path exists")  # pragma: no cover (the root always exists)


def _staging(parent, where):
    """A fresh staging folder in ``parent``: creating it is the test that the location can be written."""
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputRefused(f"{where}: {str(parent)!r} cannot be written (no permission); give a folder you can "
                            "write to")
    try:
        return Path(tempfile.mkdtemp(prefix=_STAGING, dir=parent))
    except OSError as error:
        raise OutputRefused(f"{where}: no file can be created in {str(parent)!r} ({error.strerror}); give a folder "
                            "you can write to") from None


def saved_run(folder):
    """The :data:`IDENTITY` parameters and scenario labels of the run saved in ``folder``, or None if unreadable."""
    import netCDF4

    try:
        with netCDF4.Dataset(Path(folder) / DATASET) as nc:
            study = json.loads(nc.getncattr("study"))
            scenarios = [nc.groups[g].getncattr("scenario") for g in nc.groups if g.startswith("scenario_")]
    except (OSError, KeyError, AttributeError, ValueError, RuntimeError):
        return None
    return _normalised({**{k: study.get(k) for k in IDENTITY}, "scenarios": scenarios})


def _normalised(identity):
    return json.loads(json.dumps(identity))


def describe(identity):
    """A run's identity in a few words, for messages."""
    if identity is None:
        return "its dataset cannot be read"
    schemes = identity.get("schemes") or []
    window = identity.get("window")
    text = (f"{identity.get('n_engines', 0):,} engines of {identity.get('engine')}, {len(schemes)} scheme"
            f"{'s' if len(schemes) != 1 else ''}, seed {identity.get('seed')}")
    if window:
        text += f", window {window[0] * 1e6:g}-{window[1] * 1e6:g} um"
    return text + (f", {len(identity['scenarios'])} scenarios" if identity.get("scenarios") else ", no scenarios")


def prepare_file(path, *, force=False, option="--csv"):
    """Check that the file ``path`` can be written before anything is computed; return it as a Path.

    An existing file is replaced only with ``force``; a folder, a parent
    that is a file or a location that cannot be written is refused
    (:class:`OutputRefused`). Write it with :func:`write_file`.
    """
    path = Path(path)
    where = f"{option} {str(path)!r}"
    if path.is_dir():
        raise OutputRefused(f"{where} is a folder; give a file name")
    if path.exists() and not force:
        raise OutputRefused(f"{where} exists; pass --force to replace it, or give another file name")
    parent = path.parent if path.parent.is_dir() else _existing_ancestor(path, where)
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputRefused(f"{where}: {str(parent)!r} cannot be written (no permission); give a file you can write")
    if path.exists() and not os.access(path, os.W_OK):
        raise OutputRefused(f"{where} cannot be written (no permission); give a file you can write")
    return path


def write_file(path, text):
    """Write ``text`` to ``path`` whole: into a temporary file beside it, then moved over it."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=_STAGING, dir=path.parent)
    try:
        with os.fdopen(handle, "w", newline="") as f:
            f.write(text)
        with _no_interrupt():
            os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path
