"""`stackup compare --schemes ... designed.toml` beside the scheme the comparison designs itself: no clash of names
(issue 31): the comparison's own design is renamed where a given scheme carries its name."""

from stackup._comparison import _distinct_name


def test_the_comparison_design_takes_a_name_no_given_scheme_has():
    assert _distinct_name("designed-iso-example", ["iso13778-4"]) == "designed-iso-example"
    assert _distinct_name("designed-iso-example", ["iso13778-4", "designed-iso-example"]) \
        == "designed-iso-example-this-run"
    taken = ["designed-iso-example", "designed-iso-example-this-run", "designed-iso-example-this-run-2"]
    assert _distinct_name("designed-iso-example", taken) == "designed-iso-example-this-run-3"
