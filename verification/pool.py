"""The independent cases of a study, handed to a ``concurrent.futures`` executor.

Every driver that runs many independent solves (``study``, ``sweeps``,
``efficiency``, ``paper``, ``benchmark``, ``report``) maps one picklable,
module-level case function over its cases with :func:`map_cases`; this
module only picks the executor, it schedules nothing itself:

* ``--workers K`` (K > 1): a local :class:`~concurrent.futures.ProcessPoolExecutor`
  of K spawned processes (spawned, not forked: no inherited MPI or PETSc state);
* no ``--workers`` (:data:`DEFAULT_WORKERS`: 1), or K = 1: the cases run
  one after another in this process (:class:`Serial`);
* under ``mpiexec -n K python -m mpi4py.futures -m verification ...``: the
  K − 1 MPI workers that ``mpi4py.futures`` set up, through its
  :class:`~mpi4py.futures.MPIPoolExecutor` (``--workers`` is then ignored:
  the pool's size is the launcher's).  mpi4py is imported only then.

``executor.map`` yields the results in the order of the cases, whatever
order they end in, and at most K cases run at once.  Each case runs in its
own process on its own communicator (:func:`solver`), so a dolfinx solve
never waits for the other workers; its timings are measured inside it.
"""
from __future__ import annotations

import contextlib
import logging
import multiprocessing
import multiprocessing.context
import os
import signal
import sys
from concurrent.futures import Executor, Future, ProcessPoolExecutor

from contactcore.collective import launched_size

from . import methods

#: The cases run at once when ``--workers`` is not given, by every command
#: that takes it: one, in this process.  Cases beside each other share the
#: cores, the memory bandwidth and the memory, so their timings and the
#: peak memory depend on how many run at once; one at a time is the
#: measure every table can be compared with.
DEFAULT_WORKERS = 1


class Serial(Executor):
    """An executor that runs each case in this process when it is submitted."""

    def submit(self, fn, /, *args, **kwargs) -> Future:
        future = Future()
        try:
            future.set_result(fn(*args, **kwargs))
        except Exception as exc:  # handed back through the future, as a pool would
            future.set_exception(exc)
        return future  # Ctrl-C is not: kept in a future, the cases after it would still run


def launched_rank() -> int:
    """This process's rank under mpiexec (0 without it), read from its environment."""
    return next((int(os.environ[n]) for n in ("OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK") if n in os.environ),
                0)


def distributed() -> bool:
    """Whether this command runs on several mpirun ranks as one job (not as
    an mpi4py.futures pool): the solves of fe and xfem are then spread over
    them."""
    return launched_size() > 1 and not under_mpi_pool()


def under_mpi_pool() -> bool:
    """Whether this process runs under ``mpiexec -n K python -m mpi4py.futures``
    with K > 1, as its master or as one of its workers: mpi4py.futures
    documents that the script then runs on rank 0 and that every
    ``MPIPoolExecutor`` it makes uses the other ranks.  Read from the
    launcher's environment and the modules loaded, without importing MPI."""
    return launched_size() > 1 and "mpi4py.futures" in sys.modules


def executor(workers: int | None, fresh: bool = False) -> Executor:
    """The executor for ``--workers`` (None or 1: serial).  ``fresh``: every
    case in a new process of its own, even serially (its memory is returned
    to the system after it; the efficiency ladders need this)."""
    level = logging.getLogger("verification").getEffectiveLevel()  # the workers log as the command does
    if under_mpi_pool():
        petsc_on_self()  # before the master itself meets PETSc
        from mpi4py.futures import MPIPoolExecutor
        return MPIPoolExecutor()  # its static workers outlive one executor: no initializer (it breaks the next)
    if (workers or 1) == 1 and not fresh:
        return Serial()
    return ProcessPoolExecutor(max_workers=workers or 1, mp_context=_SpawnDeaf(),
                               max_tasks_per_child=1 if fresh else None, initializer=worker_logging,
                               initargs=(level,))  # a context of its own: its workers are this pool's alone


