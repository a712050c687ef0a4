"""The main job's sizes and folders: what ``stackup compare`` and :func:`stackup.comparison.run` run by default.

A module of constants only, so the command line reads them for its help
without importing the library (it starts at once).
"""

#: Engines of the main job, of its quick variant, and the fewest it runs: the report's 95 % intervals, the plan's
#: safety stock and the sensitivity regression need about a hundred engines.
COMPARE_ENGINES, QUICK_ENGINES, COMPARE_MIN_ENGINES = 100_000, 10_000, 100
#: Engines per scheme whose films the main job checks with the mass-conserving tier (control variates).
FILM_CHECK_ENGINES = 5
#: Output folders of the main job and of its quick variant (relative to the working folder).
COMPARE_OUT, QUICK_OUT = "reports/compare", "reports/compare-quick"
