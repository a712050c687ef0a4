"""What every subcommand shares: its help formatter, option types, the run's state and log, messages in its words."""

from __future__ import annotations

import argparse
import contextlib
import re
import time

#: Exit codes: done, a store check found damage, refused (bad input or output location), interrupted (Ctrl-C).
EXIT_DONE, EXIT_DAMAGED, EXIT_REFUSED, EXIT_INTERRUPTED = 0, 1, 2, 130
#: Smallest diametral clearance a main bearing runs with, as a share of its journal diameter [-]: 0.1 per mille
#: (4.6 um on the 46 mm example journal), a tenth of the usual 0.75-1.25 per mille (MAHLE Clevite, in the
#: example engine's [targets]); a --window below it is no clearance window (most likely one in mm).
MIN_CLEARANCE_RATIO = 1e-4


class Formatter(argparse.ArgumentDefaultsHelpFormatter, argparse.RawDescriptionHelpFormatter):
    """Defaults shown where there is one to show (not for flags, nor where the help says it)."""

    def _get_help_string(self, action):
        if (action.default is None or action.default is False or action.default is argparse.SUPPRESS
                or "default" in (action.help or "")):
            return action.help
        return super()._get_help_string(action)


def share_ppm(text):
    """A share of bearings in ppm, zero or more."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of ppm") from None
    if not value >= 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"{text} ppm is not a share of bearings >= 0")
    return value


def count(minimum, what):
    """An option type: a whole number of ``what`` (plural), at least ``minimum``."""
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of {what}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"{value} {what if value != 1 else what[:-1]} is too few; give at least "
                                             f"{minimum}")
        return value

    return parse


def share(text):
    """A probability strictly between 0 and 1."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0.0 < value < 1.0:
        raise argparse.ArgumentTypeError(f"{value:g} is not a probability between 0 and 1 (e.g. 0.99)")
    return value


class State:
    """The stage under way and what a Ctrl-C now leaves behind, in words (each command keeps them current)."""

    stage = ""
    saved = "nothing was saved"

    def interrupted(self):
        return f"stackup: interrupted{f' during {self.stage}' if self.stage else ''}; {self.saved}"


class Log:
    """One plain line per stage on stdout, with the time since the start (for logs and terminals alike)."""

    def __init__(self, state):
        self.start, self.state = time.perf_counter(), state

    def __call__(self, line):
        self.state.stage = line.split(":")[0]
        print(f"[{time.perf_counter() - self.start:7.1f} s] {line}", flush=True)


def in_options(error, options):
    """The text of ``error`` (a ValueError of the library) in the command's words.

    ``options`` maps the library's parameter names to the options that set
    them: a message that starts with a parameter's name and a colon or a
    quoted value (``n_engines: ...``, ``out 'x' ...``) starts with its option
    instead, a parameter with an
    underscore in its name is spelled as its option anywhere in the message
    (``give n_engines at most ...``), and ``force=True`` reads ``--force``.
    """
    text = str(error)
    for name, option in options.items():
        if re.match(rf"{re.escape(name)}(:| ')", text):
            text = option + text[len(name):]
            break
    for name, option in options.items():
        if "_" in name:
            text = re.sub(rf"\b{re.escape(name)}\b", option, text)
    return text.replace("force=True", "--force")


#: The engine a command runs on without --engine.
DEFAULT_ENGINE = "iso-example"


@contextlib.contextmanager
def refused_in(options, *, engine=None):
    """Within the block, a ValueError of the library is raised again in the command's words (:func:`in_options`).

    With ``engine`` the default engine (the command's --engine not given), a refusal of data (measured data, a
    scheme laid on the engine: not one that starts with the option it is about, --lot, --out, nor a scheme file's
    own) that does not name the engine says it rests on it: a user who forgot --engine learns which engine their
    data met.
    """
    try:
        yield
    except ValueError as error:
        text = in_options(error, options)
        if engine == DEFAULT_ENGINE and DEFAULT_ENGINE not in text and not text.startswith(("--", "scheme file")):
            text += f" (engine: {DEFAULT_ENGINE}, the default; give yours with --engine)"
        raise ValueError(text) from None


def window_option(window_um, engine):
    """The --window (of compare and design) in m from LO HI in um, or None; a window no main bearing could have
    is refused naming why."""
    if window_um is None:
        return None
    lo, hi = window_um
    if not 0.0 < lo < hi < 1000.0:
        raise ValueError(f"--window: {lo:g} {hi:g} um is not a clearance window; give LO HI in micrometres with "
                         "0 < LO < HI < 1000, e.g. --window 45 65")
    journal = engine.journal_d.lo
    if hi * 1e-6 < MIN_CLEARANCE_RATIO * journal:
        likely = "; give LO HI in micrometres"
        for unit, scale in (("millimetres", 1e3), ("metres", 1e6)):
            if MIN_CLEARANCE_RATIO * journal <= hi * scale * 1e-6 <= 1e-3:
                likely = f"; these look like {unit}: give --window {lo * scale:.6g} {hi * scale:.6g} (micrometres)"
        raise ValueError(f"--window: {lo:g} {hi:g} um is no main bearing's clearance: {engine.name}'s "
                         f"{journal * 1e3:g} mm journal runs with some tens of micrometres (a diametral clearance "
                         f"below {MIN_CLEARANCE_RATIO * journal * 1e6:.1f} um, {1e3 * MIN_CLEARANCE_RATIO:g} per "
                         f"mille of the journal, is below its oil film){likely}")
    return lo / 1e6, hi / 1e6