class _DeafProcess(multiprocessing.context.SpawnProcess):
    """A spawned worker that starts with SIGINT blocked: a Ctrl-C that
    reaches it while it starts up (the interpreter, then the imports of
    ``__main__``'s modules, seconds under load) stays pending instead of
    raising KeyboardInterrupt there, with a traceback, before
    :func:`worker_logging` ignores it (which discards it).  The mask is
    set on the spawning thread only for the spawn; a Ctrl-C meant for the
    command meanwhile is delivered to it when the mask is put back.

    The new process's ``Popen`` is kept on the process object before the
    mask is put back: the Ctrl-C raised there lost the worker before its
    pool knew it (``start`` never returned), and :func:`_stop` could not
    end it (it went on starting, and failed with a traceback on its pool's
    queues, closed meanwhile).  Its context (:class:`_SpawnDeaf`) keeps
    the process object, so :func:`_stop` finds it there."""

    @staticmethod
    def _Popen(process_obj):
        before = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
        try:
            popen = multiprocessing.context.SpawnProcess._Popen(process_obj)  # pickles process_obj: _popen None
            process_obj._popen = popen  # what start() sets, set before a Ctrl-C can be raised
            return popen
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, before)


class _SpawnDeaf(multiprocessing.context.SpawnContext):
    """The spawn context, its processes :class:`_DeafProcess`.  One per
    pool (:func:`executor`): it keeps the processes it made, so that one
    pool's Ctrl-C (:func:`_stop`) ends that pool's workers and no other's
    (two pools in one process, the Python API in a user's script).  A
    module-wide list, as before, ended every pool's."""

    def __init__(self):
        super().__init__()
        self.processes: list[_DeafProcess] = []

    def Process(self, *args, **kwargs) -> _DeafProcess:  # what ProcessPoolExecutor calls to make a worker
        process = _DeafProcess(*args, **kwargs)
        self.processes[:] = [p for p in self.processes if p._popen is None or p._popen.poll() is None] + [process]
        return process

    def running(self) -> list:
        """The ``Popen`` of this context's processes started and not yet seen to end."""
        return [p._popen for p in self.processes if p._popen is not None and p._popen.poll() is None]


#: Every process's log line: level, logger, message.
LOG_FORMAT = "%(levelname)s %(name)s: %(message)s"


