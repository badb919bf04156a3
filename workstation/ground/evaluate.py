"""Evaluation of a classification against a reference, the way the ISPRS filter test does it.

Two views of one comparison:

* a **confusion matrix over all classes** (rows: reference class, columns: predicted class)
  with per-class precision (user's accuracy), recall (producer's accuracy) and F1;
* the **ground / non-ground** view of the ISPRS WG III/3 filter test (Sithole & Vosselman
  2004, "Experimental comparison of filter algorithms for bare-Earth extraction from airborne
  laser scanning point clouds", ISPRS J. Photogramm. 59(1-2):85-101, Table 4), with the cross
  matrix

  ============  ================  ================
  reference     filtered: ground  filtered: object
  ============  ================  ================
  ground        a                 b
  object        c                 d
  ============  ================  ================

  Type I error = b / (a + b) (bare earth rejected as object), Type II error = c / (c + d)
  (object accepted as bare earth), total error = (b + c) / n, and Cohen's kappa
  (po - pe) / (1 - pe) with po = (a + d) / n and
  pe = ((a + b)(a + c) + (c + d)(b + d)) / n².

All rates are fractions (0.0423 is 4.23 %). Points of the prediction and of the reference are
matched by order when both have the same points in the same order, else by coordinates with
a KD-tree (:func:`match_points`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass, class_name
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)

#: Classes counted as bare earth in the ground / non-ground view.
GROUND_CLASSES: tuple[int, ...] = (int(ASPRSClass.GROUND),)


@dataclass(frozen=True)
class GroundErrors:
    """ISPRS ground / non-ground errors (Sithole & Vosselman 2004). Rates are fractions.

    Attributes
    ----------
    a, b, c, d : int
        Counts: ground as ground, ground as object (Type I), object as ground (Type II),
        object as object.
    type1, type2, total_error, kappa : float
        b/(a+b), c/(c+d), (b+c)/n and Cohen's kappa; NaN where the denominator is zero.
    """

    a: int
    b: int
    c: int
    d: int
    type1: float
    type2: float
    total_error: float
    kappa: float

    @property
    def n(self) -> int:
        return self.a + self.b + self.c + self.d

    def to_dict(self) -> dict:
        return {"a": self.a, "b": self.b, "c": self.c, "d": self.d, "type1": self.type1, "type2": self.type2,
                "total_error": self.total_error, "kappa": self.kappa}


def _ratio(num: float, den: float) -> float:
    return float(num) / float(den) if den else float("nan")


def ground_errors(ref_ground, pred_ground) -> GroundErrors:
    """Type I, Type II, total error and Cohen's kappa of a ground / non-ground labelling.

    Parameters
    ----------
    ref_ground, pred_ground : (n,) array_like of bool
        True where the reference / the prediction says bare earth.

    Examples
    --------
    >>> e = ground_errors([1, 1, 1, 1, 0, 0], [1, 1, 1, 0, 1, 0])
    >>> e.a, e.b, e.c, e.d, e.type1, e.type2, round(e.total_error, 4)
    (3, 1, 1, 1, 0.25, 0.5, 0.3333)
    >>> round(e.kappa, 4)
    0.25
    """
    r = np.asarray(ref_ground, dtype=bool)
    p = np.asarray(pred_ground, dtype=bool)
    if r.shape != p.shape or r.ndim != 1:
        raise InvalidInputError(f"reference {r.shape} and prediction {p.shape} must be equal-length vectors")
    n = r.size
    a = int(np.count_nonzero(r & p))
    b = int(np.count_nonzero(r & ~p))
    c = int(np.count_nonzero(~r & p))
    d = n - a - b - c
    po = _ratio(a + d, n)
    pe = _ratio((a + b) * (a + c) + (c + d) * (b + d), float(n) * n)
    kappa = (po - pe) / (1.0 - pe) if n and pe != 1.0 else float("nan")
    return GroundErrors(a, b, c, d, _ratio(b, a + b), _ratio(c, c + d), _ratio(b + c, n), float(kappa))


def confusion_matrix(ref, pred, classes=None) -> tuple[np.ndarray, np.ndarray]:
    """Confusion matrix over class codes.

    Parameters
    ----------
    ref, pred : (n,) array_like of int
        Reference and predicted class codes.
    classes : sequence of int, optional
        Row/column order; default: the sorted union of codes present in either.

    Returns
    -------
    classes : (k,) int64
    matrix : (k, k) int64
        ``matrix[i, j]`` = points of reference class ``classes[i]`` predicted as ``classes[j]``.
        Points whose code is not in ``classes`` are not counted.

    Examples
    --------
    >>> cls, m = confusion_matrix([2, 2, 6, 6, 6], [2, 6, 6, 6, 2])
    >>> cls.tolist(), m.tolist()
    ([2, 6], [[1, 1], [1, 2]])
    """
    r = np.asarray(ref).astype(np.int64, copy=False)
    p = np.asarray(pred).astype(np.int64, copy=False)
    if r.shape != p.shape or r.ndim != 1:
        raise InvalidInputError(f"reference {r.shape} and prediction {p.shape} must be equal-length vectors")
    cls = np.union1d(np.unique(r), np.unique(p)) if classes is None else np.asarray(classes, dtype=np.int64)
    k = cls.size
    ri = np.searchsorted(cls, r) if classes is None else _index_of(cls, r)
    pi = np.searchsorted(cls, p) if classes is None else _index_of(cls, p)
    ok = (ri >= 0) & (pi >= 0)
    m = np.bincount(ri[ok] * k + pi[ok], minlength=k * k).reshape(k, k).astype(np.int64)
    return cls, m


def _index_of(cls: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Position of each value of ``v`` in ``cls`` (-1 when absent)."""
    if cls.size == 0:
        return np.full(v.shape, -1, dtype=np.int64)
    order = np.argsort(cls)
    s = cls[order]
    pos = np.clip(np.searchsorted(s, v), 0, s.size - 1)
    return np.where(s[pos] == v, order[pos], -1)


