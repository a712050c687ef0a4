"""How the report writes its numbers: one place for values with intervals, ppm, µm, hours and significant digits.

A number that is not finite is written "—" where it stands for "none"
(a share of nothing), and "∞" / "−∞" where it is a bound that was never
reached (a life the film never ends).
"""

from __future__ import annotations

import re

import numpy as np

#: Micrometres per metre.
UM = 1e6


def fixed(value, digits=1, sign=False):
    """``value`` to ``digits`` decimals, signed if ``sign``."""
    return f"{value:{'+' if sign else ''}.{digits}f}"


def signed(value, digits=0):
    """``value`` with its sign, grouped, to ``digits`` decimals, the minus a minus sign ('+27', '−1,393', '+0.41')."""
    return f"{value:+,.{digits}f}".replace("-", "−")


def signed_span(values, digits=2):
    """Signed values as one ('+0.41') or their range ('−0.52 to −0.31') where they differ at ``digits``."""
    lo, hi = (signed(v, digits) for v in (min(values), max(values)))
    return lo if lo == hi else f"{lo} to {hi}"


def interval(value, ci, digits=1):
    """'value [lower, upper]' to ``digits`` decimals; '—' where the value is not a number."""
    if not np.isfinite(value):
        return "—"
    return f"{value:.{digits}f} [{ci[0]:.{digits}f}, {ci[1]:.{digits}f}]"


def triple(q, digits=1):
    """A (value, lower, upper) triple as :func:`interval` writes it."""
    return interval(q[0], q[1:], digits)


def mean_std(mean, std, digits=2):
    """'mean ± spread' to ``digits`` decimals."""
    return f"{mean:.{digits}f} ± {std:.{digits}f}"


def significant(value, digits=3):
    """A number to ``digits`` significant digits, written out with thousands separators (26,500, not 2.65e+04)."""
    if not np.isfinite(value):
        return "∞" if value > 0 else ("−∞" if value < 0 else "—")
    if value == 0:
        return "0"
    rounded = float(f"{value:.{digits}g}")
    decimals = max(0, digits - 1 - int(np.floor(np.log10(abs(rounded)))))
    return f"{rounded:,.{decimals}f}"


def significant_triple(q, digits=3):
    """A (value, lower, upper) triple as 'value [lower, upper]' with significant digits."""
    return f"{significant(q[0], digits)} [{significant(q[1], digits)}, {significant(q[2], digits)}]"


def general(value, digits=3, sign=False):
    """``value`` in Python's general format to ``digits`` significant digits (1.26e+03), signed if ``sign``."""
    return f"{value:{'+' if sign else ''}.{digits}g}"


def whole(value):
    """``value`` rounded to a whole number, with thousands separators (83,333)."""
    return f"{value:,.0f}"


def count(value):
    """A count with thousands separators (10,465)."""
    return f"{value:,}"


def spaced(value):
    """A whole number with thin spaces as thousands separators, as in running text (10 000)."""
    return f"{value:,}".replace(",", " ")


def hours(value):
    """A life [h] rounded to hundreds, with thousands separators (38,000)."""
    return f"{np.round(value, -2):,.0f}"


def ppm_digits(value, upper=None):
    """Decimals of a share in ppm: none from 10 ppm, a tenth below, two significant digits below 1 (0.05 is not 0)."""
    if abs(value) >= 10 or (upper is not None and abs(upper) >= 10):
        return 0
    if not np.isfinite(value) or abs(value) >= 1 or value == 0:
        return 1
    return int(min(3, max(1, 1 - np.floor(np.log10(abs(value))))))


def _ppm_text(value, digits, grouped=True):
    """A share in ppm to ``digits`` decimals (thousands grouped or not); an exact zero is '0', a positive share
    that would read as zero '< 0.001' (its resolution), never '0.000'."""
    if value == 0:
        return "0"
    text = f"{value:{',' if grouped else ''}.{digits}f}"
    return f"< {10.0 ** -digits:.{digits}f}" if value > 0 and float(text.replace(",", "")) == 0 else text


