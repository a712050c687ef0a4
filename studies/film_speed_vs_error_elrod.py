"""The ``elrod-coarse`` cycle tier: time per bearing-cycle against its film error to the transient reference.

A companion of ``studies/film_speed_vs_error.py`` (whose slow runs it shares,
``--cache``): main bearings 1-3 of the same two engines (4 and 5 mirror 2 and 1)
over the same 720-step cycle, against ``reynolds-transient`` (mass-conserving,
the engine's groove), run in worker processes; in this
process, in the same run after them, ``mobility-finite`` and ``elrod-coarse`` on
several grids and step tolerances, each timed best of 3 on one core. Writes the
section "The mass-conserving coarse tier" of ``reports/film_speed_vs_error.md``
(replacing the section of an earlier run, the rest of the report untouched) and
the tier's entry of ``stackup/data/film_cycle_errors.toml``.

    python studies/film_speed_vs_error_elrod.py [--workers 2] [--cache DIR]
"""

from __future__ import annotations

import argparse
import dataclasses
import functools
import multiprocessing
import os
from concurrent.futures import ProcessPoolExecutor
from fractions import Fraction
from pathlib import Path

import numba
import numpy as np
from _common import best_time, environment
from _film_cases import engine_case
from film_speed_vs_error import ENGINES, ERRORS_FILE, QUANTITIES, _job_key, _slow_tier, relative, summary

from stackup.film import registry
from stackup.film.elrod import LARGEST_STEP, N_LAND, N_THETA, STEP_TOLERANCE
from stackup.film.orbit import STATUS, cycle_tier_errors, orbit
from stackup.film.transient import N_Z as REFERENCE_N_Z

TARGET_ERROR = 0.05
TARGET_SECONDS = 0.050
#: The tier converged: a fine grid and short steps; and the next coarser, to state how far the converged one moves.
CONVERGED = dict(n_theta=144, n_land=6, step_tolerance=0.01, largest_step=3.0)
FINER = dict(n_theta=96, n_land=4, step_tolerance=0.02, largest_step=6.0)
#: Grids and step tolerances measured; the tier's defaults first.
VARIANTS = (dict(), dict(n_theta=36), dict(n_theta=72), dict(n_land=4), dict(step_tolerance=0.02, largest_step=8.0),
            dict(step_tolerance=0.1, largest_step=20.0), dict(groove="reference grid"), FINER, CONVERGED,
            dict(CONVERGED, groove="reference grid"))
#: Main bearings run (4 and 5 of these engines mirror 2 and 1: the same cycle statistics, as the reference's table
#: above shows).
BEARINGS = (0, 1, 2)
SECTION = "## The mass-conserving coarse tier (elrod-coarse)"
REPORT = Path(__file__).resolve().parents[1] / "reports" / "film_speed_vs_error.md"


def label(options):
    merged = dict(n_theta=N_THETA, n_land=N_LAND, step_tolerance=STEP_TOLERANCE, largest_step=LARGEST_STEP) | options
    text = (f"{merged['n_theta']} x {merged['n_land']} per land, step tolerance {merged['step_tolerance']:g}, "
            f"largest step {merged['largest_step']:g} deg")
    if "groove" in options:
        text += ", groove as the reference's grid holds it"
    return text


def groove_on_the_reference_grid(case):
    """The engine's feed with the groove as wide as the reference's axial grid holds it: the reference holds its
    N_Z nodes (even over the length) at the supply pressure where |z| <= half the groove's width, so its groove
    ends at the last such node, not at the groove's edge."""
    z = np.linspace(-case.length / 2, case.length / 2, REFERENCE_N_Z)
    held = np.abs(z)[np.abs(z) <= case.feed.groove_width / 2 + 1e-12 * case.length]
    return dataclasses.replace(case.feed, groove_width=2 * held.max())


