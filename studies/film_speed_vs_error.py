"""Film tiers: time per bearing-cycle against the film error to the reference tiers.

Steady tiers (short, finite, reynolds) on a grid of L/D and eccentricity (the
load the Reynolds tier carries at each eccentricity handed to every tier).
Cycle tiers (quasi-static on each steady tier, mobility, mobility-finite) on
every main bearing of the two built-in engines over a 720-step cycle, against
the transient Reynolds tier with mass-conserving cavitation: cycle minimum and
cycle mean of the minimum film, peak pressure and friction power; the
transient tier's own time-step, grid, cavitation-model and feed-pressure
sensitivity; and journal tilt: the cheap tiers' film force and moment on a
tilted journal (:mod:`stackup.film.tilt`) against the Reynolds tier with tilt,
and the tilt equilibrium over the cycle (the crankshaft's free slope turned
back by the film's moment against its rotational compliance) against the
transient tier with the tilt as unknowns. The measured errors and costs
go to ``stackup/data/film_cycle_errors.toml`` (what
:func:`stackup.film.orbit.cheapest_cycle_tier` reads).

    python studies/film_speed_vs_error.py [--workers 2]

Writes reports/film_speed_vs_error.md (long: the transient tier dominates; the report gives its times).
The ``elrod-coarse`` tier is measured by ``studies/film_speed_vs_error_elrod.py``, which adds its section to
that report and its entry to the errors file: run it after this study (with the same ``--cache``), which
rewrites both.
"""

from __future__ import annotations

import argparse
import functools
import hashlib
import multiprocessing
import pickle
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numba
import numpy as np
from _common import best_time, environment, write_report
from _film_cases import engine_case

import stackup
from stackup.crank import support_compliance
from stackup.engines import load_engine
from stackup.film import BY_COST, ERROR_GRID, cheapest_tier, min_film_thickness, reynolds, tier_errors
from stackup.film import registry
from stackup.film.orbit import ECCENTRICITY_LIMIT, STATUS, cheapest_cycle_tier, cycle_tier_errors, orbit
from stackup.film.tilt import film_moment

DEFAULT_ERROR = 0.05
ENGINES = ("iso-example", "rozhdestvensky-4")
CHEAP_TIERS = ("short", "finite", "mobility", "mobility-finite")
QUANTITIES = {  # name: (Orbit attribute, what it is)
    "h_min": ("h_min_cycle", "cycle minimum of the minimum film"),
    "h_min_mean": ("h_min_mean", "cycle mean of the minimum film"),
    "p_max": ("p_max_cycle", "cycle maximum of the peak pressure"),
    "p_max_mean": ("p_max_mean", "cycle mean of the peak pressure"),
    "friction_power": ("friction_power_mean", "cycle mean of the friction power"),
}
#: Steady tilted journals against the Reynolds tier with tilt: eccentricity, direction of the tilt from the line of
#: centres [deg], edge offset as a share of the room the edge has in that direction.
TILT_ECCENTRICITY = (0.3, 0.6, 0.8, 0.9)
TILT_DIRECTION = (0.0, 90.0, 180.0)
TILT_SHARE = (0.5, 0.9)
#: Main bearings of each engine in the cycle's tilt cases (4 and 5 mirror 2 and 1), and the crankshaft's
#: rotational compliance scaled (1: the beam's; 10: a support that turns ten times as easily, where the film
#: holds the journal off the wall).
TILT_BEARINGS = (0, 1, 2)
TILT_COMPLIANCE_SCALE = (1.0, 10.0)
ERRORS_FILE = Path(__file__).resolve().parents[1] / "stackup" / "data" / "film_cycle_errors.toml"


def summary(result):
    """Per-bearing cycle quantities of an Orbit, as a dict of arrays."""
    out = {q: getattr(result, attr) for q, (attr, _) in QUANTITIES.items()}
    out |= {"status": result.status, "h_min_edge": result.h_min_edge_cycle,
            "h_edge_mean": result.h_min_edge.mean(axis=-1), "tilt_max": result.tilt_max}
    if result.tilt is not None:
        clearance = result.h_min + np.linalg.norm(result.position, axis=-1)  # c (1 - eps) + c eps
        floor = (1 - ECCENTRICITY_LIMIT) * clearance
        out["contact_share"] = np.mean(result.h_min_edge <= floor * (1 + 1e-3), axis=-1)
    return {k: np.atleast_1d(np.asarray(v, dtype=float)) for k, v in out.items()}


def compliance(name):
    """The crankshaft's rotational compliance at each main bearing (bearings, 2) [rad/(N m)]."""
    spec = load_engine(name).crank
    return support_compliance(spans=spec.spans, EI=spec.ei)


