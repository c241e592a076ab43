# docs/python.md says exactly what the code does: its list of signatures equals the
# functions' own (inspect.signature), and so do the type stubs (gyrores/__init__.pyi).
import ast
import inspect
import os
import re

import gyrores
import gyrores.plot

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PUBLIC = ["pair", "pairs", "asymptotics", "certify", "check", "design", "pareto", "coupling", "couplings",
          "enumerate_pairs", "sweep", "plant"]
PLOTS = ["phase", "energy", "pareto", "coupling_floor"]


def _documented_signatures():
    with open(os.path.join(ROOT, "docs", "python.md"), encoding="utf-8") as f:
        text = f.read()
    section = text[text.index("## Getting started\n"):]
    section = section[:section.index("\n## ", 1)]
    block = section[section.index("The public functions"):]
    block = block[block.index("```python\n") + len("```python\n"):]
    block = block[:block.index("```")]
    return {re.match(r"gyrores\.([\w.]+)\(", line).group(1): line.split("   #")[0].strip()
            for line in block.splitlines() if line.startswith("gyrores.")}


def _code_signatures():
    sigs = {name: f"gyrores.{name}{inspect.signature(getattr(gyrores, name))}" for name in PUBLIC}
    for name in PLOTS:
        sigs[f"plot.{name}"] = f"gyrores.plot.{name}{inspect.signature(getattr(gyrores.plot, name))}"
    return sigs


def test_docs_list_every_public_function_with_its_signature():
    assert _documented_signatures() == _code_signatures()


def test_type_stubs_match_the_code():
    with open(os.path.join(ROOT, "python", "gyrores", "__init__.pyi"), encoding="utf-8") as f:
        tree = ast.parse(f.read())
    stubs = {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}
    assert set(PUBLIC) <= set(stubs)
    for name in PUBLIC:
        params = inspect.signature(getattr(gyrores, name)).parameters
        args = stubs[name].args
        assert [a.arg for a in args.args] == list(params), name
        defaults = [ast.literal_eval(d) for d in args.defaults]
        expected = [p.default for p in params.values() if p.default is not inspect.Parameter.empty]
        assert defaults == expected, name


def test_all_names_exist():
    for name in gyrores.__all__:
        assert hasattr(gyrores, name), name