def worker_logging(level: int) -> None:
    """A worker's ``verification`` log: the command's level (``--quiet``,
    ``--verbose``) and format, on the worker's stderr.  A worker ignores
    Ctrl-C: the command that owns it stops it (:func:`map_cases`) and says
    ``interrupted`` once, without a traceback from every worker."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # a Ctrl-C pending since the start is discarded
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})  # blocked by _DeafProcess
    handler = logging.StreamHandler()
    handler.setFormatter(logging.Formatter(LOG_FORMAT))
    logger = logging.getLogger("verification")
    logger.handlers[:], logger.propagate = [handler], False
    logger.setLevel(level)


#: The variables that size the BLAS and OpenMP thread pools (Debian's
#: OpenBLAS reads the first, its OpenMP build and MUMPS the second, EFGM's
#: numpy threads the second: :func:`efgm.shape.threads`).
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")


#: Open MPI's option that starts a process's MPI alone (a "singleton")
#: without its helper daemon (orted): a worker ended by Ctrl-C while its MPI
#: started left that daemon writing "ORTE_ERROR_LOG: Broken pipe" lines
#: after the command's last line (3 of 6 workers ended 0.02-0.3 s into
#: their MPI start, none with it).  A local worker solves on COMM_SELF and
#: spawns no processes, which is all an isolated singleton cannot do.
ISOLATED_SINGLETON = "OMPI_MCA_ess_singleton_isolated"


@contextlib.contextmanager
def _threads_per_worker(workers: int | None, fresh: bool = False):
    """The environment that local workers are spawned with.  K > 1 workers:
    the cores shared out, ``max(1, cores // K)`` threads each, unless the
    user sized the thread pools already.  A serial run keeps every core
    busy (EFGM's shape functions and assembly run on one numpy thread per
    core), so K workers left at one pool of threads each would ask for K
    times the cores and run each case up to K times slower.  Any local
    worker (K > 1, or ``fresh``): an MPI of its own without Open MPI's
    daemon (:data:`ISOLATED_SINGLETON`), unless the user set it."""
    saved = {k: os.environ.get(k) for k in (*THREAD_VARIABLES, ISOLATED_SINGLETON)}
    if (workers or 1) > 1:
        for k in THREAD_VARIABLES:
            os.environ.setdefault(k, str(max(1, (os.cpu_count() or 1) // workers)))
    if ((workers or 1) > 1 or fresh) and not under_mpi_pool():
        os.environ.setdefault(ISOLATED_SINGLETON, "1")
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def map_cases(function, cases, workers: int | None = None, fresh: bool = False):
    """``function(c) for c in cases`` on :func:`executor` (``workers``,
    ``fresh``): yields the results in the order of ``cases``, each as soon
    as it and those before it are done, so that the caller reports progress
    as it goes.

    The cases are submitted one by one, not through ``pool.map``, which
    cancels the futures left when it is interrupted (see :func:`_stop`).
    The pool is shut down before the last result is handed over, and that
    last ``yield`` lies outside every ``try`` and ``with``: a caller that
    stops asking there (``zip(cases, map_cases(...))`` never asks past the
    last case) leaves a generator whose closing, when it is collected, runs
    no code.  Before, the pool's shutdown ran in that closing, and a Ctrl-C
    arriving while it waited for the workers was an error "ignored" with a
    traceback, the command going on to exit 0 with its output.  Ctrl-C, or
    a caller that stops early, ends the workers at once (:func:`_stop`)."""
    cases = list(cases)
    if not cases:
        return
    with _threads_per_worker(workers, fresh):
        pool = executor(workers, fresh)
        try:
            futures = [pool.submit(function, case) for case in cases]  # not map: it cancels them on Ctrl-C
            for future in futures[:-1]:
                yield future.result()
            last = futures[-1].result()
            pool.shutdown(wait=True)
        except Exception:
            _shut(pool)
            raise
        except BaseException:  # Ctrl-C (KeyboardInterrupt), SIGTERM, or the caller stopped early (GeneratorExit)
            _stop(pool)
            raise
    yield last


def _shut(pool: Executor) -> None:
    """A case failed: wait for the cases under way, as leaving the pool
    does, unless Ctrl-C comes meanwhile (then :func:`_stop`)."""
    try:
        pool.shutdown(wait=True)
    except BaseException:
        _stop(pool)
        raise


def _stop(pool: Executor) -> None:
    """Ctrl-C: end a local pool's workers now (they ignore SIGINT), so that
    neither leaving the pool nor the interpreter's exit waits for the cases
    under way; the cases not started fail with the broken pool, unseen.  The
    workers are taken before the shutdown, which forgets them (taken after
    it, none was ever ended, and the exit waited for the cases under way).
    No future is cancelled: Python 3.11's pool, finding its workers gone,
    sets an error on every pending future, and on a cancelled one that
    raised InvalidStateError in its thread, with a traceback.  An MPI
    pool's workers belong to the launcher."""
    processes = list((getattr(pool, "_processes", None) or {}).values())  # no public handle before Python 3.14
    if isinstance(pool, ProcessPoolExecutor):
        for process in processes:
            process.terminate()
        context = getattr(pool, "_mp_context", None)  # its own (executor): this pool's workers alone
        for popen in context.running() if isinstance(context, _SpawnDeaf) else []:  # and any whose spawn
            popen.terminate()  # the Ctrl-C cut short
        pool.shutdown(wait=False)
    else:
        pool.shutdown(wait=False, cancel_futures=True)


def workers_label(workers: int | None) -> str:
    """How many cases ran at once, for the tables whose timings depend on it."""
    if under_mpi_pool():
        return f"{launched_size() - 1} MPI workers"
    return f"{workers or 1} worker" + ("s" if (workers or 1) > 1 else "")


def petsc_on_self() -> None:
    """Under an MPI pool every rank solves alone: PETSc's world becomes
    ``COMM_SELF`` before PETSc is first imported (by dolfinx or EFGM's
    solver).  Initialised on the launcher's world, PETSc's start-up is
    collective over every rank, and a worker waits for ever for the
    master and the other workers, which never join it."""
    if under_mpi_pool() and "petsc4py.PETSc" not in sys.modules:
        import petsc4py
        from mpi4py import MPI
        petsc4py.init(comm=MPI.COMM_SELF)


def solver(name: str):
    """Method ``name``'s solve for one case, and the options that put it on
    its own communicator (``COMM_SELF`` for the methods that take ``comm``;
    for one that starts no MPI outside a launcher, not ``needs_mpi``
    (:class:`~contactcore.discretisation.Discretisation`), only under one): a case never shares its mesh or its rows with the
    other workers."""
    petsc_on_self()
    solve = methods.solver(name)
    if not methods.takes(name, "comm") or (name in methods.METHODS and not methods.discretisation(name).needs_mpi
                                           and launched_size() == 1):
        return solve, {}
    from mpi4py import MPI
    return solve, {"comm": MPI.COMM_SELF}
