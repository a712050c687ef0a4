"""ISO 13778's schemes in a comparison, as laid on its engine's drawing: their caveats and the re-centring's anchor.

Read from the texts the study stored (the engine file and the schemes'
labels), so a saved comparison says them again with no file present: the
schemes named by the standard's names are the ones the study laid on the
drawing (:func:`stackup.patterns.laid_on`).
"""

from __future__ import annotations

import json

from ..engines import load_engine
from ..patterns import ISO_SCHEMES, anchor, caveats


def iso_caveats(ds):
    """``(caveats, anchor)``: :class:`stackup.patterns.Caveats` of each scheme of the standard in the study
    (by name, in the study's order) and the :class:`stackup.patterns.Anchor` where any was re-centred (else
    None); ``((), None)`` for a dataset without its input texts."""
    files = json.loads(ds.attrs.get("input_files", "{}"))
    labels = [label for label in files.get("schemes", {}) if label in ISO_SCHEMES]
    if not labels:
        return (), None
    engine = load_engine(files["engine"]["name"], files=files["engine"])
    found = tuple(caveats(label, engine) for label in labels)
    return found, anchor() if any(c.adapted for c in found) else None
