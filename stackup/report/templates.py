"""The words of the comparison report, as ``str.format`` templates filled from the facts.

Every sentence the report writes is here, in report order; the section
builders (:mod:`~stackup.report.verdict`, :mod:`~stackup.report.methods`,
:mod:`~stackup.report.sections`) fill them with numbers written by
:mod:`~stackup.report.format`. A template named ``*_PART`` is a clause
another template takes. What a stage's tier solves and leaves out is the
stage's own sentence (``TIER_NOTES`` of :mod:`stackup.fit`,
:mod:`stackup.crank`, :mod:`stackup.film`).
"""

from __future__ import annotations

# --- header ---------------------------------------------------------------------------------------------------
TITLE = "# Scheme comparison: {engine}"
SUBTITLE = "{title}. stackup {version}, seed {seed}, {n_engines} engines × {bearings} main bearings per scheme{kept}"
SUBTITLE_SUMMARIES_PART = " (streaming summaries: quantiles and histograms to 0.1 µm)."
CONTENTS = "Contents: {links}"
CONTENTS_LINK = "[{title}](#{anchor})"
SECTION = "## {title}"
IMAGE = "![{alt}]({file})"
DATASET = "Dataset: `{file}`; the study's parameters are also in its `study` attribute (JSON)."

# --- verdict --------------------------------------------------------------------------------------------------
NO_WINDOW = ("The engine file gives no operating-clearance design window (`[targets] operating_clearance`), so no "
             "scheme can be judged by the share of bearings outside it; give one in the engine file or with "
             "`stackup compare --window LO HI`. The ranking below uses the other metrics only.")
NOT_MET = ("**No scheme meets the window {lo}–{hi} µm:** the best puts {best} of its bearings outside it. Check the "
           "window against the operating clearances below (nominal clearance plus the housing's swell) before "
           "choosing a scheme; the ranking orders the schemes all the same.")
USE = ("**Use {scheme}** for {engine}: {why}. Its operating clearance is {mean:.1f} ± {std:.1f} µm (mean ± standard "
       "deviation; the window's middle is {middle} µm).")
WHY_PART = "{share}{source} of its bearings fall outside the operating-clearance window {lo}–{hi} µm"
ESTIMATED_PART = " (estimated: {source} †)"
NEXT_PART = ", against {share} for the next, {runner}"
TIE = ("{names} tie: their 95 % intervals overlap on every ranking metric. Of these, **{cheapest}** needs the fewest "
       "shell grades, then the least surplus ({grades} grades, {surplus:.1f} % of the shells left over, against "
       "{versus}): use it unless another reason decides{stockouts}.")
TIE_VERSUS_PART = "{grades} and {surplus:.1f} % for {scheme}"
TIE_STOCKOUTS_PART = ("; it has more stock-outs, though ({stockouts:.0f} ppm of bearings waiting for a shell against "
                      "{others})")
TIE_STOCKOUT_PART = "{stockouts:.0f} ppm for {scheme}"
COSTS = ("**What it costs:** {grades} shell grade{s} to make and stock, {surplus:.1f} % of the shells made left over "
         "at the ends of the lots, {stockouts} of bearings waiting for a shell (stock-outs); the planning section "
         "gives the quantities per grade.")
FRAGILE = "**What it is fragile to:** {what}."
FRAGILE_WINDOW_PART = "{scenario}, which adds {share} outside the window"
FRAGILE_LIFE_PART = ("{scenario}, which shortens its median bearing life by {hours} h (on the engines the scenario "
                     "ran its crankshaft and film on)")
NOT_FRAGILE_PART = "none of the declared scenarios makes it worse on the window or the life"
WOULD_WIN = "**When another scheme would win:** {text}"
UNDER_SCENARIO_PART = "under {scenario}, {names} rank{s} first"
CENTRED_PART = ("{scheme} has the narrowest operating clearance ({std:.2f} µm standard deviation against "
                "{chosen_std:.2f} µm) but its mean sits {shift} µm {side} the window's middle: with shells aimed "
                "{half} µm {verb} each it would put {result}; `stackup design` designs such a scheme")
