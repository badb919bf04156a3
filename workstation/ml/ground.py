"""Ground filtering with the point classifier (``ws ground --method ml``).

The classifier's ground class becomes :attr:`ASPRSClass.GROUND`; other points become
:attr:`ASPRSClass.UNCLASSIFIED`, except points already in another class (anything but 0, 1
and 2), which keep it unless ``reclassify`` — the convention of the other ground filters
(:mod:`workstation.ground.common`).

The classifier runs its refine chain (:meth:`workstation.ml.classifier.PointClassifier.predict_codes`)
with these switches: the raised-patch step as ``raised_patches`` says (roofs and decks the
gate let in), the water step off (still water stays in the ground, as with the other
filters; ``ws ground --water``, :func:`workstation.ground.water.classify_water`, separates it)
and the roof test off (it only moves building points among the object classes); the
understorey and bridge steps as the model is saved (on in the shipped model).

With ``member_vote`` the classifier's gate (its ground before the refine chain,
:attr:`workstation.ml.classifier.Prediction.gate`) is one voter among ``auto``'s five
members (:func:`workstation.ground.auto.member_votes`), on the points ``auto`` filters
(:func:`workstation.ground.common.prepare`: noise classes, first and intermediate returns
and the low-noise step's low points take no part; the low points become class 7, the others
are not ground): a point is ground when a strict majority of the six (4) accepts it, and
``auto``'s refine chain (:meth:`workstation.ground.auto.AutoParams.chain`, its riser step
guarded by the six votes, its raised-patch step as ``raised_patches`` says) runs on that
ground. The classifier's own refine chain then serves only for its bridge-deck codes, which
stay out of the ground. The members cover what the network's provisional surface cuts
(narrow embankments, whose crests a 70 m opening removes) and the network vetoes what a
single member lets in. It costs the members' run time (about 1.5x the CPU time of the plain
path on a 0.5 M-point tile, 2-4x on the small ISPRS samples) and their memory on the whole
cloud at once: ``ws ground`` refuses it above ``--tile-points`` points.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.core.cloud import Cloud
from workstation.core.errors import StageError


@dataclass(frozen=True)
class MLGroundParams:
    """Settings of the ML ground filter.

    Attributes
    ----------
    model : str or None
        Model file (None: the shipped model).
    min_confidence : float
        Probability (0-1) of the ground class needed to call a point ground.
    reclassify : bool
        Overwrite points already in a class other than 0, 1, 2.
    device : str
        ``auto``, ``cpu`` or ``cuda``.
    raised_patches : bool
        Take out the patches of ground that drop by 1 m or more on all sides (roofs and decks
        the gate let in; :func:`workstation.ground.patches.raised_patches`; True).
    member_vote : bool
        Vote with ``auto``'s five members, the classifier's gate the sixth voter, and refine
        with ``auto``'s chain (see the module doc; False).
    """

    model: str | None = None
    min_confidence: float = 0.0
    reclassify: bool = False
    device: str = "auto"
    raised_patches: bool = True
    member_vote: bool = False


def ml_ground(cloud: Cloud, params: MLGroundParams = MLGroundParams()) -> Cloud:
    """Classify ground with the point classifier; returns a new cloud (see module doc)."""
    from workstation.ground.common import OVERWRITABLE

    from .classifier import PointClassifier, StepSwitches

    t0 = time.perf_counter()
    clf = PointClassifier.load(params.model, device=params.device)
    switches = StepSwitches(roof_test=False, raised_patches=params.raised_patches, water=False)
    pred = clf.predict_codes(cloud, switches)
    P = pred.proba
    low = np.zeros(0, np.int64)
    if params.member_vote:
        ground, low = member_vote_ground(cloud, pred.gate, params.raised_patches, params.reclassify)
        ground &= pred.codes != C.BRIDGE_DECK
    else:
        ground = pred.codes == C.GROUND
    ground &= P[:, 0] >= params.min_confidence
    if not ground.any():
        raise StageError("ground_ml", "no point was classified as ground", "check the units and the input; try another method")
    old = np.asarray(cloud.attrs["classification"]) if "classification" in cloud.attrs else np.zeros(cloud.n, np.uint8)
    may = np.ones(cloud.n, bool) if params.reclassify else np.isin(old, OVERWRITABLE)
    new = np.where(ground, C.GROUND, C.UNCLASSIFIED).astype(np.uint8)
    new[low] = C.LOW_POINT
    cls = np.where(may, new, old).astype(np.uint8)
    out = cloud.with_attrs(classification=cls, confidence=P[:, 0].astype(np.float32))
    return out.with_history("ground_ml", {"model": params.model or "shipped", "min_confidence": params.min_confidence,
                                          "reclassify": params.reclassify, "raised_patches": params.raised_patches,
                                          "member_vote": params.member_vote},
                            time.perf_counter() - t0)


def member_vote_ground(cloud: Cloud, gate: np.ndarray, raised_patches: bool = True,
                       reclassify: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The vote of ``auto``'s five members (their default parameters, grid cells sized by the
    points) and the classifier's ``gate`` (n,) bool: a strict majority of the six, then
    ``auto``'s refine chain (its raised-patch step as ``raised_patches`` says) with the six
    votes as the riser step's guard (:func:`workstation.ground.auto.refine_vote`).

    The vote runs on the points ``auto`` filters (:func:`workstation.ground.common.prepare`:
    no noise classes unless ``reclassify``, last and only returns, the low-noise step's low
    points out, local metres on the 100 m lattice), so a low outlier cannot pull a member's
    surface down.

    Returns
    -------
    ground : (n,) bool
        Ground flags of the cloud's points (False outside the prepared points).
    low : (k,) int64
        Indices of the low-noise step's low points (class 7 when written).
    """
    from workstation.ground import auto
    from workstation.ground.common import prepare_filter
    from workstation.ground.methods import fit_to_points

    p = fit_to_points(auto.AutoParams(raised_patches=raised_patches, reclassify=reclassify), cloud)
    prep = prepare_filter(cloud, p, "ground_ml")
    votes = auto.member_votes(prep.xyz, p).sum(axis=0, dtype=np.int8) + np.asarray(gate, dtype=np.int8)[prep.index]
    voted = auto.refine_vote(prep.xyz, 2 * votes > len(auto.MEMBERS) + 1, votes, p, *auto.echoes(cloud, prep))
    ground = np.zeros(cloud.n, dtype=bool)
    ground[prep.index[voted]] = True
    return ground, prep.noise
