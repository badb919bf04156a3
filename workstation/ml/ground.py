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
members (:func:`workstation.ground.auto.member_votes`): a point is ground when a strict
majority of the six (4) accepts it, and ``auto``'s refine chain
(:meth:`workstation.ground.auto.AutoParams.chain`, its riser step guarded by the six votes)
runs on that ground; the classifier's bridge decks
stay out of it. The members cover what the network's provisional surface cuts (narrow
embankments, whose crests a 70 m opening removes) and the network vetoes what a single
member lets in. It costs the members' run time (about 1.5x the CPU time of the plain path
on a 0.5 M-point tile, 2-4x on the small ISPRS samples).
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
    if params.member_vote:
        ground = member_vote_ground(cloud, pred.gate) & (pred.codes != C.BRIDGE_DECK)
    else:
        ground = pred.codes == C.GROUND
    ground &= P[:, 0] >= params.min_confidence
    if not ground.any():
        raise StageError("ground_ml", "no point was classified as ground", "check the units and the input; try another method")
    old = np.asarray(cloud.attrs["classification"]) if "classification" in cloud.attrs else np.zeros(cloud.n, np.uint8)
    may = np.ones(cloud.n, bool) if params.reclassify else np.isin(old, OVERWRITABLE)
    cls = np.where(may, np.where(ground, C.GROUND, C.UNCLASSIFIED), old).astype(np.uint8)
    out = cloud.with_attrs(classification=cls, confidence=P[:, 0].astype(np.float32))
    return out.with_history("ground_ml", {"model": params.model or "shipped", "min_confidence": params.min_confidence,
                                          "reclassify": params.reclassify, "raised_patches": params.raised_patches,
                                          "member_vote": params.member_vote},
                            time.perf_counter() - t0)


def member_vote_ground(cloud: Cloud, gate: np.ndarray) -> np.ndarray:
    """Ground flags (n,) bool of the vote of ``auto``'s five members (their default
    parameters, grid cells sized by the points) and the classifier's ``gate`` (n,) bool: a
    strict majority of the six, then ``auto``'s refine chain with the six votes as the riser
    step's guard (:func:`workstation.ground.auto.refine_vote`)."""
    from workstation.ground.auto import MEMBERS, AutoParams, member_votes, refine_vote
    from workstation.ground.methods import fit_to_points

    from .features import metric_xyz

    p = fit_to_points(AutoParams(), cloud)
    xyz = metric_xyz(cloud)[0]
    votes = member_votes(xyz, p).sum(axis=0, dtype=np.int8) + np.asarray(gate, dtype=np.int8)
    ground = 2 * votes > len(MEMBERS) + 1
    return refine_vote(xyz, ground, votes, p, cloud.attrs.get("return_number"), cloud.attrs.get("number_of_returns"))
