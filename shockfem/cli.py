"""The ``shockfem`` command: run, check, mesh, metrics, modes, amplifier, programmer, launcher,
design-machine, study, sweep, verify, bench, warm (``shockfem COMMAND --help`` for each).

Exit codes: 0 ok, 2 bad input (every problem listed, no traceback), 3 run stopped as
unstable (outputs kept), 1 a verification case failed, 130 / 143 interrupted by SIGINT / SIGTERM.
"""
from __future__ import annotations

import argparse
import gc
import json
import os
import sys
from dataclasses import dataclass
from typing import Callable

from .mpi_start import start_mpi
from .dolfinx_start import import_dolfinx

start_mpi()         # before anything imports mpi4py (dolfinx does): a lone process starts 0.3 s sooner
import_dolfinx()    # before anything imports it: without setuptools' pkg_resources, 0.1 s sooner

from .errors import EXIT_BAD_INPUT, EXIT_INTERRUPTED, EXIT_OK, EXIT_UNSTABLE, ModelError, RunInterrupted, UnstableRun
from .api import check_raw
from .importers.command import HELP as IMPORT_HELP, import_arguments, import_command
from .units import LB
from .version import __version__


class _DefaultsShown(argparse.HelpFormatter):
    """Every option's default in its help, unless it has none or its help already says it."""

    def _get_help_string(self, action):
        text = action.help or ""
        if "default" in text or action.default in (None, False, [], argparse.SUPPRESS):
            return text
        return f"{text} (default: %(default)s)"


def _scene_arguments(p: argparse.ArgumentParser, scene_help: str = "scene file (TOML)", nargs=None):
    """The scene file and its ``--set`` overrides, as every command that reads a scene takes them."""
    p.add_argument("scene", nargs=nargs, help=scene_help)
    p.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                   help="override a scene field, e.g. bodies.striker.velocity='12 m/s' (repeat for more)")


def _json_argument(p: argparse.ArgumentParser, what: str):
    p.add_argument("--json", metavar="FILE", help=f"write {what} to this JSON file")


def _run_arguments(r):
    _scene_arguments(r, nargs="?")
    r.add_argument("--resume", metavar="RUN_DIR",
                   help="continue the run in RUN_DIR from its last checkpoint (written every "
                        "scene.checkpoint_interval and when SIGTERM or SIGINT stops a run), with as many processes")
    r.add_argument("--out", help="run directory (default: results/<scene name>)")
    r.add_argument("--no-progress", action="store_true", help="no progress bar (batch jobs, logs)")
    r.add_argument("--no-fields", action="store_true", help="skip the XDMF field output")
    r.add_argument("--fidelity", choices=("rigid", "1d", "axisymmetric", "3d"),
                   help="chain scenes: the model to run (default: the scene's chain.fidelity)")


def _check_arguments(c):
    _scene_arguments(c)


def _mesh_arguments(m):
    _scene_arguments(m)
    m.add_argument("--out", help="XDMF file to write (default: results/<scene>/mesh.xdmf)")
    m.add_argument("--png", help="also render the mesh to this PNG (3D cut open by a quarter)")


def _metrics_arguments(s):
    s.add_argument("run_dir", help="a run directory written by shockfem run")
    s.add_argument("--cfc", help="filter class instead of the scene's: 60, 180, 600, 1000 or none")


def _modes_arguments(o):
    _scene_arguments(o)
    o.add_argument("--body", help="the body (default: the scene's only deformable body)")
    o.add_argument("--count", type=int, default=10, help="elastic modes to find")
    o.add_argument("--degree", type=int, choices=(1, 2), default=1,
                   help="element degree: 2 for thin plates and shells, which lock with linear solids")
    o.add_argument("--free", action="store_true", help="ignore the scene's boundary conditions (free-free)")
    o.add_argument("--mass", choices=("consistent", "lumped"), default="consistent", help="mass matrix")
    o.add_argument("--out", help="directory for modes.json and modes.xdmf (default: results/<scene>/modes)")


