"""Schemes against the numbers of ISO 13778:2017 (shared/reference/iso13778_schemes.md)."""

import numpy as np
import pytest

import stackup.schemes as schemes

MM = 1e-3
UM = 1e-6

# Literature values: the standard's stated clearance range per scheme [mm].
STATED = {1: (0.026, 0.074), 2: (0.026, 0.070), 3: (0.026, 0.058), 4: (0.026, 0.044), 5: (0.026, 0.050), 6: (0.026, 0.044)}

# Scheme 4 and 5 pairing tables of the standard: rows journal grade, columns housing grade.
TABLE_4 = {"A": ("C+C", "D+D", "E+E"), "B": ("B+B", "C+C", "D+D"), "C": ("A+A", "B+B", "C+C")}
TABLE_5 = {"A": ("B+B", "B+C", "C+C"), "B": ("A+B", "B+B", "B+C"), "C": ("A+A", "A+B", "B+B")}
GRADE_RANGES_HOUSING = {"A": (50.000, 50.006), "B": (50.006, 50.012), "C": (50.012, 50.018)}
GRADE_RANGES_JOURNAL = {"A": (46.000, 46.006), "B": (46.006, 46.012), "C": (46.012, 46.018)}
# Scheme 6: letter of k = h - j, and its shells.
LETTERS_6 = [("A+A", 15, 18), ("A+B", 9, 14), ("B+B", 3, 8), ("B+C", -3, 2), ("C+C", -9, -4), ("C+D", -15, -10), ("D+D", -18, -16)]


def test_available_lists_the_six_iso_schemes():
    names = schemes.available()
    for k in range(1, 7):
        assert f"iso13778-{k}" in names


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_clearance_limits_equal_stated_range_schemes_1_to_5(k):
    lo, hi = schemes.load(f"iso13778-{k}").clearance_limits()
    assert abs(lo - STATED[k][0] * MM) < 0.1 * UM
    assert abs(hi - STATED[k][1] * MM) < 0.1 * UM


def test_clearance_limits_scheme6_within_one_micrometre_of_stated():
    lo, hi = schemes.load("iso13778-6").clearance_limits()
    assert abs(lo - 0.026 * MM) <= 1 * UM
    assert abs(hi - 0.044 * MM) <= 1 * UM + 1e-12


@pytest.mark.parametrize("name, table", [("iso13778-4", TABLE_4), ("iso13778-5", TABLE_5)])
def test_every_cell_of_the_matrix_tables(name, table):
    scheme = schemes.load(name)
    for jg, row in table.items():
        for hg, expected in zip("ABC", row):
            h_lo, h_hi = GRADE_RANGES_HOUSING[hg]
            j_lo, j_hi = GRADE_RANGES_JOURNAL[jg]
            # lower edge, middle and just below the upper edge of each grade
            h = np.array([h_lo, 0.5 * (h_lo + h_hi), h_hi - 0.0001]) * MM
            j = np.array([j_lo, 0.5 * (j_lo + j_hi), j_hi - 0.0001]) * MM
            hh, jj = np.meshgrid(h, j)
            upper, lower = scheme.pair(hh, jj)
            assert upper.shape == (3, 3)
            assert set(np.char.add(np.char.add(upper, "+"), lower).ravel()) == {expected}, (jg, hg)


def test_top_of_the_last_grade_belongs_to_it():
    scheme = schemes.load("iso13778-4")
    assert scheme.pair(50.018 * MM, 46.018 * MM) == ("C", "C")
    assert scheme.pair(50.018 * MM, 46.000 * MM) == ("E", "E")


def test_every_cell_of_scheme6_fine_matrix():
    scheme = schemes.load("iso13778-6")
    h = np.arange(19)
    j = np.arange(19)
    hh, jj = np.meshgrid(h, j)
    # whole-micrometre readings computed the way a user would
    upper, lower = scheme.pair((50.000 + hh / 1000) * MM, (46.000 + jj / 1000) * MM)
    for pair, k_lo, k_hi in LETTERS_6:
        mask = (hh - jj >= k_lo) & (hh - jj <= k_hi)
        got = set(np.char.add(np.char.add(upper[mask], "+"), lower[mask]))
        assert got == {pair}, (pair, got)


