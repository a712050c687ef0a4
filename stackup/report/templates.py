"""The words of the comparison report, as ``str.format`` templates filled from the facts.

Every sentence the report writes is here, in report order; the section
builders (:mod:`~stackup.report.verdict`, :mod:`~stackup.report.methods`,
:mod:`~stackup.report.sections`, :mod:`~stackup.report.mechanics`) fill them
with numbers written by :mod:`~stackup.report.format`. A template named
``*_PART`` is a clause another template takes. What a stage's tier solves
and leaves out is the stage's own sentence (``TIER_NOTES`` of
:mod:`stackup.fit` and :mod:`stackup.crank`, the film tier's record's notes in
:mod:`stackup.film.registry`).
"""

from __future__ import annotations

# --- header ---------------------------------------------------------------------------------------------------
TITLE = "# Scheme comparison: {engine}"
SUBTITLE = ("{title}. stackup {version}, seed {seed}, {n_engines} engines × {bearings} main bearings per scheme{kept}; "
            "shares outside the window less than {negligible} ppm apart count as equal (`--negligible`).")
SUBTITLE_SUMMARIES_PART = " (streaming summaries: quantiles and histograms to 0.1 µm)"
CONTENTS = "Contents: {links}"
CONTENTS_LINK = "[{title}](#{anchor})"
#: The contents line's short names of the sections whose headings are long.
CONTENTS_SHORT = {"What drives the spread": "Spread", "Operating clearance: press fit, housing swell and temperature":
                  "Press fit", "Loads, oil film and bearing life": "Film and life", "Assembly, scrap and stock":
                  "Scrap and stock", "Planning: shells per grade": "Planning", "Methods and assumptions": "Methods",
                  "Limits of validity": "Limits", "Clearance per scheme": "Clearance", "Designed scheme": "Design"}
SECTION = "## {title}"
IMAGE = "![{alt}]({file})"
PARAMETER = "`{name}` {value}"
DATASET = ("Dataset: `{file}` (every parameter, defaults included, in its `study` attribute; the engine and scheme "
           "files, their sources included, in `input_files`).")
PARAMETERS_DEFAULTS = "Parameters not listed are at their defaults (`stackup.study.Study`)."

# --- verdict --------------------------------------------------------------------------------------------------
WINDOW_PART = "the operating-clearance window {lo}–{hi} µm"
CLEARANCE_PART = "operating clearance {mean:.1f} ± {std:.1f} µm"
#: Each figure stands beside the scheme it belongs to: the chosen scheme's clearance after its name, the next
#: one's after the next one's name.
USE_ONLY = "**Use {scheme}** ({clearance}): {share} of its bearings fall outside {window}."
USE_CLEARANCE = ("**Use {scheme}** ({clearance}): {share} outside {window} against {runner_share} for {runner} "
                 "({runner_clearance}).{price}")
#: Where the bearings below the minimum clearance at assembly or cold start decided.
USE_INTERFERENCE = ("**Use {scheme}** ({clearance}): {share} of its bearings below the minimum clearance at assembly "
                    "or cold start against {runner_share} for {runner} ({runner_clearance}); {window_share} outside "
                    "{window}.")
#: What the chosen scheme costs more than the next, where the clearance chose it.
PRICE_PART = " It costs {costs}."
USE_COST = "**Use {scheme}** ({clearance}): {reason}, so {decides}: {costs}."
LEVEL_PART = ("it and {runner} put {share} and {runner_share} of their bearings outside {window}, less than "
              "{negligible} ppm apart")
