"""The integration tier's shared comparison, as parameters: tests/conftest.py runs it once per session
(``small_comparison``), the tests that check it read what it was given from here."""

#: Two ISO schemes beside a designed one, two process scenarios (and the declared model uncertainties), 600 engines of
#: the example engine, 12 of them through the mechanics, on a coarse crank-angle step, no film check (the check
#: tier's own tests, tests/facts/test_multi_fidelity.py, run theirs).
STUDY = dict(schemes=("iso13778-4", "iso13778-6"), n_engines=600, seed=4, pilot_engines=3000, mechanics_engines=12,
             crank_angle_step=12.0, film_check_engines=0, progress=False)
SCENARIOS = {"bore mean +1σ": {"housing_shift": 1.0}, "misalignment ×2": {"misalignment_scale": 2.0}}
DESIGN = {"n_engines": 500, "generations": 0, "name": "designed"}