def cheap_runs(cases, bearings):
    """Summaries and one-core seconds per bearing-cycle of mobility-finite and each elrod-coarse variant."""
    numba.set_num_threads(1)
    out, seconds = {}, {}
    tiers = [("mobility-finite", "mobility-finite", {})] + [(label(v), "elrod-coarse", v) for v in VARIANTS]
    for key, method, options in tiers:
        runs, times = [], []
        for name, b in bearings:
            case = cases[name]
            extra = {}
            if method == "elrod-coarse":
                extra = dict(options, feed=case.feed)
                if extra.pop("groove", None):
                    extra["feed"] = groove_on_the_reference_grid(case)

            def call(case=case, b=b, extra=extra, method=method):
                return orbit(case.loads[b], case.crank_angle, **case.geometry(b), method=method, **extra)
            times.append(best_time(call, 3))
            runs.append(summary(call()))
        out[key] = {k: np.concatenate([r[k] for r in runs]) for k in runs[0]}
        seconds[key] = float(np.mean(times))
        print(f"{key}: {1e3 * seconds[key]:.1f} ms", flush=True)
    return out, seconds


def write_errors(errors, seconds):
    """The tier's entry of film_cycle_errors.toml (replacing an earlier one); not measured against the
    Swift-Stieber run, so it has no ``swift-stieber`` table."""
    text = ERRORS_FILE.read_text()
    row = registry.tier("elrod-coarse").error_row  # the row the tier's record reads
    head = f'[tiers."{row}"]'
    if head in text:
        start = text.index(head)
        rest = text[start:].split("\n[tiers.")
        kept = [r for r in rest[1:] if not r.startswith(f'"{row}"')]
        text = text[:start] + "\n[tiers.".join([""] + kept).lstrip("\n")
    block = [head, f"seconds = {seconds:.6g}", *(f"{q} = {errors[q]:.6g}" for q in QUANTITIES), ""]
    ERRORS_FILE.write_text(text.rstrip("\n") + "\n\n" + "\n".join(block))
    cycle_tier_errors.cache_clear()


