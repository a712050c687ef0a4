"""Modules that can be called as their main function: ``stackup.plan(ds, ...)`` beside ``stackup.plan.planner_table``.

The package face documents ``stackup.rank(ds)`` and ``stackup.plan(ds,
volume=...)`` as calls, and ``import stackup.plan`` as the module that also
holds ``planner_table`` and ``optimise_supply``. Binding the function over
the module in the package namespace gave one and lost the other; instead the
module itself answers a call by passing it to its main function, so one name
is both and neither hides the other.
"""

from __future__ import annotations

import inspect
import sys
import types


class _CallableModule(types.ModuleType):
    """A module whose call is its ``__call_target__`` function's."""

    def __call__(self, *args, **kwargs):
        return self.__call_target__(*args, **kwargs)


def callable_module(name, function):
    """Make the module ``name`` callable as ``function``, with its signature for ``help`` and ``inspect``."""
    module = sys.modules[name]
    module.__call_target__ = function
    module.__signature__ = inspect.signature(function)
    module.__class__ = _CallableModule
