"""The texts of the files a study reads, so its dataset can run it again with no file present.

A study names its engine and schemes (built-in names or file paths) or
gives schemes as :class:`~stackup.schemes.Scheme` objects (a designed
scheme). :func:`input_files` gathers the full text of every one of them —
the engine file, the files it names (a measured pressure trace) and each
scheme file — which the dataset stores in its ``input_files`` attribute;
:meth:`stackup.study.Study.from_dataset` gives them back to the study,
which then reads nothing from disk. An edited file or another working
folder can therefore not change a rerun.
"""

from __future__ import annotations

import hashlib
import json
import tomllib

from ..engines import engine_files, load_engine
from ..patterns import laid_on
from ..schemes import Scheme, from_dict, scheme_path
from ..schemes import load as load_scheme_file


def scheme_text(name_or_path, engine=None):
    """The TOML text of a scheme given by name, path or :class:`~stackup.schemes.Scheme`.

    An ISO 13778 scheme named by its name (``"iso13778-4"``) is the standard's pattern laid on ``engine``'s
    drawing (:func:`stackup.patterns.laid_on`; on the standard's own drawing, its file as it is).
    """
    if isinstance(name_or_path, Scheme):
        return name_or_path.to_toml_text()
    path = scheme_path(name_or_path)
    standard = load_scheme_file(path)  # its errors name the file, the key and the value
    if engine is not None:
        laid = laid_on(str(name_or_path), engine)
        if laid.to_toml_text() != standard.to_toml_text():
            return laid.to_toml_text()
    return path.read_text()


def input_files(engine, schemes, given=None):
    """``{"engine": {"name", "text", "extra"}, "schemes": {label: text}}`` for a study's engine and schemes.

    ``given`` (a study's ``files``) is used first; what it lacks is read
    from disk. ``schemes`` are the study's scheme labels.
    """
    given = given or {}
    engine_texts = given.get("engine") or engine_files(engine)
    known = given.get("schemes", {})
    missing = [label for label in schemes if label not in known]
    drawing = load_engine(engine_texts["name"], files=engine_texts) if missing else None
    return {"engine": engine_texts,
            "schemes": {label: known[label] if label in known else scheme_text(label, drawing) for label in schemes}}


def load_inputs(files, schemes):
    """The engine and the schemes (in the order of the labels ``schemes``) read from ``files``' texts."""
    engine = load_engine(files["engine"]["name"], files=files["engine"])
    loaded = []
    for label in schemes:
        where = f"scheme {label!r} (text stored by the study)"
        try:
            data = tomllib.loads(files["schemes"][label])
        except tomllib.TOMLDecodeError as err:
            raise ValueError(f"{where}: not valid TOML ({err})") from None
        loaded.append(from_dict(data, path=label))
    return engine, loaded


def digest(files):
    """A short hash of the input texts (a study's identity includes them)."""
    return hashlib.sha256(json.dumps(files, sort_keys=True).encode()).hexdigest()[:16]
