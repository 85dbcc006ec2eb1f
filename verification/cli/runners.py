"""Each command's runner: the parsed arguments (an ``argparse.Namespace``)
handed to the command's driver, which is imported only when its command
runs.

Contract: ``runner(args, argv)`` with ``args.out`` already the folder to
write into (:mod:`verification.cli.folders`) and ``argv`` the command line
as typed (for the result's provenance); it returns nothing and refuses bad
input with a :class:`ContactError` (its line and exit status are
``main``'s).  The table that names them is :mod:`verification.cli.commands`.
"""
from __future__ import annotations

from contactcore import ContactError, load_scene

from .. import files, methods


def floors(pairs: list[tuple[str, float]]) -> dict[str, float]:
    """The ``--floor`` pairs as a dict; a quantity given twice is refused."""
    given = {}
    for name, value in pairs:
        if name in given:
            raise ContactError(f"--floor: {name} given twice ({given[name]:g} and {value:g})")
        given[name] = value
    return given


def study_params(args) -> list[tuple[str, list[float]]]:
    """The (--param, --values) pairs of ``study``, in the order given."""
    if len(args.param) != len(args.values):
        raise ContactError(f"--values: give one --values list after each --param ({len(args.param)} --param, "
                           f"{len(args.values)} --values)")
    return list(zip(args.param, args.values))


def run(args, argv) -> None:
    """``run``: one scene, one or more methods (:func:`verification.run.run`)."""
    from ..run import run as run_scene
    run_scene(args.scene, args.method, args.out, h=args.h, degree=args.degree, paper=args.paper, fields=args.fields,
              petsc_options=dict(args.petsc_option), dmax=args.dmax, nodes_file=args.nodes, cell=args.cell,
              basis=args.basis, mesh=args.mesh, flux=args.flux, allow_large=args.allow_large, draw=args.draw, estimate=args.estimate,
              reference=args.reference, against_exact=args.against_exact, floors=floors(args.floor), argv=argv)


def against(args, argv) -> None:
    """``against``: an outside answer against one method's (:func:`verification.against_outside.against`)."""
    from ..against_outside import against as judge
    judge(args.outside, args.scene, args.method, args.degree, args.out, h=args.h, levels=args.estimate,
          exclude=args.exclude, floors=floors(args.floor), argv=argv, cell=args.cell, dmax=args.dmax)


def paper(args, argv) -> None:
    """``paper``: the paper's figures (:func:`verification.paper.paper`)."""
    from ..paper import paper as figures
    figures(args.out, tuple(args.scene), args.ref_h, workers=args.workers, argv=argv, allow_large=args.allow_large)


def closed(args, argv) -> None:
    """``closed``: the closed-form ladders (:func:`verification.convergence.closed`)."""
    from ..convergence import closed as ladders
    ladders(args.out, tuple(args.case), [(m, d) for m in methods.expand(args.method) for d in args.degree],
            argv=argv)


def benchmark(args, argv) -> None:
    """``benchmark``: efficiency beside GetFEM's level-set XFEM, one section a scene in benchmark.md."""
    from ..agreement import default_exclusion
    from ..efficiency import BENCHMARK_LADDERS, BENCHMARK_VARIANTS, REFERENCE_H, check_budgets, efficiency, ladder_rungs
    from ..peer_getfem import getfem_module
    getfem_module()  # before the long reference runs
    for s in args.scene:  # every scene's ladder, and --workers of its rungs at once, before the first scene runs
        check_budgets(load_scene(s), ladder_rungs(BENCHMARK_VARIANTS, BENCHMARK_LADDERS[s]), REFERENCE_H[s], False,
                      args.workers, offer_allow_large=False)
    sections = [efficiency(s, BENCHMARK_VARIANTS, BENCHMARK_LADDERS[s], REFERENCE_H[s],
                           default_exclusion(load_scene(s)), args.out / s, workers=args.workers, argv=argv,
                           offer_allow_large=False)
                for s in args.scene]
    files.write_text(args.out / "benchmark.md", "# Benchmark against GetFEM's level-set XFEM\n\n"
                     + "\n".join(t.replace("](efficiency.png)", f"]({s}/efficiency.png)")
                                 for s, t in zip(args.scene, sections)))


def efficiency(args, argv) -> None:
    """``efficiency``: error against run time (:func:`verification.efficiency.efficiency`)."""
    from ..agreement import default_exclusion
    from ..efficiency import efficiency as measure
    from ..study_checks import check_given_once
    check_given_once("--method", args.method)
    check_given_once("--degree", args.degree)
    exclude = args.exclude if args.exclude is not None else default_exclusion(load_scene(args.scene))
    variants = [(m, d) for m in methods.expand(args.method) for d in args.degree]
    measure(args.scene, variants, {d: args.h for d in args.degree}, args.ref_h, exclude, args.out,
            workers=args.workers, estimated=True, allow_large=args.allow_large, argv=argv)


def effectivity(args, argv) -> None:
    """``effectivity``: the estimates against fe P2 (:func:`verification.effectivity.scene_table`)."""
    from ..effectivity import scene_table
    scene_table(args.scene, args.h, args.ref_h, args.out, args.levels, args.allow_large, argv=argv)


def sweeps(args, argv) -> None:
    """``sweeps``: the stiff and extreme cases (:func:`verification.sweeps.run_sweeps`)."""
    from ..sweeps import run_sweeps
    run_sweeps(args.out, args.sweep, methods.expand(args.method), args.degree, workers=args.workers, argv=argv,
               strict=True)


def study(args, argv) -> None:
    """``study``: inputs varied over their product (:func:`verification.study.study`)."""
    from ..study import study as vary
    vary(args.scene, study_params(args), args.method, args.out, degree=args.degree, h=args.h,
         cell=args.cell, workers=args.workers, allow_large=args.allow_large, strict=True, estimate=args.estimate,
         argv=argv)


def report(args, argv) -> None:
    """``report``: every verification in DIR/report.md (:func:`verification.report.report`)."""
    from ..report import report as gather
    gather(args.out, args.quick, workers=args.workers, argv=argv)


def timing(args, argv) -> None:
    """``timing``: wall time against DOFs (:func:`verification.timing.timing`)."""
    from ..timing import timing as measure
    measure(args.scene, args.method, args.degree, args.h, args.out, argv=argv, allow_large=args.allow_large)


def shapes(args, argv) -> None:
    """``shapes``: EFGM's shape functions timed (:func:`verification.shapes.shapes`)."""
    from ..shapes import shapes as measure
    measure(args.basis, args.grid, args.points, args.repeats, args.out, argv=argv, allow_large=args.allow_large)


def scaling(args, argv) -> None:
    """``scaling``: the timing ladder under mpirun (:func:`verification.scaling.scaling`)."""
    from ..scaling import scaling as measure
    measure(args.scene, methods.expand(args.method), args.degree, args.h, args.ranks, args.out, argv=argv,
            allow_large=args.allow_large)
