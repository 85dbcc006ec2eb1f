"""Every tolerance of the test suite, with its reason, in one place."""

#: Round-off level of a patch test, relative to the largest value of the
#: field.  The systems have condition estimates up to ~1e8, so LU loses up to
#: 8 of the 16 digits in the worst case; 1e-8 is that bound, a discretisation
#: error on these meshes is 1e-3 or more.
PATCH_ROUNDOFF = 1e-8

#: An error falls "as 1/k" when the log-log slope of error against k lies
#: within this distance of -1 (a first-order perturbation in 1/k).
PENALTY_SLOPE_TOL = 0.05

#: An answer delivered without a warning may differ from the best one the
#: discretisation allows by at most this much, relative (engineering
#: accuracy: six digits of the displacement).  The condition warning of
#: contactcore.tolerances.CONDITION_WARN (5e11: cond * eps ~ 1e-4) is meant to
#: fire before round-off grows past it.
UNWARNED_ACCURACY = 1e-5

#: Expected L2 displacement rates with a smooth solution: k + 1 for P_k.  The
#: fitted slope over three meshes may fall below it by pre-asymptotic effects
#: (unstructured gmsh meshes are not exact halvings): 0.1 allowed.
RATE_MARGIN = 0.1

#: Relative agreement of a resultant computed from 101 profile samples (the
#: trapezoidal rule on a piecewise polynomial field) with a global balance.
RESULTANT = 2e-3

#: Scene B: the mean of t_T over Γ is -T/(2πR²).  The P1 value at h = 0.1
#: is 1 % low (the polygonal rod is smaller than the disc, O(h²)); 2 % bounds
#: it without hiding an error in the torque (a factor or sign).
TORQUE_BALANCE_P1 = 0.02

#: Scene B's exact t_N is zero.  With the exact normal the false t_N stays
#: below 5 % of |t_T| on P1 meshes down to h = 0.1; a chord normal gives
#: (k_N/k_T)(h/2R)|t_T| = 20 |t_T| there (SCENES.md).
FALSE_TN_P1 = 0.05
