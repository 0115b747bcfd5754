"""The installed facet.pyi against the installed module: the same public
names, every function's and method's parameters in the same order, kinds
and defaults, every class attribute, and a docstring on each."""
import ast
import importlib.util
import pathlib
import unittest

import facet

STUB = pathlib.Path(importlib.util.find_spec("facet").origin).with_name("facet.pyi")


def split_top_level(text):
    """`text` split at the commas outside brackets and quotes."""
    parts, depth, quote, current = [], 0, None, ""
    for c in text:
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(current.strip())
            current = ""
            continue
        current += c
    return parts + ([current.strip()] if current.strip() else [])


def module_parameters(function):
    """[(name, keyword_only, default or Ellipsis)] from pybind11's signature line."""
    line = function.__doc__.splitlines()[0]
    inside = line[line.index("(") + 1:line.rindex(") ->")]
    parameters, keyword_only = [], False
    for part in split_top_level(inside):
        if part == "*":
            keyword_only = True
            continue
        name, _, rest = part.partition(":")
        default = ast.literal_eval(rest.split(" = ", 1)[1]) if " = " in rest else ...
        if name != "self":
            parameters.append((name.strip(), keyword_only, default))
    return parameters


def stub_parameters(node):
    """The same list from a stub's `def`."""
    args = node.args
    positional = [a for a in args.args if a.arg != "self"]
    defaults = [...] * (len(positional) - len(args.defaults)) + [ast.literal_eval(d) for d in args.defaults]
    keyword = [ast.literal_eval(d) if d is not None else ... for d in args.kw_defaults]
    return ([(a.arg, False, d) for a, d in zip(positional, defaults)] +
            [(a.arg, True, d) for a, d in zip(args.kwonlyargs, keyword)])


class Stub(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tree = ast.parse(STUB.read_text())
        cls.top = {getattr(n, "name", None): n for n in cls.tree.body}

    def test_the_stub_names_what_the_module_has(self):
        public = {n for n in dir(facet) if not n.startswith("_")}
        stubbed = {n for n in self.top if n and not n.startswith("_")} - {"Vec3", "SceneOrPath"}
        self.assertEqual(stubbed, public)

    def test_every_function_and_method_matches_its_signature(self):
        checked = 0
        for name, node in self.top.items():
            if isinstance(node, ast.FunctionDef):
                self.assertEqual(stub_parameters(node), module_parameters(getattr(facet, name)), name)
                checked += 1
            if isinstance(node, ast.ClassDef) and name != "Error":
                cls = getattr(facet, name)
                for member in node.body:
                    if isinstance(member, ast.FunctionDef) and not member.decorator_list:
                        self.assertEqual(stub_parameters(member), module_parameters(getattr(cls, member.name)),
                                         f"{name}.{member.name}")
                        checked += 1
        self.assertGreaterEqual(checked, 13)

    def test_every_attribute_is_stubbed_and_documented(self):
        for name, node in self.top.items():
            if not isinstance(node, ast.ClassDef) or name == "Error":
                continue
            cls = getattr(facet, name)
            self.assertTrue((cls.__doc__ or "").strip(), f"{name} has no docstring")
            stubbed = {m.target.id for m in node.body if isinstance(m, ast.AnnAssign)}
            stubbed |= {m.name for m in node.body if isinstance(m, ast.FunctionDef) and m.decorator_list}
            methods = {m.name for m in node.body if isinstance(m, ast.FunctionDef) and not m.decorator_list}
            public = {a for a in dir(cls) if not a.startswith("_")}
            self.assertEqual(stubbed | (methods - {"__init__"}), public, name)
        for name in ("render", "parity", "brdf", "load_scene"):
            self.assertGreater(len(getattr(facet, name).__doc__.splitlines()), 1, f"{name} has no docstring")


if __name__ == "__main__":
    unittest.main()
