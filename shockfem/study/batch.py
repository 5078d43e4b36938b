"""A batch of runs: a table of cases -> one run directory per case -> one table of their results.

A case is a scene file with ``--set`` overrides (its factors' levels).  Every case runs as its own
``shockfem run`` process (``mpirun -n k`` before it for ``ranks`` > 1), so that a case that crashes,
hangs up its MPI ranks or is killed takes nothing else with it, and so that a case runs the same
whichever executor starts it:

* ``local``: ``workers`` cases at a time on this machine (threads that wait on their processes);
* ``dask``: a Dask distributed cluster (``distributed.LocalCluster`` of ``workers`` single-threaded
  worker processes, or the scheduler at ``scheduler``, e.g. one that dask-jobqueue started on SLURM);
  each task starts its case's process on the worker's machine (``docs/studies.md`` says why Dask).

Resumable: each case directory keeps ``case.json`` (its definition) beside the run; a case whose
``summary.json`` says ``completed`` for the same definition is not run again; one that a kill or a
signal stopped with a checkpoint goes on from it (``shockfem run --resume``); anything else runs from
the start.  A failed case is recorded (status, exit code, the tail of its error in ``case.log``) and the
others go on.  ``batch.json`` (every case's row) and ``cases.csv`` / ``cases.h5`` (the table, units in
the headers) are rewritten as each case ends.
"""
from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass, field

import h5py
import numpy as np

from ..metrics.stages import first_impacts

EXECUTORS = ("local", "dask")
TIMEOUT_S = 24 * 3600          # a case that runs longer than a day is taken as hung


@dataclass(frozen=True)
class Case:
    """One run of a batch: ``scene`` with ``overrides`` (``path=value``), named ``name`` (its directory);
    ``factors`` the levels that make it this case, for the table (``{path: level as given}``)."""
    name: str
    scene: str
    overrides: tuple[str, ...]
    factors: dict = field(default_factory=dict)

    def definition(self) -> dict:
        return {"scene": os.path.abspath(self.scene), "overrides": list(self.overrides), "factors": self.factors}


def _read_json(path: str):
    try:
        with open(path) as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def _write_json(path: str, data):
    partial = path + ".partial"
    with open(partial, "w") as fh:
        json.dump(data, fh, indent=1)
    os.replace(partial, path)


def _command(case: Case, path: str, ranks: int, resume: bool) -> list[str]:
    launcher = ["mpirun", "-n", str(ranks)] if ranks > 1 else []
    shockfem = [sys.executable, "-m", "shockfem", "run"]
    if resume:
        return launcher + shockfem + ["--resume", path, "--no-progress"]
    sets = [a for o in case.overrides for a in ("--set", o)]
    return launcher + shockfem + [case.scene, "--out", path, "--no-progress", *sets]


