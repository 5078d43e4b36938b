"""numba keys a cached function on its own file only (numba GitHub issue 1833): a compiled function calling one
from another module keeps the old code after that module changes.  ``shockfem.numba_cache.drop_stale_caches``
drops the caches of every module whose import closure changed.  On a package of three modules (``a`` calls
``b``'s compiled function, ``c`` stands alone), after ``b`` changes: without the drop, ``a`` still returns
``b``'s old value (the limitation, shown so that the test can fail); with it, the new one, and ``c``'s cache
is kept."""
import glob
import os
import subprocess
import sys
import textwrap

from shockfem.numba_cache import drop_stale_caches

CALL = """
import sys
sys.path.insert(0, {root!r})
{drop}
from pkg.a import f
print(f())
"""
DROP = "from shockfem.numba_cache import drop_stale_caches; drop_stale_caches({pkg!r}, {record!r})"


def _write(path, text):
    with open(path, "w") as f:
        f.write(textwrap.dedent(text))


def _run(root, pkg, record, drop):
    code = CALL.format(root=root, drop=DROP.format(pkg=pkg, record=record) if drop else "")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return int(out.stdout.split()[-1])


def test_a_changed_module_drops_the_caches_of_the_modules_that_import_it(tmp_path):
    root = str(tmp_path)
    pkg = os.path.join(root, "pkg")
    record = os.path.join(pkg, "__pycache__", "record.json")
    os.makedirs(pkg)
    _write(os.path.join(pkg, "__init__.py"), "")
    _write(os.path.join(pkg, "b.py"), """
        from numba import njit

        @njit(cache=True)
        def g():
            return 1
        """)
    _write(os.path.join(pkg, "a.py"), """
        from numba import njit
        from .b import g

        @njit(cache=True)
        def f():
            return g() + 10
        """)
    _write(os.path.join(pkg, "c.py"), """
        from numba import njit

        @njit(cache=True)
        def h():
            return 3

        h()
        """)
    assert _run(root, pkg, record, drop=True) == 11
    subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {root!r}); import pkg.c"], check=True)
    assert drop_stale_caches(pkg, record) == []           # nothing changed since
    c_caches = glob.glob(os.path.join(pkg, "__pycache__", "c.*.nb[ic]"))
    assert c_caches

    _write(os.path.join(pkg, "b.py"), """
        from numba import njit

        @njit(cache=True)
        def g():
            return 2
        """)
    assert _run(root, pkg, record, drop=False) == 11        # numba's own check: a's cache, with b's old g
    assert drop_stale_caches(pkg, record) == ["a", "b"]    # a imports b; c imports neither
    assert glob.glob(os.path.join(pkg, "__pycache__", "c.*.nb[ic]")) == c_caches
    assert not glob.glob(os.path.join(pkg, "__pycache__", "a.*.nb[ic]"))
    assert _run(root, pkg, record, drop=True) == 12


def test_with_no_record_every_cache_is_dropped_once(tmp_path):
    pkg = tmp_path / "pkg"
    (pkg / "__pycache__").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "m.py").write_text("x = 1\n")
    (pkg / "__pycache__" / "m.f-3.py311.nbi").write_text("")
    record = str(pkg / "__pycache__" / "record.json")
    assert drop_stale_caches(str(pkg), record) == ["", "m"]
    assert not (pkg / "__pycache__" / "m.f-3.py311.nbi").exists()
    assert drop_stale_caches(str(pkg), record) == []