@dataclass(frozen=True)
class ClassScores:
    """Per-class scores: precision = user's accuracy, recall = producer's accuracy."""

    code: int
    name: str
    support: int
    predicted: int
    precision: float
    recall: float
    f1: float

    def to_dict(self) -> dict:
        return {"code": self.code, "name": self.name, "support": self.support, "predicted": self.predicted,
                "precision": self.precision, "recall": self.recall, "f1": self.f1}


@dataclass(frozen=True)
class Evaluation:
    """Result of :func:`evaluate_labels`.

    Attributes
    ----------
    classes : (k,) int64
        Class codes, the order of ``confusion``'s rows and columns.
    confusion : (k, k) int64
        Rows: reference, columns: prediction.
    per_class : tuple of ClassScores
    overall_accuracy : float
        Fraction of matched points whose class agrees.
    ground : GroundErrors
        ISPRS ground / non-ground errors.
    n_matched, n_unmatched_pred, n_unmatched_ref : int
        Points compared, and points of each side without a partner.
    matched_by : str
        "order" or "coordinates".
    """

    classes: np.ndarray
    confusion: np.ndarray
    per_class: tuple
    overall_accuracy: float
    ground: GroundErrors
    n_matched: int
    n_unmatched_pred: int = 0
    n_unmatched_ref: int = 0
    matched_by: str = "order"
    extra: dict = field(default_factory=dict)

    @property
    def type1(self) -> float:
        return self.ground.type1

    @property
    def type2(self) -> float:
        return self.ground.type2

    @property
    def total_error(self) -> float:
        return self.ground.total_error

    @property
    def kappa(self) -> float:
        return self.ground.kappa

    def to_dict(self) -> dict:
        return {
            "type1": self.type1, "type2": self.type2, "total_error": self.total_error, "kappa": self.kappa,
            "counts": {k: v for k, v in self.ground.to_dict().items() if k in "abcd"},
            "classes": [int(c) for c in self.classes],
            "confusion": self.confusion.tolist(),
            "per_class": [s.to_dict() for s in self.per_class],
            "overall_accuracy": self.overall_accuracy,
            "n_matched": self.n_matched, "n_unmatched_pred": self.n_unmatched_pred,
            "n_unmatched_ref": self.n_unmatched_ref, "matched_by": self.matched_by,
            **self.extra,
        }


