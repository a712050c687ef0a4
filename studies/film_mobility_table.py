"""Finite-length correction of the short-bearing squeeze force: the table of the ``mobility-finite`` tier.

For each L/D, eccentricity and squeeze direction alpha (line-of-centres frame),
the finite-length Reynolds equation of the squeezed bearing
(:func:`stackup.film.reynolds.squeeze_field`) against the short bearing in
closed form: the log of the force ratio, the turn of the force and the log of
the peak-pressure ratio. Only alpha in [0, pi] is solved (the film is
symmetric about the line of centres). Then the table's interpolation error at
points between its nodes, and the solver's grid error.

    python studies/film_mobility_table.py [--workers 2]

Writes stackup/data/film_mobility_table.npz and reports/film_mobility_table.md.
"""

from __future__ import annotations

import argparse
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
from _common import environment, write_report

from stackup._kernels import mobility as kernel
from stackup.film import orbit, reynolds

LENGTH_OVER_DIAMETER = (0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7, 0.85, 1.0)
ECCENTRICITY = (0.0, 0.2, 0.4, 0.55, 0.7, 0.8, 0.87, 0.92, 0.95, 0.97, 0.98, 0.987, 0.992, 0.995)
N_ALPHA = 37
OUT = Path(__file__).resolve().parents[1] / "stackup" / "data" / "film_mobility_table.npz"


def short(eps, alpha, length_over_radius):
    """Short-bearing force (2,) and peak pressure in the units of squeeze_field."""
    rr, rt, tt = kernel.short_matrix(eps, alpha)
    force = length_over_radius**3 * np.array([rr * np.cos(alpha) + rt * np.sin(alpha),
                                              rt * np.cos(alpha) + tt * np.sin(alpha)])
    return force, 1.5 * length_over_radius**2 * kernel.peak_factor(eps, alpha, 0.0)[0]


def correction(eps, alpha, ld, **grid):
    """(log force ratio, turn, log peak ratio) of the Reynolds tier against the short bearing."""
    field = reynolds.squeeze_field(eps, alpha, 2 * ld, **grid)
    f_short, p_short = short(eps, alpha, 2 * ld)
    turn = np.angle(np.exp(1j * (np.arctan2(field.force[1], field.force[0]) - np.arctan2(f_short[1], f_short[0]))))
    return np.log(np.linalg.norm(field.force) / np.linalg.norm(f_short)), turn, np.log(field.peak / p_short)


def _row(args):
    ld, eps = args
    return [correction(eps, a, ld) for a in np.linspace(0.0, np.pi, N_ALPHA)]