def ppm_interval(value, ci, grouped=False):
    """A share in ppm with its interval, without the unit (a table cell): '0.050 [0.034, 0.065]'; an estimate
    below the resolution reads '< 0.001 [0, 0.002]', not '0.000 [0.000, 0.002]'."""
    if value == 0 and ci[1] == 0:
        return "0"
    digits = ppm_digits(value, ci[1])
    return "{} [{}, {}]".format(*(_ppm_text(v, digits, grouped) for v in (value, *ci)))


def ppm(value, ci=None):
    """A share in ppm with its unit and interval, to the value's precision: '0.050 ppm [0.034, 0.065]'.

    An exact zero without an interval, or with an interval [0, 0], is '0 ppm'; a positive share below the
    precision '< 0.001 ppm'.
    """
    if value == 0 and (ci is None or ci[1] == 0):
        return "0 ppm"
    if ci is None:
        return f"{_ppm_text(value, ppm_digits(value))} ppm"
    head, _, rest = ppm_interval(value, ci, grouped=True).partition(" [")
    return f"{head} ppm [{rest}"


def ppm_number(value):
    """A share in ppm to its precision, without the unit (a table cell); an exact zero is '0'."""
    return "0" if value == 0 else f"{value:,.{ppm_digits(value)}f}"


def um(value, digits=1):
    """A length [m] in µm to ``digits`` decimals."""
    return f"{value * UM:.{digits}f}"


def um_edge(value):
    """A window edge [m] in µm: whole micrometres unless it has a fraction (34.5, not 34)."""
    if not np.isfinite(value):
        return "∞" if value > 0 else "−∞"
    edge = round(value * UM, 3)
    return f"{edge:.0f}" if edge == round(edge) else f"{edge:g}"


def um_range(lo, hi, digits=1):
    """A range of lengths in µm (already in µm): 'lo–hi'."""
    return f"{lo:.{digits}f}–{hi:.{digits}f}"


def percent(share):
    """A share [-] in per cent: whole from 10 %, a tenth below (58 %, 1.2 %)."""
    return f"{100 * share:.0f} %" if share >= 0.1 else f"{100 * share:.1f} %"


def percent_span(values):
    """Whole percentages as one value or 'lo-hi' when they differ."""
    lo, hi = f"{min(values):.0f}", f"{max(values):.0f}"
    return lo if lo == hi else f"{lo}-{hi}"


def spread(values, digits=0):
    """(5 %, median, 95 %) as ('lo-hi', 'median') to ``digits`` decimals."""
    lo, mid, hi = values
    return f"{lo:.{digits}f}-{hi:.{digits}f}", f"{mid:.{digits}f}"


#: A source longer than this [words] is cited in short on the page (in full in the engine file).
CITED_WORDS = 30


def _balanced(text):
    return text.count("(") == text.count(")")


def cited(text, limit=CITED_WORDS):
    """A source as the page cites it: whole when at most ``limit`` words; else its citation, the part before its
    first ": " (an author and title, 2 to 15 words), or else its first sentence, or else its first clause (up to
    "; "), each only with its brackets closed; else its first ``limit`` words and "…". Without a final full stop;
    the full text stays in the engine file (the dataset's ``input_files``)."""
    text = " ".join(str(text).split()).rstrip(".;")
    if len(text.split()) <= limit:
        return text
    head = text.split(": ", 1)[0]
    if 2 <= len(head.split()) <= 15 and _balanced(head):
        return head
    for part in (re.split(r"(?<=[.?!])\s+(?=[A-Z])", text, maxsplit=1)[0].rstrip("."), text.split("; ", 1)[0]):
        if len(part.split()) <= limit and _balanced(part):
            return part
    return " ".join(text.split()[:limit]) + " …"
