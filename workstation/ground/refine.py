"""The refine steps that follow a ground filter or the point classifier's gate, and the one way
to chain them.

Each step is a plain function ``step(state, params) -> state`` of a :class:`Refine` state (local
metric points, their ground flags and what the steps need or report) and its own frozen
parameters, whose type names it:

=================  =======================================================  =========================
name               what it does                                              parameters
=================  =======================================================  =========================
``raised_patches`` patches of ground that drop on all sides leave the       :class:`PatchParams`
                   ground (roofs, decks, wagons;
                   :func:`workstation.ground.patches.raised_patches`)
``risers``         rejected points on terrain steps the ground's TIN spans  :class:`RiserParams`
                   join it (:func:`workstation.ground.risers.riser_fill`;
                   guarded by ``votes`` when given)
``crests``         terrain the ground filter cut off as an object (the      :class:`CrestParams`
                   crests of dykes and ridges, whose sides are no steeper
                   than terrain) joins the ground
                   (:func:`workstation.ground.crests.crest_fill`)
``understorey``    under canopy (read from the echoes), ground above the    :class:`UnderstoreyParams`
                   ground's lower envelope leaves it
                   (:func:`workstation.ground.understorey.refine_understorey`;
                   a no-op without return numbers)
``water``          ground on still water leaves the ground and becomes      :class:`WaterParams`
                   ``water`` (:func:`workstation.ground.water.water_surfaces`)
``bridges``        bridge decks among the ``surface`` points leave the      :class:`BridgeParams`
                   ground and become ``deck``
                   (:func:`workstation.ground.bridges.bridge_decks`)
=================  =======================================================  =========================

A *chain* is a tuple of parameter objects, run in its order by :func:`run_chain`. Its owner
declares the order as a tuple of step names (``AutoParams.steps``, ``PointClassifier.steps``)
and switches single steps off with its boolean fields of the same names; :func:`declare`
turns the names, switches and parameters into the chain.

Examples
--------
>>> import numpy as np
>>> g = np.mgrid[0:40:0.5, 0:40:0.5].reshape(2, -1).T
>>> roof = (np.abs(g - 20) < 5).all(axis=1)
>>> xyz = np.column_stack([g, np.where(roof, 6.0, 0.0)])
>>> state = Refine(xyz, np.ones(len(xyz), bool))
>>> chain = declare(("raised_patches", "risers"), on={"risers": False})
>>> [type(p).__name__ for p in chain]
['PatchParams']
>>> out = run_chain(state, chain)
>>> bool((out.ground == ~roof).all())
True
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Callable, Mapping

import numpy as np

from workstation.core.errors import InvalidInputError

from . import bridges as _bridges
from . import crests as _crests
from . import patches as _patches
from . import risers as _risers
from . import understorey as _understorey
from . import water as _water
from .bridges import BridgeParams
from .common import TinHandoff
from .crests import CrestParams
from .patches import PatchParams
from .risers import RiserParams
from .understorey import UnderstoreyParams
from .water import WaterParams


@dataclass(frozen=True, eq=False)
class Refine:
    """The state a refine chain works on (arrays are not copied; steps return new states).

    Attributes
    ----------
    xyz : (m, 3) float64
        Local metric coordinates.
    ground : (m,) bool
        Ground flags.
    votes : (m,) int or None
        How many members of a vote accepted each point (the riser step's guard; None: none).
    return_number, number_of_returns : (m,) int or None
        Echo numbers (the understorey step reads the canopy from them; the water step keeps
        water to single echoes); None when the cloud has none.
    surface : (m,) bool or None
        Points that could be terrain (the crest step) or carry a bridge deck (noise left
        out); None: all.
    water : (m,) bool or None
        Points the water step took out of the ground (None until it runs).
    water_confidence : (m,) float64 or None
        Of the water points: 1 at their surface's level, 0.5 at ``point_tolerance`` from it
        (NaN elsewhere).
    deck : (m,) bool or None
        Points of bridge decks (None until the bridge step runs).
    tins : TinHandoff
        A TIN one step leaves for a later one on the same points
        (:class:`workstation.ground.common.TinHandoff`; the raised-patch test's for the riser
        fill). States derived by ``replace`` share it: :func:`run_chain` gives each chain its
        own.
    """

    xyz: np.ndarray
    ground: np.ndarray
    votes: np.ndarray | None = None
    return_number: np.ndarray | None = None
    number_of_returns: np.ndarray | None = None
    surface: np.ndarray | None = None
    water: np.ndarray | None = None
    water_confidence: np.ndarray | None = None
    deck: np.ndarray | None = None
    tins: TinHandoff = field(default_factory=TinHandoff, repr=False, compare=False)


def raised_patches(state: Refine, p: PatchParams) -> Refine:
    """The raised patches out of the ground (:func:`workstation.ground.patches.raised_patches`)."""
    return replace(state, ground=_patches.raised_patches(state.xyz, state.ground, p, state.tins))


def risers(state: Refine, p: RiserParams) -> Refine:
    """The rejected points of unresolved terrain steps into the ground, those that at least
    ``p.min_votes`` members accepted when ``state.votes`` is given
    (:func:`workstation.ground.risers.riser_fill`)."""
    return replace(state, ground=_risers.riser_fill(state.xyz, state.ground, state.votes, p, state.tins))


def crests(state: Refine, p: CrestParams) -> Refine:
    """The crests the ground lacked into it, of the ``surface`` points when given
    (:func:`workstation.ground.crests.crest_fill`)."""
    return replace(state, ground=_crests.crest_fill(state.xyz, state.ground, p, state.surface))


def understorey(state: Refine, p: UnderstoreyParams) -> Refine:
    """The understorey out of the ground under canopy, the canopy being the share of multi-echo
    pulses per ``p.canopy_cell`` (:func:`workstation.ground.understorey.canopy_share`); the
    state unchanged without return numbers."""
    if state.return_number is None or state.number_of_returns is None:
        return state
    share = _understorey.canopy_share(state.xyz[:, :2], state.return_number, state.number_of_returns, p.canopy_cell)
    return replace(state, ground=_understorey.refine_understorey(state.xyz, state.ground, share, p))


def water(state: Refine, p: WaterParams) -> Refine:
    """The ground on still water out of the ground, into ``water`` with its confidence
    (:func:`workstation.ground.water.water_surfaces`, single echoes only when
    ``number_of_returns`` is known)."""
    on, offset = _water.water_surfaces(state.xyz, state.ground, state.number_of_returns, p)
    confidence = 1.0 - np.abs(offset) / (2 * p.point_tolerance)
    return replace(state, ground=state.ground & ~on, water=on, water_confidence=confidence)


def bridges(state: Refine, p: BridgeParams) -> Refine:
    """Bridge decks found on the lowest ``surface`` points out of the ground, into ``deck``
    (:func:`workstation.ground.bridges.bridge_decks`; a deck must reach the ground)."""
    deck = _bridges.bridge_decks(state.xyz, p, surface=state.surface, ground=state.ground)
    return replace(state, ground=state.ground & ~deck, deck=deck)


@dataclass(frozen=True)
class Step:
    """A refine step: its function and the type of its parameters."""

    run: Callable[[Refine, object], Refine]
    params: type


#: The steps by name (the names owners declare and switch).
STEPS: dict[str, Step] = {
    "raised_patches": Step(raised_patches, PatchParams),
    "risers": Step(risers, RiserParams),
    "crests": Step(crests, CrestParams),
    "understorey": Step(understorey, UnderstoreyParams),
    "water": Step(water, WaterParams),
    "bridges": Step(bridges, BridgeParams),
}
_BY_PARAMS = {s.params: s.run for s in STEPS.values()}


def check_steps(steps, field: str = "steps", allowed=None) -> tuple[str, ...]:
    """``steps`` as a tuple of step names, each known (in ``allowed``, default :data:`STEPS`)
    and given once; an :class:`InvalidInputError` naming ``field`` otherwise."""
    if isinstance(steps, str):
        raise InvalidInputError(f"{field} must be a sequence of step names, got the string {steps!r}",
                                f"e.g. ({steps!r},)", field=field)
    names = tuple(steps)
    allowed = tuple(STEPS) if allowed is None else tuple(allowed)
    bad = [n for n in names if n not in allowed]
    if bad:
        raise InvalidInputError(f"unknown refine step {bad[0]!r} in {field}", "the steps: " + ", ".join(allowed),
                                field=field)
    if len(set(names)) != len(names):
        raise InvalidInputError(f"a refine step is named twice in {field}: {', '.join(names)}", field=field)
    return names


def declare(steps, on: Mapping[str, bool] | None = None, params: Mapping[str, object] | None = None) -> tuple:
    """The chain of the named ``steps``, in their order, without those ``on`` switches off (a
    name missing from ``on`` is on), each with its parameters from ``params`` (its defaults
    where not given)."""
    on, params = on or {}, params or {}
    chain = []
    for name in check_steps(steps):
        if on.get(name, True):
            p = params.get(name)
            p = STEPS[name].params() if p is None else p
            if not isinstance(p, STEPS[name].params):
                raise InvalidInputError(f"the {name} step takes {STEPS[name].params.__name__}, "
                                        f"got {type(p).__name__}", field=name)
            chain.append(p)
    return tuple(chain)


def run_chain(state: Refine, chain) -> Refine:
    """``state`` after each step of ``chain`` (parameter objects, see :func:`declare`) in order.

    A TIN a step leaves (``state.tins``) is kept only for a riser fill right after it; the
    chain works on a handoff of its own, so the caller's ``state.tins`` is left as it was."""
    chain = tuple(chain)
    state = replace(state, tins=TinHandoff())
    for i, p in enumerate(chain):
        step = _BY_PARAMS.get(type(p))
        if step is None:
            raise InvalidInputError(f"{type(p).__name__} is no refine step's parameters",
                                    "the steps take " + ", ".join(t.__name__ for t in _BY_PARAMS), field="chain")
        state = step(state, p)
        if not (i + 1 < len(chain) and isinstance(chain[i + 1], RiserParams)):
            state.tins.clear()
    return state