def lookup(table, ld_nodes, stretched, ld, eps, alpha):
    i, t = kernel._locate(ld_nodes, ld)
    sub = (1 - t) * table[i] + t * table[i + 1]
    ratio, turn, _, _, peak = kernel.table_lookup(sub, stretched, eps, alpha)
    return ratio, turn, peak


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default="reports/film_mobility_table.md")
    parser.add_argument("--errors-only", action="store_true", help="measure the stored table, do not rebuild it")
    args = parser.parse_args(argv)

    if not args.errors_only:
        cases = [(ld, eps) for ld in LENGTH_OVER_DIAMETER for eps in ECCENTRICITY]
        with ProcessPoolExecutor(args.workers) as pool:
            rows = list(pool.map(_row, cases, chunksize=4))
        table = np.array(rows).reshape(len(LENGTH_OVER_DIAMETER), len(ECCENTRICITY), N_ALPHA, 3)
        np.savez_compressed(OUT, length_over_diameter=np.array(LENGTH_OVER_DIAMETER),
                            eccentricity=np.array(ECCENTRICITY), alpha=np.linspace(0.0, np.pi, N_ALPHA),
                            log_force_ratio=table[..., 0], turn=table[..., 1], log_peak_ratio=table[..., 2],
                            n_theta=reynolds.N_THETA_SQUEEZE, n_z=reynolds.N_Z_SQUEEZE)
        print(f"wrote {OUT}")
    orbit.mobility_table.cache_clear()
    ld_nodes, stretched, table = orbit.mobility_table()

    # interpolation error half-way between the nodes in every direction
    rng = np.random.default_rng(1)
    eps_nodes = np.array(ECCENTRICITY)
    errors = []
    for _ in range(150):
        i = rng.integers(len(ld_nodes) - 1)
        j = rng.integers(len(eps_nodes) - 1)
        ld = 0.5 * (ld_nodes[i] + ld_nodes[i + 1])
        eps = 0.5 * (eps_nodes[j] + eps_nodes[j + 1])
        alpha = (rng.integers(N_ALPHA - 1) + 0.5) * np.pi / (N_ALPHA - 1) * rng.choice([-1, 1])
        want = correction(eps, alpha, ld)
        got = lookup(table, ld_nodes, stretched, ld, eps, alpha)
        errors.append((ld, eps, alpha, np.expm1(got[0] - want[0]), got[1] - want[1], np.expm1(got[2] - want[2])))
    errors = np.array(errors)
    grid_rows = []
    for eps in (0.8, 0.95, 0.995):
        for alpha in (-np.pi / 2, 0.0, 2.5):
            coarse = correction(eps, alpha, 0.4)
            fine = correction(eps, alpha, 0.4, n_theta=2 * reynolds.N_THETA_SQUEEZE, n_z=2 * reynolds.N_Z_SQUEEZE - 1)
            grid_rows.append((eps, alpha, np.expm1(coarse[0] - fine[0]), np.expm1(coarse[2] - fine[2])))

    def worst(col):
        k = np.argmax(np.abs(errors[:, col]))
        return errors[k, col], errors[k, :3]

    lines = [
        "# Finite-length squeeze-film table of the `mobility-finite` tier",
        "",
        f"{environment()}.",
        "",
        "The finite-length Reynolds equation of a squeezed bearing (Reynolds cavitation condition, no groove, "
        f"{reynolds.N_THETA_SQUEEZE} angles finest at the thinnest film × {reynolds.N_Z_SQUEEZE} axial nodes on half "
        "the width) against the short bearing in closed form, on "
        f"L/D {list(LENGTH_OVER_DIAMETER)}, eccentricity {list(ECCENTRICITY)} and {N_ALPHA} squeeze directions "
        "over [0, 180°]. Rotation and squeeze act together as one squeeze velocity (Booker), so this one table "
        "covers every dynamic state.",
        "",
        "## Interpolation error between the nodes",
        "",
        "150 random points half-way between the nodes in L/D, eccentricity and direction (trilinear lookup, "
        "linear in L/D, -ln(1 - eps) and alpha, against a fresh solve):",
        "",
        "| quantity | mean abs error | worst error | at (L/D, eps, alpha) |",
        "|---|---|---|---|",
    ]
    for name, col, unit in (("force magnitude", 3, "%"), ("force direction", 4, "deg"), ("peak pressure", 5, "%")):
        value, where = worst(col)
        scale = 100.0 if unit == "%" else np.degrees(1.0)
        lines.append(f"| {name} | {scale * np.abs(errors[:, col]).mean():.2f} {unit} | {scale * value:+.2f} {unit} | "
                     f"({where[0]:.3f}, {where[1]:.4f}, {np.degrees(where[2]):.0f}°) |")
    lines += [
        "",
        "## Grid error of the solver (L/D 0.4, against twice the grid in both directions)",
        "",
        "| eccentricity | alpha [deg] | force | peak pressure |",
        "|---|---|---|---|",
        *(f"| {e} | {np.degrees(a):.0f} | {100 * f:+.2f} % | {100 * p:+.2f} % |" for e, a, f, p in grid_rows),
        "",
        "Reproduce: `python studies/film_mobility_table.py`.",
    ]
    print(write_report(args.out, lines).read_text())


if __name__ == "__main__":
    main()
