"""The key a misspelt one resembles: a scene file's refusals name it
("did you mean ...?"), for the scene's tables (:mod:`contactcore.scene_files`)
and a law's parameters (:mod:`contactcore.laws`, :mod:`contactcore.exact`)."""
from __future__ import annotations

import difflib


#: How alike (difflib's ratio) a key given and a key known must be for a
#: refusal to ask whether one is a misspelling of the other: 'increment'
#: and 'increments' score 0.95, 'plsu' and 'plus' 0.75, 'kN' and 'kT' 0.5
#: (two real keys, never offered for each other).
SPELLING_LIKENESS = 0.7


def closest(name: str, candidates) -> str | None:
    """The candidate most like ``name``, if any is as alike as
    :data:`SPELLING_LIKENESS`, differs from it in case alone ('e' for
    'E'), or is the only candidate that begins with it or that it begins
    with ('n' for 'nu': too short for the likeness)."""
    by_case = sorted(c for c in candidates if c.casefold() == name.casefold())
    if by_case:
        return by_case[0]
    close = difflib.get_close_matches(name, sorted(candidates), n=1, cutoff=SPELLING_LIKENESS)
    if close:
        return close[0]
    folded = name.casefold()
    prefixed = [c for c in candidates if c.casefold().startswith(folded) or folded.startswith(c.casefold())]
    return prefixed[0] if len(prefixed) == 1 else None


def hint(name: str, candidates) -> str:
    """`` (did you mean 'x'?)`` for the candidate :func:`closest` to
    ``name``, or nothing."""
    known = closest(name, candidates)
    return f" (did you mean {known!r}?)" if known else ""
