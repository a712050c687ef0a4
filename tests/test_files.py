"""Reading input files: every refusal names the file, the key, the value and what is valid."""

import pytest

from stackup._files import Table, read_toml


def test_files_that_are_not_toml_text_are_refused_by_name(tmp_path):
    (tmp_path / "folder.toml").mkdir()
    (tmp_path / "binary.toml").write_bytes(b"\x89PNG\x00\x01")
    (tmp_path / "latin.toml").write_bytes("name = 'M\xfcller'".encode("latin-1"))
    (tmp_path / "empty.toml").write_text("  \n")
    (tmp_path / "broken.toml").write_text("name = \n")
    cases = {"folder.toml": "is a folder, not a file", "missing.toml": "does not exist",
             "binary.toml": "is a binary file, not TOML text", "latin.toml": "is not UTF-8 text",
             "empty.toml": "is empty", "broken.toml": r"not valid TOML \(.*line 1"}
    for name, message in cases.items():
        with pytest.raises(ValueError, match=rf"engine file '.*{name}'?: {message}"):
            read_toml(tmp_path / name, kind="engine")


def test_a_table_reads_types_and_ranges_and_refuses_unread_keys():
    t = Table({"shared": 0.3, "sharred": 0.3, "limits": [50.0, 50.018], "n": "3"}, "engine file 'e.toml'",
              "housing_bore")
    assert t.number("shared", lo=0.0, hi=1.0, hi_open=True) == 0.3
    assert t.lengths("limits", count=2, scale=1e-3, units="mm", plausible=(1e-3, 2.0), what="bore",
                     increasing=True) == pytest.approx([0.05, 0.050018])
    with pytest.raises(ValueError, match=r"engine file 'e.toml', key housing_bore.n: '3' is text, not a number"):
        t.number("n")
    with pytest.raises(ValueError, match=r"engine file 'e.toml', key housing_bore: unknown key 'sharred'; valid keys: "
                                         r"limits, n, shared"):
        t.close()


def test_implausible_lengths_point_at_the_units():
    t = Table({"spans": [0.085, 0.085], "limits": [50.0, 50.0]}, "engine file 'e.toml'", "crank")
    with pytest.raises(ValueError, match=r"key crank.spans: 0.085 mm is not a plausible crankshaft span "
                                         r"\(20 to 2000 mm\); is `units` right\?"):
        t.lengths("spans", scale=1e-3, units="mm", plausible=(0.02, 2.0), what="crankshaft span")
    with pytest.raises(ValueError, match=r"key crank.limits: \[50.0, 50.0\] mm is not increasing"):
        t.lengths("limits", scale=1e-3, units="mm", plausible=(1e-3, 2.0), what="bore", increasing=True)
