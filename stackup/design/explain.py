"""What the designer writes at the top of a designed scheme file: what it optimised, how, and what changed."""

from __future__ import annotations

import numpy as np

from .._version import __version__

PPM = 1e6


def describe(grades):
    """A dimension's grading in words, e.g. ``3 grades (6, 6, 6 um wide)``."""
    if grades.fine:
        return f"{len(grades.labels)} classes of {(grades.hi[0] - grades.lo[0]) * 1e6:.3g} um"
    if not grades.graded:
        return "ungraded"
    lo, hi = grades.bins()
    order = np.argsort(lo)
    widths = ", ".join(f"{(hi[k] - lo[k]) * 1e6:.3g}" for k in order)
    return f"{len(grades.labels)} grades ({widths} um wide)"


def notes(design, *, problem, start_scheme, chosen, seed, n_engines):
    """Lines explaining ``design`` (a :class:`~stackup.design.Design`), for the scheme file's comments."""
    s, p, w = design.scheme, problem, problem.weights
    window = p.window
    labels = [smp.label for smp in p.samples]
    step_h = (p.housing_grid.edges[1] - p.housing_grid.edges[0]) * 1e-3
    step_j = (p.journal_grid.edges[1] - p.journal_grid.edges[0]) * 1e-3
    lines = [
        f"Scheme designed by stackup {__version__} (stackup.design) for engine {p.engine.name!r},",
        f"operating-clearance window {window[0] * PPM:.4g}-{window[1] * PPM:.4g} um (press fit, housing swell and",
        "temperature by stackup.fit.press_fit with the engine's press-fit data).",
        "",
        "What was optimised: the housing and journal grade limits, the shell grade limits (hence the aims",
        "of shells made to order, the grade centres) and the shell pair of every cell, to minimise",
        f"  J = P_out + {w.scenario:g} * max over scenarios of P_out + {w.surplus:g} * surplus "
        f"+ {w.shortfall:g} * shortfall",
        "(P_out: share of bearings outside the window; surplus, shortfall: planned shells per bearing).",
        f"Design sample: {n_engines:,} engines, seed {seed}, the same random numbers for every candidate and",
        "scenario; shells made to order aimed for the demand each design makes.",
        f"Shell grades one at a time (1 to {len(design.levels)}): each number of grades also starts from the",
        "design with one grade fewer, a grade split in two (the nested start), and keeps the better of the",
        "search's result and the nested start; more grades are kept only where they lower J.",
        f"Scenarios: {', '.join(labels[1:]) or 'none'}"
        + (f"; left out (no effect on the clearance): {', '.join(p.skipped)}" if p.skipped else "") + ".",
        "Solvers (scipy): differential evolution and edge-by-edge line searches (housing, journal limits),",
        "differential evolution and Nelder-Mead (shell limits), HiGHS MILP (pairing).",
        "Narrowest grades (a part at, or a shell aimed at, a grade's centre is read into it with probability",
        f">= {p.sort_share:g}): housing {p.housing.min_bins * step_h:.3g} um, journal "
        f"{p.journal.min_bins * step_j:.3g} um, shell {p.min_width * PPM:.3g} um; limits on {step_h:.3g} um "
        f"(housing), {step_j:.3g} um (journal), {p.shell_step * PPM:.3g} um (shell) grids.",
        "",
        f"Result on the design sample: P_out {design.outside['nominal'] * PPM:.3g} ppm nominal"
        + "".join(f", {k} {v * PPM:.3g} ppm" for k, v in list(design.outside.items())[1:]) + ";",
        f"  J = {design.objective * PPM:.4g} ppm; planned surplus {design.surplus.sum():.3f} and shortfall "
        f"{design.shortfall.sum():.4f} shells per bearing; mean operating clearance "
        f"{design.mean_clearance * PPM:.2f} um.",
        *check_lines(design.check),
        *ladder_lines(design.levels),
        f"Started from {start_scheme.name} ("
        + ("the ISO 13778 scheme with the lowest J on the design sample, " if chosen else "")
        + f"J = {design.start_objective * PPM:.4g} ppm with its preferred pairs, supply terms included). What changed:",
        f"  housing: {describe(start_scheme.housing)} -> {describe(s.housing)}",
        f"  journal: {describe(start_scheme.journal)} -> {describe(s.journal)}",
        f"  shells: {describe(start_scheme.shell)} -> {describe(s.shell)}",
        f"  mean operating clearance {design.start_mean_clearance * PPM:.2f} -> {design.mean_clearance * PPM:.2f} um "
        f"(window middle {0.5 * (window[0] + window[1]) * PPM:.4g} um);",
        f"  P_out nominal {design.start_outside['nominal'] * PPM:.3g} -> {design.outside['nominal'] * PPM:.3g} ppm"
        + (f", worst scenario {_worst(design.start_outside) * PPM:.3g} -> {_worst(design.outside) * PPM:.3g} ppm."
           if len(design.outside) > 1 else "."),
        "",
        "Shell supply offered with these grades:",
    ]
    if design.aim_share is not None:
        lines.append("  made to order: share of each lot aimed at each grade centre "
                     + ", ".join(f"{lab} {q:.3f}" for lab, q in zip(s.shell.labels, design.aim_share))
                     + ";")
        lines.append("  (where the shells are aimed: each is then sorted into the grade its reading falls in, so the")
        lines.append("  shells per grade, made and fitted, differ from these shares; the planning section gives them);")
    lines += [f"  or one process sorted into these grades: centre it at {design.supply_mean * 1e3:.5f} mm, which "
              "minimises the shells left over plus 10 x the shells short",
              f"  (stackup.plan.optimise_supply): {design.supply_mean_objective:.0f} per 10 000 engines, against "
              f"{design.supply_centred_objective:.0f} with the process centred on the grades.",
              f"Design time {design.seconds:.1f} s, {design.evaluations:,} sets of housing and journal limits scored."]
    return lines


def _worst(outside):
    values = list(outside.values())[1:]
    return max(values) if values else np.nan


def check_lines(check):
    """The check sample's figures: share outside the window per scenario with its 95 % interval, and J."""
    lo, hi = check.objective_interval
    shares = [f"{label} {check.outside[label] * PPM:.3g} [{check.interval[label][0] * PPM:.3g}, "
              f"{check.interval[label][1] * PPM:.3g}] ppm" for label in check.outside]
    return [f"Independent check ({check.samples} samples of {check.engines:,} engines no decision of the designer saw; "
            "95 % intervals):",
            f"  P_out {'; '.join(shares)};",
            f"  J = {check.objective * PPM:.4g} [{lo * PPM:.4g}, {hi * PPM:.4g}] ppm."]


def ladder_lines(levels):
    """One line per number of shell grades: J on the design sample and the design kept, and a line for each
    number of grades that did no better than fewer."""
    lines = ["Ladder (J on the design sample, ppm, of the design kept at each number of shell grades):"]
    for step in levels:
        tried = ", ".join(f"{origin} {j * PPM:.4g}" for origin, j in step.candidates.items())
        lines.append(f"  {step.asked} shell grade{'s' if step.asked > 1 else ''}: {step.objective * PPM:.4g} "
                     f"({step.origin}; tried: {tried})")
    for step in levels:
        if step.grades < step.asked:
            lines.append(f"  No {step.asked}-grade design found did better than the {step.grades}-grade one: "
                         f"it is kept, with {step.grades} grades.")
    return lines