LEVEL_NO_WINDOW_PART = "with no window to judge the clearance by"
COST_DECIDES_PART = "cost decides"
METRIC_DECIDES_PART = "the {metric} decides"
#: How the verdict compares the chosen scheme with the next on the metric that decided, and on each cheaper cost.
COST_PARTS = {
    "alpha_over_limit_pct": ("{a:.1f} % of the bearings at its worst position over 20 % of the cycle in boundary "
                             "friction against {b:.1f} %"),
    "life_below_target_pct": "{a:.1f} % of the bearings at its worst position below the life target against {b:.1f} %",
    "shell_grades": "{a:.0f} shell grades against {b:.0f}",
    "part_grades": "{a:.0f} bore and journal grades against {b:.0f}",
    "stockout_ppm": "{a:,.0f} ppm stock-outs against {b:,.0f}",
    "surplus_pct": "{a:.1f} % of the shells left over against {b:.1f} %",
    "engine_life_median_h": "median engine life {a:,.0f} h against {b:,.0f} h",
}
TIE = "{names} tie on {window}, the film and the cost: use any of them."
NO_MODEL = ("**Model uncertainty:** none declared: the verdict takes the engine file's housing stiffness, crush "
            "height and journal temperature as exact.")
MODEL_HOLDS = ("**Model uncertainty:** it stays first over the declared ranges of the {inputs} ({ranges}): no scheme "
               "puts fewer bearings outside the window at either end.")
MODEL_BREAKS = ("**Model uncertainty:** the choice changes within the declared ranges ({ranges}): {flips}. Measure "
                "{measure}.")
MODEL_FLIP_PART = "with {scenario}, {winners} do{s} better ({winner_share} against {share})"
ASSUMED_PART, MEASURED_PART, SOME_ASSUMED_PART = "assumed", "measured", "some assumed"
PROCESS_HOLDS = "**Process scenarios:** no scheme puts fewer outside under any{worst}."
PROCESS_BREAKS = "**Process scenarios:** {flips}{more}{worst}."
PROCESS_WORST_PART = "; the worst, {scenario}, puts {share} outside"
UNDER_PART = "under {scenario}, {names} put{s} fewer outside"
MORE_PART = "; likewise under {count} more"
CHECK_FIRST = "**Check first:** {notes}"
INTERFERENCE = "**Interference:** {schemes} below the {minimum} µm minimum clearance at assembly or {cold} °C; {chosen}."
INTERFERENCE_SCHEME_PART = "{share} of {scheme}'s bearings (cold: {cold} µm)"
#: Said where the recommended scheme has bearings below the minimum clearance, or where it has none.
INTERFERENCE_CHOSEN_PART = "no scheme compared has fewer than {scheme}"
INTERFERENCE_NONE_PART = "{scheme} none"
#: The operating window moved to the cold start by the chosen scheme's mean change, where its lower edge falls
#: below the minimum clearance there.
WINDOW_COLD = ("**Window:** {lo}–{hi} µm in service is {cold_lo}–{cold_hi} µm at {cold} °C in this {material} "
               "housing: not this block's window.")
SCUFFING_NOTE = ("At bearing {bearing}, {share} % of {scheme}'s bearings spend over 20 % of the cycle in boundary "
                 "friction (scuffing risk).")
SHORT_LIFE_NOTE = ("At bearing {bearing}, {share} % of {scheme}'s bearings live less than the {target} h "
                   "target{checked}.")
CHECKED_PART = " (lives on the mass-conserving check's scale)"
NO_WINDOW = ("The engine file gives no operating-clearance window (`[targets] operating_clearance`, or `--window LO "
             "HI`): the clearance cannot separate schemes.")
NOT_MET = ("No scheme meets the window {lo}–{hi} µm: the best puts {best} outside it; check the window against the "
           "operating clearances (Ranking).")
BLOCKS_LOST = "{share} of the blocks are scrapped (a housing bore read outside its drawing limits)."
CRANKS_LOST = "{share} of the crankshafts are scrapped (a journal read outside its drawing limits)."
NOT_GRADED_LOST = "{share} of {scheme}'s bearings have a part read outside every grade."
STOCKOUTS_LOST = "{share} of {scheme}'s bearings wait for a shell (stock-outs)."
SHELLS_LOST = "{scheme} scraps {share} of its shells."
EDGE_NOTE = "Journal edges touch their shells in {share} of the bearings; the lives ignore that contact."
EDGE_COUNTED_NOTE = ("Journal edges reach the wall in {share} of the bearings (each turned back at its own support, "
                     "rigid surfaces); α and the lives read the film there.")
