"""Every variable a study dataset can hold, declared once: name, dimensions, units, long name, flags.

The full dataset (every engine kept) and the streaming summaries build their
variables from this table, so a variable reads the same in both. A variable
of each sampled engine has ``"engine"`` among its dimensions; the results of
the mechanical chain (crankshaft, film, life), which runs on the first
engines only, have ``"mech_engine"`` instead, whose coordinate is the number
of the engine on ``"engine"``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import xarray as xr

from ..assembly import NOT_GRADED, STATUS
from ..crank.cycle import CYCLE_STATUS, NOT_COMPUTED
from ..film.coupled import STATES as TILT_STATUS
from ..film.cycle import FILM_STATUS
from ..film.heat import STATUS as HEAT_STATUS

#: Film status in a dataset: the film stage's codes, then bearings the stage did not run on.
FILM_STATUS_FLAGS = (*FILM_STATUS, "not_computed")
#: Status of the support moments: the march's states, then bearings it did not run on (or another tilt method).
TILT_STATUS_FLAGS = (*TILT_STATUS, "not_computed")

SED = ("scheme", "engine", "bearing")
SMB = ("scheme", "mech_engine", "bearing")
ED = ("engine", "bearing")
SG = ("scheme", "shell_grade")
#: Fixed-width string type of grade labels in a study dataset.
LABEL_DTYPE = "<U2"
#: Resolution a compact file keeps of per-bearing values, by units (:func:`stackup.io.save`): 10 nm is
#: a fiftieth of the gauges' repeatability (0.5 um) and a hundredth of their read-out, 10 kPa a
#: thousandth of a shell's contact pressure, 1 N a ten-thousandth of a main bearing's load.
STORED_RESOLUTION = {"m": 1e-8, "Pa": 1e4, "N": 1.0, "degC": 1e-2}
#: Coarser stored resolutions of variables whose spread and limits are far above their unit's: shell stress
#: (limits of hundreds of MPa) to 0.1 MPa, crush heights (tolerances of tens of um) to 0.1 um.
STORED_RESOLUTION_OF = {"shell_stress": 1e5, "shell_stress_highest": 1e5, "shell_upper_crush": 1e-7,
                        "shell_lower_crush": 1e-7}


@dataclass(frozen=True)
class Var:
    """A dataset variable's declaration."""

    dims: tuple
    units: str
    long_name: str
    flags: tuple = ()  # CF flag meanings of an integer status, by code
    dtype: str = "f8"
    fill: object = np.nan  # value until a stage fills it (a chunk's arrays start with it)

    def __call__(self, data, *, dims=None, **attrs):
        """The variable with ``data`` (on ``dims`` if given), its units, long name and flags."""
        flags = {}
        if self.flags:
            flags = {"flag_values": np.arange(len(self.flags), dtype=np.int8), "flag_meanings": " ".join(self.flags)}
        return xr.Variable(dims or self.dims, data, {"units": self.units, "long_name": self.long_name, **flags,
                                                     **attrs})

    def empty(self, sizes):
        """An array of this variable's shape for dimension ``sizes`` (dim -> length), filled with ``fill``."""
        return np.full(tuple(sizes[d] for d in self.dims), self.fill, self.dtype)

    @property
    def engine_axis(self):
        """Position of the engine dimension (``engine`` or ``mech_engine``)."""
        return next(i for i, d in enumerate(self.dims) if d in ("engine", "mech_engine"))