def run_case(case: Case, out_dir: str, ranks: int = 1, rerun: bool = False) -> dict:
    """Run ``case`` into ``out_dir/<name>`` unless it is done already (``rerun``: from the start whatever its
    directory holds); its row (``case_row``).  What an executor's worker runs: a process of its own, its
    result read back from the run directory."""
    path = os.path.join(out_dir, case.name)
    os.makedirs(path, exist_ok=True)
    same = not rerun and _read_json(os.path.join(path, "case.json")) == case.definition()
    summary = _read_json(os.path.join(path, "summary.json")) if same else None
    if summary and summary.get("status") == "completed":
        return case_row(case, summary, 0, 0.0, "skipped: completed before")
    resume = same and os.path.exists(os.path.join(path, "checkpoint", "latest.json"))
    _write_json(os.path.join(path, "case.json"), case.definition())
    t0 = time.perf_counter()
    try:
        done = subprocess.run(_command(case, path, ranks, resume), capture_output=True, text=True,
                              timeout=TIMEOUT_S, env={**os.environ, "OMPI_ALLOW_RUN_AS_ROOT": "1",
                                                      "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
        code, err = done.returncode, done.stderr
    except subprocess.TimeoutExpired as exc:
        code, err = -1, f"no end after {TIMEOUT_S} s (killed)\n{exc.stderr or ''}"
    wall = time.perf_counter() - t0
    with open(os.path.join(path, "case.log"), "w") as fh:
        fh.write(" ".join(_command(case, path, ranks, resume)) + f"\nexit code {code}\n{err}")
    summary = _read_json(os.path.join(path, "summary.json"))
    how = "resumed from its checkpoint" if resume else "run"
    if code != 0 and (summary is None or summary.get("status") in (None, "running", "completed")):
        summary = {"status": "failed", "diagnosis": (err.strip().splitlines() or ["no message"])[-1]}
    return case_row(case, summary or {"status": "failed"}, code, wall, how)


def case_row(case: Case, summary: dict, exit_code: int, wall: float, how: str) -> dict:
    """A case's row: its name, factors, status and how it ran, then the summary's headline numbers as
    ``{"name [unit]": value}``: steps, end time, energy balance, per body the final velocity, largest von
    Mises stress and plastic strain, kinetic and internal energy; per shock channel its peak, duration and
    velocity change and whether the tolerance band held; per contact its largest force and penetration."""
    row = {"case": case.name}
    row.update({f"{k} [as given]": v for k, v in case.factors.items()})
    row.update({"status": summary.get("status"), "exit code": exit_code, "how": how,
                "wall time [s]": round(wall, 3), "diagnosis": summary.get("diagnosis") or ""})
    if summary.get("chain"):
        row.update(chain_columns(summary["chain"]))
    if "steps" not in summary:
        return row
    axes = ("r", "z") if summary.get("kinematics") == "axisymmetric" else "xyz"
    row.update({"elements": summary["elements"], "steps": summary["steps"], "end time [s]": summary["end_time"],
                "energy balance error [-]": summary["energy"]["balance_error"],
                "warnings": len(summary.get("warnings", []))})
    for name, b in (summary.get("bodies") or {}).items():
        for axis, v in zip(axes, b["velocity_final"]):
            row[f"{name}.velocity_final_{axis} [m/s]"] = v
        row[f"{name}.max_von_mises [Pa]"] = b["max_von_mises"]
        row[f"{name}.max_plastic_strain [-]"] = b["max_plastic_strain"]
        for key in ("kinetic_energy", "internal_energy"):
            if key in b:
                row[f"{name}.{key} [J]"] = b[key]
    for name, ch in ((summary.get("shock") or {}).get("channels") or {}).items():
        pulse = ch.get("pulse") or {}
        for key, unit in (("peak_g", "g"), ("duration", "s"), ("velocity_change", "m/s")):
            if key in pulse:
                row[f"{name}.pulse.{key} [{unit}]"] = pulse[key]
        if "tolerance" in ch:
            row[f"{name}.pulse.within_tolerance"] = ch["tolerance"].get("passed")
    for name, c in (summary.get("contacts") or {}).items():
        row[f"contact.{name}.max_normal_force [N]"] = c.get("max_normal_force")
        row[f"contact.{name}.max_penetration [m]"] = c.get("max_penetration")
    return row


def chain_columns(chain: dict) -> dict:
    """A chain run's headline numbers (``summary.json``'s ``chain``, ``amplifier/chain.py``): its
    fidelity, the test article's final speed and the gain, each pair's restitution at its first impact,
    each body's peak stress over its yield, and whether a contact was still closed at the end."""
    row = {"chain.fidelity": chain["fidelity"], "chain.test_article_speed [m/s]": chain["test_article_speed"],
           "chain.gain [-]": chain["gain"], "chain.contact_at_end": chain["contact_at_end"]}
    for pair, e in first_impacts(chain["stages"]).items():
        row[f"chain.{pair}.restitution [-]"] = e
    for body, ratio in chain["stress_over_yield"].items():
        row[f"chain.{body}.peak_stress_over_yield [-]"] = ratio
    return row


def write_table(rows: list[dict], out_dir: str):
    """``batch.json`` (the rows), ``cases.csv`` and ``cases.h5`` (one column per key; units in the names),
    each written beside and renamed into place."""
    _write_json(os.path.join(out_dir, "batch.json"), rows)
    columns = list(dict.fromkeys(k for r in rows for k in r))
    partial = os.path.join(out_dir, "cases.csv.partial")
    with open(partial, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(columns)
        for r in rows:
            w.writerow(["" if r.get(c) is None else r.get(c) for c in columns])
    os.replace(partial, os.path.join(out_dir, "cases.csv"))
    partial = os.path.join(out_dir, "cases.h5.partial")
    with h5py.File(partial, "w") as h5:
        for c in columns:
            values = [r.get(c) for r in rows]
            if all(isinstance(v, (int, float, bool, np.number)) and v is not None for v in values):
                h5.create_dataset(c.replace("/", "_"), data=np.array(values, dtype=float))
            else:
                h5.create_dataset(c.replace("/", "_"), data=np.array(["" if v is None else str(v) for v in values],
                                                                    dtype=h5py.string_dtype()))
    os.replace(partial, os.path.join(out_dir, "cases.h5"))


def _dask_client(workers: int, scheduler: str | None, verbose: bool = False):
    """A client of the scheduler at ``scheduler``, or of a local cluster of ``workers`` single-threaded
    worker processes (closed with the client).  Dask's ``distributed`` log lines below WARNING (workers
    starting and stopping, the scheduler's address: a dozen INFO lines a sweep) are shown only if
    ``verbose``, in this process and in the local cluster's workers."""
    import logging
    from distributed import Client, LocalCluster
    level = logging.INFO if verbose else logging.WARNING
    logging.getLogger("distributed").setLevel(level)
    if scheduler:
        return Client(scheduler)
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                           silence_logs=level)
    return Client(cluster)


def run_batch(cases: list[Case], out_dir: str, executor: str = "local", workers: int | None = None,
              ranks: int = 1, scheduler: str | None = None, progress: bool = True, echo=print,
              rerun: bool = False, verbose: bool = False) -> list[dict]:
    """Run every case (``run_case``; ``rerun``: none skipped or resumed) with ``executor`` (``EXECUTORS``),
    ``workers`` at a time (default: the cores over the ranks a case takes); returns the rows in the cases'
    order, also written to ``out_dir`` as they come (``write_table``).  ``verbose``: Dask's INFO lines too."""
    if executor not in EXECUTORS:
        raise ValueError(f"executor: one of {', '.join(EXECUTORS)}, got {executor!r}")
    os.makedirs(out_dir, exist_ok=True)
    workers = workers or max(1, (os.cpu_count() or 1) // ranks)
    rows: dict[str, dict] = {}
    order = [c.name for c in cases]
    bar = None
    if progress:
        from tqdm import tqdm
        bar = tqdm(total=len(cases), unit="case", desc=os.path.basename(os.path.abspath(out_dir)))

    def finished(row):
        rows[row["case"]] = row
        write_table([rows[n] for n in order if n in rows], out_dir)
        if bar is not None:
            bar.update(1)
            bar.set_postfix_str(f"{row['case']}: {row['status']}")
        else:
            echo(f"  {row['case']}: {row['status']} ({row['how']}, {row['wall time [s]']:.1f} s)")

    if executor == "local":
        with ThreadPoolExecutor(max_workers=workers) as pool:
            for future in as_completed([pool.submit(run_case, c, out_dir, ranks, rerun) for c in cases]):
                finished(future.result())
    else:
        from distributed import as_completed as dask_completed
        with _dask_client(workers, scheduler, verbose) as client:
            futures = [client.submit(run_case, c, os.path.abspath(out_dir), ranks, rerun,
                                     key=f"shockfem-{c.name}-{i}", pure=False) for i, c in enumerate(cases)]
            for future in dask_completed(futures):
                finished(future.result())
            # the results are in: let the scheduler forget them before the workers go, or it warns that
            # closing the cluster loses computed tasks "which will be recomputed elsewhere" (they are not)
            client.cancel(futures)
            del futures
            if not scheduler:
                client.cluster.close()
    if bar is not None:
        bar.close()
    return [rows[n] for n in order]
