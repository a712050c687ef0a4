import importlib
import os
import signal
import sys
import time

import pytest

from stackup._interrupt import held_during_imports

SENDS_ITSELF_CTRL_C = "import os, signal, time\nos.kill(os.getpid(), signal.SIGINT)\ntime.sleep(0.05)\nfinished = True\n"


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


def test_a_ctrl_c_during_an_import_is_raised_where_the_import_returns(tmp_path, monkeypatch, ctrl_c_raises):
    name = _module(tmp_path, monkeypatch, SENDS_ITSELF_CTRL_C)
    reached = False
    with pytest.raises(KeyboardInterrupt), held_during_imports():
        importlib.import_module(name)
        reached = True
    assert sys.modules[name].finished and not reached
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler and sys.getprofile() is None


def test_without_it_the_same_ctrl_c_breaks_the_import(tmp_path, monkeypatch, ctrl_c_raises):
    name = _module(tmp_path, monkeypatch, SENDS_ITSELF_CTRL_C)
    with pytest.raises(KeyboardInterrupt):
        importlib.import_module(name)
    assert name not in sys.modules


def test_outside_an_import_ctrl_c_is_raised_at_once(ctrl_c_raises):
    with pytest.raises(KeyboardInterrupt), held_during_imports():
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(5)
    assert sys.getprofile() is None


def test_a_block_entered_during_an_import_does_not_hold_its_own_ctrl_c(tmp_path, monkeypatch, ctrl_c_raises):
    # a study script run by import (or a command called from a module's top level): the import around the block
    # is not the block's, and a Ctrl-C in the block's own code is raised at once
    name = _module(tmp_path, monkeypatch, "import os, signal, time\nfrom stackup._interrupt import held_during_imports\n"
                   "raised_at_once = False\ntry:\n    with held_during_imports():\n"
                   "        os.kill(os.getpid(), signal.SIGINT)\n        time.sleep(5)\n"
                   "except KeyboardInterrupt:\n    raised_at_once = True\n")
    started = time.monotonic()
    module = importlib.import_module(name)
    assert module.raised_at_once and time.monotonic() - started < 4


def test_a_held_ctrl_c_is_not_lost_when_the_block_ends_by_an_error(tmp_path, monkeypatch, ctrl_c_raises):
    name = _module(tmp_path, monkeypatch, "import os, signal\nos.kill(os.getpid(), signal.SIGINT)\n"
                   "raise RuntimeError('the import fails')\n")
    with pytest.raises(KeyboardInterrupt), held_during_imports():
        importlib.import_module(name)
    assert sys.getprofile() is None and signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_where_ctrl_c_is_ignored_it_stays_ignored():
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with held_during_imports():
            assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, previous)


def test_no_other_signal_or_timer_is_touched(ctrl_c_raises):
    alarm = signal.signal(signal.SIGALRM, signal.SIG_IGN)
    signal.setitimer(signal.ITIMER_REAL, 30.0)
    try:
        with held_during_imports():
            pass
        assert signal.getsignal(signal.SIGALRM) is signal.SIG_IGN and signal.getitimer(signal.ITIMER_REAL)[0] > 20
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, alarm)