CENTRED_SOME_PART = "about {share} outside"
CENTRED_NONE_PART = "none of its {bearings} bearings outside (below {upper} at 95 %{doubt})"
CENTRED_DOUBT_PART = ", too few to tell it from {chosen}'s {share}"
NO_WIN_PART = "no declared scenario changes the choice, and {why}"
ALSO_NARROWEST_PART = "{chosen} also has the narrowest clearance."
NO_CENTRING_PART = ("centring a scheme with a narrower clearance would not put fewer bearings outside the "
                    "window.")
EDGE_CONTACT = ("**Edge contact:** the journal's edge touches its shell in {schemes} % of each scheme's bearings "
                "whose film was computed, over {cycle} % of the cycle (median per bearing position): the "
                "crankshaft's slope at the supports, bent by the loads and the bores' and journals' misalignment, "
                "is more than the film's moment can turn back. {alike}There the rigid film has no film left to "
                "give: the edge is held at a floor of {floor:.1f} % of the radial clearance (no elastic shell edge, "
                "no EHD), which is boundary contact at the edge; α, the lives and the wear chart read the mid-plane "
                "film and do not count it (oil film section).")
EDGE_ALIKE_PART = "The choice of scheme hardly changes it. "
NOTE = "**Note:** {notes}"
FAILURES_NOTE = ("Some stages failed on part of the engines (marked in the dataset, left out of the statistics): "
                 "{lines}.")
NO_MECHANICS_NOTE = ("The crankshaft, oil film and life stages did not run: {reason}; the ranking uses the clearance "
                     "only.")
NONE_ASKED_PART = "the study asked for none (`mechanics_engines=0`)"
NO_CRANK_PART = "the engine file has no `[crank]` section"

# --- methods and assumptions ----------------------------------------------------------------------------------
PARTS = "- **Parts:** {housing}; {journal}. Parts read outside their drawing limits are scrapped."
DIMENSION_PART = "{label} {lo:.3f}–{hi:.3f} mm, {distribution} process, C_pk {cpk:.2f} (σ {std} µm)"
SHARED_PART = ", {shared:.0f} % of the variance common to one part's bearings"
GAUGE_PART = "; gauge repeatability {repeatability:.2f} µm"
READ_OUT_PART = ", read-out {resolution:g} µm"
SHELLS_TO_ORDER = ("- **Shells:** made to order per lot of {lot} engines with {surplus:.0f} % surplus, each grade "
                   "aimed at its centre (wall σ {sigma} µm), read (repeatability {repeatability} µm) and sorted into "
                   "grades; quantities planned from a pilot of {pilot} engines. Crush height {lo:.3f}–{hi:.3f} mm, "
                   "C_pk {cpk:.2f}.")
SHELLS_SORTED = ("- **Shells:** one process sorted into grades (supply `{supply}`), lots of {lot} engines with "
                 "{surplus:.0f} % surplus.")
PRESS_FIT = ("- **Press fit:** {housing} housing (equivalent outer diameter {outer:.0f} mm), {shell} shells "
             "{width:.0f} mm wide, crush height checked in a {bore:.3f} mm block at {stress:.0f} MPa; {tier} (its "
             "error against the finite-element reference: reports/press_fit_tiers.md).")
TEMPERATURES = ("- **Temperatures:** assembled at {assembly:.0f} °C, running at {running:.0f} °C (housing, shells "
                "and journal){oil}")
OIL_PART = "; oil {oil} supplied at {supply:.0f} °C, film temperature from the bearing's heat balance."
CLEARANCE = ("- **Clearance:** nominal C = D_H − (s_upper + s_lower + D_J) from true sizes, grading by the readings; "
             "operating clearance with press fit, housing swell and temperature, on all {n_engines} engines × "
             "{bearings} bearings per scheme.")
CRANKSHAFT = ("- **Crankshaft and loads:** {tier} at {speed:.0f} rpm over the cycle in {step:g}° steps, with each "
              "engine's operating clearances and its sampled bore coaxiality (drawing {coaxiality} µm) and journal "
              "run-out ({runout} µm); on the first {engines} engines of each scheme (a random sample: lots are "
              "independent).")