def class_scores(classes: np.ndarray, confusion: np.ndarray) -> tuple[ClassScores, ...]:
    """Precision, recall and F1 per class from a confusion matrix (NaN where undefined)."""
    m = np.asarray(confusion, dtype=np.float64)
    tp = np.diag(m)
    support = m.sum(axis=1)
    predicted = m.sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        prec = np.where(predicted > 0, tp / predicted, np.nan)
        rec = np.where(support > 0, tp / support, np.nan)
        f1 = np.where((prec + rec) > 0, 2 * prec * rec / (prec + rec), np.where(np.isnan(prec + rec), np.nan, 0.0))
    return tuple(
        ClassScores(int(c), class_name(int(c)), int(support[i]), int(predicted[i]), float(prec[i]), float(rec[i]), float(f1[i]))
        for i, c in enumerate(classes)
    )


def evaluate_labels(ref, pred, ground_classes=GROUND_CLASSES, classes=None) -> Evaluation:
    """Compare two class-code vectors of matched points.

    Parameters
    ----------
    ref, pred : (n,) array_like of int
        Reference and predicted ASPRS class codes of the same points.
    ground_classes : sequence of int
        Codes counted as bare earth in the ISPRS view (default: 2).
    classes : sequence of int, optional
        Confusion-matrix order (default: the sorted union of codes present).
    """
    r = np.asarray(ref).astype(np.int64, copy=False)
    p = np.asarray(pred).astype(np.int64, copy=False)
    if r.size == 0:
        raise InvalidInputError("no points to compare", "check that prediction and reference overlap")
    cls, m = confusion_matrix(r, p, classes)
    g = ground_errors(np.isin(r, ground_classes), np.isin(p, ground_classes))
    return Evaluation(cls, m, class_scores(cls, m), float(np.trace(m)) / max(int(m.sum()), 1), g, int(r.size))


def match_points(pred_xyz, ref_xyz, tolerance: float = 0.01) -> tuple[np.ndarray, np.ndarray, str]:
    """Pair points of a prediction with points of a reference.

    By order when both have the same number of points and every pair is within
    ``tolerance``; otherwise each prediction point takes its nearest reference point (KD-tree)
    within ``tolerance``, each reference point used at most once (the closest claimant wins).

    Parameters
    ----------
    pred_xyz, ref_xyz : (n, 3), (m, 3) array_like of float
    tolerance : float
        Largest 3D distance for a match, in the coordinates' unit.

    Returns
    -------
    pred_idx, ref_idx : (k,) int64
        Matched index pairs.
    how : str
        "order" or "coordinates".
    """
    a = np.asarray(pred_xyz, dtype=np.float64)
    b = np.asarray(ref_xyz, dtype=np.float64)
    if a.shape == b.shape and a.size and np.max(np.abs(a - b)) <= tolerance:
        idx = np.arange(a.shape[0], dtype=np.int64)
        return idx, idx, "order"
    from scipy.spatial import cKDTree

    origin = b.min(axis=0) if b.size else np.zeros(3)
    tree = cKDTree(b - origin)
    dist, j = tree.query(a - origin, k=1, distance_upper_bound=tolerance)
    ok = np.isfinite(dist)
    i = np.flatnonzero(ok)
    j = j[ok]
    dist = dist[ok]
    # one reference point per prediction point: keep the closest claimant
    order = np.lexsort((dist, j))
    j_sorted = j[order]
    first = np.ones(order.size, dtype=bool)
    first[1:] = j_sorted[1:] != j_sorted[:-1]
    keep = order[first]
    keep.sort()
    return i[keep].astype(np.int64), j[keep].astype(np.int64), "coordinates"


def isprs_labels_to_classes(labels) -> np.ndarray:
    """ISPRS filter-test labels (0 bare earth, 1 object) to ASPRS codes (2 ground, 1 unclassified)."""
    lab = np.asarray(labels)
    bad = ~np.isin(lab, (0, 1))
    if bad.any():
        raise InvalidInputError(
            f"{int(bad.sum())} label(s) are neither 0 (ground) nor 1 (object)", "the ISPRS reference column holds 0/1",
            field="label")
    return np.where(lab == 0, int(ASPRSClass.GROUND), int(ASPRSClass.UNCLASSIFIED)).astype(np.uint8)


