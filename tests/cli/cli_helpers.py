"""What the command-line tests share: ``stackup`` run in this process or in a fresh one, and what they check."""

import contextlib
import io
import os
import signal
import subprocess
import sys
from pathlib import Path

from stackup.cli import main
from stackup.comparison import COMPARE_MIN_ENGINES

#: An engine file of another size and bearing count, as a user writes one; a scheme file as shipped.
INLINE6 = Path(__file__).parents[1] / "data" / "inline6.toml"
ISO4 = Path(__file__).parents[2] / "schemes" / "iso13778-4.toml"
#: A small comparison with scenarios (a minute; the tests that use it stop it at once or are refused first).
SMALL_COMPARE = ["compare", "--n", str(COMPARE_MIN_ENGINES), "--schemes", "iso13778-4", "iso13778-6", "--no-design"]
#: The smallest comparison, with its own design window: about 20 s.
WINDOW_COMPARE = ["compare", "--n", str(COMPARE_MIN_ENGINES), "--schemes", "iso13778-4", "--no-scenarios", "--no-design",
                  "--window", "30", "45"]


def stackup(*args, cwd=None, env=None):
    """Run ``stackup ARGS`` in this process, as the console script runs it: a CompletedProcess with the exit code
    and what the command printed (``env``: variables set for the call; ``cwd``: the folder it runs in)."""
    out, err = io.StringIO(), io.StringIO()
    with _environment(env or {}), contextlib.chdir(cwd or os.getcwd()), contextlib.redirect_stdout(out), \
            contextlib.redirect_stderr(err):
        code = main([str(a) for a in args])
    return subprocess.CompletedProcess(["stackup", *map(str, args)], code, out.getvalue(), err.getvalue())


def stackup_process(*args, cwd=None, env=None, timeout=300):
    """Run ``stackup ARGS`` as a user would, in a fresh process; the CompletedProcess."""
    return subprocess.run([sys.executable, "-m", "stackup.cli", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, env={**os.environ, **(env or {})}, timeout=timeout)


def start(args, *, umask=None):
    """``stackup ARGS`` started in a fresh process that a Ctrl-C (SIGINT) reaches as a terminal's would (with the
    file mode mask ``umask`` if given)."""
    def before():
        interruptible()
        if umask is not None:
            os.umask(umask)

    return subprocess.Popen([sys.executable, "-m", "stackup.cli", *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=before)


def interruptible():
    """In the child before it starts: Ctrl-C as a terminal delivers it, even where pytest itself runs with SIGINT
    ignored (a background job of a shell without job control), which Python would otherwise inherit."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


@contextlib.contextmanager
def _environment(variables):
    saved = dict(os.environ)
    os.environ.update(variables)
    try:
        yield
    finally:
        os.environ.clear()
        os.environ.update(saved)


def listing(folder):
    """Every file under ``folder`` with its size and modification time."""
    return {str(p.relative_to(folder)): (p.stat().st_size, p.stat().st_mtime_ns) for p in Path(folder).rglob("*")}


def no_traceback_nor_warning(result):
    return "Traceback" not in result.stderr and "Warning" not in result.stderr


def one_line_refusal(result, *parts):
    """Exit 2, nothing on stdout, one line on stderr holding every part, no traceback."""
    assert result.returncode == 2, result.stderr
    assert result.stdout == "" and no_traceback_nor_warning(result)
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("stackup: error: "), result.stderr
    for part in parts:
        assert part in result.stderr, (part, result.stderr)
