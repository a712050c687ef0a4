"""Generate the `finite` film tier's correction table from the Reynolds reference tier.

For each L/D and eccentricity on a grid, the ratio of the Reynolds (Swift-Stieber)
dimensionless load to Ocvirk's short-bearing load, and the attitude angle.
Writes stackup/data/film_finite_table.npz (shipped with the package).

    python studies/film_finite_table.py
"""

from pathlib import Path

import numpy as np

from stackup.film.reynolds import solve_field
from stackup.film.tiers import short_load_function

LENGTH_OVER_DIAMETER = np.array([0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.75, 1.0, 1.25, 1.5, 2.0])
# up to ECCENTRICITY_LIMIT (stackup.film.journal, 0.995): above it the tier holds the last node's correction and
# flags the film
ECCENTRICITY = np.concatenate([np.linspace(0.02, 0.9, 45), np.linspace(0.91, 0.98, 8), [0.985, 0.99, 0.9925, 0.995]])


def main():
    ratio = np.empty((LENGTH_OVER_DIAMETER.size, ECCENTRICITY.size))
    attitude = np.empty_like(ratio)
    for i, ld in enumerate(LENGTH_OVER_DIAMETER):
        start = None
        for j, eps in enumerate(ECCENTRICITY):
            field = solve_field(eps, 2 * ld, start=start)
            start = field.pressure
            ratio[i, j] = field.force / ((2 * ld) ** 3 / 4 * short_load_function(eps))
            attitude[i, j] = field.attitude
        print(f"L/D {ld}: load ratio {ratio[i].min():.3f}..{ratio[i].max():.3f}")
    out = Path(__file__).resolve().parent.parent / "stackup" / "data" / "film_finite_table.npz"
    np.savez(out, length_over_diameter=LENGTH_OVER_DIAMETER, eccentricity=ECCENTRICITY, load_ratio=ratio,
             attitude=attitude)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