#: Per-bearing results of the mechanical chain (crankshaft, film, life).
MECHANICS = {
    "reaction_max": Var(SMB, "N", "maximum bearing load over the engine cycle (NaN where crank_status is not_computed)"),
    "h_min": Var(SMB, "m", "minimum oil film thickness over the bearing surface and the engine cycle: the journal's "
                           "tilt and the elastic layer included (Rozhdestvensky et al.'s inf h_min; negative where "
                           "the asperities are pressed past their mean planes) with tilt_method coupled; the "
                           "thinnest over the width, rigid surfaces, with equilibrium; the mid-plane's with free"),
    "h_min_midplane": Var(SMB, "m", "minimum oil film thickness in the bearing's mid-plane over the engine cycle "
                                    "(the film tier of film_method_used, without tilt)"),
    "h_min_mean": Var(SMB, "m", "cycle mean of the minimum oil film thickness over the bearing surface (the film of "
                                "Levanov's method 1, negative films counted as 0)"),
    "h_min_edge": Var(SMB, "m", "minimum oil film thickness over the bearing width and the engine cycle, with the "
                                "journal's tilt (edge film; h_min with tilt_method coupled or equilibrium)"),
    "tilt_loss": Var(SMB, "m", "cycle-minimum film lost to the journal's tilt: h_min_midplane - h_min_edge"),
    "tilt_max": Var(SMB, "rad", "largest tilt of the journal against its bore over the cycle (the crankshaft's "
                                "slope at the support turned back by the support moments: tilt_method coupled, "
                                "or equilibrium)"),
    "tilt_free_max": Var(SMB, "rad", "largest slope of the crankshaft at the support over the cycle, without "
                                     "support moments (the tilt's upper bound)"),
    "edge_contact_share": Var(SMB, "1", "share of the engine cycle at which an edge of the tilted journal is in "
                                        "asperity contact: the film over the surface below the critical film at an "
                                        "edge (tilt_method coupled; otherwise at the limit film)"),
    "edge_contact_load": Var(SMB, "N", "largest bearing load at the crank angles with an edge in contact (NaN: "
                                       "none)"),
    "edge_contact_angle": Var(SMB, "degree", "crank angle of the thinnest film over the surface where an edge is "
                                             "in contact (NaN: none)"),
    "tilt_status": Var(SMB, "1", "status of the support moments over the cycle (tilt_method coupled)",
                       TILT_STATUS_FLAGS, "i1", len(TILT_STATUS)),
    "tilt_unresolved": Var(SMB, "1", "share of the support moments' solved crank angles, last cycle, whose force and "
                                     "turn-back balance was not resolved to the tolerance (tilt_method coupled; NaN "
                                     "otherwise)"),
    "p_max": Var(SMB, "Pa", "peak oil film pressure over the engine cycle (Rozhdestvensky et al.'s p_max)"),
    "p_max_mean": Var(SMB, "Pa", "cycle mean of the peak oil film pressure (Rozhdestvensky et al.'s p*_max)"),
    "film_status": Var(SMB, "1", "status of the bearing's film over the cycle (dynamic tiers: whether the journal "
                                 "orbit became periodic, and why not)", FILM_STATUS_FLAGS, "i1",
                       len(FILM_STATUS)),
    "law_fit_error": Var(SMB, "m", "rms displacement error of the bearing law fitted to the bearing's steady film "
                                   "(NaN: the engine's law, bearing_law='paper')"),
    "alpha": Var(SMB, "1", "share of the cycle with the film below the critical film (boundary friction)"),
    "life": Var(SMB, "s", "bearing resource, Levanov et al. 2015 method 1 on the film the study names (life_film)"),
    "h_min_check": Var(SMB, "m", "h_min corrected by the mass-conserving check tier (elrod-coarse): the study "
                                 "tier's cycle-minimum mid-plane film times the two tiers' ratio less one (both on "
                                 "the aligned journal at the bearing's heat balance) added to it; on the first "
                                 "film_check_engines engines (NaN on the others)"),
    "h_min_mean_check": Var(SMB, "m", "h_min_mean corrected as h_min_check, by the tiers' ratio of cycle-mean "
                                      "films; on the first film_check_engines engines (NaN on the others)"),
    "life_check": Var(SMB, "s", "life (Levanov et al. 2015 method 1) on the check tier's film, on the first "
                                "film_check_engines engines (NaN on the others)"),
    "life_wear_chart": Var(SMB, "s", "bearing resource, Levanov et al. 2015 method 2 (wear chart over the bearing "
                                     "surface, Greenwood-Tripp asperity contact; inf: never in boundary friction)"),
    "wear_rate": Var(SMB, "m s-1", "wear speed of the deepest point of the bearing surface (method 2)"),
    "film_temperature": Var(SMB, "degC", "effective oil film temperature (heat balance with feed and side flow)"),
    "friction_power": Var(SMB, "W", "friction power of the film, cycle mean"),
    "oil_flow": Var(SMB, "m3 s-1", "oil flow through the bearing (feed and side flow), cycle mean"),
    "feed_flow": Var(SMB, "m3 s-1", "pressure-driven feed flow through the groove or hole, cycle mean"),
    "heat_status": Var(SMB, "1", "status of the bearing's heat balance", HEAT_STATUS, "i1", 0),
    "film_valid": Var(SMB, "1", "the bearing's film is a number: its orbit became periodic (or its quasi-static "
                                "film stayed within the eccentricity limit) and did not fail", dtype="?", fill=False),
    "crank_status": Var(("scheme", "mech_engine"), "1", "status of the crankshaft beam stage", CYCLE_STATUS, "i1",
                        NOT_COMPUTED),
}

