"""Press-fit design charts: shell stress, contact pressure and clearance against crush height.

Steel against aluminium housing, crush height 0-0.15 mm, housing OD/ID
1.25-2.0, operating temperature 20-150 degC, shell wall 1.6 against 3.0 mm;
bore 50.2 mm, length 15 mm. The journal is sized for 50 um nominal clearance
(46.95 mm, about 47 mm, with the 1.6 mm wall; 44.15 mm with the 3.0 mm wall).
Crush is checked in a block of the bore's size at 100 MPa on the plain steel
shell's section. Design limits: Kopeliovich's ranges, contact pressure at
least 8-10 MPa and compression at most 400-500 MPa (dotted: each end).

    python studies/press_fit_design_charts.py

Writes reports/press_fit_design_charts.md and its PNG figures.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from stackup.fit import press_fit  # noqa: E402

BORE = 50.2e-3
LENGTH = 15e-3
CRUSH = np.linspace(0.0, 0.15e-3, 151)
WALLS = (1.6e-3, 3.0e-3)
NOMINAL_CLEARANCE = 50e-6
OUT = Path("reports/press_fit_design_charts")
#: Kopeliovich, *Crush height of engine bearings*, sec. 2: least contact pressure and largest compression [Pa].
PRESSURE_MIN = (8e6, 10e6)
STRESS_MAX = (400e6, 500e6)


def chart(wall, curves, title, path):
    """Three panels against crush height; ``curves`` is a list of (label, style, PressFit)."""
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for label, style, r in curves:
        axes[0].plot(CRUSH * 1e3, r.shell_stress / 1e6, style, label=label)
        axes[1].plot(CRUSH * 1e3, r.contact_pressure / 1e6, style, label=label)
        axes[2].plot(CRUSH * 1e3, r.clearance * 1e6, style, label=label)
    for limit in STRESS_MAX:
        axes[0].axhline(limit / 1e6, color="k", lw=0.8, ls=":")
    for limit in PRESSURE_MIN:
        axes[1].axhline(limit / 1e6, color="k", lw=0.8, ls=":")
    axes[2].axhline(NOMINAL_CLEARANCE * 1e6, color="k", lw=0.8, ls=":")
    for ax, ylabel in zip(axes, ("shell compressive stress [MPa]", "contact pressure [MPa]", "operating clearance [µm]")):
        ax.set_xlabel("crush height per half shell [mm]")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[2].legend(fontsize=7)
    fig.suptitle(f"{title} — shell wall {wall * 1e3:.1f} mm, bore {BORE * 1e3:.1f} mm", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def fit(wall, material, ratio, temperature):
    return press_fit(housing_bore=BORE, housing_outer=ratio * BORE, shell_wall=wall, crush_height=CRUSH,
                     bearing_width=LENGTH, housing_material=material, shell_material="steel-back",
                     temperature=temperature, check_bore=BORE, journal_d=BORE - 2 * wall - NOMINAL_CLEARANCE)


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    rows = []
    figures = []
    for wall in WALLS:
        curves = [(f"{m}, OD/ID {k}", ("-" if m == "steel" else "--") + c, fit(wall, m, k, 20.0))
                  for m in ("steel", "aluminium") for k, c in zip((1.25, 1.5, 2.0), ("C0", "C1", "C2"))]
        name = f"material_ratio_wall{wall * 1e3:.1f}.png"
        chart(wall, curves, "Housing material and OD/ID at 20 °C", OUT / name)
        figures.append(name)
        curves = [(f"{m}, {t:.0f} °C", ("-" if m == "steel" else "--") + c, fit(wall, m, 1.5, t))
                  for m in ("steel", "aluminium") for t, c in zip((20.0, 80.0, 150.0), ("C0", "C1", "C3"))]
        name = f"temperature_wall{wall * 1e3:.1f}.png"
        chart(wall, curves, "Operating temperature, OD/ID 1.5", OUT / name)
        figures.append(name)
        for m in ("steel", "aluminium"):
            for t in (20.0, 150.0):
                r = fit(wall, m, 1.5, t)
                ok = (r.contact_pressure >= PRESSURE_MIN[1]) & (r.shell_stress <= STRESS_MAX[0])
                window = f"{CRUSH[ok].min() * 1e3:.3f}–{CRUSH[ok].max() * 1e3:.3f}" if ok.any() else "none"
                lost = CRUSH[r.loss_of_fit].max() * 1e3 if r.loss_of_fit.any() else None
                rows.append(f"| {wall * 1e3:.1f} | {m} | {t:.0f} | {window} | "
                            f"{'—' if lost is None else f'≤ {lost:.3f}'} | "
                            f"{r.housing_swell[100] * 1e6:.1f} | {(r.clearance[100] - NOMINAL_CLEARANCE) * 1e6:+.1f} |")
    lines = [
        "# Press-fit design charts",
        "",
        __doc__.split("\n\n")[1].replace("\n", " "),
        "Thick-ring (Lamé) tier, steel-back shells, steel journal, assembly at 20 °C.",
        "",
        f"Crush window: crush heights giving contact pressure ≥ {PRESSURE_MIN[1] / 1e6:.0f} MPa and shell "
        f"compression ≤ {STRESS_MAX[0] / 1e6:.0f} MPa (the strict ends of Kopeliovich's ranges; OD/ID 1.5). Swell and clearance change at 0.10 mm crush.",
        "",
        "| wall [mm] | housing | temperature [°C] | crush window [mm] | fit lost at crush [mm] | swell at 0.10 mm [µm] | clearance change at 0.10 mm [µm] |",
        "|---|---|---|---|---|---|---|",
        *rows,
        "",
        *(f"![{f}](press_fit_design_charts/{f})\n" for f in figures),
        "Reproduce: `python studies/press_fit_design_charts.py`.",
    ]
    (OUT.parent / "press_fit_design_charts.md").write_text("\n".join(lines) + "\n")
    print("wrote", OUT.parent / "press_fit_design_charts.md")


if __name__ == "__main__":
    main()