EDGE_SURFACE_NOTE = ("Journal edges run below h_lim,cr in {share} of the bearings (support moments balanced, film "
                     "over the surface); α and the lives read that film.")
FAILURES_NOTE = "Stages failed on some engines (left out of the statistics): {lines}."
NO_MECHANICS_NOTE = "The crankshaft, film and life stages did not run ({reason}): the ranking uses the clearance only."
NONE_ASKED_PART = "the study asked for none, `mechanics_engines=0`"
NO_CRANK_PART = "the engine file has no `[crank]` section"
BELOW_MINIMUM_COLUMN = "below min. clearance [ppm]"
WORST_PROCESS = "worst process scenario: outside [ppm]"
WORST_MODEL = "worst model uncertainty: outside [ppm]"
WORST_CELL = "{share} ({scenario})"

# --- ranking --------------------------------------------------------------------------------------------------
#: The ranking's metrics in words.
METRICS = {"below_minimum_ppm": "share below the minimum clearance (assembly, cold start)",
           "outside_window_ppm": "share outside the window",
           "alpha_over_limit_pct": "scuffing risk (α > 20 %) at the worst position",
           "life_below_target_pct": "lives below the target at the worst position",
           "shell_grades": "shell grades", "part_grades": "bore and journal grades", "stockout_ppm": "stock-outs",
           "surplus_pct": "surplus", "engine_life_median_h": "median engine life"}
RANKING_RULE = ("Window {lo}–{hi} µm ({whose}). Metrics in turn: {metrics}; on each, the best scheme and those "
                "level with it (95 % intervals overlapping, or under {negligible} ppm apart on the share outside, 1 "
                "point on the surplus) go on.")
STUDY_WINDOW_PART, ENGINE_WINDOW_PART = "the study's", "the engine's"
ESTIMATED_NOTE = "† Fewer than {fewest} bearings counted outside: {how}; counted: {counted}."
COUNTED_PART = "{count} ({scheme})"
CONDITIONAL_HOW = "estimated with the shells integrated out (no lots or stock-outs: reports/tails_vs_peers.md)"
SPLITTING_HOW = "estimated by generalized splitting through the assembly chain (`stackup.tail`)"
NON_DISCRIMINATING = "{metrics} {verb} not separate the schemes here."
SAME_VALUE_PART = " ({value:.3g}{unit} for every scheme)"
#: Units of those metrics as the sentence writes a value of theirs.
METRIC_UNITS = {"alpha_over_limit_pct": " % of the bearings", "life_below_target_pct": " % of the bearings",
                "engine_life_median_h": " h"}
NONE_PART = " (none in any scheme)"
#: The film and life metrics of the ranking as the sentence naming those that do not separate schemes says them.
NON_DISCRIMINATING_NAMES = {"alpha_over_limit_pct": "boundary friction over 20 % of the cycle",
                            "life_below_target_pct": "lives below the target",
                            "engine_life_median_h": "the median engine life"}
#: Of those, the names that take a plural verb alone.
NON_DISCRIMINATING_PLURAL = {"life_below_target_pct"}
CENTRED = ("**Centring:** {scheme} has the narrowest operating clearance ({std:.2f} µm standard deviation against "
           "{chosen_std:.2f} µm) but its mean sits {shift} µm {side} the window's middle: with shells aimed {half} µm "
           "{verb} each it would put {result}; `stackup design` designs such a scheme.")
CENTRED_SOME_PART = "about {share} outside"
CENTRED_NONE_PART = "none of its {bearings} bearings outside (below {upper} at 95 %)"

# --- scenarios ------------------------------------------------------------------------------------------------
SCENARIOS_INTRO = ("Each scenario reruns the study's engines (same seed and parts) with one change; shares outside the "
                   "window counted [ppm]; in bold the lowest and those the counts cannot tell from it.")
SCENARIOS_SAME = "{labels} {verb} every share outside the window as in the study (they act on the films only)."
NO_SCENARIOS = "The comparison ran no scenarios."
MODEL_RANGES = "Model-uncertainty ranges:"
MODEL_RANGE = "- {input}: {source}; measure {measure}."