def reference_classes(cloud: Cloud) -> np.ndarray:
    """ASPRS class codes of a reference cloud: its ``classification``, or its ISPRS ``label``."""
    if "label" in cloud.attrs:
        return isprs_labels_to_classes(cloud.attrs["label"])
    if "classification" in cloud.attrs:
        return np.asarray(cloud.attrs["classification"])
    raise InvalidInputError("the reference has neither a classification nor a label column",
                            "give a classified LAS/LAZ or an ISPRS text file (x y z label)")


def read_reference(path, bounds=None) -> Cloud:
    """Read a reference cloud: LAS/LAZ (classification) or an ISPRS text sample (x y z label).

    Text files are read as four columns ``x y z label`` (label 0 ground, 1 object). With
    ``bounds`` (xmin, ymin, xmax, ymax[, zmin, zmax]) only the points inside, inclusive.
    """
    p = Path(path)
    if p.suffix.lower() in (".txt", ".csv", ".xyz", ".pts"):
        c = read_isprs_text(p)
        if bounds is None:
            return c
        from workstation.io.registry import inside_bounds

        c = inside_bounds(c, np.asarray(bounds, dtype=np.float64))
        if c.n == 0:
            raise InvalidInputError("no reference points inside --bounds", "compare the box with the file's bounds",
                                    path=p, field="--bounds")
        return c
    from workstation.io import read_cloud

    return read_cloud(p, bounds=bounds)


def read_isprs_text(path) -> Cloud:
    """Read an ISPRS filter-test sample (whitespace separated ``X Y Z label``) into a Cloud.

    The label goes to the attribute ``label`` (0 bare earth, 1 object) and to
    ``classification`` (2 ground, 1 unclassified).
    """
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("file not found", "check the path", path=p)
    try:
        from workstation.io import read_cloud

        c = read_cloud(p, columns="x,y,z,label")
        # "label" may be stored under its own name or as an alias of classification
        lab = np.asarray(c.attrs["label"] if "label" in c.attrs else c.attrs["classification"])
    except (ModuleNotFoundError, ImportError):  # text IO not installed in this build
        d = np.loadtxt(p, ndmin=2)
        if d.shape[1] < 4:
            raise InvalidInputError(f"has {d.shape[1]} columns, expected X Y Z label", path=p) from None
        c = Cloud(d[:, :3])
        lab = d[:, 3]
    lab = np.round(lab).astype(np.uint8)
    return c.with_attrs(label=lab, classification=isprs_labels_to_classes(lab))


def evaluate_clouds(pred: Cloud, ref: Cloud, *, tolerance: float = 0.01, ground_classes=GROUND_CLASSES,
                    pred_attr: str = "classification", min_matched: float = 0.5) -> tuple[Evaluation, np.ndarray, np.ndarray]:
    """Match two clouds and evaluate ``pred``'s classes against ``ref``'s.

    ``min_matched`` (fraction): at least this share of the smaller cloud's points must find a
    partner, or the metrics would describe a few stray points (a wrong file, CRS or tolerance)
    and :class:`InvalidInputError` is raised instead.

    Returns
    -------
    evaluation : Evaluation
    pred_idx, ref_idx : (k,) int64
        The matched pairs (for plots).
    """
    if pred_attr not in pred.attrs:
        raise InvalidInputError(f"the prediction has no '{pred_attr}'", "run ws ground first", field=pred_attr)
    rc = reference_classes(ref)
    pi, ri, how = match_points(pred.xyz, ref.xyz, tolerance)
    names = f"{pred.meta.get('source', 'prediction')} vs {ref.meta.get('source', 'reference')}: "
    if pi.size == 0:
        raise InvalidInputError(
            f"{names}no point of the prediction matches a reference point",
            f"the clouds must hold the same points (within {tolerance} CRS units)")
    smaller = min(pred.n, ref.n)
    if pi.size < min_matched * smaller:
        raise InvalidInputError(
            f"{names}only {pi.size} of {smaller} points matched ({pi.size / smaller:.1%}; prediction {pred.n}, "
            f"reference {ref.n} points): the metrics would describe a few stray points",
            f"check that both files hold the same points in the same CRS and units, and the matching tolerance "
            f"({tolerance} CRS units); at least {min_matched:.0%} must match", field="min_matched")
    ev = evaluate_labels(rc[ri], np.asarray(pred.attrs[pred_attr])[pi], ground_classes)
    ev = Evaluation(ev.classes, ev.confusion, ev.per_class, ev.overall_accuracy, ev.ground, ev.n_matched,
                    pred.n - pi.size, ref.n - ri.size, how)
    if pi.size < max(pred.n, ref.n):
        log.warning("matched %d of %d predicted and %d reference points", pi.size, pred.n, ref.n)
    return ev, pi, ri