OIL_FILM = ("- **Oil film:** `{method}` tier, {tier}, with the bearing's heat balance (feed and side flow)"
            "{errors}.")
FILM_ERRORS_PART = ("; its largest error against the transient Reynolds reference with mass-conserving cavitation on "
                    "the built-in engines' bearings: {h_min:.0f} % on the cycle-minimum film, {h_min_mean:.0f} % on "
                    "its cycle mean, at {milliseconds:.1f} ms per bearing-cycle for the orbit alone "
                    "(reports/film_speed_vs_error.md; the film stage with its heat balance and the tilt equilibrium "
                    "against the crankshaft cycle: reports/bench_chain.md)")
LIFE = ("- **Life:** Levanov et al. (2015) method 1 (eqs. 4-5) on the {film} of the minimum film over the cycle"
        "{why}; critical film h_lim,cr = {critical} µm from the journal's and the shell's roughness (Rz {journal_rz} "
        "+ {shell_rz} µm, eq. 3; {roughness_source}), limiting wear {wear_limit} µm and wear speed {wear_rate:.0e} "
        "m/s ({wear_source}). Method 2 (eqs. 6-7): a wear chart over the bearing surface where the film is below "
        "h_lim,cr, with the asperity contact pressure of Greenwood and Tripp. An engine's life is that of its "
        "weakest bearing.")
CYCLE_MEAN_PART = (" (the paper's Table 1 pairs films of 5-9 µm with 5-17 % of the cycle in boundary friction, which "
                   "only the cycle mean allows)")
NOT_CYCLE_MEAN_PART = " (a comparison: the paper implies the cycle mean)"
STATISTICS = ("- **Statistics:** 95 % intervals: order statistics for quantiles, Clopper–Pearson for shares, normal "
              "approximation for means. Scenarios reuse the study's seed (common random numbers), so their changes "
              "are differences on the same parts.")
SUMMARIES = ("- **Summaries:** this dataset keeps streaming summaries: quantiles and histograms to 0.1 µm, exact "
             "counts.")

# --- limits of validity ---------------------------------------------------------------------------------------
LIMITS_BEFORE_LIFE = (
    "- Housing bores are round and straight: no distortion from bolt tension, no thermal distortion of the block, "
    "no form error of the journals unless the engine file samples one.",
    "- The press fit is plane-stress linear elasticity of rings: no plastic deformation of the lining, no fretting, "
    "no relaxation of the crush over the engine's life.",
    "- The crankshaft is a beam on point supports at the main bearings; the block is rigid; the loads come from the "
    "engine file's pressure model, not a measured cylinder pressure, unless the file gives one.",
    "- The oil film is isothermal at the bearing's effective temperature; no elastic deformation of the bearing "
    "(EHD), no surface texture beyond the roughness in the critical film. The cheap dynamic film tiers carry no "
    "film content: they cannot see the oil short downstream of a moving load, which is most of their error against "
    "the mass-conserving transient reference (the feed groove they leave out moves that reference by a few per "
    "cent; reports/film_speed_vs_error.md).",
    "- The journal's tilt in its bearing balances the film's restoring moment (short-bearing, tilt squeeze "
    "neglected) against the crankshaft's rotational compliance at its support, a beam on point supports: where the "
    "film cannot hold the slope the edge is held at the eccentricity limit's floor (no elastic deformation of the "
    "shell edge): boundary contact at the edge, which α, the lives and the wear chart, reading the mid-plane film, "
    "do not count. The tilt follows the load quasi-statically (an edge stays on the wall while a contact there "
    "balances the journal, and leaves it when none does): the share of the cycle at the wall differs from the "
    "transient reference's, both ways (reports/film_speed_vs_error.md).",
)
LIFE_LIMIT = ("- {bias}Life follows Levanov et al. (2015), whose constants were fitted to another engine: compare "
              "schemes rather than read the hours as a guarantee.")