# --- designed scheme ------------------------------------------------------------------------------------------
DESIGNED = ("`{name}` was designed for this engine and window by `stackup.design` ({evaluations} candidate limit "
            "sets, {seconds:.0f} s) from `{start}`, the ISO scheme with the lowest objective, and judged like every "
            "other scheme: {outcome}{against} Its reasons are the comments of its scheme text. Grade limits in µm "
            "from each dimension's lower drawing limit:")
DESIGN_OUTCOME_PART = "rank {rank}"
DESIGN_AGAINST_PART = ", against {outcome} for `{start}`."
DESIGN_START_ABSENT_PART = " (`{start}` is not among the schemes compared)."
UNGRADED = "ungraded"
GRADE_PART = "{label} {lo:+.1f}…{hi:+.1f}"

# --- what drives the spread -----------------------------------------------------------------------------------
NO_SENSITIVITY = "The Sobol indices come with `stackup.compare` (its `sensitivity` dataset); none was given."
#: Sobol outputs in words.
OUTPUTS = {"clearance_operating": "operating clearance", "h_min": "smallest mid-plane film", "life": "life"}
TIGHTEN_FIRST = ("**Tighten first ({scheme}, {output}):** the {first}, S_T {st:.2f} [{st_lo:.2f}, {st_hi:.2f}] "
                 "(S_1 {s1:.2f}), then the {second} ({second_st:.2f}).{gauges}")
GAUGES_PART = " Gauges matter through misgrading: {gauges}."
GAUGE_INDEX_PART = "{name} {st:.2f}"
SOBOL_EXPLAINED = ("S_1: the share of the output's variance an input explains alone; S_T: with its interactions "
                   "(the grading among them). Process mean shifts are scenarios; the film and life use few engines.")

# --- clearance, press fit -------------------------------------------------------------------------------------
CLEARANCE_INTRO = ("Nominal diametral clearance (no swell, one temperature, as the standard states ranges) against "
                   "each scheme's stated range and, where it differs, its worst case over the allowed pairs (fitted, "
                   "swell included: Press fit).")
NONE_STATED = "none ({worst})"
READ_OUT = ("{scheme} reads bores and journals to {step} µm, so a part up to half a step outside its class is paired "
            "as inside it: its worst case, {worst_lo:.1f}–{worst_hi:.1f} µm, reaches beyond the stated "
            "{stated_lo:.0f}–{stated_hi:.0f} µm.")
FIT_INTRO = ("Operating clearance: housing and shells at the operating temperature, swollen by the press fit, the "
             "journal at its own temperature; press-fit checks at {temperatures} °C. Limits and sources (in full: the "
             "engine file):")
SCENARIO_LIVES_INTRO = ("**Lives** under the scenarios that ran the films ({pairs}+ paired engines): {scheme}'s "
                        "median change per position and per engine; any scheme's position whose life rises beyond "
                        "its 95 % interval.")
LIVES_POSITION_COLUMN = "per position [h]"
LIVES_ENGINE_COLUMN = "per engine [h]"
LIVES_RISE_COLUMN = "lives that rise"
LIVES_SPAN = "{lo} (bearing {bearing}) to {hi}"
LIVES_SAME = "none changes (nothing to act on)"
LIVES_NONE_RISE = "none"
LIVES_RISE = "at {where}"
LIVES_RISE_WITH_FILM = "{count} of {total} ({lo} to {hi} h): cycle-mean film {film_lo} to {film_hi} µm{minimum}"
#: Where lives rise with the cycle-mean film while the cycle minimum thins (method 1's direction).
LIVES_RISE_THINNER_MINIMUM = ", cycle minimum {span} µm{where} (method 1 reads the mean)"
LIVES_RISE_THINNER_AT = " at {count}"
LIFE_RISE_PART = "bearing {bearing} of {scheme} ({change} h; cycle-mean film {film} µm)"
FIT_ALL_PASS = "No bearing of any scheme {checks} at any checked temperature."
FIT_LOW_PRESSURE = "falls below {pressure:.0f} MPa of contact pressure"
FIT_HIGH_STRESS = "compresses its shells beyond {stress:.0f} MPa"
FIT_LOST = "loses its fit"
PRESS_FIT_LIMITS_SOURCE = ("- contact pressure at least {pressure:.0f} MPa, shell compression at most {stress:.0f} "
                           "MPa: {source};")
