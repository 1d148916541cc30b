"""The type stubs (gearcoupling/__init__.pyi) describe the module as built: every name, and
every function's and method's parameters in order."""

import ast
import re
from pathlib import Path

import gearcoupling as gc

STUBS = ast.parse((Path(gc.__file__).parent / "__init__.pyi").read_text())


def stub_parameters(function: ast.FunctionDef) -> list[str]:
    arguments = function.args
    names = [a.arg for a in arguments.posonlyargs + arguments.args + arguments.kwonlyargs]
    return [name for name in names if name != "self"]


def bound_parameters(function) -> list[str]:
    """Parameter names from pybind11's signature line, e.g. 'f(self: X, coupling: object, ...)'."""
    signature = function.__doc__.splitlines()[0]
    inside = signature[signature.index("(") + 1:signature.rindex(")")]
    names = re.findall(r"(?:^|, )(\*|\w+)(?=: |, |$)", inside)
    return [name for name in names if name not in ("self", "*")]


def test_every_function_and_class_is_stubbed_with_its_parameters():
    stubbed = {node.name: node for node in STUBS.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(gc) if not name.startswith("_") and callable(getattr(gc, name))}
    assert public - set(stubbed) == set()
    for name, node in stubbed.items():
        if name == "Client" and not hasattr(gc, "Client"):
            continue  # built without the service (GC_BUILD_SERVICE=OFF)
        assert hasattr(gc, name), name
        if isinstance(node, ast.FunctionDef) and type(getattr(gc, name)).__name__ == "builtin_function_or_method":
            assert stub_parameters(node) == bound_parameters(getattr(gc, name)), name
        if isinstance(node, ast.ClassDef) and name in ("Client", "Model"):
            for method in (m for m in node.body if isinstance(m, ast.FunctionDef)
                           and not m.name.startswith("_") and not m.decorator_list):
                assert stub_parameters(method) == bound_parameters(getattr(getattr(gc, name), method.name)), \
                    f"{name}.{method.name}"