#: The mechanical chain's values that come from the film: NaN for a bearing whose film is not a number
#: (``film_valid`` false; ``film_status`` says why: collapsed, not_periodic or failed), so that no statistic
#: or ranking reads a film held at the eccentricity limit or an orbit that did not close.
FILM_NUMBERS = ("h_min", "h_min_midplane", "h_min_mean", "h_min_check", "h_min_mean_check", "life_check",
                "h_min_edge", "tilt_loss", "edge_contact_share", "edge_contact_load", "edge_contact_angle", "p_max",
                "p_max_mean", "alpha", "life",
                "life_wear_chart", "wear_rate", "film_temperature", "friction_power", "oil_flow", "feed_flow",
                "h_min_history")
_NOT_A_NUMBER = "; NaN where film_valid is false (film_status collapsed, not_periodic or failed)"
MECHANICS = {name: replace(var, long_name=var.long_name + _NOT_A_NUMBER) if name in FILM_NUMBERS else var
             for name, var in MECHANICS.items()}

#: Press-fit results per bearing.
FIT = {
    "contact_pressure": Var(SED, "Pa", "contact pressure between shell backs and housing bore in service"),
    "shell_stress": Var(SED, "Pa", "mean compressive hoop stress of the shell wall in service (positive in compression)"),
    "housing_swell": Var(SED, "m", "elastic growth of the housing bore diameter from the shell press fit"),
    "clearance_operating": Var(SED, "m", "diametral operating clearance: press fit, swell and temperature "
                                         "(NaN where status is not assembled)"),
    "clearance_assembly": Var(SED, "m", "diametral clearance at the assembly temperature, housing, shells and "
                                        "journal at it, swell included (NaN where status is not assembled)"),
    "clearance_cold": Var(SED, "m", "diametral clearance at the cold start (cold_start_temperature), housing, "
                                    "shells and journal at it, swell included (NaN where status is not assembled)"),
    "contact_pressure_lowest": Var(SED, "Pa", "lowest contact pressure between shell backs and housing bore over "
                                              "the temperatures checked (press_fit_temperatures; 0: fit lost)"),
    "shell_stress_highest": Var(SED, "Pa", "highest compressive hoop stress of the shell wall over the temperatures "
                                           "checked (press_fit_temperatures)"),
}