CRUSH_SOURCE = "- crush height {lo:.3f}–{hi:.3f} mm: {source};"
MINIMUM_SOURCE = "- minimum clearance {minimum} µm at {assembly} and {cold} °C{cold_source}: {source};"
#: The cold start's source where it is not the engine file's own temperature.
COLD_SOURCE_PART = " ({source})"
SOAKED_COLUMN = "at {assembly} / {cold} °C [µm]"
JOURNAL_SOURCE = "- journal {excess:g} K hotter than its housing ({source});"
WINDOW_SOURCE = "- operating-clearance window {lo:.1f}–{hi:.1f} µm: {source}{end}"
NO_SOURCE = "no source given"
NOT_GIVEN_JOURNAL = "not given in the engine file (journal and housing at one temperature)"

# --- loads, film and life -------------------------------------------------------------------------------------
NO_FILM = "The film and life stages did not run (see the verdict)."
FILM_INTRO = ("Minimum film{where} over the cycle (`{method}`) on the first {engines} engines of each scheme; α: the "
              "share of the cycle below h_lim,cr = {critical} µm (scuffing risk above 20 %); Levanov's method-1 "
              "lives per position, an engine's its weakest bearing's (target {target} h){scaled}. Loads differ "
              "between schemes by at most {spread} kN{failed}.{none}{same}")
SCALED_PART = ", on the mass-conserving check's scale"
SURFACE_PART = (" over the bearing surface (the journal's tilt turned back by the support moments of crankshaft and "
                "block, an elastic layer under the film; tilt_method coupled)")
WIDTH_PART = " over the width (the tilted journal, rigid surfaces)"
FAILED_PART = "; the crankshaft failed on {failed} engines (left out)"
METHOD1_RANGE = ("At bearing{s} {bearings} {scheme}'s {statistic}, the film method 1 reads, is {films} µm, below "
                 "h_lim,cr = {critical} µm: there Levanov's law gives lives of hours or less (β above 2), far outside "
                 "the 5-9 µm films his constants were fitted on. Read such a life as no film margin left, not as "
                 "hours.")
CORRECTED = ("Checked by `{method}` on {pairs} engines per scheme (control variates on {engines}), {scheme}'s "
             "means per position: cycle-minimum film {h_min} µm, cycle-mean film {h_min_mean} µm, life {life} h.")
CORRECTED_SPAN = "{lo}–{hi} (±{half}; study tier {cheap_lo}–{cheap_hi})"
OPPOSED_TRENDS = ("With more clearance (last figure) the cycle-minimum film thins {where} (Spearman ρ {film}, "
                  "{pairs}+ bearings each) while method 1's life lengthens (ρ {life}): it reads the cycle-mean film.")
EVERY_POSITION = "at every position"
AT_POSITIONS = "at bearings {bearings}"
NO_SCUFFING_PART = " No bearing spends over 20 % of the cycle below h_lim,cr."
SAME_SCUFFING_PART = " α over 20 % at bearing {bearing} in {share} % of every scheme's bearings."
NONE_SHORT_PART = " No bearing's life falls below the target."
ALPHA_COLUMN = "α > 20 %, worst position [% of its bearings]"
SHORT_COLUMN = "life < {target:.0f} h, worst position [% of its bearings]"
AT_POSITION = "{share} (bearing {bearing})"
POSITIONS = ("Per position for {scheme} (medians over engines): the largest load at bearing{s} {heaviest}, the "
             "thinnest films at bearing{thin_s} {thinnest}; tilt: the largest; edge: engines whose edge touches "
             "(share of the cycle).")