LIFE_BIAS_PART = ("Method 1 reads the cycle-mean film, which the film tier puts up to {error:.0f} % thicker than the "
                  "transient reference (Methods): at this study's median cycle-mean film, {film} µm, that makes a "
                  "life {ratio:.1f} times as long ({life} h against {thinner_life} h at {thinner_film} µm), and the "
                  "method caps a life at Δh_lim/γ = {cap} h. ")
LIMITS_AFTER_LIFE = (
    "- Each scheme is judged on its preferred and allowed pairs as written in its file; the shell supply is planned "
    "from a pilot sample and lots are independent.",
)

# --- ranking --------------------------------------------------------------------------------------------------
#: The ranking's metrics in words.
METRICS = {"outside_window_ppm": "share outside the design window",
           "alpha_over_limit_pct": "share of bearings with more than 20 % of the cycle in boundary friction",
           "life_median_h": "median bearing life"}
RANKING_RULE = ("Operating-clearance design window {lo}–{hi} µm ({whose}). Rule: {rule}. Tied schemes share a "
                "rank.{robustness}")
STUDY_WINDOW_PART, ENGINE_WINDOW_PART = "the study's", "the engine's"
ROBUSTNESS_PART = (" Robustness: the worst change of each metric over the declared scenarios ({scenarios}), each "
                   "run with the same seed (counted shares); the lives change only under the scenarios that run the "
                   "mechanical chain, on their first engines against the study's same engines.")
WORST_PART = "{change} ({scenario})"
ESTIMATED_NOTE = ("† Fewer than {fewest} bearings of the study fell outside the window, too few for a tight interval: "
                  "the share is {how}; the study counted {counted}.")
COUNTED_PART = "{count} ({scheme})"
CONDITIONAL_HOW = ("estimated with the shells integrated out (`stackup.design.estimate.outside_share`: each bearing's "
                   "probability of ending outside the window with the shells its pair's grades hold, on independent "
                   "samples of the scheme's parts, aims and grading; its 95 % interval is Student's on the samples' "
                   "spread, which leaves out that the estimate sees no lots, stock-outs or substitutions: against a "
                   "study's counts see reports/design_scheme.md, against plain Monte Carlo of the whole study chain "
                   "on 10^8 bearings reports/tails_vs_peers.md)")
SPLITTING_HOW = ("estimated by generalized splitting through the same assembly chain (`stackup.tail`; bins never run "
                 "short there), its 95 % interval from the spread of the estimate's independent root bearings, as "
                 "wide as the equivalent count")
NON_DISCRIMINATING = ("The {metric}{same} does not separate the schemes here: every pair of 95 % intervals overlaps, "
                      "so it does not decide the ranking.")
SAME_VALUE_PART = " ({value:.3g} for every scheme)"

# --- designed scheme ------------------------------------------------------------------------------------------
DESIGNED = ("`{name}` was designed for this engine and window by `stackup.design` before the study ({evaluations} "
            "candidate limit sets, {seconds:.0f} s), starting from `{start}`, the ISO scheme with the lowest "
            "objective on the design sample. The study above then judged it on its own engines like every other "
            "scheme: {outcome}{against}")
DESIGN_OUTCOME_PART = "rank {rank}, {share} ppm outside the window{estimated}"
DESIGN_AGAINST_PART = ", against {outcome} for `{start}`."
DESIGN_START_ABSENT_PART = " (`{start}` is not among the schemes compared here)."
DESIGN_CHANGED = "What changed (grade limits in µm from the lower drawing limit of each dimension):"
DESIGN_SHARES = ("Share outside the window on the design sample (the designer's own engines, common random numbers), "
                 "nominal and under each declared scenario:")
DESIGN_WHY = ("Why, in the designer's words (also the comments of the scheme text stored in the dataset's "
              "`input_files`):")
UNGRADED = "ungraded"
GRADE_PART = "{label} {lo:+.1f}…{hi:+.1f}"