def _amplifier_arguments(a):
    from .amplifier.gain import ARCHITECTURES
    a.add_argument("--architecture", choices=ARCHITECTURES, default=ARCHITECTURES[0],
                   help="a gun fires the first mass into the others, or the whole stack falls onto an anvil")
    a.add_argument("--article", required=True, help="test article mass, e.g. '12 lb'")
    a.add_argument("--target", required=True, help="test article speed to reach, e.g. '1600 ft/s'")
    a.add_argument("--launch", required=True, help="first-mass (or stack) speed, e.g. '325 ft/s'")
    a.add_argument("--restitution", type=float, default=0.9, help="coefficient of restitution of every collision")
    a.add_argument("--masses", type=int, default=5, help="number of masses, test article included")
    a.add_argument("--material", default="high_strength_steel", help="library material for the sizes")
    a.add_argument("--aspect", type=float, default=1.0, help="length / diameter of the cylinders")
    _json_argument(a, "the design")


def _programmer_arguments(pg):
    from .programmer.shapes import SHAPES
    pg.add_argument("--article", required=True, help="mass brought to rest, e.g. '12 lb'")
    pg.add_argument("--shape", required=True, choices=SHAPES, help="pulse shape")
    pg.add_argument("--peak", required=True, help="peak acceleration, e.g. '10000 gee'")
    pg.add_argument("--duration", required=True, help="pulse duration, e.g. '5 ms'")
    pg.add_argument("--foam", default="aluminium_foam", help="library foam for the pad's crush stress and density")
    pg.add_argument("--plateau", help="crush stress of the pad (default: the library foam's), e.g. '5 MPa'")
    pg.add_argument("--densification", default=0.7, type=float,
                    help="usable crush strain of the pad (default 0.7: foams densify near 70-75%%)")
    pg.add_argument("--fluid-density", default="870 kg/m^3", help="dashpot liquid (default: hydraulic oil)")
    pg.add_argument("--bulk-modulus", default="1.5 GPa", help="dashpot liquid's bulk modulus (default: oil)")
    pg.add_argument("--discharge", default=0.7, type=float, help="orifice discharge coefficient Cd (sharp: 0.6-0.7)")
    pg.add_argument("--max-pressure", default="70 MPa", help="highest dashpot pressure allowed")
    pg.add_argument("--half-angle", default="7 deg", help="split cone half-angle")
    pg.add_argument("--friction", default=0.1, type=float, help="cone-ring friction coefficient")
    pg.add_argument("--ring", default="mild_steel", help="library metal of the clamp ring")
    pg.add_argument("--elongation", default=0.2, type=float, help="usable hoop strain of a yielding ring")
    _json_argument(pg, "the requirement and the concepts")


def _launcher_arguments(ln):
    _scene_arguments(ln)
    ln.add_argument("--out", help="results directory (default: results/<name>)")
    ln.add_argument("--lightest", action="store_true",
                    help="find the lightest launcher meeting the scene's [design] table, then fire it")
    ln.add_argument("--trade", type=int, metavar="N", default=0,
                    help="trade curves of the lightest launcher at N points (implies --lightest): weight against "
                         "pressure, length against bore")


def _design_machine_arguments(dm):
    from .amplifier.gain import ARCHITECTURES
    from .launcher.gas import GASES
    from .programmer.shapes import SHAPES
    dm.add_argument("--article", required=True, help="the unit under test's mass, e.g. '12 lb'")
    dm.add_argument("--shape", choices=SHAPES, default="rectangle", help="pulse shape")
    dm.add_argument("--peak", default="10000 gee", help="pulse peak")
    dm.add_argument("--duration", default="5 ms", help="pulse duration")
    dm.add_argument("--article-diameter", help="default: the fixture study's 60 mm ogive scaled to the mass")
    dm.add_argument("--architecture", choices=ARCHITECTURES, default=ARCHITECTURES[0],
                    help="a gun fires the first mass into the others, or the whole stack falls onto an anvil")
    dm.add_argument("--masses", type=int, default=5, help="amplifier masses, the striker last")
    dm.add_argument("--launch", default="325 ft/s", help="first mass's launch speed")
    dm.add_argument("--material", default="high_strength_steel", help="library metal of masses, housing, frame")
    dm.add_argument("--gas", choices=tuple(GASES), default="air", help="launcher gas")
    dm.add_argument("--max-pressure", default="5000 psi", help="launcher reservoir limit")
    dm.add_argument("--max-barrel-length", default="20 ft", help="launcher barrel limit")
    dm.add_argument("--max-bore", default="36 in", help="launcher bore limit")
    dm.add_argument("--striker-ratio", type=float, default=10.0, help="striker over payload mass, at least "
                                                                      "(the housing may ask for more)")
    dm.add_argument("--safety-factor", type=float, default=1.5, help="yield over allowable stress")
    dm.add_argument("--catch-deceleration", help="the payload's catcher (default: half the pulse's peak)")
    dm.add_argument("--oil-pressure", default="120 MPa", help="the design oil pressure the premise's map sizes its "
                                                            "bores by, and the most the stops' hydraulic buffers work "
                                                            "at (the machine's dashpot bore is its column designer's)")
    dm.add_argument("--out", help="directory for machine.json and machine.md (default: results/machine/<N>lb)")