TOUCHING_PART = "{share:.0f} %"
TOUCHING_SHARE_PART = " ({share:.0f} %)"
NOT_A_NUMBER = ("Of {total} bearing-cycles, {counts} gave no film (NaN, `film_status`), left out of every film and "
                "life statistic; {engines} engine{engines_s} with such a bearing {have} no engine life.")
NOT_A_NUMBER_COUNT_PART = "{count} {status}"
ALL_PERIODIC = "Every one of the {total} bearing-cycles reached a periodic orbit."
EDGE_CYCLES = ("In {edge} of them ({share:.0f} %) the tilted journal's edge reaches the wall at some crank angle, "
               "where the film is held at a floor of {floor:.1f} % of the radial clearance (no elastic edge, no "
               "EHD): boundary contact that α and the lives, read at the mid-plane, do not count. `--tilt-method "
               "coupled` balances the support moments with the crankshaft and the block and reads α and the lives "
               "over the bearing surface, on an elastic layer (reports/coupled_supports.md).")
EDGE_COUNTED = ("In {edge} of them ({share}) a tilted journal's edge reaches the wall: {positions}{others}. "
                "There the rigid film is held at {floor:.1f} % of the radial clearance; α and the lives read it. "
                "`--tilt-method coupled` adds the other supports' moments and an elastic layer "
                "(reports/coupled_supports.md).")
EDGE_OTHERS_PART = "; at {count} other position{s} in under {share} of the bearings"
#: The positions of EDGE_COUNTED where at every one fewer of the bearings than FEW_TOUCHING_PCT touch.
EDGE_FEW_PART = "at {count} position{s}, each in under {share} of the bearings"
EDGE_SURFACE = ("In {edge} of them ({share:.0f} %) an edge of the journal, its tilt turned back by the support "
                "moments, runs below h_lim,cr = {critical} µm over part of the cycle: {positions}. There the film over "
                "the surface is computed on the elastic layer (below zero: the asperities pressed past their mean "
                "planes); α and the lives read it. The support moments repeated from cycle to cycle in {periodic} of the "
                "bearings (`tilt_status`; the others are taken at the march's last cycle).")
EDGE_TOLERANCE = ("With coaxiality and run-out ×{factor} ({label}, {pairs} paired engines) {scheme}'s share of the "
                  "cycle {contact} {changes} (median per position, bearings {first}–{last}){beyond}.")
EDGE_TOLERANCE_NONE = "does not change"
BELOW_CRITICAL = "with an edge below h_lim,cr"
AT_WALL = "with an edge at the wall"
EDGE_TOLERANCE_BEYOND = "; the change is clear of zero (95 % interval) at bearing{s} {bearings}"
EDGE_TOLERANCE_WITHIN = ", within its 95 % interval of zero everywhere"
EDGE_UNRESOLVED = (" At {median} of the march's solved crank angles (median over the engines; {high} at the 95th "
                   "percentile; `tilt_unresolved`) the force and turn-back balance was not resolved: Newton's full "
                   "step stayed longer than its tolerance where the film's moment stops growing with the tilt, and the "
                   "last iterate is taken.")
EDGE_POSITION_PART = "bearing {bearing} ({lo}–{hi} of the cycle; {film} µm at up to {load} kN near {angle}°)"
HEAT = ("The heat balance puts the films at {temperature} °C (5-95 %; median {temperature_median} °C{supply}), "
        "{power} W of friction per bearing and {flow} L/min of oil.")
SUPPLY_PART = ", oil supplied at {supply:.0f} °C"

# --- assembly, planning ---------------------------------------------------------------------------------------
ASSEMBLY = ("Of {bearings} bearings per scheme (and up to {shells} shells made), those not assembled stay in the "
            "dataset with their reason (`status`).")
ASSEMBLY_SHARED = "Every scheme loses the same {losses} (the same parts)."
LOSSES = {"block_scrapped": "{count} bearings to scrapped blocks",
          "crank_scrapped": "{count} to scrapped crankshafts",
          "not_graded": "{count} to parts read outside every grade",
          "shell_stockout": "{count} to shell stock-outs"}
