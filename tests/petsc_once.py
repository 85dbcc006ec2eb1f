"""One factorisation for one solve: how the tests drive
:class:`contactcore.linear_solver.Factorisation` on a small matrix."""
from contactcore.linear_solver import Factorisation


def solve_once(A, b, x, *, force_scale: float = 0.0, **options):
    """Solve ``A x = b`` in place with a :class:`Factorisation` of
    ``options``, destroyed after; its report (or its SolverError)."""
    factorisation = Factorisation(**options)
    try:
        factorisation.factorise(A)
        return factorisation.solve(b, x, force_scale)
    finally:
        factorisation.destroy()