def _study_arguments(st):
    from .study.registry import SIZES, STUDIES
    st.add_argument("name", choices=tuple(STUDIES),
                    help="the study: " + "; ".join(f"{name}, {study.question}" for name, study in STUDIES.items()))
    st.add_argument("--size", choices=SIZES, default="default",
                    help="smoke: coarse and short (what the tests run); default: the study's answer")
    st.add_argument("--out", help="results directory (default: results/<name>)")
    st.add_argument("--resume", action="store_true",
                    help="read back the finite-element cases a stopped or earlier run of the study completed (the "
                         "same scene), resume those stopped with a checkpoint; the rest runs again")


def _sweep_arguments(sw):
    _scene_arguments(sw)
    sw.add_argument("--vary", action="append", default=[], metavar="PATH=LEVELS",
                    help="a factor and its levels, e.g. bodies.striker.velocity=\"[5, 10, 20] m/s\" (repeat for more)")
    sw.add_argument("--cases", metavar="TABLE.csv", help="instead of --vary: a CSV table, one column per scene path, "
                                                       "one row per case (a 'case' column names them)")
    sw.add_argument("--design", choices=("full", "fractional"), default="full",
                    help="full factorial, or a two-level fractional factorial (pyDOE3)")
    sw.add_argument("--generators", help="fractional: pyDOE3's generators, e.g. 'a b c abc' (D = ABC)")
    sw.add_argument("--resolution", type=int, default=3, help="fractional without generators: the smallest design "
                                                              "of this resolution")
    sw.add_argument("--out", help="directory of the case directories and the table (default: results/<scene>_sweep)")
    sw.add_argument("--executor", choices=("local", "dask"), default="local",
                    help="local processes, or a Dask distributed cluster (a LocalCluster, or --scheduler)")
    sw.add_argument("--workers", type=int, help="cases at a time (default: the cores over --ranks)")
    sw.add_argument("--verbose", action="store_true", help="show Dask's INFO log lines (workers starting, stopping)")
    sw.add_argument("--ranks", type=int, default=1, help="MPI processes per case (mpirun -n RANKS)")
    sw.add_argument("--scheduler", help="dask: the address of a running scheduler (e.g. tcp://host:8786)")
    sw.add_argument("--no-progress", action="store_true", help="a line per case instead of a progress bar")


def _verify_arguments(v):
    v.add_argument("names", nargs="*", metavar="CASE", help="cases to run (default: all; --list names them)")
    v.add_argument("--list", action="store_true", help="list the cases")
    _json_argument(v, "the results")
    v.add_argument("--size", choices=("coarse", "default", "fine"), default="default", help="mesh size of the cases")
    v.add_argument("--workdir", default="results/verify", help="where the cases' runs are written")


def _bench_arguments(b):
    _json_argument(b, "the results")
    b.add_argument("--quick", action="store_true", help="small meshes only (a smoke test)")
    b.add_argument("--steps", type=int, default=200, help="time steps timed at each mesh size")


def _warm_arguments(w):
    w.add_argument("names", nargs="*", metavar="FAMILY_OR_SCENE", default=["axisymmetric", "3d"],
                   help="a family (axisymmetric, 3d) or a scene file (default: both families)")


@dataclass(frozen=True)
class Command:
    """One ``shockfem`` command: its help, its arguments and what runs it."""
    help: str
    arguments: Callable[[argparse.ArgumentParser], None]
    run: Callable[[argparse.Namespace], int]


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="shockfem", description=" ".join(__doc__.replace("``", "").split("\n\n")[0].split()),
                                epilog=" ".join(__doc__.split("\n\n")[1].split()))
    p.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, command in COMMANDS.items():
        # every option's default shown in its help
        parser = sub.add_parser(name, help=command.help, description=command.help, formatter_class=_DefaultsShown)
        command.arguments(parser)
        parser.set_defaults(usage_error=parser.error)
    return p


