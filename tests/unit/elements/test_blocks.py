"""Every element pass takes the same arguments (``blocks.PASS_ARGUMENTS``), so that the solver calls any of
them alike; the lane passes are the block driver's, one per element and copy, each under its own name."""
import inspect

from shockfem.elements import blocks, cells as ec, kernels

CHOICES = [(kind, False) for kind in (ec.TRIANGLE, ec.QUADRILATERAL, ec.TETRAHEDRON, ec.HEXAHEDRON)] + \
    [(ec.QUADRILATERAL, True), (ec.HEXAHEDRON, True)]


def test_every_pass_takes_the_same_arguments():
    for kind, one_point in CHOICES:
        for elastic_only in (True, False):
            py_func = kernels.element_pass(kind, one_point, elastic_only).py_func
            assert tuple(inspect.signature(py_func).parameters) == blocks.PASS_ARGUMENTS, (kind, one_point)


def test_the_lane_passes_are_the_drivers_each_named_and_filed_under_its_element():
    """Named apart (numba's symbols for two functions of one name collide in a cache) and filed under the
    element's module (its cache beside the module's file, dropped when the module changes)."""
    names = set()
    lanes = ((ec.QUADRILATERAL, True, "one_point_quads"), (ec.HEXAHEDRON, True, "one_point_hexes"),
             (ec.TETRAHEDRON, False, "linear_tets"))
    for kind, one_point, module in lanes:
        for elastic_only in (True, False):
            py_func = kernels.element_pass(kind, one_point, elastic_only).py_func
            assert py_func.__code__.co_code == blocks._element_pass.__code__.co_code
            assert py_func.__module__ == f"shockfem.elements.{module}"
            assert inspect.getfile(py_func).endswith(f"{module}.py")
            names.add(py_func.__qualname__)
    assert len(names) == 6
