"""Accuracy records of a work folder, found by their shape in its JSON files, and their sections.

Each finder walks a parsed JSON document and returns the dicts that hold one kind of result,
whatever file or key they were written under (a command's ``--json`` output saved to a file,
a stage record, a demo summary):

* QC verdict (``ws qc``'s ``qc.json``): a ``verdict`` dict with ``pass`` and ``criteria``;
* registration (``ws register --matrix-out X.json``, the scans stage of ``ws run``): a 4×4
  ``transform`` with ``inlier_rmse``, or an ``edges`` table of a multi-scan registration;
* ground evaluation (``ws evaluate --json``): ``type1``, ``type2`` and ``total_error``
  (ISPRS Type I / II and total error) or ``kappa`` beside them.
"""

from __future__ import annotations

import html
from pathlib import Path

import numpy as np

from .html import fig_b64, fmt, img


def kv_table(rows) -> str:
    """A two-column table of (name, value) rows, without a header row."""
    return "<table><tbody>" + "".join(f"<tr><th>{html.escape(str(k))}</th><td>{fmt(v)}</td></tr>"
                                      for k, v in rows) + "</tbody></table>"


def walk(doc, match, limit: int = 16) -> list[tuple[str, dict]]:
    """(key path, dict) of the dicts of ``doc`` for which ``match(dict)`` is true, breadth
    first; a matching dict is not searched further."""
    out, stack = [], [("", doc)]
    while stack and len(out) < limit:
        key, d = stack.pop(0)
        if isinstance(d, dict):
            if match(d):
                out.append((key, d))
                continue
            stack.extend((f"{key}.{k}" if key else str(k), v) for k, v in d.items() if isinstance(v, (dict, list)))
        elif isinstance(d, list):
            stack.extend((f"{key}[{i}]", v) for i, v in enumerate(d[:200]) if isinstance(v, dict))
    return out


def _is_verdict(d: dict) -> bool:
    v = d.get("verdict")
    return isinstance(v, dict) and isinstance(v.get("pass"), bool) and isinstance(v.get("criteria"), list)


def _is_registration(d: dict) -> bool:
    t = d.get("transform")
    if isinstance(d.get("inlier_rmse"), (int, float)) and isinstance(t, list) and len(t) == 4:
        return True
    e = d.get("edges")
    return isinstance(e, list) and bool(e) and all(isinstance(x, dict) and "inlier_rmse" in x for x in e)


def _is_ground_eval(d: dict) -> bool:
    return all(isinstance(d.get(k), (int, float)) for k in ("type1", "type2")) and (
        "total_error" in d or "kappa" in d)


def find_all(docs: dict, kind: str) -> list[tuple[Path, str, dict]]:
    """(file, key path, dict) of every result of ``kind`` ("qc", "registration",
    "ground_eval") in ``docs`` (path -> parsed JSON)."""
    match = {"qc": _is_verdict, "registration": _is_registration, "ground_eval": _is_ground_eval}[kind]
    return [(p, k, d) for p, doc in docs.items() for k, d in walk(doc, match)]


def plot_registration(d: dict, title: str) -> str | None:
    """The residuals of a registration: the inlier RMSE and fitness of each ICP level (coarse
    to fine), the distances of control pairs after the fit, or the inlier RMSE of each edge of
    a multi-scan registration. None when the record holds none of them."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    levels = [x for x in d.get("levels") or [] if isinstance(x, dict) and "inlier_rmse" in x]
    pairs = np.asarray(d.get("pairs_residuals") or [], dtype=float)
    edges = [x for x in d.get("edges") or [] if isinstance(x, dict) and isinstance(x.get("inlier_rmse"), (int, float))]
    panels = [p for p, ok in (("levels", levels), ("pairs", pairs.size), ("edges", edges)) if ok]
    if not panels:
        return None
    fig, axes = plt.subplots(1, len(panels), figsize=(5.2 * len(panels), 3.4), squeeze=False)
    for ax, kind in zip(axes[0], panels):
        if kind == "levels":
            x = np.arange(1, len(levels) + 1)
            ax.plot(x, [lv["inlier_rmse"] for lv in levels], "o-", label="inlier RMSE")
            ax.set_xticks(x, [f"{lv.get('distance', 0):.3g}" for lv in levels])
            ax.set_xlabel("ICP level (max correspondence distance)")
            ax.set_ylabel("inlier RMSE")
            tw = ax.twinx()
            tw.plot(x, [lv.get("fitness", np.nan) for lv in levels], "s--", color="#e07b00", label="fitness")
            tw.set_ylabel("fitness")
            tw.set_ylim(0, 1.05)
        elif kind == "pairs":
            ax.hist(pairs, bins=min(30, max(5, pairs.size)), color="#4a7ab7", edgecolor="white")
            ax.set_xlabel("control pair distance after registration")
            ax.set_ylabel("pairs")
        else:
            ax.bar(range(len(edges)), [e["inlier_rmse"] for e in edges],
                   color=["#4a7ab7" if e.get("kept", True) else "#bbb" for e in edges], edgecolor="black", lw=0.4)
            ax.set_xticks(range(len(edges)), [f"{e.get('source', '?')}→{e.get('target', '?')}" for e in edges],
                          rotation=60, ha="right", fontsize=7)
            ax.set_ylabel("inlier RMSE (grey: pruned)")
    fig.suptitle(title)
    return fig_b64(fig)


_REG_KEYS = (("fitness", "fitness (share of source points matched)"), ("inlier_rmse", "inlier RMSE"),
             ("converged", "converged"), ("correspondences", "correspondences"), ("fine_method", "fine method"),
             ("kernel", "robust kernel"), ("rotation_error_deg", "rotation error (degrees)"),
             ("translation_error_m", "translation error (m)"), ("pairs_rmse", "control pairs RMSE"))


def registration_html(found: list, root: Path) -> list[str]:
    """A block per registration record: its figures and its residual plot."""
    out = []
    for p, key, d in found:
        where = str(p.relative_to(root)) + (f" ({key})" if key else "")
        rows = [(name, d[k]) for k, name in _REG_KEYS if k in d]
        if isinstance(d.get("seconds"), dict) and "total" in d["seconds"]:
            rows.append(("seconds", d["seconds"]["total"]))
        block = f"<h3>{html.escape(where)}</h3>" + (kv_table(rows) if rows else "")
        fig = plot_registration(d, f"Registration residuals — {where}")
        out.append(block + (img(fig, f"Registration residuals: {where}") if fig else ""))
    return out


_EVAL_KEYS = (("points", "points evaluated"), ("n_matched", "points compared"), ("overall_accuracy", "overall accuracy"),
              ("ground_fraction", "ground share (reference)"),
              ("type1", "Type I (ground rejected)"), ("type2", "Type II (objects accepted as ground)"),
              ("total_error", "total error"), ("kappa", "Cohen's kappa"))


def ground_eval_html(found: list, root: Path, confusion_html) -> list[str]:
    """A block per ground evaluation: its rates and ``confusion_html(record, where)`` (the
    figure of the confusion matrix the record holds, "" when none)."""
    out = []
    for p, key, d in found:
        where = str(p.relative_to(root)) + (f" ({key})" if key else "")
        rows = [(name, d[k]) for k, name in _EVAL_KEYS if k in d]
        out.append(f"<h3>{html.escape(where)}</h3>" + kv_table(rows) + confusion_html(d, where))
    return out
