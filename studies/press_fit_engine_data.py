"""The built-in engines' press-fit data and ISO 13778 details, measured on sampled engines.

For each built-in ISO-size engine and each ISO 13778 scheme: housing swell,
the press-fit check at the engine's declared temperatures (lowest contact
pressure, highest shell stress, against the engine's limits), the operating
clearance against the engine's design window, and shell stock-outs. Then what
each ISO 13778 detail changes, on the same random numbers:

- the example engine's data before this revision (crush 0.100-0.137 mm, no
  lining, window 45-65 um, one temperature) against now;
- scheme 6 with and without its intermediate pairs (A+C for B+B, A+D for B+C,
  B+D for C+C), with shells made to order and sorted from one process;
- the journal read once (one plane off centre, one direction) against the mean
  of four readings, and the shell wall read once against the larger of two;
- the aluminium engine's bores with and without the bolt-tension scatter.

    python studies/press_fit_engine_data.py [--engines 100000]

Writes reports/press_fit_engine_data.md.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from importlib import resources
from pathlib import Path

import numpy as np
from _common import environment, write_report

from stackup.assembly import ASSEMBLED, SHELL_STOCKOUT
from stackup import schemes
from stackup.engines import load_engine
from stackup.fit import press_fit_extremes
from stackup.study import Study

ISO = tuple(f"iso13778-{k}" for k in range(1, 7))
UM, MPA = 1e6, 1e-6


def builtin_folder():
    return Path(str(resources.files("stackup") / "data" / "engines"))


def variant(folder, engine, name, changes):
    """A copy of a built-in engine file with text replaced (each old text must be there once)."""
    text = (builtin_folder() / f"{engine}.toml").read_text()
    for old, new in changes:
        if text.count(old) != 1:
            raise ValueError(f"{engine}.toml: {old!r} found {text.count(old)} times")
        text = text.replace(old, new)
    text = text.replace(f'name = "{engine}"', f'name = "{name}"')
    path = Path(folder) / f"{name}.toml"
    path.write_text(text)
    return str(path)


def block(text, start, end):
    """The lines of ``text`` from the one starting with ``start`` up to (not with) the one with ``end``."""
    i = text.index(start)
    return text[i:text.index(end, i)]


def run(engine, schemes, n, seed):
    return Study(engine=engine, schemes=schemes, n_engines=n, mechanics_engines=0, progress=False, seed=seed).run()


def measure(ds, engine_path):
    """Per scheme: swell, check at the declared temperatures, operating clearance, stock-outs."""
    engine = load_engine(engine_path)
    limits = engine.press_fit_limits
    lo, hi = engine.clearance_window
    rows = {}
    for i, scheme in enumerate(ds.scheme.values):
        status = ds.status.values[i]
        ok = status == ASSEMBLED
        wall = 0.5 * (ds.shell_upper_wall.values[i][ok] + ds.shell_lower_wall.values[i][ok])
        crush = 0.5 * (ds.shell_upper_crush.values[i][ok] + ds.shell_lower_crush.values[i][ok])
        ext = press_fit_extremes(housing_bore=ds.housing_bore.values[ok], shell_wall=wall, crush_height=crush,
                                 **engine.press_fit.extremes_kwargs())
        c = ds.clearance_operating.values[i][ok]
        swell = ds.housing_swell.values[i][ok]
        rows[str(scheme)] = {
            "bearings": status.size, "assembled": int(ok.sum()),
            "stockout": int(np.count_nonzero(status == SHELL_STOCKOUT)),
            "swell": (swell.min(), swell.mean(), swell.max()),
            "p_low": ext.lowest_contact_pressure.min(), "p_low_t": np.unique(ext.lowest_pressure_temperature),
            "s_high": ext.highest_shell_stress.max(), "s_high_t": np.unique(ext.highest_stress_temperature),
            "p_out": np.mean(ext.lowest_contact_pressure < limits.contact_pressure_min),
            "s_out": np.mean(ext.highest_shell_stress > limits.shell_stress_max),
            "clearance": (c.min(), *np.quantile(c, [0.001, 0.5, 0.999]), c.max()), "c_mean": c.mean(), "c_std": c.std(),
            "nominal_std": ds.clearance_nominal.values[i][ok].std(),
            "outside": np.mean((c < lo) | (c > hi)),
            "used_pairs": int(np.count_nonzero(ok & (ds.shell_option.values[i] > 0))),
        }
    return engine, rows


def engine_table(engine, rows):
    limits = engine.press_fit_limits
    temps = engine.press_fit.temperatures
    head = [
        f"### {engine.name}: {engine.title}",
        "",
        f"Housing {engine.press_fit.housing_material}, OD {engine.press_fit.housing_outer * 1e3:.0f} mm; crush height "
        f"{engine.shell_wall.crush.lo * 1e3:.3f}-{engine.shell_wall.crush.hi * 1e3:.3f} mm; lining "
        f"{engine.press_fit.lining_thickness * 1e3:.2f} mm {engine.press_fit.lining_material or '-'}; checked at "
        f"{', '.join(f'{t:g}' for t in temps)} °C (clearance at {engine.press_fit.temperature:g} °C); limits "
        f"p ≥ {limits.contact_pressure_min * MPA:g} MPa, σ ≤ {limits.shell_stress_max * MPA:g} MPa; window "
        f"{engine.clearance_window[0] * UM:.1f}-{engine.clearance_window[1] * UM:.1f} µm.",
        "",
        "| scheme | swell min / mean / max [µm] | lowest p [MPa] (at °C) | highest σ [MPa] (at °C) | p < limit | σ > limit "
        "| operating clearance min / 0.1 % / median / 99.9 % / max [µm] | outside window | stock-outs |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    body = [
        f"| {s} | {r['swell'][0] * UM:.1f} / {r['swell'][1] * UM:.1f} / {r['swell'][2] * UM:.1f} "
        f"| {r['p_low'] * MPA:.1f} ({', '.join(f'{t:g}' for t in r['p_low_t'])}) "
        f"| {r['s_high'] * MPA:.0f} ({', '.join(f'{t:g}' for t in r['s_high_t'])}) "
        f"| {r['p_out']:.2%} | {r['s_out']:.2%} "
        f"| {' / '.join(f'{v * UM:.1f}' for v in r['clearance'])} | {r['outside']:.2%} | {r['stockout']} |"
        for s, r in rows.items()
    ]
    return head + body + [""]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="reports/press_fit_engine_data.md")
    args = parser.parse_args(argv)
    n, seed = args.engines, args.seed
    t0 = time.perf_counter()
    lines = ["# Engine press-fit data and ISO 13778 details, measured", "", f"{environment()}; {n:,} engines "
             f"(five bearings each), seed {seed}, mechanical chain off. Every comparison uses the same random numbers.",
             "", "## The built-in ISO-size engines", ""]
    results = {}
    with tempfile.TemporaryDirectory() as folder:
        for name in ("iso-example", "iso-example-aluminium"):
            engine, rows = measure(run(name, ISO, n, seed), name)
            results[name] = rows
            lines += engine_table(engine, rows)
            lines += ["Crush height: " + " ".join(engine.press_fit.crush_source.split()), "",
                      "Window: " + " ".join(engine.clearance_window_source.split()), ""]

        # the example engine as it was: Kopeliovich's aluminium-housing crush on the iron housing
        text = (builtin_folder() / "iso-example.toml").read_text()
        before = variant(folder, "iso-example", "iso-example-before", [
            ("limits = [0.065, 0.090]", "limits = [0.100, 0.137]"),
            ("lining_thickness = 0.30           # [mm]\n", ""),
            ('lining_material = "aluminium-tin"\n', ""),
            ("cold_temperature = -25.0          # cold start [degC]\n", ""),
            ("hot_temperature = 130.0           # hottest housing at full load (oil out of the bearing) [degC]\n", ""),
            (block(text, "[press_fit.limits]", "[crank]"), ""),
            ('relative_clearance = [0.00075, 0.00125]', "operating_clearance = [0.045, 0.065]"),
            ("form = { ovality = 0.003, taper = 0.003, planes = [0.25, 0.75], directions = 2 }", ""),
            ('gauge = { repeatability = 0.0005, readings = 2, combine = "max" }', "gauge = { repeatability = 0.0005 }"),
        ])
        engine_before, rows_before = measure(run(before, ISO, n, seed), before)
        after = results["iso-example"]
        lines += ["## The example engine before and after", "",
                  "Before: crush height 0.100-0.137 mm (Kopeliovich's aluminium-housing values), plain steel shells "
                  "(check force on the full wall), checked at the operating temperature only against 8 MPa / "
                  "450 MPa, window 45-65 µm, journal and shell wall read once. After: the engine file as shipped.", "",
                  "| scheme | swell mean before → after [µm] | swell max before → after [µm] | lowest p before → after "
                  "[MPa] | highest σ before → after [MPa] | median clearance before → after [µm] | outside window "
                  "before → after |", "|---|---|---|---|---|---|---|"]
        for s in ISO:
            b, a = rows_before[s], after[s]
            lines.append(f"| {s} | {b['swell'][1] * UM:.1f} → {a['swell'][1] * UM:.1f} | {b['swell'][2] * UM:.1f} → "
                         f"{a['swell'][2] * UM:.1f} | {b['p_low'] * MPA:.1f} → {a['p_low'] * MPA:.1f} | "
                         f"{b['s_high'] * MPA:.0f} → {a['s_high'] * MPA:.0f} | {b['clearance'][2] * UM:.1f} → "
                         f"{a['clearance'][2] * UM:.1f} | {b['outside']:.2%} → {a['outside']:.2%} |")
        lines.append("")

        # scheme 6 with and without its intermediate pairs
        plain6 = Path(folder) / "iso13778-6-no-pairs.toml"
        text6 = Path(schemes.load("iso13778-6").path).read_text()
        plain6.write_text(text6[:text6.index("[pairing.alternatives]")].replace('name = "iso13778-6"',
                                                                                'name = "iso13778-6-no-pairs"'))
        sorted_engine = variant(folder, "iso-example", "iso-example-sorted", [
            ('supply = "to-order"', 'supply = "sorted"\nprocess = { distribution = "normal", cpk = 1.0 }'),
            ("sigma = 0.001\n", ""),
        ])
        lines += ["## Scheme 6: intermediate pairs before a stock-out", "",
                  "The same engines and shells assembled by scheme 6 with its intermediate pairs (clause 6.1 b: A+C "
                  "for B+B, A+D for B+C, B+D for C+C, same wall sums) and without. Shells made to order (the "
                  "example engine's supply: each grade in the quantity the pilot's demand asks for) and sorted "
                  "from one process (Cpk 1.0 over the scheme's shell range: grade quantities follow the process).",
                  "", "| shell supply | bearings | stock-outs without pairs | stock-outs with pairs | bearings fitted "
                  "with a pair | change | preferred pairs of the stock-outs left |", "|---|---|---|---|---|---|---|"]
        for label, engine_path in (("made to order", "iso-example"), ("sorted, Cpk 1.0", sorted_engine)):
            ds = run(engine_path, ("iso13778-6", str(plain6)), n, seed)
            _, rows = measure(ds, engine_path)
            w, wo = rows["iso13778-6"], rows["iso13778-6-no-pairs"]
            change = (w["stockout"] - wo["stockout"]) / wo["stockout"] if wo["stockout"] else 0.0
            lines.append(f"| {label} | {w['bearings']:,} | {wo['stockout']:,} ({wo['stockout'] / wo['bearings']:.3%}) "
                         f"| {w['stockout']:,} ({w['stockout'] / w['bearings']:.3%}) | {w['used_pairs']:,} | "
                         f"{change:+.0%} | {stockout_pairs(ds, 0, 'iso13778-6')} |")
        lines += ["", "A+A, A+B, C+D and D+D have no pair of the four grades with their wall sum: their stock-outs "
                  "stay.", ""]

        # measurement notes: journals read once or as the mean of four, round or with form error; walls read once
        form = "form = { ovality = 0.003, taper = 0.003, planes = [0.25, 0.75], directions = 2 }"
        journal_gauge = "gauge = { repeatability = 0.0005 }\n# Form error"
        cases = [
            ("round journals, one reading", [(form, "")]),
            ("3 µm form, one reading off centre",
             [(form, "form = { ovality = 0.003, taper = 0.003, planes = [0.25], directions = 1 }")]),
            ("round journals, mean of four readings",
             [(form, ""), (journal_gauge, "gauge = { repeatability = 0.0005, readings = 4 }\n# Form error")]),
            ("3 µm form, mean of four readings (shipped)", []),
            ("shell wall read once (else shipped)",
             [('gauge = { repeatability = 0.0005, readings = 2, combine = "max" }', "gauge = { repeatability = 0.0005 }")]),
        ]
        lines += ["## Measurement notes of ISO 13778", "",
                  "Journals read with one 2-point reading a quarter of the width off centre, or as the mean of two "
                  "planes and two directions (the engine as shipped), each for round journals and for journals "
                  "with 3 µm ovality and taper (uniform up to the tolerance); shell walls read as the larger of two "
                  "readings (shipped) against one. Misgraded journals: read into another class than the one their "
                  "true mean diameter, read without error, falls in (scheme 6 rounds both to the micrometre).", "",
                  "| case | scheme | misgraded journals | operating clearance std [µm] | median [µm] | outside window |",
                  "|---|---|---|---|---|---|"]
        for k, (label, changes) in enumerate(cases):
            engine_path = variant(folder, "iso-example", f"iso-example-reading-{k}", changes) if changes else "iso-example"
            ds = run(engine_path, ("iso13778-4", "iso13778-6"), n, seed)
            _, rows = measure(ds, engine_path)
            for s in ("iso13778-4", "iso13778-6"):
                r = rows[s]
                lines.append(f"| {label} | {s} | {misgrading(ds, s):.2%} | {r['c_std'] * UM:.2f} | "
                             f"{r['clearance'][2] * UM:.2f} | {r['outside']:.2%} |")
        lines.append("")

        no_bolt = variant(folder, "iso-example-aluminium", "iso-example-aluminium-no-bolt-scatter", [
            ("bolt_scatter = 0.0015", "")])
        lines += ["## Bolt-tension scatter of the light-alloy bores", "",
                  "The aluminium engine's bores moved at assembly by a normal change of 1.5 µm standard deviation "
                  "(its file) against none.", "",
                  "| case | scheme | nominal clearance std [µm] | operating clearance std [µm] | outside window |",
                  "|---|---|---|---|---|"]
        for label, engine_path in (("no bolt scatter", no_bolt), ("bolt scatter 1.5 µm", "iso-example-aluminium")):
            _, rows = measure(run(engine_path, ("iso13778-4", "iso13778-6"), n, seed), engine_path)
            for s in ("iso13778-4", "iso13778-6"):
                r = rows[s]
                lines.append(f"| {label} | {s} | {r['nominal_std'] * UM:.2f} | {r['c_std'] * UM:.2f} | "
                             f"{r['outside']:.2%} |")
        lines.append("")
    lines += [f"Run time {time.perf_counter() - t0:.0f} s. Reproduce: `python studies/press_fit_engine_data.py "
              f"--engines {n} --seed {seed}`."]
    write_report(args.out, lines)


def stockout_pairs(ds, i, scheme):
    """The preferred shell pairs of scheme ``i``'s stock-outs, most frequent first, e.g. "C+D 44"."""
    s = schemes.load(scheme)
    out = ds.status.values[i] == SHELL_STOCKOUT
    upper, lower = s.pair_indices(*s.grade_indices(ds.housing_bore_reading.values[out],
                                                    ds.journal_d_reading.values[out]))
    labels = np.array(s.shell.labels)
    pairs, counts = np.unique(np.char.add(np.char.add(labels[upper], "+"), labels[lower]), return_counts=True)
    return ", ".join(f"{p} {c:,}" for p, c in sorted(zip(pairs, counts), key=lambda x: -x[1])) or "none"


def misgrading(ds, scheme):
    """Share of journals read into another class of ``scheme`` than their true mean diameter."""
    s = schemes.load(scheme)
    read = s.journal.classify(s.read(ds.housing_bore_reading.values, ds.journal_d_reading.values)[1])
    true = s.journal.classify(s.read(ds.housing_bore.values, ds.journal_d.values)[1])
    return float(np.mean(read != true))


if __name__ == "__main__":
    main()