def steady_tilt_case(job):
    """A steady tilted journal of an engine's bearing: the Reynolds tier with tilt against the cheap film moment.

    job: (engine, eccentricity, direction [deg], share of the room). Returns the dimensionless force and moment of
    the Reynolds tier, the short-bearing and the finite-corrected cheap tier.
    """
    name, eps, direction, share = job
    case = engine_case(name)
    length_over_radius = case.length / (case.diameter / 2)
    xi = np.array([eps, 0.0])
    v = -0.5 * np.array([-xi[1], xi[0]])  # steady journal: rotation only
    d = np.array([np.cos(np.radians(direction)), np.sin(np.radians(direction))])
    room = min(np.roots([1.0, 2 * s * xi @ d, eps**2 - 1.0]).real.max() for s in (1.0, -1.0))
    e = share * room * d
    field = reynolds.tilted_field(xi, v, e, length_over_radius)
    # unit journal (R = 1, c = 1, mu = omega = 1): forces per mu omega R L^3/c^2 are F/L^3, moments M/L^4
    length = length_over_radius
    geometry = dict(journal_radius=1.0, bearing_width=length, radial_clearance=1.0, viscosity=1.0, speed=1.0)
    out = {"reynolds": (field.force, field.moment)}
    for method in ("short", "finite"):
        film = film_moment(xi, v, e * 2 / length, **geometry, method=method)
        out[method] = (film.force / length**3, film.moment / length**4)
    return out


def _job_key(job):
    name, bearing, options = job
    parts = [f"{k}={hashlib.sha1(np.ascontiguousarray(v).tobytes()).hexdigest() if isinstance(v, np.ndarray) else v}"
             for k, v in sorted(options.items())]
    return hashlib.sha1(f"{stackup.__version__}|{name}|{bearing}|{'|'.join(parts)}".encode()).hexdigest()


def _slow_tier(job, cache=None):
    """One slow run in a worker: (engine, bearing, options) -> summary and seconds.

    Options: ``method`` (default reynolds-transient), ``step`` of the crank angle, ``tilt``, and the
    transient tier's own options. With a ``cache`` folder, a run done before is read back.
    """
    if cache is not None:
        path = Path(cache) / f"{_job_key(job)}.pkl"
        if path.exists():
            return pickle.loads(path.read_bytes())
        result = _slow_tier(job)
        path.write_bytes(pickle.dumps(result))
        return result
    name, bearing, options = job
    options = dict(options)
    numba.set_num_threads(1)
    case = engine_case(name, step=options.pop("step", 1.0))
    method = options.pop("method", "reynolds-transient")
    if method == "reynolds-transient":
        options.setdefault("feed", case.feed)  # the engine's groove at its supply pressure
    t0 = time.perf_counter()
    result = orbit(case.loads[bearing], case.crank_angle, **case.geometry(bearing), method=method, **options)
    return summary(result), time.perf_counter() - t0


def errors_by_case():
    rows = []
    for ld in ERROR_GRID["length_over_diameter"]:
        for eps in ERROR_GRID["eccentricity"]:
            field = reynolds.solve_field(eps, 2 * ld)
            load = field.force * 1e6
            h_ref = 1e-3 * (1 - eps)
            errs = {}
            for method in ("short", "finite"):
                f = min_film_thickness(load, journal_d=2.0, bearing_width=2.0 * ld, clearance=2e-3, viscosity=1.0,
                                       speed=1.0, method=method)
                errs[method] = float(f.h_min) / h_ref - 1
            rows.append((ld, eps, errs["short"], errs["finite"]))
    return rows


def steady_timing(case):
    """Time of one bearing-cycle of each steady tier run quasi-statically (Reynolds on 12 angles, scaled)."""
    loads = case.loads[1]
    geometry = case.geometry(1)
    timing = {m: best_time(lambda: orbit(loads, case.crank_angle, **geometry, method=m), 5)
              for m in ("short", "finite")}
    magnitude = np.linalg.norm(loads, axis=-1)
    points = np.unique(np.concatenate([np.argsort(magnitude)[-6:], np.linspace(0, loads.shape[0] - 1, 6).astype(int)]))
    t0 = time.perf_counter()
    min_film_thickness(magnitude[points], journal_d=case.diameter, bearing_width=case.length, clearance=case.clearance,
                       viscosity=case.viscosity[1], speed=case.speed, method="reynolds")
    timing["reynolds"] = (time.perf_counter() - t0) / points.size * loads.shape[0]
    return timing


def cheap_tiers(cases):
    """Summaries and one-core time per bearing-cycle of the cheap cycle tiers (and quasi-static Reynolds)."""
    numba.set_num_threads(1)
    out, seconds = {}, {}
    for tier in CHEAP_TIERS:
        runs = []
        for case in cases.values():
            call = lambda case=case: orbit(case.loads, case.crank_angle, **case.geometry(), method=tier)  # noqa: E731
            seconds.setdefault(tier, []).append(best_time(call, 5) / case.loads.shape[0])
            runs.append(summary(call()))
        out[tier] = {k: np.concatenate([r[k] for r in runs]) for k in runs[0]}
        seconds[tier] = float(np.mean(seconds[tier]))
    return out, seconds


