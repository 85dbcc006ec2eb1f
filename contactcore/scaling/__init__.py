"""Units and placement: every method solves the scene made dimensionless.

The package's face: its public names, from the modules below.

* :mod:`~contactcore.scaling.scales`: the scales of a scene (``L``, ``o``,
  ``S``, ``U``) and the map to its dimensionless form and back (its
  docstring states the map);
* :mod:`~contactcore.scaling.sizes`: the sizes of a scene's largest state
  from its data alone, what round-off is relative to;
* :mod:`~contactcore.scaling.fields`: a Result's fields read in the user's units;
* :mod:`~contactcore.scaling.solve`: the decorator that makes every
  method's one ``solve`` solve the dimensionless scene.

Arrows: ``solve`` → ``fields`` → ``scales``; ``solve`` → ``scales``;
``sizes`` → ``scales``.
"""
from .fields import ScaledFields
from .scales import Scales, user_points
from .sizes import Sizes, rigid_translation, softer_displacement, softer_stress
from .solve import DECIMAL_DIGITS, decimal_quotient, dimensionless, dimensionless_inputs

__all__ = ["DECIMAL_DIGITS", "ScaledFields", "Scales", "Sizes", "decimal_quotient", "dimensionless",
           "dimensionless_inputs", "rigid_translation", "softer_displacement", "softer_stress", "user_points"]