def _scene(args):
    from .scene import load_scene
    return load_scene(args.scene, args.set)


def _raw(args) -> dict:
    """The raw scene of ``args.scene`` with its ``--set`` overrides."""
    from .scene import apply_overrides, read_toml
    return apply_overrides(read_toml(args.scene), args.set)


def _chain_raw(args):
    """The raw chain scene of ``args.scene`` with its overrides, or None for an ordinary scene."""
    from .scene import is_chain
    raw = _raw(args)
    return raw if is_chain(raw) else None


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    from .scene import SceneError
    try:
        return _dispatch(args)
    except SceneError as e:
        what = "scene" if args.command in ("run", "check", "mesh", "modes") else "input"
        print(f"The {what} has problems:", file=sys.stderr)
        for problem in e.problems:
            print(f"  {problem}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except ModelError as e:
        print(f"error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except UnstableRun as e:
        print(f"unstable: {e.diagnosis}", file=sys.stderr)
        return EXIT_UNSTABLE
    except RunInterrupted as e:
        print(f"interrupted: {e} (the run's outputs were finished and kept)", file=sys.stderr)
        return EXIT_INTERRUPTED + e.signum


# full collections of the cyclic garbage collector in a ``shockfem`` process: one for every FULL_COLLECTION_EVERY
# collections of the middle generation (Python's default: 10)
FULL_COLLECTION_EVERY = 100


def console() -> int:
    """The ``shockfem`` console script and ``python -m shockfem``: ``main`` with fewer full garbage
    collections, then the objects alive are frozen (``gc.freeze``) before the interpreter ends.

    Each full collection walks every object that dolfinx, numba and matplotlib made (about a million): three
    of them took 0.14 s of a 2.1 s ``shockfem run`` as they start, and the interpreter's last ones 0.40-0.47 s
    after it.  The young generations still collect as often as before, and with them the garbage a time
    loop makes; at the end, files and MPI are closed, and the memory goes back to the system with the
    process.  ``main`` itself leaves the collector alone: a program that calls it goes on.

    ``main`` runs on a deep data stack (``data_stack.py``): numba's compile of a first run stops mapping and
    unmapping the interpreter's frame blocks millions of times."""
    from .data_stack import call_on_deep_data_stack
    young, middle, _ = gc.get_threshold()
    gc.set_threshold(young, middle, FULL_COLLECTION_EVERY)
    code = call_on_deep_data_stack(main)
    gc.freeze()
    return code


def _dispatch(args) -> int:
    return COMMANDS[args.command].run(args)


def _check(args) -> int:
    what = check_raw(_raw(args), warn=lambda w: print(f"WARNING: {w}"),
                     base_dir=os.path.dirname(os.path.abspath(args.scene)))     # mesh files beside the scene
    print(f"{args.scene}: ok ({what})")
    return EXIT_OK


def _run(args) -> int:
    if args.resume:
        return _resume(args)
    if not args.scene:
        args.usage_error("give a scene file, or --resume RUN_DIR")
    chain = _chain_raw(args)
    if chain is not None:
        from .amplifier.chain import resolve_chain, run_chain_scene
        spec, _, _ = resolve_chain(chain, args.fidelity)
        run_chain_scene(chain, args.out or os.path.join("results", spec.name, spec.fidelity), args.fidelity,
                        progress=not args.no_progress)
        return EXIT_OK
    if args.fidelity:
        raise ModelError("--fidelity: only a chain scene (a [chain] table) runs at a chosen fidelity")
    if not args.no_fields:
        _start_pictures()
    from .runner import run_scene
    scene = _scene(args)
    out = args.out or os.path.join("results", scene.name)
    run_scene(scene, out, progress=not args.no_progress, write_fields=not args.no_fields)
    return EXIT_OK


def _mesh(args) -> int:
    from .geometry import build_mesh
    from .geometry.quality import check_mesh
    from .output.fields import write_mesh
    scene = _scene(args)
    meshed = build_mesh(scene)
    tdim = meshed.mesh.topology.dim
    print(f"{meshed.source}: {meshed.mesh.topology.index_map(tdim).size_global} cells, "
          f"regions: {', '.join(meshed.region_ids)}")
    check_mesh(scene, meshed)
    out = args.out or os.path.join("results", scene.name, "mesh.xdmf")
    write_mesh(meshed, out)
    print(f"wrote {out} (cell tags: body number; facet tags: region number, see the log above)")
    if args.png:
        from .output.render import render_mesh
        render_mesh(meshed, args.png, scene.name, body_names=[b.name for b in scene.bodies],
                    axisymmetric=scene.kinematics == "axisymmetric")
        print(f"wrote {args.png}")
    return EXIT_OK


def _sweep(args) -> int:
    from .api import sweep
    if bool(args.vary) == bool(args.cases):
        raise ModelError("sweep: give the factors (--vary PATH=LEVELS, repeated) or a table of cases (--cases), "
                         "one of the two")
    if args.ranks < 1 or (args.workers is not None and args.workers < 1):
        raise ModelError("sweep: --ranks and --workers take a whole number of at least 1")
    name = os.path.splitext(os.path.basename(args.scene))[0]
    out = args.out or os.path.join("results", f"{name}_sweep")
    rows = sweep(args.scene, args.vary, out, args.design, args.generators or "", args.resolution, args.set, args.cases,
                 args.executor, args.workers, args.ranks, args.scheduler, progress=not args.no_progress,
                 verbose=args.verbose)
    done = sum(r["status"] == "completed" for r in rows)
    print(f"{done} of {len(rows)} cases completed; the table: {os.path.join(out, 'cases.csv')}")
    return EXIT_OK if done == len(rows) else 1


def _study(args) -> int:
    from .study import registry
    if args.resume:
        from .study.cases import RESUME_ENV
        os.environ[RESUME_ENV] = "1"
    registry.run(args.name, args.size, args.out or os.path.join("results", args.name))
    return EXIT_OK


def _verify(args) -> int:
    from .verify import run_cases, CASES
    if args.list:
        for name, case in CASES.items():
            print(f"{name:24s} {case.__doc__.strip().splitlines()[0]}")
        return EXIT_OK
    results = run_cases(args.names or list(CASES), args.size, args.workdir)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=2, default=float)
    return EXIT_OK if all(r["passed"] for r in results) else 1


def _bench(args) -> int:
    from .bench import run_bench
    results = run_bench(quick=args.quick, steps=args.steps)
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(results, fh, indent=2, default=float)
    return EXIT_OK


def _resume(args) -> int:
    """``shockfem run --resume DIR``: the run as it was started (a chain scene's run goes on to its report)."""
    given = [name for name, used in (("a scene file", args.scene), ("--set", args.set), ("--fidelity", args.fidelity),
                                     ("--no-fields", args.no_fields), ("--out", args.out)) if used]
    if given:
        raise ModelError(f"--resume continues the run as it was started: drop {', '.join(given)}")
    from .output.checkpoint import latest
    origin = latest(args.resume)["origin"] or {}
    if "chain" in origin:
        from .amplifier.chain import run_chain_scene
        run_chain_scene(origin["chain"], args.resume, origin["fidelity"], progress=not args.no_progress,
                        resume=True)
    else:
        if origin.get("write_fields", True):
            _start_pictures()
        from .runner import resume_run
        resume_run(args.resume, progress=not args.no_progress)
    return EXIT_OK


def _start_pictures():
    """The run's picture process started before the solver is imported (``PictureProcess.start_early``), on
    rank 0 and with pictures wanted, as the run would start it."""
    from mpi4py import MPI
    from .output.picture_process import PictureProcess, pictures_wanted
    if MPI.COMM_WORLD.rank == 0 and pictures_wanted():
        PictureProcess.start_early()


def _launcher(args) -> int:
    from .launcher.gun import fire
    from .launcher.output import design_lines, shot_lines, sizing, write_design, write_shot
    from .launcher.scene import resolve_design, resolve_launcher
    raw = _raw(args)
    name, gun, options = resolve_launcher(raw)
    out = args.out or os.path.join("results", name)
    if args.lightest or args.trade:
        from .launcher.design import around, length_against_bore, lightest_launcher, trade
        velocity, limits = resolve_design(raw)
        design = lightest_launcher(gun, velocity, limits, options)
        for line in design_lines(design):
            print(line)
        trades = {}
        if args.trade and design.feasible:
            g = design.gun
            trades["weight_vs_pressure"] = trade(g, velocity, limits, options, "reservoir_pressure",
                                                 around(g.reservoir_pressure, limits.min_pressure,
                                                        limits.max_pressure, args.trade))
            trades["length_vs_bore"] = length_against_bore(g, velocity, around(g.bore, limits.min_bore, 4 * g.bore,
                                                                               args.trade), options)
        for path in write_design(out, design, trades):
            print(f"wrote {path}")
        gun = design.gun
    shot = fire(gun)
    try:
        size = sizing(gun, options)
    except ValueError as e:
        raise ModelError(f"ASME sizing: {e}") from None
    write_shot(out, shot, size)
    for line in shot_lines(name, shot, size):
        print(line)
    print(f"results in {out}")
    return EXIT_OK


def _design_machine(args) -> int:
    from .machine.design import design_machine
    from .machine.output import summary_lines, write_machine
    from .machine.spec import read_spec
    names = ("article", "shape", "peak", "duration", "article_diameter", "architecture", "masses", "launch",
             "material", "gas", "max_pressure", "max_barrel_length", "max_bore", "striker_ratio", "safety_factor",
             "catch_deceleration", "oil_pressure")
    spec = read_spec({k: getattr(args, k) for k in names if getattr(args, k) is not None})
    out = args.out or os.path.join("results", "machine", f"{spec.article_mass / LB:.3g}lb")
    machine = design_machine(spec, out, echo=print)
    for line in summary_lines(machine):
        print(line)
    paths = write_machine(machine, out)
    with open(paths[0]) as fh:
        cad = json.load(fh)["cad"]
    print(f"  CAD: {len(cad['solids'])} named solids in {paths[2]}, read back to volumes within "
          f"{cad['max_volume_error']:.1e}, the designed parts' masses within {cad['max_mass_error']:.1e}")
    for path in paths:
        print(f"wrote {path}")
    return EXIT_OK


def _amplifier(args) -> int:
    from .amplifier import rigid
    from .amplifier.gain import cylinder_size, design
    from .scene.checker import Checker
    from .scene.library import LIBRARY, property_si
    ck = Checker()      # the options, checked like a scene's fields (every problem, exit 2)
    options = vars(args)
    values = {name: ck.quantity({f"--{name}": options[name]}, f"--{name}", "", dimension, positive=True)
              for name, dimension in (("article", "mass"), ("target", "velocity"), ("launch", "velocity"))}
    ck.number({"--restitution": args.restitution}, "--restitution", "", 0.9, 0.0, 1.0,
              "a coefficient of restitution", low_open=True)
    if args.masses < 2:
        ck.fail("--masses", f"a chain needs at least 2 masses, got {args.masses}")
    ck.choice({"--material": args.material}, "--material", "", tuple(LIBRARY))
    if not args.aspect > 0:
        ck.fail("--aspect", f"must be > 0, got {args.aspect}")
    ck.done()
    d = design(args.architecture, values["article"], values["target"], values["launch"], args.restitution,
               args.masses)
    print(f"{args.architecture}, {args.masses} masses, e = {args.restitution:g}: speed gain "
          f"{d.gain:.4g} ({values['launch']:.4g} -> {values['target']:.4g} m/s)")
    if not d.feasible:
        print(f"not possible: {d.reason}")
        return EXIT_BAD_INPUT
    rho = property_si(args.material, "density", "density")
    d.sizes = [cylinder_size(m, rho, args.aspect) for m in d.masses]
    run = (rigid.launched_chain(d.masses, values["launch"], args.restitution) if args.architecture == "launched-chain"
           else rigid.stack_on_anvil(d.masses, values["launch"], args.restitution))
    print(f"{'mass':>5s} {'kg':>11s} {'lb':>10s} {'diameter mm':>12s} {'length mm':>10s} {'first pass m/s':>15s} "
          f"{'final m/s':>10s}")
    for k, (m, size) in enumerate(zip(d.masses, d.sizes), start=1):
        fp = run.first_pass[k - 1]
        print(f"{k:5d} {m:11.4g} {m / LB:10.4g} {size['diameter'] * 1e3:12.4g} {size['length'] * 1e3:10.4g} "
              f"{'-' if fp != fp else format(fp, '.5g'):>15s} {run.final[k - 1]:10.5g}")
    print(f"mass ratio m(k+1)/m(k) = {d.stage_ratio:.4g}; intermediate masses {d.intermediate_mass:.4g} kg "
          f"({d.intermediate_mass / LB:.4g} lb); energy efficiency {d.efficiency:.1%} "
          f"({args.material} cylinders, L/D = {args.aspect:g}; rigid-body model: {len(run.collisions)} collisions)")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({**d.as_dict(), "first_pass": run.first_pass.tolist(), "final": run.final.tolist(),
                       "collisions": len(run.collisions)}, fh, indent=2, default=float)
    return EXIT_OK


def _programmer(args) -> int:
    from .programmer.concepts import crushable_pad, orifice_dashpot, split_cone
    from .programmer.report import format_report
    from .programmer.requirement import requirement
    from .programmer.shapes import SHAPES
    from .scene.checker import Checker
    from .scene.library import LIBRARY
    from .units import to_si
    ck = Checker()      # the options, checked like a scene's fields (every problem, exit 2)
    o = {f"--{k.replace('_', '-')}": v for k, v in vars(args).items()}
    q = {name: ck.quantity(o, name, "", dimension, positive=True)
         for name, dimension in (("--article", "mass"), ("--peak", "acceleration"), ("--duration", "time"),
                                 ("--fluid-density", "density"), ("--bulk-modulus", "pressure"),
                                 ("--max-pressure", "pressure"), ("--half-angle", "angle"))}
    shape = ck.choice(o, "--shape", "", SHAPES)
    for name, low, high in (("--densification", 0.0, 1.0), ("--discharge", 0.0, 1.0), ("--elongation", 0.0, 1.0)):
        ck.number(o, name, "", None, low, high, "a fraction", low_open=True)
    if not 0.0 <= args.friction < 1.0:
        ck.fail("--friction", f"must be in [0, 1), got {args.friction}")
    foams = tuple(k for k, v in LIBRARY.items() if "crush_curve" in v)
    metals = tuple(k for k, v in LIBRARY.items() if "yield_stress" in v)
    ck.choice(o, "--foam", "", foams)
    ck.choice(o, "--ring", "", metals)
    plateau = ck.quantity(o, "--plateau", "", "pressure", positive=True) if args.plateau else None
    ck.done()
    req = requirement(shape, q["--peak"], q["--duration"], q["--article"])
    foam, ring = LIBRARY[args.foam], LIBRARY[args.ring]
    concepts = [
        crushable_pad(req, plateau or to_si(foam["crush_curve"][0][1], "pressure"), args.densification,
                      to_si(foam["density"], "density")),
        # mineral oil's specific heat, about 1.9 kJ/(kg K)
        orifice_dashpot(req, q["--fluid-density"], args.discharge, q["--bulk-modulus"], q["--max-pressure"], 1900.0),
        split_cone(req, q["--half-angle"], args.friction, to_si(ring["yield_stress"], "pressure"),
                   to_si(ring["youngs_modulus"], "pressure"), args.elongation, to_si(ring["density"], "density")),
    ]
    print(format_report(req, concepts))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"requirement": req.as_dict(), "concepts": [c.as_dict() for c in concepts]}, fh, indent=2)
    return EXIT_OK