def tilt_cost(cases):
    """One core's time per bearing-cycle of mobility-finite without and with the tilt marched over the cycle [s]."""
    numba.set_num_threads(1)
    seconds = {"mobility-finite": [], "with tilt": []}
    for name, case in cases.items():
        n = case.loads.shape[0]
        c_rot = compliance(name)
        base = best_time(lambda case=case: orbit(case.loads, case.crank_angle, **case.geometry(),
                                                 method="mobility-finite"), 5)
        tilted = best_time(lambda case=case, c_rot=c_rot: orbit(case.loads, case.crank_angle, **case.geometry(),
                                                                method="mobility-finite", tilt=case.tilt,
                                                                tilt_compliance=c_rot), 5)
        seconds["mobility-finite"].append(base / n)
        seconds["with tilt"].append(tilted / n)
    return {k: float(np.mean(v)) for k, v in seconds.items()}


def relative(a, b):
    return a / b - 1


def write_errors(out, seconds, references):
    """The measured costs and worst errors against each reference, as data for cheapest_cycle_tier."""
    lines = [f"# Written by studies/film_speed_vs_error.py (stackup {stackup.__version__}): one bearing's 720-step",
             "# cycle on one core [s], and the largest relative error over the main bearings of the built-in",
             "# engines against reynolds-transient with mass-conserving (Elrod-Adams) cavitation, and in",
             "# [tiers.X.swift-stieber] against the same tier with the Reynolds condition. Regenerate with that study.",
             ""]
    reference_tier = registry.reference_tier().name
    measured = (*CHEAP_TIERS, "reynolds", reference_tier)
    rows = {registry.tier(tier).error_row for tier in measured}  # each tier's row, as its record names it
    for tier in measured:
        for label, reference in references.items():
            lines.append(f'[tiers."{registry.tier(tier).error_row}"{label}]')
            if not label:
                lines.append(f"seconds = {seconds[tier]:.6g}")
            for q in QUANTITIES:
                same = tier == reference_tier and not label
                err = 0.0 if same else float(np.max(np.abs(relative(out[tier][q], reference[q]))))
                lines.append(f"{q} = {err:.6g}")
            lines.append("")
    # the tiers other studies measure (studies/film_speed_vs_error_elrod.py) keep their entries
    kept = ERRORS_FILE.read_text().split("\n[tiers.")[1:] if ERRORS_FILE.exists() else []
    for block in kept:
        if block.split('"')[1] not in rows:
            lines.append("[tiers." + block.rstrip("\n"))
            lines.append("")
    ERRORS_FILE.write_text("\n".join(lines))
    cycle_tier_errors.cache_clear()
    print(f"wrote {ERRORS_FILE}")


def worst(values, reference):
    """Largest relative error (signed) over the bearings."""
    e = relative(values, reference)
    return e[np.argmax(np.abs(e))]


def cheapest_cycle_text():
    """The cheapest cycle tier within DEFAULT_ERROR of the reference, or that none cheaper than it is, in words."""
    tier = cheapest_cycle_tier(DEFAULT_ERROR)
    both = "on both the cycle minimum and the cycle mean of the minimum film"
    if tier == "reynolds-transient":
        return f"No cycle tier cheaper than the reference is within {100 * DEFAULT_ERROR:.0f} % of it {both}"
    return f"Cheapest cycle tier within {100 * DEFAULT_ERROR:.0f} % of the reference {both}: **{tier}**"