# -- plots -------------------------------------------------------------------------------------
def plot_errors(xy, ref_ground, pred_ground, path, title: str = "", overwrite: bool = True,
                max_points: int = 200_000) -> Path:
    """Plan-view PNG: correct points grey, Type I errors (ground missed) red, Type II blue.

    Parameters
    ----------
    xy : (n, 2+) array_like of float
    ref_ground, pred_ground : (n,) array_like of bool
    max_points : int
        At most this many correct points are drawn (a fixed random subset); errors all are.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from workstation.io import atomic_path

    xy = np.asarray(xy)[:, :2]
    r = np.asarray(ref_ground, bool)
    p = np.asarray(pred_ground, bool)
    t1 = r & ~p
    t2 = ~r & p
    ok = ~(t1 | t2)
    if ok.sum() > max_points:
        # draw a fixed random subset of the correct points (every error is drawn)
        keep = np.flatnonzero(ok)
        keep = np.random.default_rng(0).choice(keep, max_points, replace=False)
        ok = np.zeros_like(ok)
        ok[keep] = True
    o = xy.min(axis=0) if xy.size else np.zeros(2)
    fig, ax = plt.subplots(figsize=(8, 8), dpi=110)
    s = max(0.2, min(4.0, 2e4 / max(xy.shape[0], 1)))
    n_ok = int(np.count_nonzero(~(t1 | t2)))
    ax.scatter(*(xy[ok] - o).T, s=s, c="0.8", lw=0, label=f"correct ({n_ok})", rasterized=True)
    ax.scatter(*(xy[t1] - o).T, s=3 * s, c="tab:red", lw=0, label=f"Type I: ground as object ({t1.sum()})")
    ax.scatter(*(xy[t2] - o).T, s=3 * s, c="tab:blue", lw=0, label=f"Type II: object as ground ({t2.sum()})")
    ax.set_aspect("equal")
    ax.set_xlabel(f"x - {o[0]:.2f}")
    ax.set_ylabel(f"y - {o[1]:.2f}")
    ax.legend(loc="upper right", fontsize=8, markerscale=3)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    with atomic_path(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, format="png")
    plt.close(fig)
    return Path(path)


def plot_confusion(ev: Evaluation, path, title: str = "", overwrite: bool = True) -> Path:
    """Confusion-matrix PNG with counts and row-normalised colours (recall per reference class)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from workstation.io import atomic_path

    m = ev.confusion
    k = m.shape[0]
    with np.errstate(invalid="ignore", divide="ignore"):
        norm = np.nan_to_num(m / m.sum(axis=1, keepdims=True))
    fig, ax = plt.subplots(figsize=(1.2 * k + 3, 1.0 * k + 2.5), dpi=110)
    im = ax.imshow(norm, cmap="Blues", vmin=0, vmax=1)
    labels = [f"{c} {class_name(int(c))}" for c in ev.classes]
    ax.set_xticks(range(k), labels, rotation=45, ha="right", fontsize=8)
    ax.set_yticks(range(k), labels, fontsize=8)
    ax.set_xlabel("predicted")
    ax.set_ylabel("reference")
    for i in range(k):
        for j in range(k):
            ax.text(j, i, str(int(m[i, j])), ha="center", va="center", fontsize=8,
                    color="white" if norm[i, j] > 0.5 else "black")
    fig.colorbar(im, ax=ax, fraction=0.046, label="fraction of reference class")
    ax.set_title(title or f"Type I {100 * ev.type1:.2f} %  Type II {100 * ev.type2:.2f} %  "
                 f"total {100 * ev.total_error:.2f} %  kappa {100 * ev.kappa:.1f} %", fontsize=9)
    fig.tight_layout()
    with atomic_path(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, format="png")
    plt.close(fig)
    return Path(path)
