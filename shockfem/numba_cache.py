"""numba's caches of the package dropped where a module they were compiled from has changed.

numba keys a cached function on its own file's time stamp and size only: a compiled function that calls
one defined in another module keeps that module's old code in its cache after the module changes (numba
GitHub issue 1833, a documented limitation).  shockfem's passes call across modules everywhere (a contact
pair's fused step in ``contact/pair_step.py`` calls ``contact/kernels.py``; the element passes call the
materials' updates), so an update of one file could leave runs computing with a mix of old and new code.
It happened (a measured case): after ``contact/kernels.py`` changed, the 3D two-rod
contact case in one process, whose step ``pair_step`` had cached, put forces 220 N apart from the
same case's MPI path at its first step, which calls the kernels directly.

``drop_stale_caches`` runs as shockfem is imported, before any of its modules compiles.  It reads which
of the package's modules each module imports (``ast``, all the imports in the file, those inside
functions too), and keeps them with the files' stamps in ``__pycache__/numba-dependencies.json``; only a
file whose stamp changed is read again.  Where any module in a module's import closure has changed since
the last import, it deletes that module's numba cache files (``<module>.*.nbi`` and ``.nbc``, where numba
keeps them), so that numba compiles it again.  With no record yet (a fresh checkout, or caches from before
this module), every cache of the package is dropped once.  Without a writable ``__pycache__`` it does
nothing; numba then keeps its caches elsewhere, as it would.
"""
from __future__ import annotations

import json
import os

PACKAGE = os.path.dirname(os.path.abspath(__file__))
RECORD = os.path.join(PACKAGE, "__pycache__", "numba-dependencies.json")


def drop_stale_caches(package: str = PACKAGE, record: str = RECORD) -> list[str]:
    """Delete the numba cache files of every module of ``package`` whose import closure changed since the
    last call (all of them if there is no ``record``), and write the new record; returns the modules whose
    caches were dropped."""
    before = _read(record)
    modules = _modules(package)
    known = before.get("modules", {})
    now = {}
    for name, path in modules.items():
        st = os.stat(path)
        stamp = [st.st_mtime_ns, st.st_size]
        old = known.get(name)
        imports = old["imports"] if old and old["stamp"] == stamp else _imports(name, path, modules)
        now[name] = {"stamp": stamp, "imports": imports}
    if set(now) == set(known) and all(now[m]["stamp"] == known[m]["stamp"] for m in now):
        return []                         # no file changed (every import but the first after an edit)
    closures = {name: _closure_key(name, now) for name in now}
    stale = sorted(name for name in now if known.get(name, {}).get("closure") != closures[name])
    for name in now:
        now[name]["closure"] = closures[name]
    if stale:
        for name in stale:
            _delete_caches(modules[name])
    if stale or set(now) != set(known):
        _write(record, {"modules": now})
    return stale


def _modules(package: str) -> dict[str, str]:
    """Module name (dotted, relative to the package; "" for its ``__init__``) -> file, for every file."""
    out = {}
    for folder, dirs, files in os.walk(package):
        dirs[:] = [d for d in dirs if d != "__pycache__"]
        rel = os.path.relpath(folder, package)
        parts = [] if rel == "." else rel.split(os.sep)
        for f in files:
            if f.endswith(".py"):
                name = parts if f == "__init__.py" else parts + [f[:-3]]
                out[".".join(name)] = os.path.join(folder, f)
    return out


def _imports(name: str, path: str, modules: dict[str, str]) -> list[str]:
    """The package's modules that the file of module ``name`` imports (relative or as ``shockfem.x``)."""
    import ast                              # here, as the other imports below: only when a file changed
    with open(path, encoding="utf-8") as f:
        tree = ast.parse(f.read(), path)
    package = name.split(".") if path.endswith("__init__.py") else name.split(".")[:-1]
    package = [p for p in package if p]
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)] if node.level > 1 else list(package)
            elif node.module and node.module.split(".")[0] == "shockfem":
                base = []
            else:
                continue
            target = base + (node.module.split(".")[1 if not node.level else 0:] if node.module else [])
            found.add(".".join(target))
            for alias in node.names:          # ``from . import kernels``: a module of the package
                found.add(".".join(target + [alias.name]))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "shockfem":
                    found.add(".".join(alias.name.split(".")[1:]))
    return sorted(m for m in found if m in modules and m != name)


def _closure_key(name: str, now: dict) -> str:
    """A hash of the stamps of every module that ``name`` imports, directly or not, and its own."""
    import hashlib
    seen, todo = set(), [name]
    while todo:
        m = todo.pop()
        if m not in seen:
            seen.add(m)
            todo.extend(now[m]["imports"])
    text = ";".join(f"{m}:{now[m]['stamp'][0]}:{now[m]['stamp'][1]}" for m in sorted(seen))
    return hashlib.sha1(text.encode()).hexdigest()


def _delete_caches(path: str):
    """Delete numba's cache files of the module in file ``path``: its index (.nbi) and data (.nbc) files, in
    the directory numba keeps them for that file."""
    import glob
    folder = _cache_folder(path)
    if folder is None:
        return
    stem = os.path.splitext(os.path.basename(path))[0]
    for f in glob.glob(os.path.join(glob.escape(folder), f"{glob.escape(stem)}.*.nb[ic]")):
        try:
            os.remove(f)
        except FileNotFoundError:          # another process (an MPI rank, a test worker) took it first
            pass


def _cache_folder(path: str) -> str | None:
    """Where numba keeps the caches of functions of file ``path``: its first locator that takes the file
    (the user's ``NUMBA_CACHE_DIR``, else the file's ``__pycache__``, else numba's user-wide folder)."""
    from numba.core.caching import CacheImpl      # numba's own choice of folder (imported only if needed)
    for locator in CacheImpl._locator_classes:
        found = locator.from_function(_cache_folder, path)
        if found is not None:
            return found.get_cache_path()
    return None


def _read(record: str) -> dict:
    try:
        with open(record, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def _write(record: str, data: dict):
    """Write ``data`` to ``record`` as a whole (a rename): another process reads the old record or the new."""
    partial = f"{record}.{os.getpid()}.partial"
    try:
        os.makedirs(os.path.dirname(record), exist_ok=True)
        with open(partial, "w", encoding="utf-8") as f:
            json.dump(data, f)
        os.replace(partial, record)
    except OSError:                 # a read-only install: numba keeps its caches elsewhere then
        pass
