"""Points in chunks over threads, and one BLAS call at a time.

EFGM's assembly and evaluation are numpy kernels over many points: taken
in chunks whose temporaries stay in the cores' caches, and spread over
threads (numpy releases the GIL in its kernels), they run at a few times
the speed of one call over every point.  The sizes here were measured on
this machine; the threads follow the share of the cores a process is
given (``OMP_NUM_THREADS``, as for BLAS).

One hazard sets the rules: the serial OpenBLAS build gives wrong answers
when called from two threads at once (measured here: singular moment
matrices in a threaded assembly that is regular serially).  So every
matrix product of a threaded kernel goes through :func:`matmul`, which
holds :data:`_BLAS`, and the small inverses avoid LAPACK altogether
(:func:`efgm.shape.moments._spd_inverse`).

Contract: :func:`parallel_map` yields ``function(item)`` in the items'
order, whatever the threads; :func:`matmul` is ``a @ b``.
"""
from __future__ import annotations

import os
import threading
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from contactcore.collective import launched_size

#: Gauss points whose stiffness blocks are made together
#: (:meth:`efgm.operators.Approximation.stiffness`): large enough to amortise
#: numpy's per-call cost, small enough for the (P, K) temporaries to stay in
#: cache (measured best among 2048, 8192 and 32768).
CHUNK = 32768

#: Points evaluated together by :meth:`MLS.evaluate`: its (K, P)
#: temporaries (K ≈ 16 neighbours) then stay in the cores' caches.  Measured
#: on 2 cores under a load of about 4, 101² grid, linear basis, 2e5 random
#: points, median of 3 per size, sizes alternated: 3.1e5 / 3.4e5 / 3.2e5 /
#: 2.5e5 / 2.2e5 points/s for 1024 / 2048 / 4096 / 8192 / 32768.
POINT_CHUNK = 2048

#: One BLAS call at a time: numpy's matmul calls BLAS, and the serial
#: OpenBLAS build gives wrong answers when called from two threads at once
#: (measured here: singular moment matrices in a threaded assembly that
#: is regular serially).  The products are a small part of a chunk's work;
#: the rest runs in parallel (:func:`parallel_map`).
_BLAS = threading.Lock()


def matmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a @ b`` under :data:`_BLAS` (einsum, BLAS-free, is 5-15x slower here)."""
    with _BLAS:
        return a @ b


def threads() -> int:
    """How many threads :func:`parallel_map` uses: ``OMP_NUM_THREADS`` when
    set (the share of the cores that a study's workers and the scaling
    benchmark's ranks are given, as for BLAS); else one per rank under
    mpirun (MPI's one rank per core), one per core without it."""
    try:
        return max(1, int(os.environ["OMP_NUM_THREADS"]))
    except (KeyError, ValueError):
        return 1 if launched_size() > 1 else os.cpu_count() or 1


def parallel_map(function, items):
    """``function`` of each item, in order, on :func:`threads` threads (numpy
    releases the GIL in its kernels); a generator, so a consumer can reduce
    the results as they come."""
    items = list(items)
    if len(items) < 2 or threads() == 1:
        yield from map(function, items)
        return
    with ThreadPoolExecutor(threads()) as pool:
        yield from pool.map(function, items)