def _modes(args) -> int:
    from .geometry import build_mesh
    from .modal.eigen import body_modes
    from .modal.labels import label_modes
    from .modal.output import write_modes
    scene = _scene(args)
    deformable = [b.name for b in scene.bodies if not b.rigid]
    body = args.body or (deformable[0] if len(deformable) == 1 else None)
    if body is None:
        raise ModelError(f"--body: the scene has {len(deformable)} deformable bodies ({', '.join(deformable)}); "
                         f"name one")
    if args.count < 1:
        raise ModelError(f"--count: must be >= 1, got {args.count}")
    meshed = build_mesh(scene)
    modes = body_modes(scene, meshed, body, args.count, args.degree, not args.free, args.mass)
    labels = label_modes(modes, meshed.cell_tags.find([b.name for b in scene.bodies].index(body) + 1))
    out = args.out or os.path.join("results", scene.name, "modes")
    data = write_modes(out, modes, labels)
    print(f"{body}: {data['boundary']} ({'; '.join(modes.conditions) or 'no conditions'}), {scene.kinematics}, "
          f"degree-{args.degree} elements, {args.mass} mass, {modes.dofs} dofs, {modes.rigid} rigid-body modes, "
          f"{modes.wall_time_s:.2f} s")
    print(f"damping in a run: {data['damping']}")
    for m in data["modes"]:
        damped = (f"  rings at {m['damped_frequency_hz']:.6g} Hz, {m['damping_ratio']:.3%} of critical"
                  + ("" if m.get("in_band", True) else " (outside the band)") if modes.damping is not None else "")
        print(f"  mode {m['mode']:3d} {m['frequency_hz']:14.6g} Hz  {m['label']}{damped}")
    print(f"wrote {os.path.join(out, 'modes.json')} and modes.xdmf")
    return EXIT_OK


