"""The study's tables in Markdown, as docs/peer-contact.md shows them.

Per method of ours: per profile quantity the worst sample and (in
brackets) the RMS difference from GetFEM, in % of ours' largest value,
one column per h; Γ's open / stick / slip shares, largest |t_N| and time
of each run; and the method's and GetFEM's own moves from each h to the
next.

Contract: :func:`markdown` takes :func:`~.runs.study`'s three
dictionaries and returns the text, one section per method.
"""
from __future__ import annotations


def _share(s: dict) -> str:
    return (f"{100 * s['open']:.1f} % / {100 * s['stick']:.2f} % / {100 * s['slip']:.1f} %, "
            f"{s['max_tN']:.4g} Pa ({s['seconds']:.3g} s)")


def _table(columns: dict) -> list[str]:
    """One row per profile quantity, one column per entry of ``columns``
    (heading -> :func:`differences` rows): worst (RMS) in %."""
    first = next(iter(columns.values()))
    lines = ["| profile, quantity | " + " | ".join(columns) + " |", "|---|" + "---|" * len(columns)]
    for i, row in enumerate(first):
        lines.append(f"| {row.profile} {row.quantity} | "
                     + " | ".join(f"{100 * c[i].worst:.3g} ({100 * c[i].rms:.3g})" for c in columns.values()) + " |")
    return lines


def markdown(rows: dict, splits: dict, moves: dict) -> str:
    """The study's tables, per method of ours: per profile quantity the
    worst sample and (in brackets) the RMS difference from GetFEM, in % of
    ours' largest value, one column per h; Γ's open/stick/slip shares,
    largest |t_N| and time of each run; and the method's and GetFEM's own
    moves from each h to the next (in % of the finer answer's largest)."""
    out = []
    for method in dict.fromkeys(m for m, _ in rows):
        hs = [h for m, h in rows if m == method]
        lines = [f"{method} against GetFEM", "", *_table({f"h = {h:g}": rows[method, h] for h in hs}), "",
                 f"| h | {method}: open / stick / slip, max abs t_N | GetFEM: open / stick / slip, max abs t_N |",
                 "|---|---|---|"]
        lines += [f"| {h:g} | {_share(splits[h, method])} | {_share(splits[h, 'peer'])} |" for h in hs]
        steps = list(zip(hs, hs[1:]))
        if steps:
            lines += ["", f"{method}'s and GetFEM's own moves", "",
                      *_table({f"{who} h = {a:g} → {b:g}": moves[label, b]
                               for label, who in ((method, method), ("peer", "GetFEM")) for a, b in steps})]
        out.append("\n".join(lines) + "\n")
    return "\n".join(out)
