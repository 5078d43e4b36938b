"""Where numba's compile time goes: every kernel a run compiles, its signatures, its own compile time and
the size of its machine code, and the compiler passes' shares.

    NUMBA_CACHE_DIR=$(mktemp -d) python scripts/compile-profile.py studies/foundation/bar_impact.toml
    NUMBA_CACHE_DIR=$(mktemp -d) python scripts/compile-profile.py studies/gallery/split_cone.toml --steps-s 2e-6

An empty ``NUMBA_CACHE_DIR`` makes numba compile everything (its own locator comes first and finds nothing;
the package's ``__pycache__`` is not read).  The scene runs for ``--steps-s`` of simulated time (a few steps
call every kernel the scene has), through ``runner.run_scene`` as ``shockfem run`` does, with no pictures.

numba broadcasts a ``numba:compile`` event around each compile of a dispatcher (a function that is not
``inline="always"``) and a ``numba:run_pass`` event around each compiler pass.  A compile includes the
compiles of the dispatchers it calls (typing the caller compiles the callee); a kernel's *own* time below
is its compile minus those nested in it.  An ``inline="always"`` function has no compile of its own: its IR
is copied into each caller, which types and optimises it again, so its cost is in its callers' own times.
Times are of the process's CPU (``time.process_time``), so a shared machine's other work does not count.
"""
from __future__ import annotations

import argparse
import collections
import os
import sys
import tempfile
import time


class CompileRecorder:
    """Exclusive CPU time per compiled dispatcher signature and per compiler pass, from numba's events."""

    def __init__(self):
        self.stack = []                 # (kind, key, start, time of nested events of the same kind)
        self.pass_stack = []
        self.kernels = collections.defaultdict(lambda: {"signatures": 0, "own_s": 0.0, "total_s": 0.0})
        self.passes = collections.Counter()
        self.dispatchers = {}

    def on_compile(self, event):
        if event.is_start:
            disp = event.data["dispatcher"]
            key = f"{disp.py_func.__module__}.{disp.py_func.__qualname__}"
            self.dispatchers.setdefault(key, set()).add(disp)
            self.stack.append([key, time.process_time(), 0.0])
        else:
            key, start, nested = self.stack.pop()
            took = time.process_time() - start
            entry = self.kernels[key]
            entry["signatures"] += 1
            entry["total_s"] += took
            entry["own_s"] += took - nested
            if self.stack:
                self.stack[-1][2] += took

    def on_pass(self, event):
        if event.is_start:
            self.pass_stack.append([event.data["name"], time.process_time(), 0.0])
        else:
            name, start, nested = self.pass_stack.pop()
            took = time.process_time() - start
            self.passes[name] += took - nested
            if self.pass_stack:
                self.pass_stack[-1][2] += took


def _listener(callback):
    """A numba event listener that hands every event, start and end, to ``callback``."""
    from numba.core import event

    class Forward(event.Listener):
        def on_start(self, ev):
            callback(ev)

        def on_end(self, ev):
            callback(ev)

    return Forward()


def machine_code(dispatchers) -> str:
    """The assembly of every signature the ``dispatchers`` (one kernel's: a closure may have several) compiled."""
    return "".join(d.inspect_asm(sig) for d in dispatchers for sig in d.signatures)


def inline_always_functions() -> int:
    """How many ``inline="always"`` functions the package defines (read from its source)."""
    import shockfem
    root = os.path.dirname(shockfem.__file__)
    count = 0
    for folder, _, files in os.walk(root):
        for f in files:
            if f.endswith(".py"):
                with open(os.path.join(folder, f), encoding="utf-8") as fh:
                    count += fh.read().count('inline="always"')
    return count


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", help="a scene TOML")
    parser.add_argument("--steps-s", type=float, default=2e-6, help="simulated time to run [s]")
    parser.add_argument("--top", type=int, default=25, help="kernels listed, by their own time")
    parser.add_argument("--asm", metavar="DIR", help="write each kernel's assembly into DIR (to compare two builds)")
    args = parser.parse_args(argv)
    os.environ.setdefault("SHOCKFEM_PICTURES", "0")
    t0 = time.process_time()
    from numba.core import event

    import shockfem.materials            # numba's inliner as every run compiles with it (numba_inline.py)

    from shockfem.runner import run_scene
    from shockfem.scene import read_toml, resolve
    rec = CompileRecorder()
    event.register("numba:compile", _listener(rec.on_compile))
    event.register("numba:run_pass", _listener(rec.on_pass))
    t_import = time.process_time() - t0
    raw = read_toml(args.scene)
    raw["scene"]["end_time"] = args.steps_s
    with tempfile.TemporaryDirectory() as out:
        os.environ.setdefault("SHOCKFEM_MESH_CACHE", os.path.join(out, "meshes"))
        t1 = time.process_time()
        run_scene(resolve(raw), os.path.join(out, "run"), progress=False, quiet=True)
        t_run = time.process_time() - t1
    compiled = sum(k["own_s"] for k in rec.kernels.values())
    print(f"# {args.scene}: CPU {t_import:.1f} s imports, {t_run:.1f} s the run, of which "
          f"{compiled:.1f} s numba compiling {sum(k['signatures'] for k in rec.kernels.values())} "
          f"signatures of {len(rec.kernels)} kernels; the package has {inline_always_functions()} "
          f'inline="always" functions')
    print("\n| kernel | signatures | own compile CPU [s] | with its callees [s] | machine code [kB] |")
    print("|---|---:|---:|---:|---:|")
    ranked = sorted(rec.kernels.items(), key=lambda kv: -kv[1]["own_s"])
    for key, k in ranked[:args.top]:
        size = len(machine_code(rec.dispatchers[key]))
        print(f"| `{key.replace('shockfem.', '')}` | {k['signatures']} | {k['own_s']:.1f} | {k['total_s']:.1f} | "
              f"{size / 1024:.0f} |")
    rest = ranked[args.top:]
    if rest:
        print(f"| {len(rest)} others | {sum(k['signatures'] for _, k in rest)} | "
              f"{sum(k['own_s'] for _, k in rest):.1f} | | |")
    print("\n| compiler pass | CPU [s] |")
    print("|---|---:|")
    for name, took in rec.passes.most_common(8):
        print(f"| {name} | {took:.1f} |")
    if args.asm:
        os.makedirs(args.asm, exist_ok=True)
        for key, dispatchers in rec.dispatchers.items():
            with open(os.path.join(args.asm, key + ".s"), "w", encoding="utf-8") as f:
                f.write(machine_code(dispatchers))
    return 0


if __name__ == "__main__":
    sys.exit(main())
