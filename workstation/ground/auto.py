"""``auto``: a majority vote of five complementary filters, one parameter set for all terrain.

Members: SMRF with a 30 m window (catches wide roofs) whose object test follows the terrain's
trend slope (``trend_slope=1``: mountainsides are not cut as objects), SMRF with a tighter elevation test
(threshold 0.3 m, scalar 1.0; fewer low objects accepted), PMF (square windows, a different
failure mode on slopes), CSF (a cloth: bridges objects, follows terraces) and PTD (a TIN grown
from seeds: follows slopes and breaklines). A point is ground when at least three say so.
Then the patches of voted ground that drop by 1 m or more on all sides (roofs, decks, wagons)
are taken out (:mod:`workstation.ground.patches`), the rejected points on terrain steps that the
vote's TIN spans are put back (:mod:`workstation.ground.risers`), and, where the echoes show a
canopy, the understorey the vote let in (:mod:`workstation.ground.understorey`; a no-op without
return numbers). Its figures against each member's are in docs/benchmarks.md ("Ground
filtering").
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .csf import CSFParams, csf_ground
from .options import FilterOptions
from .patches import PatchParams, raised_patches
from .pmf import PMFParams, pmf_ground
from .ptd import PTDParams, ptd_ground
from .risers import RiserParams, riser_fill
from .smrf import SMRFParams, smrf_ground
from .understorey import UnderstoreyParams, canopy_share, refine_understorey

STAGE = "ground.auto"


@dataclass(frozen=True)
class AutoParams(FilterOptions):
    """Parameters of the ``auto`` vote and the options of every filter
    (:class:`~workstation.ground.options.FilterOptions`; those of the members are not used).
    Lengths in metres.

    Attributes
    ----------
    smrf_wide : SMRFParams
        First member (slope 0.15, window 30 m, slope-adaptive object test ``trend_slope=1``).
    smrf_tight : SMRFParams
        Second member (slope 0.15, window 30 m, threshold 0.3 m, scalar 1.0).
    pmf : PMFParams
        Third member (PMF defaults).
    csf : CSFParams
        Fourth member (CSF defaults).
    ptd : PTDParams
        Fifth member (PTD defaults).
    min_votes : int
        Votes needed for ground (3 of 5).
    raised_patches : bool
        Take out the patches of voted ground that stand above all the ground around them
        (roofs, decks, wagons; :mod:`workstation.ground.patches`; True).
    patch_params : PatchParams
    risers : bool
        Put back the rejected points on terrain steps that at least one member accepted
        (:mod:`workstation.ground.risers`; True).
    riser_params : RiserParams
    understorey : bool
        Take the understorey out of the ground under canopy (True; needs return numbers).
    understorey_params : UnderstoreyParams
    """

    smrf_wide: SMRFParams = field(default_factory=lambda: SMRFParams(slope=0.15, window=30.0, trend_slope=1.0))
    smrf_tight: SMRFParams = field(default_factory=lambda: SMRFParams(slope=0.15, window=30.0, threshold=0.3, scalar=1.0))
    pmf: PMFParams = field(default_factory=PMFParams)
    csf: CSFParams = field(default_factory=CSFParams)
    ptd: PTDParams = field(default_factory=PTDParams)
    min_votes: int = 3
    raised_patches: bool = True
    patch_params: PatchParams = field(default_factory=PatchParams)
    risers: bool = True
    riser_params: RiserParams = field(default_factory=RiserParams)
    understorey: bool = True
    understorey_params: UnderstoreyParams = field(default_factory=UnderstoreyParams)


PRESETS: dict[str, AutoParams] = common.presets(AutoParams)  # one parameter set for all terrain


MEMBERS = ("smrf_wide", "smrf_tight", "pmf", "csf", "ptd")


def member_votes(xyz: np.ndarray, p: AutoParams) -> np.ndarray:
    """(5, m) bool: the ground of each member (:data:`MEMBERS` order) on local metric points."""
    return np.stack([smrf_ground(xyz, p.smrf_wide), smrf_ground(xyz, p.smrf_tight), pmf_ground(xyz, p.pmf),
                     csf_ground(xyz, p.csf), ptd_ground(xyz, p.ptd)])


def refine_vote(xyz: np.ndarray, ground: np.ndarray, votes: np.ndarray, p: AutoParams,
                share: np.ndarray | None = None) -> np.ndarray:
    """The steps after the vote: raised patches out, risers in, and (with ``share``) the
    understorey out; ``votes`` (m,) is the number of members that accepted each point."""
    if p.raised_patches:
        ground = raised_patches(xyz, ground, p.patch_params)
    if p.risers:
        ground = riser_fill(xyz, ground, votes, p.riser_params)
    if p.understorey and share is not None:
        ground = refine_understorey(xyz, ground, share, p.understorey_params)
    return ground


def auto_ground(xyz: np.ndarray, p: AutoParams, share: np.ndarray | None = None) -> np.ndarray:
    """Ground flags (m,) bool of local metric points by the majority vote, refined under
    canopy where ``share`` (:func:`workstation.ground.understorey.canopy_share`) is given."""
    votes = member_votes(xyz, p).sum(axis=0, dtype=np.int8)
    return refine_vote(xyz, votes >= p.min_votes, votes, p, share)


def auto(cloud: Cloud, params: AutoParams | None = None, **overrides) -> Cloud:
    """Classify ground by the ``auto`` vote (SMRF wide, SMRF tight, PMF, CSF, PTD).

    Returns
    -------
    Cloud
        ``classification`` 2 on ground, 1 elsewhere (other classes kept unless ``reclassify``).
    """
    p = replace(params or AutoParams(), **overrides)
    return common.run_filter(cloud, p, STAGE, lambda prep: auto_ground(prep.xyz, p, _canopy_share(cloud, prep, p)))


def _canopy_share(cloud: Cloud, prep: common.Prepared, p: AutoParams) -> np.ndarray | None:
    """:func:`~workstation.ground.understorey.canopy_share` of the prepared points, None when
    the understorey step is off or the cloud has no return numbers."""
    if not (p.understorey and "return_number" in cloud.attrs and "number_of_returns" in cloud.attrs):
        return None
    return canopy_share(prep.xyz[:, :2], np.asarray(cloud.attrs["return_number"])[prep.index],
                        np.asarray(cloud.attrs["number_of_returns"])[prep.index], p.understorey_params.canopy_cell)
