"""Ctrl-C held back while a module is being imported, so the command always sees it as a KeyboardInterrupt.

CPython does not deliver a KeyboardInterrupt raised inside an import to the
code that started the import: it becomes an ImportError ("initialization
failed") when it lands in an extension module's initialisation, is printed and
dropped ("Exception ignored in ... _get_module_lock") when it lands in
importlib's module-lock callback, and makes ``python -m`` end by SIGINT instead
of with the command's exit code when it lands in code an extension runs through
``PyRun_String`` (Cython's module set-up). The command imports numpy, scipy,
pandas, xarray and numba lazily for about a second after it starts, so a Ctrl-C
then met one of the three.

Within :func:`held_during_imports`, a Ctrl-C that arrives while an import
started inside the block is under way is held: a profile function (this thread
only, and only while a Ctrl-C is held) watches for the outermost such import's
frame to return and raises KeyboardInterrupt there, so the import statement
raises it once the module is imported. Anywhere else Ctrl-C raises at
once, as Python's own handler does.
"""

from __future__ import annotations

import signal
import sys
import threading
from contextlib import contextmanager

#: The files of importlib's frames: a frame of one of them on the stack means an import is under way.
IMPORTLIB_FILES = frozenset({"<frozen importlib._bootstrap>", "<frozen importlib._bootstrap_external>"})


class _Hold:
    """The block's state: its frame (imports outside it are not the block's) and the import a Ctrl-C waits for."""

    def __init__(self, entry):
        self.entry = entry
        self.waiting_for = None  # the outermost importlib frame of the import under way when Ctrl-C came

    def outermost_import(self, frame):
        """The outermost importlib frame between ``frame`` and the block's, or None."""
        found = None
        while frame is not None and frame is not self.entry:
            if frame.f_code.co_filename in IMPORTLIB_FILES:
                found = frame
            frame = frame.f_back
        return found

    def interrupt(self, signum, frame):
        """SIGINT: KeyboardInterrupt, or held until the import under way returns."""
        if self.waiting_for is not None:
            return  # a second Ctrl-C while one is held: the same interrupt
        outer = self.outermost_import(frame) if sys.getprofile() is None else None
        if outer is None:
            raise KeyboardInterrupt
        self.waiting_for = outer
        sys.setprofile(self.watch)

    def watch(self, frame, event, arg):
        """Profile function while a Ctrl-C is held: on the awaited import's return, KeyboardInterrupt (raised in
        a profile function, it leaves the returning frame in place of its result)."""
        if event == "return" and frame is self.waiting_for:
            self.release()
            raise KeyboardInterrupt

    def release(self):
        """Stop waiting; whether a Ctrl-C was held."""
        held = self.waiting_for is not None
        if held:
            sys.setprofile(None)
            self.waiting_for = None
        return held


@contextmanager
def held_during_imports():
    """Within the block, a Ctrl-C that arrives during an import is raised as KeyboardInterrupt right after it.

    Does nothing where Ctrl-C does not raise KeyboardInterrupt to begin with
    (SIGINT ignored, as in a background job, or another handler installed) and
    off the main thread. A Ctrl-C is raised at once where a profiler is
    running (the hold needs the thread's profile function).
    """
    if (signal.getsignal(signal.SIGINT) is not signal.default_int_handler
            or threading.current_thread() is not threading.main_thread()):
        yield
        return
    hold = _Hold(sys._getframe(2))  # the with statement's frame (above contextlib's __enter__)
    signal.signal(signal.SIGINT, hold.interrupt)
    try:
        yield
    finally:
        held = hold.release()
        signal.signal(signal.SIGINT, signal.default_int_handler)
        if held:  # the block ended while its import still ran (an exception left it): the Ctrl-C is not lost
            raise KeyboardInterrupt
