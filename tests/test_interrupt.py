import importlib
import os
import signal
import sys
import time

import pytest

from stackup._interrupt import held_during_imports


@pytest.fixture
def ctrl_c_raises():
    """Ctrl-C as an interactive Python has it, also where pytest runs with SIGINT ignored (a background job)."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


def _module(tmp_path, monkeypatch, body):
    name = f"_stackup_interrupt_probe_{time.monotonic_ns()}"
    (tmp_path / f"{name}.py").write_text(body)
    monkeypatch.syspath_prepend(str(tmp_path))
    return name


def test_a_ctrl_c_during_an_import_is_raised_after_the_import_finishes(tmp_path, monkeypatch, ctrl_c_raises):
    name = _module(tmp_path, monkeypatch, "import os, signal, time\nos.kill(os.getpid(), signal.SIGINT)\n"
                   "time.sleep(0.05)\nfinished = True\n")
    with pytest.raises(KeyboardInterrupt), held_during_imports():
        importlib.import_module(name)
        while True:  # the held-back interrupt arrives within a few of the handler's rechecks
            time.sleep(0.001)
    assert sys.modules[name].finished
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_without_it_the_same_ctrl_c_breaks_the_import(tmp_path, monkeypatch, ctrl_c_raises):
    name = _module(tmp_path, monkeypatch, "import os, signal, time\nos.kill(os.getpid(), signal.SIGINT)\n"
                   "time.sleep(0.05)\nfinished = True\n")
    with pytest.raises(KeyboardInterrupt):
        importlib.import_module(name)
    assert name not in sys.modules


def test_outside_an_import_ctrl_c_is_raised_at_once(ctrl_c_raises):
    with pytest.raises(KeyboardInterrupt), held_during_imports():
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(5)
    assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)


def test_where_ctrl_c_is_ignored_it_stays_ignored():
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with held_during_imports():
            assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, previous)