PLAN_NEEDS_ENGINES = ("Planning needs each engine's shell demand: run the study with `keep=\"everything\"`.")
PLAN = ("For {scheme}, from this study's engines (`stackup plan` plans any other and explains the columns): order "
        "{ordered:,} shells per lot of {lot:,} engines (two per bearing and {surplus:.3g} % more, {how}); the gauge "
        "scraps {scrap:.2g} % of them; the stock per lot covers a lot's demand for its grade in {level:.4g} % of "
        "lots.")
PLAN_TO_ORDER = "made to order, each grade aimed at its share of the demand"
PLAN_SORTED = "one wall process sorted into the grades"

# --- methods and assumptions ----------------------------------------------------------------------------------
PARTS = "- **Parts:** {housing}; {journal}; parts read outside their limits are scrapped."
DIMENSION_PART = "{label} {lo:.3f}–{hi:.3f} mm, {distribution}, C_pk {cpk:.2f} (σ {std} µm)"
SHARED_PART = ", {shared:.0f} % of variance shared per part"
GAUGE_PART = ", gauge {repeatability:.2f} µm"
READ_OUT_PART = ", read-out {resolution:g} µm"
SHELLS_TO_ORDER = ("- **Shells:** made to order per lot of {lot} engines, {surplus:.0f} % surplus, aimed at grade "
                   "centres (wall σ {sigma} µm), read ({repeatability} µm) and sorted; planned from {pilot} pilot "
                   "engines. Crush height {lo:.3f}–{hi:.3f} mm, C_pk {cpk:.2f}.")
SHELLS_SORTED = ("- **Shells:** one process sorted into grades (supply `{supply}`), lots of {lot} engines with "
                 "{surplus:.0f} % surplus.")
PRESS_FIT = ("- **Press fit:** {housing} housing (equivalent outer diameter {outer:.0f} mm), {shell} shells {width:.0f} "
             "mm wide, crush checked in a {bore:.3f} mm block at {stress:.0f} MPa; {tier} (reports/press_fit_tiers.md).")
TEMPERATURES = ("- **Temperatures:** assembled at {assembly:.0f} °C; housing and shells at {running:.0f} °C, the "
                "journal at {journal:.0f} °C{oil}")
#: ISO 13778's schemes laid on the engine's drawing (stackup.patterns): where their shells are re-centred from, and
#: their caveats (also what `stackup schemes --engine` prints under each scheme).
ISO_ANCHOR_PART = ("grades scaled, shells re-centred from {engine}: the standard's smallest clearance ({clearance} µm, "
                   "{operating} µm running with {engine}'s assumed housing_outer {outer:.0f} mm) sits {place} "
                   "{engine}'s window {lo}–{hi} µm and keeps that place in this engine's window")
#: Where in a window a clearance sits (share of the window's width).
ISO_PLACE = {"below": "{share:.0f} % of its width below", "in": "{share:.0f} % across",
             "above": "{share:.0f} % of its width above"}
ISO_ANCHOR = "- **ISO schemes on this drawing:** {anchor}."
ISO_CAVEATS = "- **ISO scheme caveats:** {items}."
ISO_NARROW_PART = "{scheme} {parts} grades {width} µm < 3 {of} σ ({sigma} µm)"
ISO_HELD_PART = ("{schemes}: the window asks for a smallest clearance of {target} µm, below the standard's {floor} µm "
                 "scaled to the journal, so the shells stay there: the window moves nothing")
OIL_PART = "; oil {oil} supplied at {supply:.0f} °C, film temperature from each bearing's heat balance."
CLEARANCE = ("- **Clearance:** nominal C = D_H − (s_upper + s_lower + D_J) from true sizes, graded by readings; "
             "operating clearance on all {n_engines} engines × {bearings} bearings.")
CRANKSHAFT = ("- **Crankshaft:** {tier} at {speed:.0f} rpm in {step:g}° steps, with each engine's operating "
              "clearances, bore coaxiality ({coaxiality} µm) and journal run-out ({runout} µm); on the first "
              "{engines} engines of each scheme.")