#: Variables of the dataset that keeps every engine, in dataset order.
FULL = {
    "housing_bore": Var(ED, "m", "housing bore diameter (true)"),
    "housing_bore_reading": Var(ED, "m", "housing bore diameter as read by the gauge"),
    "journal_d": Var(ED, "m", "journal diameter (true)"),
    "journal_d_reading": Var(ED, "m", "journal diameter as read by the gauge"),
    "block_scrapped": Var(("engine",), "1", "block scrapped: a bore read outside its drawing limits", dtype="?",
                          fill=False),
    "crank_scrapped": Var(("engine",), "1", "crankshaft scrapped: a journal read outside its drawing limits",
                          dtype="?", fill=False),
    "housing_grade": Var(SED, "1", "housing bore grade (empty: not graded)", dtype=LABEL_DTYPE, fill=""),
    "journal_grade": Var(SED, "1", "journal grade (empty: not graded)", dtype=LABEL_DTYPE, fill=""),
    "shell_upper_grade": Var(SED, "1", "upper shell grade fitted (empty: none)", dtype=LABEL_DTYPE, fill=""),
    "shell_lower_grade": Var(SED, "1", "lower shell grade fitted (empty: none)", dtype=LABEL_DTYPE, fill=""),
    "shell_upper_wall": Var(SED, "m", "upper shell crown wall thickness (true; NaN where status says none fitted)"),
    "shell_lower_wall": Var(SED, "m", "lower shell crown wall thickness (true; NaN where status says none fitted)"),
    "shell_upper_crush": Var(SED, "m", "crush height of the upper shell (NaN where none fitted)"),
    "shell_lower_crush": Var(SED, "m", "crush height of the lower shell (NaN where none fitted)"),
    "clearance_nominal": Var(SED, "m", "nominal diametral clearance D_H - (s_upper + s_lower + D_J), no swell "
                                       "(NaN where status is not assembled)"),
    **FIT,
    "loss_of_fit": Var(SED, "1", "the shells have no interference left at operating temperature", dtype="?",
                       fill=False),
    "loss_of_fit_any_temperature": Var(SED, "1", "the shells lose their interference at one of the temperatures "
                                                 "checked (press_fit_temperatures)", dtype="?", fill=False),
    "bore_offset": Var(("engine", "bearing", "axis"), "m", "housing bore centre off the straight bearing line (coaxiality)"),
    "journal_eccentricity": Var(("engine", "bearing", "axis"), "m",
                                "main journal centre off the crankshaft axis at crank angle 0 (run-out)"),
    **MECHANICS,
    "status": Var(SED, "1", "assembly status of the bearing", STATUS, "i1", NOT_GRADED),
    "shell_option": Var(SED, "1", "shell pair used: 0 preferred, k > 0 the scheme's k-th alternative, -1 none",
                        dtype="i1", fill=-1),
    "shells_made": Var(SG, "1", "shells made and sorted into the grade"),
    "shells_used": Var(SG, "1", "shells of the grade fitted to bearings"),
    "shells_left": Var(SG, "1", "shells of the grade left in stock at the ends of the lots"),
    "shells_scrapped": Var(("scheme",), "1", "shells read outside every grade of the scheme (scrapped)"),
    "grade_in_scheme": Var(SG, "1", "the scheme has this shell grade"),
    "clearance_stated": Var(("scheme", "bound"), "m", "clearance range stated by the scheme's source"),
    "clearance_limit": Var(("scheme", "bound"), "m", "worst-case nominal clearance over the scheme's allowed combinations"),
    "reading_resolution": Var(("scheme", "part"), "m", "step the scheme reads housing bores and journals to "
                                                         "(0: continuous); readings round to the nearest step"),
}

#: Histories over the cycle of the engines of the mechanical chain (``Study(history=True)``).
HISTORY = {
    "load_history": Var((*SMB, "crank_angle", "axis"), "N",
                        "bearing load over the cycle (force of the journal on the bearing)"),
    "h_min_history": Var((*SMB, "crank_angle"), "m", "minimum oil film thickness over the bearing surface over the "
                                                     "cycle" + _NOT_A_NUMBER),
}

#: Variables a chunk computes for each of its engines.
PER_ENGINE = {name: var for name, var in FULL.items() if "engine" in var.dims}
#: Variables a chunk computes for each of its engines in the mechanical chain (histories on request).
PER_MECH = {**MECHANICS, **HISTORY}

#: Grade labels (fixed-width strings; stored as int8 codes, :mod:`stackup.study.store`).
LABELS = ("housing_grade", "journal_grade", "shell_upper_grade", "shell_lower_grade")

#: Bins of the clearance histograms of the streaming summaries: from BIN_START [m], BIN_WIDTH [m] wide.
BIN_START, BIN_WIDTH, BINS = 0.0, 0.1e-6, 3000  # up to 300 um
#: Bearings the streaming summaries keep at each end of the operating clearance.
WORST = 20

