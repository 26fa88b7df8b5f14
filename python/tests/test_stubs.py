"""The typed stubs (foresight/_foresight.pyi) describe the native module as it is: every public
name of the module is in the stubs and every function and method takes the parameters the
stubs list, in the same order (read from pybind11's signature line in each docstring)."""
import ast
import pathlib

import foresight
from foresight import _foresight

STUB = pathlib.Path(foresight.__file__).with_name("_foresight.pyi")


def parameter_names(doc):
    """The parameter names of a pybind11 signature line 'name(a: T, b: T = d) -> R'."""
    line = doc.splitlines()[0]
    inside = line[line.index("(") + 1:line.rindex(") ->")]
    names, depth, current = [], 0, ""
    for char in inside + ",":
        if char in "[(":
            depth += 1
        elif char in "])":
            depth -= 1
        if char == "," and depth == 0:
            names.append(current.split(":")[0].strip())
            current = ""
        else:
            current += char
    return [n for n in names if n and n != "self"]


def stub_parameters(function):
    return [a.arg for a in function.args.args if a.arg != "self"]


def test_every_public_name_has_a_stub():
    tree = ast.parse(STUB.read_text())
    stubbed = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {t.id for node in tree.body if isinstance(node, (ast.Assign, ast.AnnAssign))
                for t in (node.targets if isinstance(node, ast.Assign) else [node.target])
                if isinstance(t, ast.Name)}
    public = {name for name in dir(_foresight) if not name.startswith("_")}
    assert public <= stubbed, f"no stub for {sorted(public - stubbed)}"


def test_stub_signatures_match_the_module():
    tree = ast.parse(STUB.read_text())
    checked = 0
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            native = getattr(_foresight, node.name)
            assert stub_parameters(node) == parameter_names(native.__doc__), node.name
            checked += 1
        elif isinstance(node, ast.ClassDef) and node.name != "InputError":
            cls = getattr(_foresight, node.name)
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    doc = getattr(cls, item.name).__doc__
                    assert stub_parameters(item) == parameter_names(doc), \
                        f"{node.name}.{item.name}"
                    checked += 1
                elif isinstance(item, ast.AnnAssign):
                    assert hasattr(cls, item.target.id), f"{node.name}.{item.target.id}"
    assert checked > 20