OIL_FILM = "- **Oil film:** `{method}` tier, {tier}, with each bearing's heat balance{errors}."
FILM_ERRORS_PART = ("; error against the transient mass-conserving Reynolds reference up to {h_min:.0f} % on the "
                    "cycle-minimum film, {h_min_mean:.0f} % on its mean; {milliseconds:.1f} ms per bearing-cycle "
                    "(reports/film_speed_vs_error.md)")
CHECKED_ERRORS_PART = ("; against the mass-conserving check on this engine thick by up to {h_min:.0f} % on the "
                       "cycle-minimum film, {h_min_mean:.0f} % on its mean (reports/film_speed_vs_error.md)")
LIFE = ("- **Life:** Levanov et al. (2015) method 1 on the {film} of the minimum film{why} and Δh_lim = "
        "{method1_limit} µm (Δh_lim/γ = {method1_scale:.1e} s, the scale of the paper's method-1 results), method 2 on "
        "{wear_limit} µm ({wear_source}); h_lim,cr = {critical} µm from Rz {journal_rz} + {shell_rz} µm; wear speed "
        "{wear_rate:.0e} m/s.")
CYCLE_MEAN_PART = " (as the paper's 5-9 µm films need)"
NOT_CYCLE_MEAN_PART = " (the paper implies the cycle mean)"
STATISTICS = ("- **Statistics:** 95 % intervals: order statistics (quantiles), Clopper–Pearson (shares), normal "
              "(means).")
SUMMARIES = "- **Summaries:** streaming summaries: quantiles and histograms to 0.1 µm, exact counts."

# --- limits of validity ---------------------------------------------------------------------------------------
LIMITS_BEFORE_LIFE = (
    "- Bores round and straight (no bolt or thermal distortion); journals round unless the engine file samples a "
    "form error.",
    "- Press fit: plane-stress linear elastic rings; no plastic lining, fretting or relaxation of the crush. The "
    "housing's equivalent ring, the crush process and the journal's temperature: declared ranges (Scenarios).",
    "- Oil film: isothermal at the bearing's effective temperature, no EHD; the cheap dynamic tiers carry no film "
    "content (most of their error, reports/film_speed_vs_error.md).",
)
CRANK_LIMIT = "- Crankshaft: a beam on point supports; {block}; loads from the engine file's pressure model."
BLOCK_RIGID = "block rigid against tilt"
BLOCK_OWN_SUPPORT = "each support turns with the block (assumed) under its own moment"
BLOCK_COUPLED = ("the supports' moments balanced together with the block's angular compliance (an assumed "
                 "derivation)")
BLOCK_HELD = "the crankshaft's slope held in the film (no support moments)"
LIFE_LIMIT = ("- {bias}Levanov's constants were fitted to another engine: compare schemes rather than read the hours "
              "as a guarantee.")
LIFE_BIAS_PART = ("Method 1 reads the cycle-mean film, up to {error:.0f} % thicker than the transient reference: at "
                  "the median {film} µm that makes a life {ratio:.1f} times as long ({life} h against {thinner_life} "
                  "h at {thinner_film} µm); the method caps a life at Δh_lim/γ = {cap} h. ")
LIFE_CHECKED_PART = ("Lives are scaled per position by the mass-conserving check's ratio, assumed the same for every "
                     "engine there. ")
LIMITS_AFTER_LIFE = (
    "- Schemes are judged on their preferred and allowed pairs as written; lots are independent.",
)


def plural(count, many="s", one=""):
    """The ending of a word for ``count`` things: ``many`` unless there is one."""
    return one if count == 1 else many


def listed(items, last="and"):
    """Items written out: 'a', 'a and b', 'a, b and c' (``last="or"``: 'a, b or c')."""
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + f" {last} " + items[-1]


def bold_listed(names):
    """Names in bold, written out (:func:`listed`)."""
    return listed(f"**{n}**" for n in names)
