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
    with pytest.raises(ValueError, match=r"key crank.limits: \[50, 50\] mm is a tolerance of zero width"):
        t.lengths("limits", scale=1e-3, units="mm", plausible=(1e-3, 2.0), what="bore", increasing=True)


def test_materials_files_are_read_strictly(tmp_path):
    from stackup import materials

    cases = {
        "[mg]\nmodulus = 45\npoisson = 0.35\nexpansion = 26e-6\n":
            r"materials file 'm.toml', key mg.modulus: 45 Pa is outside the valid range \[1e\+08, 1e\+13\] Pa",
        "[mg]\nmodulus = '45e9'\npoisson = 0.35\nexpansion = 26e-6\n": r"key mg.modulus: '45e9' is text, not a number",
        "[mg]\nmodulus = 45e9\npoisson = 0.35\nexpansion = 26e-6\nmodulos = 1\n":
            r"key mg: unknown key 'modulos'; valid keys: .*did you mean 'modulus'\?",
        "[mg]\nmodulus = 45e9\nexpansion = 26e-6\n": r"key mg.poisson: missing",
        "units = 'mm'\n": r"key units: 'mm' is not one of 'SI'",
        "mg = 3\n": r"key mg: 3 is a number, not a table",
    }
    for text, message in cases.items():
        (tmp_path / "m.toml").write_text(text)
        with pytest.raises(ValueError, match=message):
            materials.load(tmp_path / "m.toml")
    with pytest.raises(ValueError, match=r"materials file '.*': is a folder, not a file"):
        materials.load(tmp_path)


def test_oils_file_is_read_strictly():
    from stackup.film import oil

    good = ("[o]\nkv40 = 62e-6\nkv100 = 10.8e-6\nhths150 = 3.1e-3\ndensity15 = 852.0\nmultigrade = true\n"
            "pressure_coefficient = 1.1e-8\nsource = 's'\n")
    assert oil.read_oils(good, name="oils.toml")["o"] == oil.get("SAE-5W-30").__class__(
        **{**oil.get("SAE-5W-30").__dict__, "name": "o", "source": "s", "assumed": False})
    cases = {("kv40 = 62e-6", "kv40 = 62"): r"oils file 'oils.toml', key o.kv40: 62 m\^2/s is outside",
             ("multigrade = true", "multigrade = 'yes'"): r"key o.multigrade: 'yes' is text, not true/false",
             ("source = 's'", "sorce = 's'"): r"key o.source: missing \(is 'sorce' a misspelling of it\?\)"}
    for (old, new), message in cases.items():
        with pytest.raises(ValueError, match=message):
            oil.read_oils(good.replace(old, new), name="oils.toml")


def test_a_scheme_needs_no_stated_clearance_and_refuses_wrong_types(tmp_path):
    from stackup import schemes

    text = (schemes.builtin_folder() / "iso13778-4.toml").read_text()
    (tmp_path / "s.toml").write_text(text.replace("stated_clearance = [0.026, 0.044]\n", ""))
    assert schemes.load(tmp_path / "s.toml").stated_clearance is None
    cases = {("A = [50.000, 50.006]", 'A = ["50.000", 50.006]'): r"key housing.grades.A: '50.000' is text, not a number",
             ("[housing]", "[housing]\noverlap = 'false'"): r"key housing.overlap: 'false' is text, not true/false",
             ("[housing]", "[housing]\nresolution = 1.0"): r"key housing.resolution: 1 mm is not a plausible read-out",
             ("A = [50.000, 50.006]", "A = [50000, 50.006]"): r"key housing.grades.A: 50000 mm is not a plausible "
                                                               r"housing bore diameter .*is `units` right\?",
             ("[pairing.table]", "[pairing]\nletters = { a = 'A+A' }\n[pairing.table]"): r"key pairing.letters: .*no matrix",
             ("[journal]", "[journal]\ngrade = 1"): r"key journal: unknown key 'grade'.*did you mean 'grades'\?"}
    for (old, new), message in cases.items():
        assert old in text
        (tmp_path / "s.toml").write_text(text.replace(old, new, 1))
        with pytest.raises(ValueError, match=rf"scheme file 's.toml', {message}"):
            schemes.load(tmp_path / "s.toml")
    (tmp_path / "d").mkdir()
    with pytest.raises(ValueError, match=r"scheme file '.*d': is a folder, not a file"):
        schemes.load(tmp_path / "d")
    text6 = (schemes.builtin_folder() / "iso13778-6.toml").read_text()
    (tmp_path / "s.toml").write_text(text6.replace("step = 0.001", 'step = "0.001"', 1))
    with pytest.raises(ValueError, match=r"key housing.classes.step: '0.001' is text, not a number"):
        schemes.load(tmp_path / "s.toml")


def test_a_table_reads_lists_of_finite_numbers():
    import numpy as np

    t = Table({"arc": [90, 270.0], "rows": [[1.0, 2.0], [3.0, 4.0]], "ragged": [[1.0], [2.0, 3.0]],
               "text": [1.0, "2"], "nan": [1.0, float("nan")]}, "engine file 'e.toml'", "crank")
    np.testing.assert_array_equal(t.numbers("arc"), [90.0, 270.0])
    assert t.numbers("rows", rows=True).shape == (2, 2)
    assert t.numbers("absent", [1.0]).tolist() == [1.0]
    for name, rows in (("rows", False), ("ragged", True), ("text", False)):
        with pytest.raises(ValueError, match=rf"engine file 'e.toml', key crank.{name}: .* is not a list of numbers"):
            t.numbers(name, rows=rows)
    with pytest.raises(ValueError, match=r"engine file 'e.toml', key crank.nan: nan is not a finite number"):
        t.numbers("nan")


def test_a_table_reads_optional_tables_and_sources():
    t = Table({"wear": {"source": " "}}, "engine file 'e.toml'")
    assert t.optional("oil_feed") is None
    with pytest.raises(ValueError, match=r"engine file 'e.toml', key wear.source: empty; say where the numbers"):
        t.optional("wear").source("source")
    t.close()  # both keys are valid, the absent one too