def section(cases, bearings, out, seconds, reference, ref_seconds, cached=False):
    """The report's section, as lines."""
    default = label({})
    snapped = label(dict(groove="reference grid"))
    worst = {}
    for key in out:
        e = {q: relative(out[key][q], reference[q]) for q in QUANTITIES}
        worst[key] = {q: e[q][np.argmax(np.abs(e[q]))] for q in QUANTITIES}
    d = worst[default]
    within = abs(d["h_min"]) <= TARGET_ERROR and abs(d["h_min_mean"]) <= TARGET_ERROR
    fast = seconds[default] <= TARGET_SECONDS
    lines = [
        SECTION, "",
        f"{environment()}; written by `studies/film_speed_vs_error_elrod.py`.", "",
        "The transient Reynolds equation with the reference's mass-conserving (Elrod) cavitation, squeeze and "
        "feed groove, on a coarse grid with a Newton solve per adaptive BDF2 step (`stackup.film.elrod`), on the "
        f"{len(bearings)} main bearings of "
        + " and ".join(f"`{n}`" for n in cases)
        + ", against the reference of the table above ("
        + ("read back from an earlier run's cache, `--cache`" if cached else "recomputed in this run") + "). "
        f"Target: within {100 * TARGET_ERROR:.0f} % of the reference on the cycle minimum and cycle mean of the "
        f"minimum film at <= {1e3 * TARGET_SECONDS:.0f} ms per bearing-cycle. With its defaults ({default}) "
        f"the tier is within {100 * abs(d['h_min']):.1f} % (cycle minimum) and {100 * abs(d['h_min_mean']):.1f} % "
        f"(cycle mean) of the reference: the accuracy target is {'met' if within else 'missed'}; it costs "
        f"{1e3 * seconds[default]:.0f} ms per bearing-cycle on one core, "
        f"{seconds[default] / seconds['mobility-finite']:,.0f} times `mobility-finite` and "
        f"{ref_seconds / seconds[default]:,.0f} times less than the reference (its time from its own run, "
        "possibly under another load): the speed target is "
        f"{'met' if fast else 'missed'} on this machine ({load_note()}). Against the same reference `mobility-finite` "
        f"is off by {100 * abs(worst_of(out['mobility-finite'], reference, 'h_min')):.1f} % and "
        f"{100 * abs(worst_of(out['mobility-finite'], reference, 'h_min_mean')):.1f} %. "
        + groove_note(cases, bearings, out, reference, default, snapped, ref_seconds),
        "",
        "| grid | time per bearing-cycle [ms] | ratio to mobility-finite | cycle-min h_min: worst | "
        "cycle-mean h_min: worst | sup p_max: worst | p*_max: worst | N*: worst | status |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for key in out:
        w = worst[key]
        counts = np.bincount(out[key]["status"].astype(int), minlength=len(STATUS))
        lines.append(f"| {key} | {1e3 * seconds[key]:.1f} | {seconds[key] / seconds['mobility-finite']:.3g} | "
                     + " | ".join(f"{100 * w[q]:+.1f} %" for q in QUANTITIES) + f" | {counts.tolist()} |")
    lines += ["", f"| reynolds-transient (reference) | {1e3 * ref_seconds:.0f} | "
              f"{ref_seconds / seconds['mobility-finite']:.3g} | — | — | — | — | — | |", "",
              "Per bearing, cycle minimum / cycle mean of the minimum film [µm] (status counts: "
              + ", ".join(STATUS) + "):", "",
              "| engine | bearing | reference | mobility-finite | elrod-coarse |", "|---|---|---|---|---|"]
    for k, (name, b) in enumerate(bearings):
        lines.append(f"| {name} | {b + 1} | " + " | ".join(
            f"{1e6 * r['h_min'][k]:.2f} / {1e6 * r['h_min_mean'][k]:.2f}"
            for r in (reference, out["mobility-finite"], out[default])) + " |")
    lines += ["", "Reproduce: `python studies/film_speed_vs_error_elrod.py`.", ""]
    return lines


#: Load average above the timing process's own core beyond which the machine counts as shared while timed.
OTHER_LOAD = 0.5


def load_note():
    """The machine's load while the cheap tiers were timed (the cores are shared; the timing itself keeps one
    busy), and what it means for the times."""
    one, five, _ = os.getloadavg()
    note = f"load average {one:.1f} (1 min) and {five:.1f} (5 min) on {os.cpu_count()} cores while timed, this run's "
    if max(one, five) - 1.0 <= OTHER_LOAD:
        return note + "one core included: the machine was otherwise idle"
    return (note + "one core included: other work shared the machine, so the times, and the ratios between the "
            "variants below, are uncertain; rerun on an idle one before reading the speed against the target")


def converged_note(bearings, out, reference, default):
    """The tier against its own converged solution on the engine's groove, and that solution on the reference's
    groove against the reference (which tells whether the converged solution is the reference's problem solved
    finely)."""
    fine, fine_snapped = label(CONVERGED), label(dict(CONVERGED, groove="reference grid"))
    check = {q: relative(out[fine_snapped][q], reference[q]) for q in ("h_min", "h_min_mean")}
    error = {q: relative(out[default][q], out[fine][q]) for q in ("h_min", "h_min_mean")}
    within = all(np.max(np.abs(e)) <= TARGET_ERROR for e in error.values())
    moved = max(np.max(np.abs(relative(out[label(FINER)][q], out[fine][q]))) for q in ("h_min", "h_min_mean"))
    return (f"Converged, the tier itself ({fine}; its cycle minimum and mean within {100 * moved:.1f} % of the next "
            f"coarser, {label(FINER)}) on the reference's groove (the only one an independent check exists for) "
            "agrees with the independent "
            f"reference within {100 * np.max(np.abs(check['h_min'])):.1f} % (cycle minimum) and "
            f"{100 * np.max(np.abs(check['h_min_mean'])):.1f} % (cycle mean) on every bearing; on the engine's "
            "groove it is the fine solution the reference's grid cannot give. Against it the tier's defaults are "
            f"within {100 * np.max(np.abs(error['h_min'])):.1f} % (cycle minimum) and "
            f"{100 * np.max(np.abs(error['h_min_mean'])):.1f} % (cycle mean) "
            f"({'; '.join(f'{n} {b + 1}: {100 * v:+.1f} / {100 * w:+.1f} %' for (n, b), v, w in zip(bearings, error['h_min'], error['h_min_mean']))}): "
            f"the accuracy target is {'met' if within else 'missed'} against the converged solution of the "
            "engine's own groove.")


def groove_note(cases, bearings, out, reference, default, snapped, ref_seconds):
    """What the largest cycle-minimum gap is made of: the reference's groove on its axial grid."""
    e = relative(out[default]["h_min"], reference["h_min"])
    k = int(np.argmax(np.abs(e)))
    s = relative(out[snapped]["h_min"], reference["h_min"])
    m = relative(out[snapped]["h_min_mean"], reference["h_min_mean"])
    name, b = bearings[k]
    return (f"The largest gap, {100 * e[k]:+.1f} % on the cycle minimum at `{name}` bearing {b + 1}, is the "
            "reference's: there the journal's thinnest film lies over the feed groove (the upper shell), and the "
            f"reference's {REFERENCE_N_Z} axial nodes, evenly spaced, hold the supply pressure only up to the last "
            "node inside the groove, so its groove is narrower than the engine's and its lands carry more. Given "
            f"the groove as the reference's grid holds it, this tier is within {100 * np.max(np.abs(s)):.1f} % "
            f"(cycle minimum) and {100 * np.max(np.abs(m)):.1f} % (cycle mean) of the reference on every bearing "
            f"({'; '.join(f'{n} {bb + 1}: {100 * v:+.1f} %' for (n, bb), v in zip(bearings, s))}), and the "
            "reference's error table above, which refined its grid at a bearing whose thinnest film is away from "
            f"the groove, does not show it (a reference with nodes on the groove's edges needs "
            f"{edge_nodes(cases)}, against the {REFERENCE_N_Z} whose run took {ref_seconds / 60:.1f} min per "
            "bearing-cycle here; not run). " + converged_note(bearings, out, reference, default))


def edge_nodes(cases):
    """Axial nodes, evenly spaced, that put one on each edge of each engine's groove (the fewest)."""
    counts = []
    for name, case in cases.items():
        # nodes at -L/2 + k L / N; an edge at +-w/2 with w/L = p/q (lowest terms) needs N (1 + p/q) / 2 whole
        ratio = case.feed.groove_width / case.length
        share = Fraction(ratio).limit_denominator(1000)
        if abs(float(share) - ratio) > 1e-9 * ratio:
            counts.append(f"over 2,000 axial nodes for `{name}`")
            continue
        spans = share.denominator * (1 if (share.numerator + share.denominator) % 2 == 0 else 2)
        counts.append(f"{spans + 1} axial nodes for `{name}`")
    return " and ".join(counts)


def worst_of(values, reference, q):
    e = relative(values[q], reference[q])
    return e[np.argmax(np.abs(e))]


def write_section(lines):
    """Replace the section in the report (or append it)."""
    text = REPORT.read_text()
    if SECTION in text:
        start = text.index(SECTION)
        after = text.find("\n## ", start + len(SECTION))
        text = text[:start] + (text[after + 1:] if after >= 0 else "")
    REPORT.write_text(text.rstrip("\n") + "\n\n" + "\n".join(lines))
    print(f"wrote {REPORT}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--cache", help="folder keeping each slow run (shared with film_speed_vs_error.py)")
    args = parser.parse_args(argv)
    if args.cache:
        Path(args.cache).mkdir(parents=True, exist_ok=True)
    cases = {name: engine_case(name) for name in ENGINES}
    bearings = [(name, b) for name in ENGINES for b in BEARINGS]
    jobs = [(name, b, {}) for name, b in bearings]
    cached = bool(args.cache) and all((Path(args.cache) / f"{_job_key(job)}.pkl").exists() for job in jobs)
    with ProcessPoolExecutor(args.workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        results = list(pool.map(functools.partial(_slow_tier, cache=args.cache), jobs))
    out, seconds = cheap_runs(cases, bearings)  # timed after the slow runs, alone in this process

    def stack(runs):
        return {k: np.array([r[0][k] for r in runs]).reshape(-1) for k in runs[0][0]}

    reference = stack(results)
    ref_seconds = float(np.mean([r[1] for r in results]))
    default = label({})
    write_errors({q: float(np.max(np.abs(relative(out[default][q], reference[q])))) for q in QUANTITIES},
                 seconds[default])
    write_section(section(cases, bearings, out, seconds, reference, ref_seconds, cached))


if __name__ == "__main__":
    main()
