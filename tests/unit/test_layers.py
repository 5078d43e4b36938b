"""Imports point downstream: a module imports only its own layer and the layers below it.

The layers, lowest first, follow the data flow (``docs/theory.md``, "Layers"): the compiled laws and
element kernels need nothing of shockfem; the parts catalogue is pure geometry the scene checker reads;
the scene is meshed (geometry), becomes a model, runs in the solver loop, is written (output) and
measured (metrics); whole runs, the engineering models, the studies and the command line sit on top.
Every import is counted, at module level or inside a function, relative or absolute.
"""
import ast
import pathlib

import shockfem

PACKAGE = pathlib.Path(shockfem.__file__).parent

LAYERS = [
    {"units", "errors", "compat", "version", "mpi_start", "dolfinx_start", "numba_cache", "data_stack", "numba_inline"},
    {"materials"},
    {"elements"},
    {"parts"},
    {"scene"},
    {"importers"},
    {"geometry"},
    {"model"},
    {"forces", "contact", "fluid", "target"},
    {"solver"},
    {"output"},
    {"metrics"},
    {"runner"},
    {"modal", "launcher", "amplifier", "programmer", "penetration"},
    {"machine"},
    {"verify", "study", "bench", "warm"},
    {"api", "cli", "__main__", "__init__"},
]
RANK = {name: k for k, layer in enumerate(LAYERS) for name in layer}


def _unit(module: str) -> str:
    """The layer unit of a dotted module name inside the package: its first component below shockfem."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def _module_name(path: pathlib.Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    return ".".join(rel.parts)


def _imports(source: str, module: str):
    """(line, imported module) of every shockfem import in the source of ``module``, relative ones resolved."""
    parts = module.split(".")
    package = parts[:-1] if parts[-1] != "__init__" else parts[:-1]
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if not target.startswith("shockfem"):
                continue
            if node.module is None or target == "shockfem":
                # "from .. import compat": each name may be a module of its own
                for alias in node.names:
                    yield node.lineno, f"{target}.{alias.name}"
            else:
                yield node.lineno, target
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("shockfem"):
                    yield node.lineno, alias.name


def upward_imports(source: str, module: str) -> list[str]:
    """The imports of ``module`` that point to a layer above its own."""
    own = _unit(module)
    return [f"{module}:{line} ({own}) imports {target} ({_unit(target)})"
            for line, target in _imports(source, module)
            if _unit(target) in RANK and RANK[_unit(target)] > RANK[own]]


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        yield path, _module_name(path)


def test_every_module_has_a_layer():
    units = {_unit(name) for _, name in _modules()}
    assert units - set(RANK) == set(), "give these modules a layer in LAYERS"


def test_imports_point_downstream():
    upward = [v for path, name in _modules() for v in upward_imports(path.read_text(), name)]
    assert upward == [], "imports that point up a layer:\n" + "\n".join(upward)


def test_the_checker_sees_upward_imports():
    """Relative (one and two levels, inside a function) and absolute imports of a higher layer are
    caught; the package's own and lower layers are not."""
    source = """
from ..model import Model
from . import cells
from ..materials.layout import P_MU
import shockfem.solver.explicit

def later():
    from .. import runner
"""
    found = upward_imports(source, "shockfem.elements.fake")
    assert [f.split(" imports ")[1] for f in found] == ["shockfem.model (model)", "shockfem.solver.explicit (solver)",
                                                        "shockfem.runner (runner)"]


# Inside ``elements``: the cells' geometry and the passes' shared helpers, the block driver of the lane passes,
# the passes, and the choice among them.  A pass builds on the driver; the driver knows no element.
ELEMENT_LAYERS = [
    {"cells", "one_point"},
    {"blocks"},
    {"full_integration", "linear_tets", "one_point_hexes", "one_point_quads"},
    {"kernels", "__init__"},
]
ELEMENT_RANK = {name: k for k, layer in enumerate(ELEMENT_LAYERS) for name in layer}


def test_every_element_module_has_a_layer():
    names = {path.stem for path in (PACKAGE / "elements").glob("*.py")}
    assert names - set(ELEMENT_RANK) == set(), "give these modules of elements/ a layer in ELEMENT_LAYERS"


def test_the_element_passes_build_on_the_block_driver():
    upward = []
    for path in sorted((PACKAGE / "elements").glob("*.py")):
        own = path.stem
        for line, target in _imports(path.read_text(), _module_name(path)):
            parts = target.split(".")
            if parts[:2] == ["shockfem", "elements"] and len(parts) > 2 and \
                    ELEMENT_RANK.get(parts[2], -1) > ELEMENT_RANK[own]:
                upward.append(f"elements.{own}:{line} imports {target}")
    assert upward == [], "imports inside elements/ that point up:\n" + "\n".join(upward)
