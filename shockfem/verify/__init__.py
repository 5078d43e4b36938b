"""``shockfem verify``: verification against exact solutions and published results."""
from __future__ import annotations

import time

from mpi4py import MPI

from .registry import CASES, GROUPS


def run_cases(names, size: str = "default", workdir: str = "results/verify", echo=print) -> list[dict]:
    """Run the named cases (a group name, such as ``hard``, stands for its cases); print each check as it
    completes; return all checks."""
    names = [case for n in names for case in GROUPS.get(n, [n])]
    unknown = [n for n in names if n not in CASES]
    if unknown:
        from ..scene import SceneError
        raise SceneError([f"verify: unknown case(s) {', '.join(unknown)} (see shockfem verify --list)"])
    results = []
    rank0 = MPI.COMM_WORLD.rank == 0
    if rank0:
        echo(f"{'check':44s} {'reference':>13s} {'result':>13s} {'error':>10s} {'tol':>8s}  pass   wall[s]")
    for name in names:
        t0 = time.perf_counter()
        checks = CASES[name](size, f"{workdir}/{name}")
        for c in checks:
            c["case"] = name
            c["size"] = size
            if rank0:
                echo(f"{c['name']:44s} {c['reference']:13.6g} {c['result']:13.6g} {c['error']:10.3g} "
                     f"{c['tolerance']:8.2g}  {'PASS' if c['passed'] else 'FAIL'}  {c['wall_time_s']:7.2f}")
                if c.get("note"):
                    echo(f"    {c['note']}")
        results.extend(checks)
        if rank0:
            echo(f"  ({name}: {time.perf_counter() - t0:.1f} s including meshing and compilation)")
    if rank0:
        n_pass = sum(r["passed"] for r in results)
        echo(f"{n_pass} of {len(results)} checks passed")
    return results
