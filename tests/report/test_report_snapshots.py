"""The report's first page of a small comparison, compared exactly with snapshot files.

The other report tests find each sentence by its template and the facts' numbers
(``test_report.py``); these pin the whole verdict and the decision table of one small,
deterministic comparison (``snapshot_comparison`` in ``conftest.py``), so any change to
what the first page says, or how, shows as a diff of ``snapshots/*.md`` under review.
The snapshots hold no wall time and no package version.

A regression snapshot, not a reference value: after an intended change to the
report's words or numbers, rewrite the files and review their diff::

    STACKUP_UPDATE_SNAPSHOTS=1 pytest tests/report/test_report_snapshots.py
"""

import difflib
import os
from pathlib import Path

import pytest

from stackup.report import write_report

SNAPSHOTS = Path(__file__).parent / "snapshots"
#: Set to 1 to rewrite the snapshot files from the current code instead of comparing with them.
UPDATE = os.environ.get("STACKUP_UPDATE_SNAPSHOTS") == "1"


@pytest.fixture(scope="module")
def first_page(snapshot_comparison, tmp_path_factory):
    """The report's first page up to the contents line: the verdict block and the decision table."""
    c = snapshot_comparison
    text = write_report(c.dataset, tmp_path_factory.mktemp("report"), scenarios=c.scenarios,
                        sensitivity=c.sensitivity, tails=c.tails).read_text()
    start = text.index("<!-- verdict -->")
    end = text.index("<!-- /verdict -->") + len("<!-- /verdict -->")
    table = next(block for block in text[end:].split("\n\n") if block.strip().startswith("| "))
    return {"verdict": text[start:end] + "\n", "decision_table": table.strip() + "\n"}


def matches_snapshot(text, name):
    """Compare ``text`` with ``snapshots/{name}.md`` exactly (or rewrite the file with STACKUP_UPDATE_SNAPSHOTS=1)."""
    path = SNAPSHOTS / f"{name}.md"
    if UPDATE:
        path.write_text(text)
        return
    how = f"if the change is intended, rewrite it with STACKUP_UPDATE_SNAPSHOTS=1 pytest tests/report/{Path(__file__).name} " \
          "and review the diff"
    assert path.is_file(), f"no snapshot {path}: {how}"
    expected = path.read_text()
    if text != expected:
        diff = "".join(difflib.unified_diff(expected.splitlines(True), text.splitlines(True), str(path), "report"))
        pytest.fail(f"the report's {name.replace('_', ' ')} differs from its snapshot ({how}):\n{diff}")


@pytest.mark.parametrize("part", ["verdict", "decision_table"])
def test_the_first_page_matches_its_snapshot(first_page, part):
    matches_snapshot(first_page[part], f"snapshot_comparison_{part}")
