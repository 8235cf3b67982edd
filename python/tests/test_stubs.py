"""The type stubs (soilcut/_soilcut.pyi) against the built extension: every
public name, method and parameter of one is in the other, so the stubs
cannot fall behind a change of the Rust side."""

from __future__ import annotations

import ast
import inspect
import pathlib

import soilcut
from soilcut import _soilcut

STUB = pathlib.Path(soilcut.__file__).with_name("_soilcut.pyi")
# What Python or PyO3 adds to every class (a constructor, or the other
# comparisons beside a defined __eq__): the stubs name what the extension
# defines (its constructor as __init__).
AUTOMATIC = {"__doc__", "__module__", "__new__", "__ne__", "__lt__", "__le__", "__gt__", "__ge__"}


def stub_tree() -> dict[str, ast.AST]:
    tree = ast.parse(STUB.read_text(encoding="utf-8"))
    return {
        node.name: node for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))
    }


def parameters(node: ast.FunctionDef) -> list[str]:
    args = node.args
    return [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs if a.arg != "self"]


def runtime_parameters(obj) -> list[str] | None:
    if type(obj).__name__ == "wrapper_descriptor":
        return None  # a slot (__eq__, __hash__): Python's names, not the extension's
    try:
        signature = inspect.signature(obj)
    except (TypeError, ValueError):
        return None  # no text signature
    return [p for p in signature.parameters if p not in ("self", "$self", "cls")]


def own_members(cls) -> set[str]:
    return set(vars(cls)) - AUTOMATIC


def test_every_name_of_the_extension_is_stubbed_and_no_more():
    stubs = stub_tree()
    runtime = {
        name
        for name, value in vars(_soilcut).items()
        if not name.startswith("_") and (inspect.isclass(value) or callable(value))
    }
    assert runtime == set(stubs), "stubs and extension differ"


def test_functions_take_the_stubbed_parameters():
    for name, node in stub_tree().items():
        if isinstance(node, ast.FunctionDef):
            assert runtime_parameters(getattr(_soilcut, name)) == parameters(node), name


def is_property(node: ast.FunctionDef) -> bool:
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def test_classes_have_the_stubbed_methods_and_parameters():
    for name, node in stub_tree().items():
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(_soilcut, name)
        stubbed = {m.name: m for m in node.body if isinstance(m, ast.FunctionDef)}
        attributes = {a.target.id for a in node.body if isinstance(a, ast.AnnAssign)}
        properties = {method for method, m in stubbed.items() if is_property(m)}
        own = own_members(cls)
        # PyO3 installs a class's __getattr__ as its __getattribute__ slot.
        if "__getattribute__" in own:
            own = own - {"__getattribute__"} | {"__getattr__"}
        # A class with __getattr__ serves its `fields` (Step: history.csv's
        # columns, listed once in Rust): the stubs type each of them.
        served = set(cls.fields) if "__getattr__" in own else set()
        assert served <= properties, f"{name}: {served - properties} not stubbed"
        assert own == (set(stubbed) - {"__init__"} - served) | attributes, name
        for method, m in stubbed.items():
            if is_property(m):
                continue
            expected = parameters(m)
            # The constructor's signature is the class's (PyO3's __new__).
            runtime = "__getattribute__" if method == "__getattr__" else method
            got = runtime_parameters(cls if method == "__init__" else getattr(cls, runtime))
            if got is not None:
                assert got == expected, f"{name}.{method}"