def test_scheme6_whole_micrometre_reading_lands_in_its_class():
    scheme = schemes.load("iso13778-6")
    # The hard case: naive floor division puts some whole-micrometre readings one class low.
    readings = [50.000e-3 + k * 1e-6 for k in range(19)] + [(50.000 + k / 1000) * MM for k in range(19)]
    assert any(np.floor((r - 50.000e-3) / 1e-6) != round((r - 50.000e-3) / 1e-6) for r in readings)
    assert list(scheme.housing.classify(np.array(readings))) == list(range(19)) * 2
    h_idx, j_idx = scheme.classify(np.array([50.018e-3, 50.0e-3 + 18e-6, 0.050017]), np.array([46.0e-3, 46.017e-3, 46.001e-3]))
    assert list(h_idx) == [18, 18, 17]
    assert list(j_idx) == [0, 17, 1]
    # a class is [x, x + 1 um): just below the next whole micrometre stays in x
    assert scheme.housing.classify(50.0179e-3) == 17


def test_pair_is_vectorised_over_any_shape():
    scheme = schemes.load("iso13778-5")
    h = np.full((2, 3, 4), 50.009e-3)
    upper, lower = scheme.pair(h, 46.009e-3)
    assert upper.shape == lower.shape == (2, 3, 4)
    assert np.all(upper == "B") and np.all(lower == "B")


def test_ungraded_scheme1_returns_dash():
    upper, lower = schemes.load("iso13778-1").pair([50.001e-3, 50.017e-3], [46.0e-3, 46.018e-3])
    assert list(upper) == ["-", "-"] and list(lower) == ["-", "-"]


def test_out_of_range_raises_or_marks():
    scheme = schemes.load("iso13778-4")
    with pytest.raises(ValueError, match=r"housing_d: .* outside scheme iso13778-4's range"):
        scheme.pair(50.0185e-3, 46.003e-3)
    upper, lower = scheme.pair([50.0185e-3, 50.003e-3], [46.003e-3, 45.999e-3], out_of_range="mark")
    assert list(upper) == ["", ""] and list(lower) == ["", ""]
    with pytest.raises(ValueError, match="out_of_range: 'ignore' is not one of"):
        scheme.pair(50.003e-3, 46.003e-3, out_of_range="ignore")


def test_nan_reading_is_rejected():
    with pytest.raises(ValueError, match="journal_d: nan is not a finite number"):
        schemes.load("iso13778-4").pair(50.003e-3, np.nan)


@pytest.mark.parametrize("name", ["iso13778-2", "iso13778-5"])
def test_alternatives_b_b_or_a_c(name):
    scheme = schemes.load(name)
    assert scheme.options("B", "B") == [("B", "B"), ("A", "C")]
    assert scheme.options("A", "A")[0] == ("A", "A")


def test_scheme6_intermediate_pairs_have_the_preferred_wall_sum():
    # ISO 13778 clause 6.1 b: intermediate pairs from adjacent grades; with equal 6 um grades
    # B+B = A+C, B+C = A+D, C+C = B+D in wall sum, so they stand in before a bearing is a stock-out
    scheme = schemes.load("iso13778-6")
    grades = scheme.grades["shell"]
    for preferred, alternative in (("B+B", "A+C"), ("B+C", "A+D"), ("C+C", "B+D")):
        assert [f"{u}+{l}" for u, l in scheme.options(*preferred.split("+"))] == [preferred, alternative]
        sums = [tuple(round((grades[u][k] + grades[l][k]) / UM) for k in (0, 1))
                for u, l in (p.split("+") for p in (preferred, alternative))]
        assert sums[0] == sums[1]
    for unmatched in ("A+A", "A+B", "C+D", "D+D"):  # no pair of four grades has their sum
        assert len(scheme.options(*unmatched.split("+"))) == 1
    # the stated range holds with them
    assert scheme.clearance_limits() == pytest.approx((0.026 * MM, 0.045 * MM), abs=1e-9)


def test_scheme_sources_carry_the_standards_title():
    for name in (f"iso13778-{k}" for k in range(1, 7)):
        assert ("Plain bearings — Quality assurance of thin-walled half bearings — Selective assembly of "
                "bearings to achieve a narrow clearance range") in schemes.load(name).source


def test_scheme3_overlapping_shell_grades_sort_to_nearest_centre():
    shell = schemes.load("iso13778-3").shell
    # A 1.980-1.984 and B 1.977-1.981 overlap on 1.980-1.981; centres 1.982 and 1.979
    got = shell.classify(np.array([1.9802, 1.9808, 1.9775, 1.9765]) * MM)
    assert [shell.labels[i] for i in got] == ["B", "A", "B", "C"]


def test_grades_in_metres():
    g = schemes.load("iso13778-4").grades
    assert g["housing"]["B"] == pytest.approx((50.006e-3, 50.012e-3), abs=1e-12)
    assert list(g["shell"]) == ["A", "B", "C", "D", "E"]
    assert g["journal"]["C"][1] == pytest.approx(46.018e-3, abs=1e-12)