def verdict(out, seconds, reference):
    """The report's opening: which cycle tier to use, what its error is made of, what is fragile."""
    ss = out["reynolds-transient, Swift-Stieber"]
    mf = out["mobility-finite"]
    qs = [worst(out[t]["h_min"], reference["h_min"]) for t in ("short", "finite", "reynolds")]
    within = cheapest_cycle_text() + (". " if cheapest_cycle_tier(DEFAULT_ERROR) != "reynolds-transient" else
                                      ": the study's default film_error (0.5) admits `mobility-finite` and states "
                                      "its error. ")
    return (
        within + f"`mobility-finite`: one bearing's cycle costs {1e3 * seconds['mobility-finite']:.1f} ms on "
        f"one core ({seconds['mobility-finite'] / seconds['mobility']:.1f} times the short-bearing `mobility`, "
        f"{seconds['reynolds-transient'] / seconds['mobility-finite']:,.0f} times less than the reference). Against "
        "the transient Reynolds tier with the same (Reynolds) cavitation condition it is within "
        f"{100 * abs(worst(mf['h_min'], ss['h_min'])):.1f} % on the cycle minimum and "
        f"{100 * abs(worst(mf['h_min_mean'], ss['h_min_mean'])):.1f} % on the cycle mean of the minimum film "
        "(`stackup/data/film_cycle_errors.toml`, `swift-stieber`): "
        "its error with the cavitation model set aside (the tabulated finite-length correction, the mid-plane "
        "pi-film of the mobility method, and no feed groove: the mobility tiers see a complete bearing). Against "
        "the mass-conserving reference it is off by up to "
        f"{100 * abs(worst(mf['h_min'], reference['h_min'])):.1f} % (cycle minimum) and "
        f"{100 * abs(worst(mf['h_min_mean'], reference['h_min_mean'])):.1f} % (cycle mean), always on the thick "
        "side: the rest is the cavitation model - the film downstream of a moving load is short of oil, which no "
        "tier without a film content can see (the reference's own run with the Reynolds condition is off by "
        f"{100 * abs(worst(ss['h_min'], reference['h_min'])):.0f} % and "
        f"{100 * abs(worst(ss['h_min_mean'], reference['h_min_mean'])):.0f} %). "
        "The short-bearing `mobility` tier overestimates the film of these L/D 0.33-0.48 bearings by up to "
        f"{100 * abs(worst(out['mobility']['h_min'], reference['h_min'])):.0f} %. The quasi-static tiers miss the "
        f"squeeze film: their cycle minimum is off by {', '.join(f'{100 * e:+.0f} %' for e in qs)} (short, "
        "finite, Reynolds), so no steady tier, however exact, fixes a quasi-static cycle. Tilt: see its section."
    )


