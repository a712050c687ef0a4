"""Where a run writes: claimed and checked before anything is computed, then written whole or not at all.

A run's files are written into a staging folder (hidden, beside or inside
the output folder) and moved into place only when every file is written, so
an error or Ctrl-C leaves the output folder as it was. Before anything is
computed, :func:`prepare_folder` claims the output folder (a lock file
beside it, held with ``flock`` for the run's life and released by the
system when the process dies, even by ``kill -9``: two runs on one folder
cannot both claim it), removes the staging folders a killed run left for it
(whoever holds the claim knows no other run is writing them), and refuses an
output folder that is a file, cannot be written, holds files that are not a
run, or holds another run (unless ``force``); :func:`prepare_file` does the
same for one output file. Folders and files are created with the user's
umask, as any program's (a colleague can read the report where the umask
lets them).
"""

from __future__ import annotations

import glob
import hashlib
import json
import os
import shutil
import signal
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

try:
    import fcntl
except ImportError:  # pragma: no cover (Windows: the claim falls back to creating the lock file exclusively)
    fcntl = None

#: The dataset of a comparison; a folder holding it (or a report) holds a run.
DATASET = "compare.nc"
#: Files a comparison writes (globs), replaced together when a run replaces another.
RUN_FILES = (DATASET, "report.md", "report.html", "*.png", "*.csv")
#: Study parameters that tell two comparisons apart.
IDENTITY = ("engine", "schemes", "n_engines", "seed", "window", "tilt_method")
_STAGING = ".stackup-partial-"
_CLAIM = ".stackup-claim-"


class OutputRefused(ValueError):
    """An output location that a run must not write to, with the reason and what to do instead."""


@dataclass
class Staged:
    """A run's output on its way: written into ``staging``, moved to ``target`` by :meth:`commit`."""

    target: Path
    staging: Path
    claim: "Claim | None" = field(default=None, repr=False)
    #: Files (globs) of the target the staged files replace: a run's, or a report's alone (:func:`stage_report`).
    replaces: tuple = RUN_FILES

    def commit(self):
        """Move the staged files into the target folder (replacing a previous run's files); return the target.

        The claim is released after the move: the next run on the folder sees this run's files.
        """
        with _no_interrupt():
            if self.target.is_dir():
                for pattern in self.replaces:
                    for old in self.target.glob(pattern):
                        old.unlink()
                for new in self.staging.iterdir():
                    os.replace(new, self.target / new.name)
                self.staging.rmdir()
            else:
                _make_parents(self.target.parent)
                os.replace(self.staging, self.target)
            self._release()
        return self.target

    def discard(self):
        """Remove the staged files and release the claim: the target stays as it was."""
        with _no_interrupt():
            shutil.rmtree(self.staging, ignore_errors=True)
            self._release()

    def _release(self):
        if self.claim is not None:
            self.claim.release()
            self.claim = None


class Claim:
    """A run's exclusive claim on an output location: a lock file held with ``flock`` (see the module docstring).

    The lock file ``.stackup-claim-<name>`` lies in the nearest existing
    folder above the output location and holds the claiming process's id
    (for the message another run gets). The system releases the lock when
    the process ends however it ends; :meth:`release` also removes the file.
    """

    def __init__(self, target, where):
        self.where = where
        for _ in range(10):  # the lock file may be removed under us by the run we waited for: take the new one
            self.base, self.key = _claim_place(target)
            self.path = self.base / f"{_CLAIM}{self.key}"
            self._fd = _locked(self.path, where)
            if self._fd is not None:
                return
        raise OutputRefused(f"{where}: another stackup run keeps claiming it; try again")  # pragma: no cover

    def release(self):
        if self._fd is None:
            return
        try:
            self.path.unlink(missing_ok=True)
        finally:
            os.close(self._fd)
            self._fd = None


def _claim_place(target):
    """(nearest existing folder above ``target``, a name for ``target`` relative to it) of a claim."""
    target = Path(os.path.abspath(target))
    base = target.parent
    while not base.exists():
        base = base.parent
    if not base.is_dir():
        raise OutputRefused(f"{str(base)!r} is a file, not a folder")
    relative = target.relative_to(base).parts
    name = "-".join(relative)
    if len(name) > 80:  # a file name has a limit; the hash keeps it unique
        name = name[:60] + "-" + hashlib.sha1(name.encode("utf-8", "surrogateescape")).hexdigest()[:12]
    return base, name


def _locked(path, where):
    """The descriptor of ``path`` locked by this process, None to try again, or OutputRefused if another holds it."""
    try:
        fd = os.open(path, os.O_RDWR | os.O_CREAT | (0 if fcntl else os.O_EXCL), 0o666)
    except FileExistsError:  # pragma: no cover (no fcntl: an existing file is a claim unless its process is gone)
        if _process_alive(_claimant(path)):
            raise OutputRefused(_busy(where, _claimant(path))) from None
        path.unlink(missing_ok=True)
        return None
    except PermissionError:
        raise OutputRefused(f"{where}: {str(path.parent)!r} cannot be written (no permission); give a folder you "
                            "can write to") from None
    except OSError as error:  # e.g. /proc: writable by its mode, yet it holds no new file
        raise OutputRefused(f"{where}: no file can be created in {str(path.parent)!r} ({error.strerror}); give a "
                            "folder you can write to") from None
    if fcntl is not None:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise OutputRefused(_busy(where, _claimant(path))) from None
        try:
            same = os.fstat(fd).st_ino == os.stat(path).st_ino
        except FileNotFoundError:
            same = False
        if not same:  # the holder we waited for removed it as it finished
            os.close(fd)
            return None
    os.ftruncate(fd, 0)
    os.write(fd, f"{os.getpid()}\n".encode())
    return fd


