"""``auto``: a majority vote of five complementary filters, one parameter set for all terrain.

Members: SMRF with a 30 m window (catches wide roofs) whose object test follows the terrain's
trend slope (``trend_slope=1``: mountainsides are not cut as objects), SMRF with a tighter elevation test
(threshold 0.3 m, scalar 1.0; fewer low objects accepted), PMF (square windows, a different
failure mode on slopes), CSF (a cloth: bridges objects, follows terraces) and PTD (a TIN grown
from seeds: follows slopes and breaklines). A point is ground when at least three say so.
Then the refine chain declared in :attr:`AutoParams.steps` runs on the vote
(:mod:`workstation.ground.refine`): the patches of voted ground that drop by 1 m or more on all
sides (roofs, decks, wagons) are taken out, the rejected points on terrain steps that the
vote's TIN spans are put back (those at least one member accepted), and, where the echoes show
a canopy, the understorey the vote let in is taken out (a no-op without return numbers).
Bridge decks leave the ground last, as in every filter (``bridges``,
:func:`workstation.ground.common.write_classes`). Its figures against each member's are in
docs/benchmarks.md ("Ground filtering").
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .csf import CSFParams, csf_ground
from .options import FilterOptions
from .patches import PatchParams
from .pmf import PMFParams, pmf_ground
from .ptd import PTDParams, ptd_ground
from .refine import Refine, check_steps, declare, run_chain
from .risers import RiserParams
from .smrf import SMRFParams, smrf_ground
from .understorey import UnderstoreyParams

STAGE = "ground.auto"
#: The refine steps ``auto`` can run after its vote: each step's switch field and its
#: parameters field in :class:`AutoParams`.
STEP_NAMES = {"raised_patches": "patch_params", "risers": "riser_params", "understorey": "understorey_params"}


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
    steps : tuple of str
        The refine chain after the vote, in order (:mod:`workstation.ground.refine`), of the
        steps in :data:`STEP_NAMES` (bridge decks leave the ground after it, as in every
        filter: ``bridges``): ``("raised_patches", "risers", "understorey")``.
    raised_patches : bool
        Run the ``raised_patches`` step: take out the patches of voted ground that stand above
        all the ground around them (roofs, decks, wagons; :mod:`workstation.ground.patches`;
        True).
    patch_params : PatchParams
    risers : bool
        Run the ``risers`` step: put back the rejected points on terrain steps that at least
        one member accepted (:mod:`workstation.ground.risers`; True).
    riser_params : RiserParams
    understorey : bool
        Run the ``understorey`` step: take the understorey out of the ground under canopy
        (True; needs return numbers).
    understorey_params : UnderstoreyParams
    """

    smrf_wide: SMRFParams = field(default_factory=lambda: SMRFParams(slope=0.15, window=30.0, trend_slope=1.0))
    smrf_tight: SMRFParams = field(default_factory=lambda: SMRFParams(slope=0.15, window=30.0, threshold=0.3, scalar=1.0))
    pmf: PMFParams = field(default_factory=PMFParams)
    csf: CSFParams = field(default_factory=CSFParams)
    ptd: PTDParams = field(default_factory=PTDParams)
    min_votes: int = 3
    steps: tuple[str, ...] = ("raised_patches", "risers", "understorey")
    raised_patches: bool = True
    patch_params: PatchParams = field(default_factory=PatchParams)
    risers: bool = True
    riser_params: RiserParams = field(default_factory=RiserParams)
    understorey: bool = True
    understorey_params: UnderstoreyParams = field(default_factory=UnderstoreyParams)

    def __post_init__(self):
        object.__setattr__(self, "steps", check_steps(self.steps, "steps", STEP_NAMES))

    def chain(self) -> tuple:
        """The refine chain (:func:`workstation.ground.refine.declare`): the declared ``steps``
        that are switched on, with their parameters."""
        return declare(self.steps, on={n: getattr(self, n) for n in STEP_NAMES},
                       params={n: getattr(self, f) for n, f in STEP_NAMES.items()})


PRESETS: dict[str, AutoParams] = common.presets(AutoParams)  # one parameter set for all terrain


MEMBERS = ("smrf_wide", "smrf_tight", "pmf", "csf", "ptd")


def member_votes(xyz: np.ndarray, p: AutoParams) -> np.ndarray:
    """(5, m) bool: the ground of each member (:data:`MEMBERS` order) on local metric points.

    The two SMRF members and CSF's empty-particle surface share one minimum grid and one
    opening sequence (:class:`workstation.ground.smrf.SharedSurfaces`); every member's flags
    are those of its run alone.
    """
    from .csf import surface_params
    from .smrf import SharedSurfaces

    shared = SharedSurfaces(xyz, [q for q in (p.smrf_wide, p.smrf_tight, surface_params(xyz, p.csf)) if q is not None])
    return np.stack([smrf_ground(xyz, p.smrf_wide, shared), smrf_ground(xyz, p.smrf_tight, shared),
                     pmf_ground(xyz, p.pmf), csf_ground(xyz, p.csf, shared), ptd_ground(xyz, p.ptd)])


def refine_vote(xyz: np.ndarray, ground: np.ndarray, votes: np.ndarray, p: AutoParams,
                return_number: np.ndarray | None = None, number_of_returns: np.ndarray | None = None) -> np.ndarray:
    """Ground flags (m,) bool after the refine chain of ``p`` (:meth:`AutoParams.chain`) on the
    vote's ``ground``; ``votes`` (m,) is the number of members that accepted each point, the
    echo numbers (when known) show the canopy to the understorey step."""
    state = Refine(xyz, ground, votes, return_number, number_of_returns)
    return run_chain(state, p.chain()).ground


def auto_ground(xyz: np.ndarray, p: AutoParams, return_number: np.ndarray | None = None,
                number_of_returns: np.ndarray | None = None) -> np.ndarray:
    """Ground flags (m,) bool of local metric points by the majority vote and the refine chain
    (see :func:`refine_vote`)."""
    votes = member_votes(xyz, p).sum(axis=0, dtype=np.int8)
    return refine_vote(xyz, votes >= p.min_votes, votes, p, return_number, number_of_returns)


def auto(cloud: Cloud, params: AutoParams | None = None, **overrides) -> Cloud:
    """Classify ground by the ``auto`` vote (SMRF wide, SMRF tight, PMF, CSF, PTD).

    Returns
    -------
    Cloud
        ``classification`` 2 on ground, 1 elsewhere (other classes kept unless ``reclassify``).
    """
    p = replace(params or AutoParams(), **overrides)
    return common.run_filter(cloud, p, STAGE, lambda prep: auto_ground(prep.xyz, p, *echoes(cloud, prep)))


def echoes(cloud: Cloud, prep: common.Prepared) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Return number and number of returns of the prepared points, (None, None) when the cloud
    has no return numbers."""
    if not ("return_number" in cloud.attrs and "number_of_returns" in cloud.attrs):
        return None, None
    return (np.asarray(cloud.attrs["return_number"])[prep.index],
            np.asarray(cloud.attrs["number_of_returns"])[prep.index])
