"""`stackup design` as a user meets it: refusals in the command's words (its options, micrometres), one line,
exit 2, before any design runs; both figures of a design (design sample, independent check) printed."""

import pytest
from cli_helpers import stackup

from stackup import schemes


@pytest.mark.parametrize("options, says", [
    (["--grades", "0"], "--grades: 0 is not valid"),
    (["--window", "65", "45"], "--window: 65 45 um is not a clearance window"),
    (["--housing-grades", "27"], "--housing-grades: 27 is not valid"),
    (["--n", "10"], "--n: 10 is not valid"),
])
def test_a_bad_option_is_refused_in_one_line_in_the_command_words(options, says, tmp_path):
    done = stackup("design", *options, "--out", "scheme.toml", cwd=tmp_path)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("stackup: error: ") and says in lines[0], done.stderr
    for python_name in ("shell_grades", "housing_grades", "n_engines", "window=", "e-05", "e-06"):
        assert python_name not in lines[0]
    assert "Traceback" not in done.stderr and done.stdout == ""
    assert not (tmp_path / "scheme.toml").exists()


def test_a_library_refusal_reaches_the_user_under_the_option_that_set_it():
    from stackup.commands._options import in_options
    from stackup.commands.design import OPTIONS

    said = in_options(ValueError("shell_grades: 30 is not valid; at most 26 grades"), OPTIONS)
    assert said == "--grades: 30 is not valid; at most 26 grades"
    assert in_options(ValueError("n_engines: 5 is below 100"), OPTIONS) == "--n: 5 is below 100"
    assert in_options(ValueError("engine file 'x.toml': no such file"), OPTIONS) == "engine file 'x.toml': no such file"
    # a parameter named inside the message, and the force flag, in the command's words too
    assert (in_options(ValueError("n_engines: 10 engines need 2 GB; give n_engines at most 5, or pass force=True"),
                       OPTIONS) == "--n: 10 engines need 2 GB; give --n at most 5, or pass --force")


def test_design_prints_the_share_outside_on_the_design_and_on_the_check_sample(tmp_path):
    done = stackup("design", "--grades", "2", "--n", "300", "--generations", "0", "--no-scenarios",
                   "--out", "two.toml", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    line = next(x for x in done.stdout.splitlines() if x.startswith("share outside the window, nominal:"))
    assert "on the design sample" in line and "on the independent check sample" in line
    assert len(schemes.load(tmp_path / "two.toml").shell.labels) <= 2