SEVENTH = """
name = "house-scheme"
units = "mm"
stated_clearance = [0.030, 0.046]
[housing]
grades = { L = [50.000, 50.009], H = [50.009, 50.018] }
[journal]
grades = { L = [46.000, 46.009], H = [46.009, 46.018] }
[shell]
grades = { X = [1.976, 1.981], Y = [1.981, 1.986] }
[pairing.table]
L = { L = "X+X", H = "X+Y" }
H = { L = "X+Y", H = "X+X" }
[pairing.alternatives]
"X+Y" = ["Y+X"]
"""


def test_a_seventh_scheme_as_a_file_needs_no_code(write_toml, monkeypatch):
    path = write_toml("house-scheme.toml", SEVENTH)
    scheme = schemes.load(path)
    assert scheme.pair(50.010e-3, 46.001e-3) == ("X", "Y")
    assert scheme.options("X", "Y") == [("X", "Y"), ("Y", "X")]
    lo, hi = scheme.clearance_limits()
    # worst cells by hand: journal H, housing L with X+Y; journal L, housing H with X+Y
    assert lo == pytest.approx((50.000 - 46.018 - (1.981 + 1.986)) * MM, abs=1e-12)
    assert hi == pytest.approx((50.018 - 46.000 - (1.976 + 1.981)) * MM, abs=1e-12)
    monkeypatch.setenv("STACKUP_SCHEME_PATH", str(path.parent))
    assert "house-scheme" in schemes.available()
    assert schemes.load("house-scheme").name == "house-scheme"


@pytest.mark.parametrize(
    "change, message",
    [
        (('B = [50.006, 50.012]', 'B = [50.012, 50.006]'),
         r"scheme file 'bad.toml', key housing.grades.B: upper limit 50.006 mm is below lower limit 50.012 mm"),
        (('B = [50.006, 50.012]', 'B = [50.007, 50.012]'),
         r"scheme file 'bad.toml', key housing.grades: gap between grade A \(up to 50.006\) and grade B \(from 50.007\)"),
        (('B = [50.006, 50.012]', 'B = [50.005, 50.012]'),
         r"scheme file 'bad.toml', key housing.grades: grades A and B overlap .* set housing.overlap = true"),
        (('B = { A = "B+B", B = "C+C", C = "D+D" }', 'B = { A = "B+B", B = "C+Z", C = "D+D" }'),
         r"scheme file 'bad.toml', key pairing.table.B.B: unknown shell grade 'Z' \(grades: A, B, C, D, E\)"),
        (('B = { A = "B+B", B = "C+C", C = "D+D" }', 'B = { A = "B+B", C = "D+D" }'),
         r"scheme file 'bad.toml', key pairing: no pairing for journal grade 'B' with housing grade 'B'"),
        (('units = "mm"', 'units = "inch"'), r"scheme file 'bad.toml', key units: 'inch' is not one of 'mm', 'm'"),
        (('A = { A = "C+C"', 'Q = { A = "C+C"'), r"key pairing.table.Q: unknown journal grade 'Q'"),
    ],
)
def test_loader_errors_name_file_key_and_value(write_toml, change, message):
    text = (schemes.builtin_folder() / "iso13778-4.toml").read_text()
    old, new = change
    assert old in text
    path = write_toml("bad.toml", text.replace(old, new, 1))
    with pytest.raises(ValueError, match=message):
        schemes.load(path)


def test_matrix_with_a_short_row_is_rejected(write_toml):
    text = (schemes.builtin_folder() / "iso13778-6.toml").read_text()
    path = write_toml("bad6.toml", text.replace('"dddccccccbbbbbbaaaa"', '"dddccccccbbbbbbaaa"', 1))
    with pytest.raises(ValueError, match=r"key pairing.matrix\[0\]: 18 letters for 19 housing classes"):
        schemes.load(path)


def test_unknown_scheme_name():
    with pytest.raises(ValueError, match=r"scheme: 'iso13778-9' is not a known scheme \(available: .*iso13778-1"):
        schemes.load("iso13778-9")


def test_grade_indices_read_out_then_classify():
    s6 = schemes.load("iso13778-6")
    rng = np.random.default_rng(3)
    housing, journal = rng.uniform(50.0e-3, 50.018e-3, 200), rng.uniform(46.0e-3, 46.018e-3, 200)
    graded = s6.grade_indices(housing, journal)
    expected = s6.classify(*s6.read(housing, journal))
    np.testing.assert_array_equal(graded[0], expected[0])
    np.testing.assert_array_equal(graded[1], expected[1])