def _claimant(path):
    try:
        return int(Path(path).read_text().split()[0])
    except (OSError, ValueError, IndexError):
        return None


def _process_alive(pid):  # pragma: no cover (used without fcntl only)
    if pid is None:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _busy(where, pid):
    who = f"another stackup run (process {pid})" if pid else "another stackup run"
    return f"{where} is being written by {who}; wait for it to finish, or give another folder"


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
    parent = folder if folder.is_dir() else _existing_ancestor(folder, where)
    if not os.access(parent, os.W_OK | os.X_OK):
        raise OutputRefused(f"{where}: {str(parent)!r} cannot be written (no permission); give a folder you can "
                            "write to")
    claim = Claim(folder, where)
    try:
        _remove_stale(folder, claim)
        if folder.is_dir():
            _check_contents(folder, where, identity, force)
        prefix = _STAGING if folder.is_dir() else f"{_STAGING}{claim.key}-"
        return Staged(folder, _staging(parent, where, prefix), claim)
    except BaseException:
        claim.release()
        raise


def stage_report(folder, *, option="--out"):
    """A staging folder inside ``folder`` for a report written again (``stackup report``): on :meth:`Staged.commit`
    its files replace the report's (``report.md``, ``report.html``, the figures), never the dataset beside them."""
    folder = Path(folder)
    where = f"{option} {str(folder)!r}"
    if folder.exists() and not folder.is_dir():
        raise OutputRefused(f"{where} is a file, not a folder; give a folder for the report")
    _make_parents(folder)
    return Staged(folder, _staging(folder, where), replaces=tuple(p for p in RUN_FILES if p != DATASET))


def _remove_stale(folder, claim):
    """Remove the staging folders a run on ``folder`` left behind (killed): under the claim no run writes them."""
    stale = [*claim.base.glob(f"{_STAGING}{glob.escape(claim.key)}-*")]
    if folder.is_dir():
        stale += [p for p in folder.glob(f"{_STAGING}*")]
    for path in stale:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path, ignore_errors=True)


def _check_contents(folder, where, identity, force):
    entries = [p for p in folder.iterdir() if not p.name.startswith((_STAGING, _CLAIM))]
    if not entries:
        return
    if not any((folder / name).is_file() for name in (DATASET, "report.md")):
        raise OutputRefused(f"{where} is not empty and holds no stackup run (it holds {entries[0].name!r}); give a "
                            "new or empty folder")
    saved = saved_run(folder, options=tuple(k for k in identity or () if k not in (*IDENTITY, "scenarios", "design")))
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


def _staging(parent, where, prefix=_STAGING):
    """A fresh staging folder in ``parent``, with the mode the umask gives: creating it tests the location."""
    try:
        path = Path(tempfile.mkdtemp(prefix=prefix, dir=parent))
    except OSError as error:
        raise OutputRefused(f"{where}: no file can be created in {str(parent)!r} ({error.strerror}); give a folder "
                            "you can write to") from None
    path.chmod(0o777 & ~umask())  # mkdtemp makes it private (0700); the output folder it becomes must not be
    return path


def umask():
    """The process's umask (read without changing it where the system says it)."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _make_parents(folder):
    """Create ``folder`` and its missing parents with the umask's mode."""
    folder.mkdir(parents=True, exist_ok=True)


def saved_run(folder, options=()):
    """The identity of the run saved in ``folder``, or None if unreadable.

    Its :data:`IDENTITY` parameters (the schemes as given, without the one
    the run designed), its scenario labels and whether it designed a scheme
    (``design``), and the study parameters named in ``options``: what
    :func:`run_identity` gives for the same run.
    """
    import netCDF4

    try:
        with netCDF4.Dataset(Path(folder) / DATASET) as nc:
            study = json.loads(nc.getncattr("study"))
            designed = nc.getncattr("designed_scheme") if "designed_scheme" in nc.ncattrs() else None
            scenarios = [nc.groups[g].getncattr("scenario") for g in sorted(
                (g for g in nc.groups if g.startswith("scenario_")), key=lambda g: int(g.split("_")[1]))]
    except (OSError, KeyError, AttributeError, ValueError, RuntimeError):
        return None
    identity = {k: study.get(k) for k in (*IDENTITY, *options)}
    identity["tilt_method"] = identity["tilt_method"] or "equilibrium"  # a study saved before the key
    identity["schemes"] = [s for s in identity["schemes"] or [] if s != designed]  # the run designed it
    return _normalised({**identity, "scenarios": scenarios, "design": designed is not None})


def run_identity(*, engine, schemes, n_engines, seed, window, scenarios, design, tilt_method="equilibrium",
                 **study_options):
    """A comparison's identity as :func:`saved_run` reads it back (``window`` in m or None, ``design`` a bool;
    ``study_options``: further study parameters the run was given, as the study stores them)."""
    return _normalised({**study_options, "engine": engine, "schemes": list(schemes), "n_engines": n_engines,
                        "seed": seed, "window": list(window) if window else None, "tilt_method": tilt_method,
                        "scenarios": list(scenarios), "design": bool(design)})


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
    if identity.get("tilt_method") not in (None, "equilibrium"):
        text += f", tilt {identity['tilt_method']}"
    if identity.get("design"):
        text += ", a designed scheme"
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
    _make_parents(path.parent)
    handle, temporary = tempfile.mkstemp(prefix=_STAGING, dir=path.parent)
    try:
        os.chmod(temporary, 0o666 & ~umask())  # mkstemp makes it private (0600); the file it becomes must not be
        with os.fdopen(handle, "w", newline="", encoding="utf-8") as f:
            f.write(text)
        with _no_interrupt():
            os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return path