#: Streaming summaries (``keep="summaries"``): the counts, extremes and moments they reduce to.
SUMMARY = {
    **{f"clearance_{label}_histogram": Var(("scheme", "clearance_bin"), "1", f"assembled bearings per "
                                           f"{BIN_WIDTH * 1e6:g} um bin of the {label} clearance")
       for label in ("nominal", "operating")},
    **{f"clearance_{label}_mean": Var(("scheme",), "m", f"mean {label} diametral clearance")
       for label in ("nominal", "operating")},
    **{f"clearance_{label}_std": Var(("scheme",), "m", f"standard deviation of the {label} diametral clearance")
       for label in ("nominal", "operating")},
    **{f"worst_{side}": Var(("scheme", "rank", "field"), "mixed",
                            f"the {WORST} bearings with the {extreme} operating clearance and their inputs "
                            "(see field; lengths in m)")
       for side, extreme in (("low", "smallest"), ("high", "largest"))},
    "status_count": Var(("scheme", "status"), "1", "bearings per assembly status"),
    "outside_window_count": Var(("scheme",), "1",
                                "assembled bearings with the operating clearance outside the design window"),
    "loss_of_fit_count": Var(("scheme",), "1", "assembled bearings whose shells lose their interference at one of "
                                              "the temperatures checked (press_fit_temperatures)"),
    "low_contact_pressure_count": Var(("scheme",), "1",
                                      "assembled bearings with contact pressure below design_contact_pressure_min at "
                                      "one of the temperatures checked"),
    "high_shell_stress_count": Var(("scheme",), "1", "assembled bearings with shell stress above "
                                                     "design_shell_stress_max at one of the temperatures checked"),
    "contact_pressure_min": Var(("scheme",), "Pa", "lowest contact pressure of an assembled bearing over the "
                                                   "temperatures checked"),
    "shell_stress_max": Var(("scheme",), "Pa", "highest shell stress of an assembled bearing over the temperatures "
                                               "checked"),
    **{f"clearance_{label}_{stat}": Var(("scheme",), "m", f"{what} diametral clearance at {when}")
       for label, when in (("assembly", "assembly"), ("cold", "the cold start"))
       for stat, what in (("mean", "mean"), ("std", "standard deviation of the"))},
    "below_minimum_clearance_count": Var(("scheme",), "1", "assembled bearings whose clearance at assembly or at the "
                                                           "cold start is below minimum_clearance"),
    "housing_swell_mean": Var(("scheme",), "m", "mean elastic growth of the housing bore from the press fit"),
    "housing_swell_std": Var(("scheme",), "m", "standard deviation of the growth of the housing bore from the press fit"),
    "clearance_operating_sampled": Var(SMB, "m", "diametral operating clearance of the bearings of the mechanical chain"),
}

#: Sobol indices of the root inputs per output and scheme (a comparison's sensitivity dataset,
#: :func:`stackup.comparison.sensitivity_dataset`), each with its 95 % bootstrap bounds.
SOBOL_INDICES = {
    "S1": Var(("output", "scheme", "input"), "1",
              "first-order Sobol index (share of the variance the input explains alone)"),
    "S1_lo": Var(("output", "scheme", "input"), "1", "lower 95 % bootstrap bound of S1"),
    "S1_hi": Var(("output", "scheme", "input"), "1", "upper 95 % bootstrap bound of S1"),
    "ST": Var(("output", "scheme", "input"), "1",
              "total Sobol index (share of the variance the input explains with its interactions)"),
    "ST_lo": Var(("output", "scheme", "input"), "1", "lower 95 % bootstrap bound of ST"),
    "ST_hi": Var(("output", "scheme", "input"), "1", "upper 95 % bootstrap bound of ST"),
}
#: The sensitivity dataset's variables, in dataset order.
SENSITIVITY = {**SOBOL_INDICES,
               "evaluations": Var(("output", "scheme"), "1", "engines through the chain", dtype="i8", fill=0)}

#: Shares of bearings beyond each edge of the design window per scheme (a comparison's tails dataset,
#: :func:`stackup.comparison.tails_dataset`); ``{method}`` in a long name is the estimator, as the dataset's
#: ``method`` attribute names it. ``tail_roots_in_tail`` is the splitting estimator's only, ``tail_outside_*``
#: the conditional one's.
TAILS = {
    "tail_share": Var(("scheme", "side"), "1", "share of assembled bearings beyond the window edge ({method})"),
    "tail_standard_error": Var(("scheme", "side"), "1", "standard error of tail_share"),
    "tail_interval": Var(("scheme", "side", "bound"), "1", "95 % interval of tail_share"),
    "tail_bearings": Var(("scheme", "side"), "1", "bearings the estimate evaluated"),
    "tail_roots_in_tail": Var(("scheme", "side"), "1", "root bearings of the estimate with descendants in the tail"),
    "tail_outside_share": Var(("scheme",), "1", "share of assembled bearings outside the window ({method})"),
    "tail_outside_interval": Var(("scheme", "bound"), "1", "95 % interval of tail_outside_share"),
}


@dataclass(frozen=True)
class Coord:
    """A coordinate's declaration: its long name, and its units where its values have some."""

    long_name: str
    units: str | None = None

    @property
    def attrs(self):
        return {"long_name": self.long_name} if self.units is None else {"units": self.units,
                                                                          "long_name": self.long_name}