def _metrics(args) -> int:
    from .scene.specs import CFC_CLASSES
    from .metrics.report import shock_report
    from .scene import SceneError
    problems = []
    for name in ("resolved_scene.json", "summary.json", "history.csv"):
        if not os.path.exists(os.path.join(args.run_dir, name)):
            problems.append(f"{args.run_dir}: no {name} (give the directory of a shockfem run)")
    cfc = None
    if args.cfc is not None:
        cfc = 0 if args.cfc == "none" else int(args.cfc) if args.cfc.isdigit() else -1
        if cfc not in CFC_CLASSES + (0,):
            problems.append(f"--cfc: must be one of {', '.join(map(str, CFC_CLASSES))} or none, got {args.cfc!r}")
    if problems:
        raise SceneError(problems)
    _, lines = shock_report(args.run_dir, cfc)
    print("\n".join(lines) if lines else "no test articles, accelerometers or contact events in this run")
    print(f"metrics in {os.path.join(args.run_dir, 'summary.json')} (key 'shock')")
    return EXIT_OK


def _warm(args) -> int:
    from .warm import warm
    warm(args.names, report=lambda name, cpu_s: print(f"{name}: {cpu_s:.1f} s CPU", flush=True))
    return EXIT_OK


COMMANDS = {
    "run": Command("run a scene and write a run directory, or resume a stopped run", _run_arguments, _run),
    "check": Command("validate a scene without running it", _check_arguments, _check),
    "mesh": Command("mesh a scene's bodies (cached in the checkout's meshes/ for its own scenes, else in "
                    "~/.cache/shockfem/meshes, or in $SHOCKFEM_MESH_CACHE), report their quality and write the mesh "
                    "as XDMF", _mesh_arguments, _mesh),
    "metrics": Command("(re)compute the shock metrics of a run directory: pulses, spectra, stage table (into its "
                       "summary.json, with plots)", _metrics_arguments, _metrics),
    "modes": Command("natural frequencies and mode shapes of a body (SLEPc)", _modes_arguments, _modes),
    "amplifier": Command("size a velocity amplifier's masses (rigid-body design tool)", _amplifier_arguments,
                         _amplifier),
    "programmer": Command("size pulse programmers (crushable pad, orifice dashpot, split cone) for a specified "
                          "pulse (closed forms)", _programmer_arguments, _programmer),
    "launcher": Command("fire a gas gun described by a [launcher] scene; ASME sizing", _launcher_arguments,
                        _launcher),
    "design-machine": Command("design the whole shock tester for an article and a pulse: fixture, amplifier, "
                              "launcher, stops, guides, frame; loads against allowables", _design_machine_arguments,
                              _design_machine),
    "study": Command("run a study and write its report (report.md with tables and figures)", _study_arguments,
                     _study),
    "sweep": Command("run a scene over a design of its fields' levels (or a table of cases), a run directory per "
                     "case, both cores or a Dask cluster, resumable; the cases' results in one table",
                     _sweep_arguments, _sweep),
    "import": Command(IMPORT_HELP, import_arguments, import_command),
    "verify": Command("verification against exact and published solutions", _verify_arguments, _verify),
    "bench": Command("element-cycles per second at several mesh sizes", _bench_arguments, _bench),
    "warm": Command("compile numba's kernels into their cache, so that later runs compute at once", _warm_arguments,
                    _warm),
}


if __name__ == "__main__":
    raise SystemExit(main())