# --- what drives the spread -----------------------------------------------------------------------------------
NO_SENSITIVITY = ("The Sobol indices come with `stackup.compare` (its `sensitivity` dataset); none was given.")
#: Sobol outputs in words.
OUTPUTS = {"clearance_operating": "operating clearance", "h_min": "smallest film", "life": "life"}
TIGHTEN_FIRST = ("**Tighten first ({scheme}, {output}):** the {first}, with a total index of {st:.2f} [{st_lo:.2f}, "
                 "{st_hi:.2f}] of the variance (first-order {s1:.2f}), then the {second} ({second_st:.2f}).{gauges}")
GAUGES_PART = " The gauges matter through misgrading: {gauges} (total indices)."
GAUGE_INDEX_PART = "{name} {st:.2f}"
SOBOL_EXPLAINED = (
    "Sobol indices of the root inputs: each sample engine is built from its own sizes, gauge errors, the shells "
    "taken from their grades' bins and crush heights, and goes through grading, pairing and the press fit (and for "
    "the film and the life through the crankshaft and the oil film). The first-order index S_1 is the share of the "
    "output's variance an input explains alone; the total index S_T adds its interactions. The gap between them, "
    "and a sum of S_1 below one, is the grading: a reading near a grade boundary sends a part to another pair. "
    "Process mean shifts are not inputs here: the declared scenarios shift them. Every index is an estimate from a "
    "finite sample: an S_1 above its S_T, or an interval reaching below 0 or above 1, is that sample's error (the "
    "film and life use far fewer engines than the clearance), not a share; read the intervals.")

# --- clearance, press fit -------------------------------------------------------------------------------------
CLEARANCE_INTRO = ("Nominal diametral clearance of every assembled bearing (no swell or temperature, as the "
                   "standard's stated ranges), against each scheme's stated range and its worst case over the "
                   "allowed combinations.")
NONE_STATED = "— (none stated)"
READ_OUT = ("{scheme} reads housing bores and journals to {step} µm: a reading rounded to the nearest {step} µm lands "
            "in its class, so a part up to half a step outside the class is paired as if inside it. That is why its "
            "worst case, {worst_lo:.1f}–{worst_hi:.1f} µm, reaches beyond the stated {stated_lo:.0f}–{stated_hi:.0f} "
            "µm; the share outside the stated range counts those bearings.")
FIT_INTRO = ("The shells' crush height presses them into the housing; the housing bore swells and the clearance "
             "changes with temperature. The clearance is that at the operating temperature; the two press-fit checks "
             "are made at every declared temperature ({temperatures} °C: cold start, assembly, operating, hot), "
             "because they bite at different ends: the shell stress where the housing has shrunk most onto the steel "
             "backs (cold for a light-alloy housing), the contact pressure where it has grown most (hot for "
             "aluminium, cold for a cast iron that expands less than steel). The limits and where they come from:")
PRESS_FIT_LIMITS_SOURCE = ("- contact pressure at least {pressure:.0f} MPa and shell compression at most "
                           "{stress:.0f} MPa: {source};")
CRUSH_SOURCE = "- crush height {lo:.3f}–{hi:.3f} mm: {source};"
WINDOW_SOURCE = "- operating-clearance window {lo:.1f}–{hi:.1f} µm: {source}."
NO_SOURCE = "no source given"

# --- loads, film and life -------------------------------------------------------------------------------------
NO_CRANK = "The crankshaft stage did not run (see the verdict's note)."
CRANK_INTRO = ("Cycle-maximum load of each main bearing (mean ± 95 % interval of the mean, and the largest) on the "
               "first {engines} engines of each scheme{target}; engines with a bearing not assembled are skipped and "
               "marked in `crank_status`.")
TARGET_PART = ", as many as a ±{target:g} % interval of the mean film needs"
NO_FILM = "The film and life stages did not run (see the verdict's note)."
FILM_INTRO = ("Minimum film thickness of each bearing over the cycle (`{method}` tier) at its effective oil "
              "temperature; α is the share of the cycle with the film below the critical film h_lim,cr = {critical} "
              "µm (above 20 % the risk of scuffing rises sharply); life by Levanov et al. (2015): method 1 on the "
              "film the methods section names, and method 2's wear chart. Bearing lives pool every bearing of the "
              "engines; an engine's life is that of its weakest bearing (its B10 and the share of engines below the "
              "life target, {target} h, the engine's).")
