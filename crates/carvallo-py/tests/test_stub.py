"""The type stub `crates/carvallo-py/carvallo.pyi` against the compiled module: the same public
names both ways (every function, class and attribute of the module declared in the stub, and
nothing declared that the module lacks), and for every function the same parameters in the same
order, of the same kinds (positional or keyword-only), with the same defaults where PyO3's text
signature states them.

Breaking perturbations, each tried once: deleting `def lean_rider` from the stub fails the
first test (missing from the stub); adding a `def nothing_here() -> None` fails it the other
way; deleting `torque_lean` from the stub's `simulate` fails the second test (the parameter
lists differ)."""

import ast
import inspect
import types

import carvallo
from conftest import ROOT

STUB = ROOT / "crates" / "carvallo-py" / "carvallo.pyi"


def compiled_module() -> types.ModuleType:
    """The extension module itself: `carvallo`, or its `carvallo.carvallo` when maturin wraps it
    in a package whose `__init__.py` re-exports it."""
    inner = getattr(carvallo, "carvallo", None)
    return inner if isinstance(inner, types.ModuleType) else carvallo


def stub_declarations() -> dict[str, ast.AST]:
    """The stub's module-level declarations by name: functions, classes and annotated
    attributes (`__version__: str`). Plain assignments (`Params = Union[...]`) are type aliases
    of the stub, not names of the module, and imports are the stub's own."""
    out = {}
    for node in ast.parse(STUB.read_text(encoding="utf-8")).body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            out[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            out[node.target.id] = node
    return out


def module_names() -> set[str]:
    m = compiled_module()
    names = {n for n in dir(m) if not n.startswith("_")}
    if hasattr(m, "__version__"):
        names.add("__version__")
    return names


def test_the_stub_declares_every_public_name_of_the_module_and_no_other():
    stub, module = set(stub_declarations()), module_names()
    assert "lean_rider" in module, sorted(module)
    missing = sorted(module - stub)
    extra = sorted(stub - module)
    assert not missing, f"names of the module missing from {STUB.name}: {missing}"
    assert not extra, f"names of {STUB.name} the module does not have: {extra}"


def stub_parameters(node: ast.FunctionDef) -> list[tuple[str, str, object]]:
    """(name, kind, default) of each parameter; default `inspect.Parameter.empty` when there is
    none, `...` when the stub's is not a literal."""
    a = node.args
    out = []
    positional = a.posonlyargs + a.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(a.defaults)) + list(a.defaults)
    for arg, default in zip(positional, defaults):
        out.append((arg.arg, "positional", default))
    for arg, default in zip(a.kwonlyargs, a.kw_defaults):
        out.append((arg.arg, "keyword", inspect.Parameter.empty if default is None else default))

    def literal(d):
        if d is inspect.Parameter.empty:
            return d
        try:
            return ast.literal_eval(d)
        except ValueError:
            return ...

    return [(name, kind, literal(d)) for name, kind, d in out]


def module_parameters(f) -> list[tuple[str, str, object]]:
    kinds = {
        inspect.Parameter.POSITIONAL_ONLY: "positional",
        inspect.Parameter.POSITIONAL_OR_KEYWORD: "positional",
        inspect.Parameter.KEYWORD_ONLY: "keyword",
    }
    return [(p.name, kinds[p.kind], p.default) for p in inspect.signature(f).parameters.values()]


def test_every_functions_parameters_are_the_modules():
    m = compiled_module()
    checked = []
    for name, node in sorted(stub_declarations().items()):
        if not isinstance(node, ast.FunctionDef):
            continue
        f = getattr(m, name)
        if not isinstance(f, types.BuiltinFunctionType):
            continue  # the figures of `carvallo.plot` are Python functions, checked by name only
        ours, theirs = stub_parameters(node), module_parameters(f)
        assert [p[:2] for p in ours] == [p[:2] for p in theirs], f"{name}: {ours} against {theirs}"
        for (p, _, d_stub), (_, _, d_mod) in zip(ours, theirs):
            # PyO3 writes `...` for a default it cannot show as a literal (`Vec::new()`).
            if d_mod is not ... and d_stub is not ...:
                assert (d_stub is inspect.Parameter.empty) == (d_mod is inspect.Parameter.empty) and (
                    d_stub == d_mod or d_stub is inspect.Parameter.empty
                ), f"{name}({p}): the stub's default {d_stub!r}, the module's {d_mod!r}"
        checked.append(name)
    assert "lean_rider" in checked and "simulate" in checked, checked
