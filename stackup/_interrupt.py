"""Ctrl-C held back while a module is being imported, so the command always sees it as a KeyboardInterrupt.

CPython does not deliver a KeyboardInterrupt raised inside an import to the
code that started the import: it becomes an ImportError ("initialization
failed") when it lands in an extension module's initialisation, is printed and
dropped ("Exception ignored in ... _get_module_lock") when it lands in
importlib's module-lock callback, and makes ``python -m`` end by SIGINT instead
of with the command's exit code when it lands in code an extension runs through
``PyRun_String`` (Cython's module set-up). The command imports numpy, scipy,
pandas, xarray and numba lazily for about a second after it starts, so a Ctrl-C
then met one of the three. The handler here lets the import finish and raises
the interrupt at the first bytecode after it; anywhere else it raises at once,
as Python's own handler does.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

#: The files of importlib's frames: a frame of one of them on the stack means an import is under way.
IMPORTLIB_FILES = frozenset({"<frozen importlib._bootstrap>", "<frozen importlib._bootstrap_external>"})
#: Seconds between two looks at whether a held-back Ctrl-C's import has finished.
RECHECK = 0.02


def _importing(frame):
    """Whether ``frame`` or a frame that called it is importlib's."""
    while frame is not None:
        if frame.f_code.co_filename in IMPORTLIB_FILES:
            return True
        frame = frame.f_back
    return False


def _interrupt(signum, frame):
    """SIGINT (and the timer's SIGALRM while one is held back): KeyboardInterrupt, once no import is under way."""
    if _importing(frame):
        signal.setitimer(signal.ITIMER_REAL, RECHECK)
        return
    raise KeyboardInterrupt


@contextmanager
def held_during_imports():
    """Within the block, a Ctrl-C that arrives during an import is raised as KeyboardInterrupt right after it.

    Does nothing where Ctrl-C does not raise KeyboardInterrupt to begin with
    (SIGINT ignored, as in a background job, or another handler installed), off
    the main thread, and where the platform has no interval timer.
    """
    if (signal.getsignal(signal.SIGINT) is not signal.default_int_handler or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
        yield
        return
    alarm = signal.signal(signal.SIGALRM, _interrupt)
    signal.signal(signal.SIGINT, _interrupt)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        signal.signal(signal.SIGALRM, alarm)
