"""The package's layering: no import cycle anywhere (imports inside functions included), the contracts of
pyproject.toml kept, and the package face's modules reachable as modules."""

import ast
import importlib
import inspect
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import stackup

#: The package's source in this checkout (the tests may run against an installed copy of it).
REPOSITORY = Path(__file__).resolve().parents[1]
PACKAGE = REPOSITORY / "stackup"


def _modules():
    """Module name -> (file, is_package) of every module of the package."""
    found = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        found[".".join(parts[:-1] if is_package else parts)] = (path, is_package)
    return found


def import_graph():
    """Module -> modules of the package it imports, from every import statement (inside functions too).

    ``from a import b`` counts as importing ``a.b`` where that is a module and ``a`` otherwise, as Python
    and import-linter read it.
    """
    modules = _modules()

    def owner(name):
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name

    graph = {}
    for name, (path, is_package) in modules.items():
        here = name if is_package else name.rpartition(".")[0]
        targets = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets.update(alias.name for alias in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = here
                    for _ in range(node.level - 1):
                        anchor = anchor.rpartition(".")[0]
                    base = f"{anchor}.{base}" if node.module else anchor
                targets.update(f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names)
        graph[name] = {owner(t) for t in targets if t.split(".")[0] == "stackup" and owner(t) not in ("", name)}
    return graph


def cycles(graph):
    """Strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index, low, on_stack, stack, found, counter = {}, {}, set(), [], [], [0]
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_no_import_cycle_in_the_package_imports_inside_functions_included():
    assert cycles(import_graph()) == []


def test_cycle_finder_finds_a_cycle_through_a_function_level_import():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_graph_sees_imports_inside_functions():
    graph = import_graph()
    # the subcommands import the library on use, so the command starts at once
    assert "stackup.report" in graph["stackup.commands.report"]


@pytest.mark.skipif(shutil.which("lint-imports", path=str(Path(sys.executable).parent)) is None,
                    reason="import-linter is not installed (pip install '.[test]')")
def test_layer_contracts_are_kept():
    run = subprocess.run([shutil.which("lint-imports", path=str(Path(sys.executable).parent))],
                         cwd=REPOSITORY, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-3000:]


@pytest.mark.parametrize("name, call", [("plan", "plan"), ("rank", "rank")])
def test_plan_and_rank_are_modules_and_calls(name, call):
    module = importlib.import_module(f"stackup.{name}")
    assert getattr(stackup, name) is module
    assert inspect.signature(module) == inspect.signature(getattr(module, call))
    assert callable(module)


def test_planner_table_and_optimise_supply_reachable_as_the_docs_say():
    import stackup.plan

    assert callable(stackup.plan.planner_table) and callable(stackup.plan.optimise_supply)


def test_no_package_face_hides_one_of_its_modules_behind_a_function():
    """STYLE: a module's public name is never reused in its package's face (``stackup.report.verdict`` is the
    module, whatever the face re-exports), so every module stays reachable as an attribute of its package."""
    hidden = []
    for name in sorted(_modules()):
        module = importlib.import_module(name)
        parent, _, short = name.rpartition(".")
        if parent and getattr(sys.modules[parent], short, None) is not module:
            hidden.append(name)
    assert hidden == []