#: The coordinate of every dimension of a study's datasets and a comparison's, declared once.
COORDS = {
    "scheme": Coord("selective-fitting scheme"),
    "engine": Coord("sampled engine (block, crankshaft and its shells)"),
    "mech_engine": Coord("engine of the mechanical chain (its number on the engine dimension)"),
    "bearing": Coord("main bearing position"),
    "shell_grade": Coord("shell grade label"),
    "bound": Coord("interval bound"),
    "axis": Coord("engine-fixed axis: towards the bearing cap, transverse"),
    "part": Coord("graded part"),
    "crank_angle": Coord("crank angle from firing TDC of the first cylinder fired", "degree"),
    "status": Coord("assembly status"),
    "clearance_bin": Coord("clearance bin centre", "m"),
    "rank": Coord("rank among the extremes"),
    "field": Coord("recorded quantity"),
    "output": Coord("output variable (h_min, life: the engine's weakest bearing)"),
    "input": Coord("root input (stackup.study.roots)"),
    "side": Coord("edge of the design window"),
}
#: Values of the coordinates that are the same in every dataset.
BOUNDS, SIDES, PARTS, AXES = ("lower", "upper"), ("lower", "upper"), ("housing", "journal"), ("cap", "transverse")


def coords(**values):
    """Coordinates as :class:`xarray.Dataset` takes them, name -> (name, values, attrs), each with the attributes
    :data:`COORDS` declares (e.g. ``coords(scheme=names, bound=BOUNDS)``)."""
    # a tuple of values goes in as a list: xarray would take a tuple for one value
    return {name: (name, list(v) if isinstance(v, tuple) else v, COORDS[name].attrs) for name, v in values.items()}



def flag(variable, meaning):
    """The code of ``meaning`` in a status variable's CF ``flag_meanings`` (e.g. ``flag(ds.status, "assembled")``)."""
    meanings = variable.attrs["flag_meanings"].split()
    if meaning not in meanings:
        raise ValueError(f"{variable.name}: {meaning!r} is not one of its flags ({', '.join(meanings)})")
    return int(variable.attrs["flag_values"][meanings.index(meaning)])


#: The engine's design data every study dataset carries, with units (not as attributes, which have none).
DESIGN = {
    "clearance_window": Var(("bound",), "m", "design window of the diametral operating clearance"),
    "life_target": Var((), "s", "bearing life the engine asks for"),
    "crush_height_limits": Var(("bound",), "m", "drawing limits of the crush height of a half shell"),
    "design_contact_pressure_min": Var((), "Pa", "least contact pressure between shell back and housing in service"),
    "design_shell_stress_max": Var((), "Pa", "largest compressive hoop stress of the shell wall"),
    "press_fit_temperatures": Var(("press_fit_check",), "degC", "temperatures the press fit is checked at (cold "
                                                                "start, assembly, operating, hot)"),
    "minimum_clearance": Var((), "m", "least diametral clearance a bearing may have at assembly or the cold start"),
    "cold_start_temperature": Var((), "degC", "coldest temperature the bearings are assembled or started at"),
    "critical_film": Var((), "m", "critical film thickness h_lim,cr = Rz journal + Rz shell (Levanov et al. 2015, "
                                  "eq. 3): below it, boundary friction"),
}


def design_variables(engine):
    """The :data:`DESIGN` variables of ``engine`` (its window, life target, crush limits and press-fit limits)."""
    limits = engine.press_fit_limits
    values = {"clearance_window": engine.clearance_window, "life_target": engine.life_target,
              "crush_height_limits": (engine.shell_wall.crush.lo, engine.shell_wall.crush.hi),
              "design_contact_pressure_min": limits.contact_pressure_min,
              "design_shell_stress_max": limits.shell_stress_max,
              "press_fit_temperatures": engine.press_fit.temperatures,
              "minimum_clearance": engine.minimum_clearance,
              "cold_start_temperature": engine.press_fit.cold_start_temperature,
              "critical_film": engine.wear.critical_film}
    return {name: var(np.asarray(values[name], dtype=float)) for name, var in DESIGN.items()}


def scheme_variables(schemes):
    """The schemes' stated and worst-case clearance ranges, as every study dataset carries them."""
    stated = np.array([s.stated_clearance if s.stated_clearance else (np.nan, np.nan) for s in schemes])
    resolution = np.array([[s.housing.resolution, s.journal.resolution] for s in schemes])
    return {"clearance_stated": FULL["clearance_stated"](stated),
            "clearance_limit": FULL["clearance_limit"](np.array([s.clearance_limits() for s in schemes])),
            "reading_resolution": FULL["reading_resolution"](resolution)}