POSITIONS = ("The bearing positions carry different loads: bearing{s} {heaviest} carr{verb} the largest cycle-maximum "
             "load here ({most:.1f} kN on average against {least:.1f} kN at the least loaded), and the thinnest films "
             "are at bearing{thin_s} {thinnest}, so the film and life pooled over positions are multimodal. Per "
             "position (median over engines):")
FILM_DETAIL = ("Misalignment reaches the film: the journal tilts in its bearing by the crankshaft's slope at the "
               "support (the beam bent by the loads and by the engine's sampled bore coaxiality and journal "
               "run-out), so the film is thinnest at an edge. Per position: largest tilt over the cycle [mrad, median "
               "over engines] / engines whose journal edge touches the bearing (in brackets the share of the cycle "
               "it touches, median over those engines) / median edge film (where most do not touch) / peak film "
               "pressure over the cycle and its cycle mean [MPa, medians]:")
DETAIL_CELL = "{tilt:.2f} / {touching} / {edge_film} / {peak:.0f} / {mean_peak:.0f}"
TOUCHING_PART = "{share:.0f} %"
TOUCHING_SHARE_PART = " ({share:.0f} %)"
EDGE_CONTACT_CELL = "edge contact"
EDGE_FILM_CELL = "{film:.2f} µm"
NOT_A_NUMBER = ("Films that are not a number, of {total} bearing-cycles: {counts}. Their films and lives are NaN in "
                "the dataset (the reason in `film_status`, `film_valid` false) and left out of every film and life "
                "statistic above and of the ranking ({lost} bearing{lost_s}); the {engines} engine{engines_s} with "
                "such a bearing {have} no engine life and {are} left out of the share of engines below the life "
                "target.")
NOT_A_NUMBER_COUNT_PART = "{count} {status}"
ALL_PERIODIC = ("Every one of the {total} bearing-cycles reached a periodic orbit (`film_status` periodic, or "
                "edge_contact: periodic, with an edge at the wall).")
EDGE_CYCLES = ("In {edge} of them ({share:.0f} %) the tilted journal reaches the bearing's edge at some crank angle "
               "(`edge_contact`): the tilt balances the film's restoring moment (short-bearing, tilt squeeze "
               "neglected) against the crankshaft's rotational compliance at the support, and where the film cannot "
               "hold the beam's slope the edge film is held at the eccentricity limit's floor, not a computed film "
               "(boundary contact at the edge); α and the lives use the mid-plane film.")
HEAT = ("The heat balance puts the films at {temperature} °C (5-95 % of the bearings; median {temperature_median} "
        "°C{supply}), with {power} W of friction power per bearing (median {power_median} W) and {flow} L/min of oil "
        "through it (median {flow_median} L/min, feed and side flow; `film_temperature`, `friction_power`, "
        "`oil_flow`).")
SUPPLY_PART = ", oil supplied at {supply:.0f} °C"

# --- assembly, planning ---------------------------------------------------------------------------------------
ASSEMBLY = "Bearings not assembled are kept in the dataset with their reason (`status`); none are dropped."
PLAN_NEEDS_ENGINES = ("Planning needs each engine's shell demand: run the study with `keep=\"everything\"` (the "
                      "summaries keep only the totals in the grade usage below).")
PLAN = ("From `stackup.plan` on this study's own engines and shell lots: expected demand per grade (95 % interval), "
        "the share of the shell production that landed in the grade when read and sorted, the surplus over {volume} "
        "engines, and the safety stock per production lot ({lot} engines) for a {level:g} % chance that the lot's "
        "demand is covered. `stackup plan --scheme NAME --volume N` plans any volume and service level.")


def plural(count, many="s", one=""):
    """The ending of a word for ``count`` things: ``many`` unless there is one."""
    return one if count == 1 else many


def listed(items):
    """Items written out: 'a', 'a and b', 'a, b and c'."""
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def bold_listed(names):
    """Names in bold, written out (:func:`listed`)."""
    return listed(f"**{n}**" for n in names)