def tilt_summary(steady_tilt, tilt_ref, tilt_cheap, tilt_seconds):
    """The tilt section's opening: what the film does to the tilt, the cheap tier's error, what it costs."""
    arm = {m: max(np.linalg.norm(out[m][1] - out["reynolds"][1]) / np.linalg.norm(out["reynolds"][0])
                  for out in steady_tilt.values()) for m in ("short", "finite")}
    moment = {m: [abs(np.linalg.norm(out[m][1]) / np.linalg.norm(out["reynolds"][1]) - 1)
                  for (_, _, d, _), out in steady_tilt.items() if d != 90.0] for m in ("short", "finite")}
    across = [abs(np.linalg.norm(out["finite"][1]) / np.linalg.norm(out["reynolds"][1]) - 1)
              for (_, _, d, _), out in steady_tilt.items() if d == 90.0]
    held = [(k, r[0]) for k, r in tilt_ref.items() if k[3] and k[2] == 1.0]
    soft = [(k, r[0]) for k, r in tilt_ref.items() if k[3] and k[2] == 10.0]
    share_ref = [r["contact_share"][0] for _, r in held]
    share_cheap = [tilt_cheap[k[:3]]["contact_share"][0] for k, _ in held]
    gaps = [100 * (b - a) for a, b in zip(share_ref, share_cheap)]
    mean_errors = [relative(tilt_cheap[k[:3]]["h_edge_mean"][0], r["h_edge_mean"][0]) for k, r in held + soft]
    soft_min = [(1e6 * r["h_min_edge"][0], 1e6 * tilt_cheap[k[:3]]["h_min_edge"][0]) for k, r in soft]
    squeeze = [(100 * tilt_ref[(name, 1, 10.0, True)][0]["contact_share"][0],
                100 * tilt_ref[(name, 1, 10.0, False)][0]["contact_share"][0],
                100 * tilt_cheap[(name, 1, 10.0)]["contact_share"][0]) for name in ENGINES]
    return (
        "The film's moment turns the journal back, but on these engines it cannot hold the crankshaft's slope: "
        "with the crankshaft's own rotational compliance at the supports both the reference and the cheap tier "
        f"put an edge at the wall over {100 * min(share_ref):.0f}-{100 * max(share_ref):.0f} % (reference) and "
        f"{100 * min(share_cheap):.0f}-{100 * max(share_cheap):.0f} % (cheap) of the cycle at bearings 1-3: "
        "under the peak loads, and while the journal lingers near the wall after them, the moment a film can "
        "give grows only like the logarithm of the edge film (the pressure vanishes at the bearing's end, where "
        "the film is thinnest), far below the moment that would hold the beam's slope against the crankshaft's "
        "compliance at the support. The edge contacts of "
        "the study are therefore not an artefact of a missing film moment; what would relieve them lies outside "
        "the rigid, isoviscous film: the bearing's and the block's own compliance (the support's angular "
        "compliance of Rozhdestvensky et al.'s eq. 5), elastic deformation of the lining, a crankshaft stiffer at "
        "its journals than the equivalent beam. With a support ten times as compliant the films hold the "
        "journals off the wall at most angles: cycle-minimum edge films "
        + ", ".join(f"{a:.2f} / {b:.2f}" for a, b in soft_min)
        + " um (reference / cheap, bearings 1-3 of each engine). The tilt's own squeeze matters where the edge "
        "nears the wall: the reference without it puts an edge at the wall over "
        + " and ".join(f"{b:.0f} % instead of {a:.0f} %" for a, b, _ in squeeze)
        + " of the cycle (bearing 2 of each engine, x 10); the cheap tier, which marches the tilt with that "
        "squeeze (`stackup.film.tilt.march_tilt`), has "
        + " and ".join(f"{c:.0f} %" for _, _, c in squeeze)
        + ". At the crankshaft's compliance the cheap tier "
        f"is at the wall {min(gaps):+.0f} to {max(gaps):+.0f} points of the cycle from the reference (bearings "
        "1-3 of each engine). "
        "The cheap treatment's cycle-mean edge film is within "
        f"{100 * max(abs(e) for e in mean_errors):.0f} % of the reference's in every case, on the thick side "
        "(the mid-plane orbit's own error against the mass-conserving reference included). Its film moment: the "
        f"short bearing overestimates the moment of these bearings by up to {100 * max(moment['short']):.0f} % "
        "(tilt in the plane of the journal's offset), the finite correction brings that to "
        f"{100 * max(moment['finite']):.0f} % (tilt across that plane: up to {100 * max(across):.0f} %, table "
        f"below); the moment's arm is within {100 * arm['finite']:.1f} % of the "
        f"length (finite; short {100 * arm['short']:.1f} %). Cost: +"
        f"{1e3 * (tilt_seconds['with tilt'] - tilt_seconds['mobility-finite']):.2f} ms per bearing-cycle "
        f"({tilt_seconds['with tilt'] / tilt_seconds['mobility-finite']:.1f} times `mobility-finite` alone; the "
        "whole chain against the crankshaft cycle: reports/bench_chain.md)."
    )


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default="reports/film_speed_vs_error.md")
    parser.add_argument("--cache", help="folder keeping each slow run, so a rerun redoes only what changed")
    args = parser.parse_args(argv)
    if args.cache:
        Path(args.cache).mkdir(parents=True, exist_ok=True)

    cases = {name: engine_case(name) for name in ENGINES}
    n_bearings = {name: c.loads.shape[0] for name, c in cases.items()}
    # the transient runs first, in worker processes, while this process times the cheap tiers
    jobs = [(name, b, {}) for name in ENGINES for b in range(n_bearings[name])]
    jobs += [(name, b, {"cavitation": "reynolds"}) for name in ENGINES for b in range(n_bearings[name])]
    jobs += [(name, b, {"method": "reynolds"}) for name in ENGINES for b in range(n_bearings[name])]
    checks = {"1440 steps": ("iso-example", 1, {"step": 0.5}), "grid 270 x 31": ("iso-example", 1,
                                                                                   {"n_theta": 270, "n_z": 31}),
              "feed hole at 0.3 MPa instead of the groove": ("iso-example", 1, {"feed": None,
                                                                                "feed_pressure": 0.3e6}),
              "feed hole at 0.3 MPa instead of the groove, diesel": ("rozhdestvensky-4", 1,
                                                                     {"feed": None, "feed_pressure": 0.3e6})}
    tilt_jobs = {}
    for name in ENGINES:
        case = cases[name]
        c_rot = compliance(name)
        for b in TILT_BEARINGS:
            for scale in TILT_COMPLIANCE_SCALE:
                tilt_jobs[(name, b, scale, True)] = {"tilt": case.tilt[b], "tilt_compliance": scale * c_rot[b]}
        # the reference without the tilt's own squeeze, to show what it does
        tilt_jobs[(name, 1, 10.0, False)] = {"tilt": case.tilt[1], "tilt_compliance": 10.0 * c_rot[1],
                                             "tilt_squeeze": False}
    steady_jobs = [(name, eps, d, share) for name in ENGINES for eps in TILT_ECCENTRICITY for d in TILT_DIRECTION
                   for share in TILT_SHARE]
    all_jobs = jobs + list(checks.values()) + [(n, b, o) for (n, b, _, _), o in tilt_jobs.items()]
    # the cheap tiers are timed first, alone on the machine; then the slow runs in worker processes
    # (spawned: numba's OpenMP threads do not survive a fork)
    timing = steady_timing(cases["iso-example"])
    out, seconds = cheap_tiers(cases)
    tilt_cheap = {}
    for (name, b, scale, squeeze), options in tilt_jobs.items():
        case = cases[name]
        if squeeze:
            tilt_cheap[(name, b, scale)] = summary(orbit(case.loads[b], case.crank_angle, **case.geometry(b),
                                                         method="mobility-finite", **options))
    tilt_seconds = tilt_cost(cases)
    with ProcessPoolExecutor(args.workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        results = list(pool.map(functools.partial(_slow_tier, cache=args.cache), all_jobs))
        steady_tilt = list(pool.map(steady_tilt_case, steady_jobs))
    n_main = sum(n_bearings.values())
    ref_runs, ss_runs, qs_runs = results[:n_main], results[n_main:2 * n_main], results[2 * n_main:3 * n_main]
    check_runs = dict(zip(checks, results[3 * n_main:3 * n_main + len(checks)]))
    tilt_ref = dict(zip(tilt_jobs, results[3 * n_main + len(checks):]))
    steady_tilt = dict(zip(steady_jobs, steady_tilt))

    def stack(runs):
        return {k: np.array([r[0][k] for r in runs]).reshape(-1) for k in runs[0][0]}

    reference = stack(ref_runs)
    out["reynolds-transient, Swift-Stieber"] = stack(ss_runs)
    out["reynolds"] = stack(qs_runs)
    seconds["reynolds"] = float(np.mean([r[1] for r in qs_runs]))
    seconds["reynolds-transient"] = float(np.mean([r[1] for r in ref_runs]))
    seconds["reynolds-transient, Swift-Stieber"] = float(np.mean([r[1] for r in ss_runs]))
    out["reynolds-transient"] = reference
    write_errors(out, seconds, {"": reference, '."swift-stieber"': out["reynolds-transient, Swift-Stieber"]})

    errors = tier_errors()
    default = cheapest_tier(DEFAULT_ERROR)
    steady_cases = errors_by_case()
    lines = [
        "# Film tiers: speed against error",
        "",
        f"{environment()}.",
        "",
        "## Verdict",
        "",
        verdict(out, seconds, reference),
        "",
        "## Steady tiers against the Reynolds tier",
        "",
        f"Largest relative error of h_min over L/D {list(ERROR_GRID['length_over_diameter'])} and eccentricity "
        f"{list(ERROR_GRID['eccentricity'])} (between the nodes of the finite tier's table), and the time of one "
        "bearing over a 720-step cycle (quasi-static orbit; the Reynolds tier timed on a dozen angles and scaled).",
        "",
        "| tier | worst h_min error | time per bearing-cycle [s] | ratio to short |",
        "|---|---|---|---|",
        *(f"| {m} | {100 * errors[m]:.2f} % | {timing[m]:.4g} | {timing[m] / timing['short']:.3g} |" for m in BY_COST),
        "",
        f"Default steady tier: the cheapest within {100 * DEFAULT_ERROR:.0f} % → **{default}** "
        "(`Study(film_method='auto', film_error=...)` picks it the same way).",
        "",
        "Per case (h_min error of each tier against Reynolds):",
        "",
        "| L/D | eccentricity | short | finite |",
        "|---|---|---|---|",
        *(f"| {ld} | {eps} | {100 * s:+.1f} % | {100 * f:+.3f} % |" for ld, eps, s, f in steady_cases),
        "",
        "## Cycle tiers against the transient reference",
        "",
        "Every main bearing of "
        + " and ".join(f"`{n}` ({1e3 * c.diameter:.0f} mm × {1e3 * c.length:.0f} mm, {1e6 * c.clearance:.0f} µm "
                       f"diametral clearance, {c.speed:.0f} rad/s)" for n, c in cases.items())
        + " (each at the middle of its engine file's clearance window; reports/rozhdestvensky_table2.md runs the "
        "heavy diesel at the paper's clearance)"
        + " over a 720-step cycle: loads from the crankshaft on the bearing "
        "law, effective viscosity from the study chain's heat balance "
        f"({', '.join(f'{1e3 * cases[n].viscosity.mean():.1f} mPa s' for n in ENGINES)}). Reference: "
        "`reynolds-transient` (finite-difference Reynolds equation with squeeze, Elrod-Adams mass-conserving "
        "cavitation, the engine's feed groove at its supply pressure as a fixed-pressure boundary, massless journal "
        "integrated by BDF2 to a "
        "periodic orbit). Relative error of each tier per bearing: mean and worst over the "
        f"{n_main} bearings; time of one bearing's cycle on one core (the cheap tiers best of 5, alone; the "
        "Reynolds tiers once each, two at a time on the two cores).",
        "",
        "| tier | time per bearing-cycle [s] | ratio to mobility | cycle-min h_min: mean / worst | "
        "cycle-mean h_min: mean / worst | sup p_max: worst | p*_max: worst | N*: worst |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for tier in (*CHEAP_TIERS, "reynolds", "reynolds-transient, Swift-Stieber"):
        e = {q: relative(out[tier][q], reference[q]) for q in QUANTITIES}
        t = seconds[tier]
        lines.append(f"| {tier} | {t:.3g} | {t / seconds['mobility']:.3g} | "
                     f"{100 * np.mean(np.abs(e['h_min'])):.1f} % / {100 * e['h_min'][np.argmax(np.abs(e['h_min']))]:+.1f} % | "
                     f"{100 * np.mean(np.abs(e['h_min_mean'])):.1f} % / "
                     f"{100 * e['h_min_mean'][np.argmax(np.abs(e['h_min_mean']))]:+.1f} % | "
                     + " | ".join(f"{100 * e[q][np.argmax(np.abs(e[q]))]:+.1f} %" for q in ("p_max", "p_max_mean",
                                                                                            "friction_power"))
                     + " |")
    lines += [
        f"| reynolds-transient (reference) | {seconds['reynolds-transient']:.3g} | "
        f"{seconds['reynolds-transient'] / seconds['mobility']:.3g} | — | — | — | — | — |",
        "",
        "Per bearing, cycle minimum / cycle mean of the minimum film [µm]:",
        "",
        "| engine | bearing | " + " | ".join(("reference", *CHEAP_TIERS)) + " |",
        "|---|---|" + "---|" * (1 + len(CHEAP_TIERS)),
    ]
    k = 0
    for name in ENGINES:
        for b in range(n_bearings[name]):
            row = [reference] + [out[t] for t in CHEAP_TIERS]
            lines.append(f"| {name} | {b + 1} | " + " | ".join(f"{1e6 * r['h_min'][k]:.2f} / {1e6 * r['h_min_mean'][k]:.2f}"
                                                              for r in row) + " |")
            k += 1
    statuses = {t: np.bincount(out[t]["status"].astype(int), minlength=len(STATUS)).tolist()
                for t in ("mobility", "mobility-finite")}
    statuses["reference"] = np.bincount(reference["status"].astype(int), minlength=len(STATUS)).tolist()
    lines += [
        "",
        "Orbit status (" + ", ".join(STATUS) + "): " + "; ".join(f"{t}: {list(v)}" for t, v in statuses.items()) + ".",
        "",
        "### The reference's own error",
        "",
        "Iso-example bearing 2 with the reference's options changed one at a time (relative change of the "
        "cycle minimum / cycle mean of the minimum film and of the peak pressure):",
        "",
        "| change | cycle-min h_min | cycle-mean h_min | sup p_max | time [s] |",
        "|---|---|---|---|---|",
    ]
    base = {q: reference[q][1] for q in QUANTITIES}
    diesel_base = {q: reference[q][n_bearings["iso-example"] + 1] for q in QUANTITIES}
    for label, (res, secs) in check_runs.items():
        ref = diesel_base if "diesel" in label else base
        lines.append(f"| {label} | {100 * relative(res['h_min'][0], ref['h_min']):+.2f} % | "
                     f"{100 * relative(res['h_min_mean'][0], ref['h_min_mean']):+.2f} % | "
                     f"{100 * relative(res['p_max'][0], ref['p_max']):+.2f} % | {secs:.0f} |")
    lines += [
        f"| Swift-Stieber cavitation instead of mass-conserving | "
        f"{100 * relative(out['reynolds-transient, Swift-Stieber']['h_min'][1], base['h_min']):+.2f} % | "
        f"{100 * relative(out['reynolds-transient, Swift-Stieber']['h_min_mean'][1], base['h_min_mean']):+.2f} % | "
        f"{100 * relative(out['reynolds-transient, Swift-Stieber']['p_max'][1], base['p_max']):+.2f} % | — |",
        "",
        "## Journal tilt",
        "",
        tilt_summary(steady_tilt, tilt_ref, tilt_cheap, tilt_seconds),
        "",
        "### The film's force and moment on a tilted journal",
        "",
        "A steady journal (rotation only) of each engine's bearing at the eccentricity given, tilted in the "
        "direction given from its line of centres so that the edge takes the share given of the room it has "
        "there. Reference: the finite-difference Reynolds equation with the tilted film and the Swift-Stieber "
        "condition (`stackup.film.reynolds.tilted_field`, 360 x 41); the cheap tier: the short-bearing film per "
        "line, closed forms over the width (`stackup.film.tilt.film_moment`, `short`), and that force and moment "
        "scaled and turned by the `mobility-finite` tier's finite-length correction (`finite`). Relative error "
        "of the force and of the moment; the moment's error also as a share of the force times the length "
        "(the error of its arm).",
        "",
        "| engine | eccentricity | direction [deg] | share of the room | reference: force / moment | short: force "
        "/ moment / arm | finite: force / moment / arm |",
        "|---|---|---|---|---|---|---|",
    ]
    for (name, eps, direction, share), out in steady_tilt.items():
        f_ref, m_ref = out["reynolds"]
        row = f"| {name} | {eps} | {direction:.0f} | {share} | {np.linalg.norm(f_ref):.3g} / {np.linalg.norm(m_ref):.3g} |"
        for method in ("short", "finite"):
            f, m = out[method]
            row += (f" {100 * (np.linalg.norm(f) / np.linalg.norm(f_ref) - 1):+.0f} % / "
                    f"{100 * (np.linalg.norm(m) / np.linalg.norm(m_ref) - 1):+.0f} % / "
                    f"{100 * np.linalg.norm(m - m_ref) / np.linalg.norm(f_ref):.1f} % |")
        lines.append(row)
    lines += [
        "",
        "### The tilt over the cycle",
        "",
        "Main bearings 1-3 of each engine (4 and 5 mirror 2 and 1) at the middle of the clearance window, the "
        "journal's free tilt the crankshaft's slope at the support (`stackup.crank.support_slopes`), the "
        "compliance it meets the crankshaft's own at the support (`stackup.crank.support_compliance`, x 1) or ten "
        "times that (x 10: a support that turns more easily). Reference: `reynolds-transient` with the tilt as two "
        "more unknowns of each step (force and moment balanced, the tilt's squeeze in the film; an edge that would "
        "pass the wall held on it). Cheap: `mobility-finite` with the tilt marched over the cycle on its mid-plane "
        "orbit (the film's moment with the tilt's own squeeze, `stackup.film.tilt.march_tilt`). Films in um: the "
        "cycle minimum of the mid-plane film, the "
        "cycle minimum and mean of the edge film, the share of the cycle with an edge at the limit "
        f"({1e6 * (1 - ECCENTRICITY_LIMIT) * cases['iso-example'].clearance / 2:.3f} / "
        f"{1e6 * (1 - ECCENTRICITY_LIMIT) * cases['rozhdestvensky-4'].clearance / 2:.3f} um), the largest tilt "
        "in the film (mrad; the free slope's in brackets).",
        "",
        "| engine | bearing | compliance | reference: mid / edge min / edge mean / at limit / tilt | cheap: mid / "
        "edge min / edge mean / at limit / tilt | edge mean error |",
        "|---|---|---|---|---|---|",
    ]
    for (name, b, scale, squeeze), (res, _) in tilt_ref.items():
        if not squeeze:
            continue
        cheap = tilt_cheap[(name, b, scale)]
        free = np.linalg.norm(cases[name].tilt[b], axis=-1).max()

        def cells(r):
            return (f"{1e6 * r['h_min'][0]:.2f} / {1e6 * r['h_min_edge'][0]:.3f} / {1e6 * r['h_edge_mean'][0]:.2f} / "
                    f"{100 * r['contact_share'][0]:.0f} % / {1e3 * r['tilt_max'][0]:.2f}")
        lines.append(f"| {name} | {b + 1} | x {scale:g} | {cells(res)} | {cells(cheap)} ({1e3 * free:.2f}) | "
                     f"{100 * relative(cheap['h_edge_mean'][0], res['h_edge_mean'][0]):+.0f} % |")
    lines += [
        "",
        "The tilt's own squeeze (bearing 2, compliance x 10): the reference with the earlier steps' film content "
        "taken at the current tilt (the cheap tiers' simplification) against the reference:",
        "",
        "| engine | edge min / edge mean / at limit, with the tilt's squeeze | without | change of the edge mean |",
        "|---|---|---|---|",
    ]
    for name in ENGINES:
        with_squeeze = tilt_ref[(name, 1, 10.0, True)][0]
        without = tilt_ref[(name, 1, 10.0, False)][0]

        def short_cells(r):
            return (f"{1e6 * r['h_min_edge'][0]:.3f} / {1e6 * r['h_edge_mean'][0]:.2f} / "
                    f"{100 * r['contact_share'][0]:.0f} %")
        lines.append(f"| {name} | {short_cells(with_squeeze)} | {short_cells(without)} | "
                     f"{100 * relative(without['h_edge_mean'][0], with_squeeze['h_edge_mean'][0]):+.1f} % |")
    lines += [
        "",
        f"Cost: `mobility-finite` {1e3 * tilt_seconds['mobility-finite']:.2f} ms per bearing-cycle on one core, "
        f"{1e3 * tilt_seconds['with tilt']:.2f} ms with the tilt marched over the cycle (+"
        f"{1e3 * (tilt_seconds['with tilt'] - tilt_seconds['mobility-finite']):.2f} ms; the whole chain against "
        "the crankshaft cycle: reports/bench_chain.md).",
    ]
    lines += [
        "",
        cheapest_cycle_text() + " (`stackup.film.orbit.cheapest_cycle_tier`, from "
        "`stackup/data/film_cycle_errors.toml`, which this study writes).",
        "",
        "Reproduce: `python studies/film_speed_vs_error.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
