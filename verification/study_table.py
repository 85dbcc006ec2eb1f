"""What ``study`` writes of its rows: study.csv's columns (:data:`STATS`,
:func:`stats_of`, :func:`point_columns`) and study.md's section
(:func:`markdown`: its plots, its table in the scene's units, what the
maxima and shares are, and with ``--estimate`` the estimate's columns and
warnings).

Contract: text and column names only, from the rows
:func:`verification.study.solve_case` made; it writes no file and solves
nothing.
"""
from __future__ import annotations

from contactcore.scene import Units

from . import files
from .study_gamma import COLUMNS as GAMMA_COLUMNS, ESTIMATE_COLUMNS, PARTIAL_SHARE
from .study_parameters import described
from .study_plots import _shown

#: A point's outputs on Γ, as study.csv names them (:func:`verification.study._outputs` records them).
OUTPUTS = ["max_gN", "max_gT", "max_tN", "max_tT", "mean_tN", "mean_tT"]
#: study.md's headers of :data:`OUTPUTS` (each followed by its unit in the scene's).
OUTPUT_HEADERS = ["max |g_N|", "max |g_T|", "max |t_N|", "max |t_T|", "mean t_N", "mean t_T"]

STATS = ["method", "degree", "status", "dofs", "total", "condition", "backward_error", *OUTPUTS, *GAMMA_COLUMNS,
         "message"]


def stats_of(rows: list[dict], estimate: bool = False) -> list[str]:
    """study.csv's columns after the point's: :data:`STATS`, with
    ``partial_share`` after the slip share where a row has it, and
    ``study --estimate``'s columns before the message."""
    partial = any(PARTIAL_SHARE in r for r in rows)
    columns = [c for k in STATS for c in ([k, PARTIAL_SHARE] if k == "slip_share" and partial else [k])]
    return [*columns[:-1], *(ESTIMATE_COLUMNS if estimate else []), columns[-1]]


def point_columns(params: list[str]) -> list[str]:
    """The columns naming a point: one per parameter, named after it, so
    that ``units.json`` and study.md give each its unit
    (:func:`verification.files.column_unit`: ``h (mm)``, ``angle (degree)``;
    a one-parameter study's was ``value``, with none: grader11's fault 4)."""
    return list(params)


def plot_name(names: list[str], param: str) -> str:
    """The file of ``param``'s plot: study.png alone, study_<param>.png among several."""
    return "study.png" if len(names) == 1 else f"study_{param}.png"


def markdown(scene_name: str, names: list[str], rows: list[dict], units: Units = Units(),
             measured_by: str = "1 worker", estimate: bool = False) -> str:
    """The study's section: its plots and its table, in the scene's
    ``units``, and how many workers measured its times (``measured_by``,
    :func:`verification.pool.workers_label`); what the maxima and shares
    are (:data:`OUTPUTS_NOTE`); with ``estimate``, the estimate's columns
    and each warning once, after the points that gave it."""
    failed = [r for r in rows if r["status"] == "failed"]
    what = " × ".join(f"{p} ({described(p, units)})" for p in names)
    labels = point_columns(names)
    shares = [c for c in stats_of(rows) if c.endswith("_share")]
    extra = [*ESTIMATE_COLUMNS[:-1]] if estimate else []
    return (f"## Study: scene {scene_name}, {what}\n\n"
            + "".join(f"![study {p}]({plot_name(names, p)})\n" for p in names) + "\n"
            + f"Times in s, measured by {measured_by} at once (cases beside each other share the cores).\n"
            + OUTPUTS_NOTE + (ESTIMATE_NOTE if estimate else "") + "\n"
            + files.markdown_table(rows, [*labels, "method", "status", "dofs", "total", *OUTPUTS, *shares,
                                          "stick_length", "max_tN_away", "max_tT_away", *extra, "message"],
                                   [*(files.labelled(p, p, units) for p in names), "method", "status", "DOFs",
                                    "total (s)",
                                    *(files.labelled(text, q, units) for text, q in zip(OUTPUT_HEADERS, OUTPUTS)),
                                    *(c.removesuffix("_share") for c in shares),
                                    *(files.labelled(text, q, units) for text, q in GAMMA_HEADERS),
                                    *(files.labelled(text, q, units) for text, q in ESTIMATE_HEADERS[:len(extra)]),
                                    "message"])
            + (f"\n{len(failed)} of {len(rows)} points failed; the study went on.\n" if failed else "")
            + (_estimate_warnings(names, rows) if estimate else ""))


#: study.md's headers of the Γ columns after the shares and of the estimate's.
GAMMA_HEADERS = [("stick length", "stick_length"), ("max |t_N| away from ends", "max_tN_away"),
                 ("max |t_T| away from ends", "max_tT_away")]
ESTIMATE_HEADERS = [("est. error (worst relative RMS)", "est_worst"), ("where", "est_worst_at"),
                    ("est. error t_N (RMS)", "est_tN"), ("est. error t_T (RMS)", "est_tT"),
                    ("estimate warnings", "est_warnings"), ("status changed (samples)", "status_changed")]
#: Under study.md's table: what its maxima and shares are.
OUTPUTS_NOTE = ("\nmax |g_N| … mean t_T are over Γ's quadrature points at the last increment, Γ's ends included: "
                "where Γ meets the domain's boundary the tractions of an exact or stiff law are singular, so "
                "max |t_N| and max |t_T| there follow the mesh more than the method. max |t_N| (|t_T|) away from "
                "ends leaves out Γ's points within the agreement's default distance of a singular point "
                "(`verification.agreement.default_exclusion` of the point's scene, the samples `run`'s "
                "agreement and estimates leave out). open, stick, slip (and partial) are the shares of Γ's length "
                "in each status at the last increment (increments.csv's `open_fraction`, `slip_fraction`); "
                "stick length is the sticking share's length.\n")
#: Under an estimated study's table: how the estimate is made.
ESTIMATE_NOTE = ("\nEstimated from each point's runs at 2h and h (the row is the run at h), as `run --h 2h --estimate` "
                 "estimates: the worst relative RMS error of Γ's profile gN, gT, tN, tT away from singular points "
                 "and which (summary.json's `worst`), the RMS estimated error of t_N and t_T there, the number of "
                 "the estimate's warnings (listed below), and at how many of Γ's profile samples the status "
                 "(open, stick, slip) differs between 2h and h: where it does, the split moved between the runs "
                 "and no estimate of the point is asymptotic, an indication only.\n")


def _estimate_warnings(names: list[str], rows: list[dict]) -> str:
    """Each estimate warning once, after the points and methods that gave it."""
    given: dict[str, list[str]] = {}
    for r in rows:
        where = ", ".join([*(f"{p} = {_shown(r[p])}" for p in names), r["method"]])
        for w in r.get("est_messages", []):
            given.setdefault(w, []).append(where)
    return ("\nEstimate warnings:\n\n" + "".join(f"- {'; '.join(at)}: {w}\n" for w, at in given.items())
            if given else "")
