"""The line search that globalises Newton's semismooth steps.

Every correction ``δu`` of a nonlinear law is scaled by the largest
``α = 2⁻ʲ`` (j <= LINE_SEARCH_HALVINGS) that satisfies Armijo's rule on the
merit ``‖R‖₂`` over the free rows,

    ‖R(u + α δu)‖₂ <= (1 − ARMIJO α) ‖R(u)‖₂,

and a full step that passes is doubled (at most LINE_SEARCH_EXPANSIONS
times) while the merit keeps falling, unless it settles the status map it
was solved with.  ``δu = −J⁻¹R`` is a descent direction of ``½‖R‖²`` for
any generalised Jacobian ``J`` of the semismooth residual (GetFEM's
contact bricks, PETSc's ``vinewtonrsls``), so a small enough step always
decreases it and a cycle between status maps cannot survive.  The two
steps taken without Armijo's decrease: a law step that no halving lets
descend (a kink of the merit that is not a zero), taken whole, and a
secant step whose merit does not rise.

Contract: a mixin of :class:`contactcore.newton.increments._Newton`; it
reads ``itf``, ``law``, ``state`` and ``ranks``, calls the residual's
``_residual`` and ``_merit`` (:class:`~contactcore.newton.residual._Residual`)
and the settling test ``_settles``
(:class:`~contactcore.newton.convergence._Convergence`), and writes
nothing.  It returns ``(α, evaluated)``, ``evaluated`` the law's response
and ``_residual`` at ``u + α δu`` where it was computed (None for a secant
step that no halving lets descend: the caller then pins a point).
"""
from __future__ import annotations

from .. import tolerances as tol


class _LineSearch:
    """Armijo's backtracking and doubling on ``‖R‖₂`` (module doc)."""

    def _line_search(self, u, du, b, R, status, secant: bool = False, tangent=None):
        """The largest ``α = 2⁻ʲ`` (j <= LINE_SEARCH_HALVINGS) whose step
        ``u + α δu`` decreases the merit ``‖R‖₂`` by Armijo's rule
        ``‖R(u + α δu)‖ <= (1 − ARMIJO α) ‖R(u)‖`` — the globalised
        semismooth Newton of GetFEM's contact bricks and PETSc's
        ``vinewtonrsls``: ``δu = −J⁻¹R`` is a descent direction of ``½‖R‖²``
        for any generalised Jacobian ``J`` of the semismooth residual, so a
        small enough step always decreases it and breaks a cycle between
        status maps.  If none does, a law step is taken whole (the merit has
        a kink there that is no zero, and smaller steps only cycle about it),
        a secant step at its smallest with no response (the caller then
        pins a point, :meth:`_pinned`).  A ``secant`` step
        (a body free to turn, :meth:`_solve`) is taken whole where it only
        keeps the merit: along that rotation the merit is flat until a
        point re-enters its stick window, which is where the step goes.  A full step that
        passes is doubled while the merit keeps falling (at most
        LINE_SEARCH_EXPANSIONS times): a regularised tangent, stiffer than
        the law's, asks for longer steps than it gives; not one that
        :meth:`_settles` the ``tangent`` it was solved with: that step
        solved its map's linear problem, Newton stops there, and a longer
        one could only win by round-off.  Also returns the
        law's response and :meth:`_residual` at ``u + α δu`` where it was
        evaluated (None elsewhere): the next iterate's, computed alike."""
        merit, seen = self._merit(R), {}

        def along(alpha):
            trial = u + alpha * du
            response = self.itf.respond(self.law, trial, self.state, status, self.ranks)
            seen[alpha] = (response, self._residual(trial, b, response))
            return self._merit(seen[alpha][1][0])

        alpha = 1.0
        for _ in range(tol.LINE_SEARCH_HALVINGS):
            value = along(alpha)
            if value <= (1.0 - tol.ARMIJO * alpha) * merit or (secant and alpha == 1.0 and value <= merit):
                break
            alpha /= 2
        else:
            # a law step that no halving lets descend stands at a kink of
            # the merit that is not a zero (a point whose stick and slip
            # each send Newton to the other): taken whole, it leaves the
            # cycle; a secant step is then pinned instead (_pinned)
            return (alpha, None) if secant else (1.0, seen[1.0])
        if alpha < 1.0 or self._settles(tangent, seen[alpha][0]):
            return alpha, seen[alpha]
        for _ in range(tol.LINE_SEARCH_EXPANSIONS):
            longer = along(2 * alpha)
            if longer >= value:
                break
            alpha, value = 2 * alpha, longer
        return alpha, seen[alpha]
