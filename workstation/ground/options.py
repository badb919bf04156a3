"""The options every ground filter's parameters share: which points take part, the low-noise
step before the filter and the bridge-deck step after it.

Each method's parameter dataclass (:class:`workstation.ground.smrf.SMRFParams`, ...) derives
from :class:`FilterOptions`; :func:`workstation.ground.common.run_filter` reads these fields
the same way for every method. They are keyword-only, so a method's own fields keep their
positions in its constructor. This module stands apart from :mod:`workstation.ground.common`
because :mod:`workstation.ground.noise`, which defines the low-noise step's parameters,
imports :mod:`~workstation.ground.common` itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .bridges import BridgeParams
from .noise import LowNoiseParams


@dataclass(frozen=True, kw_only=True)
class FilterOptions:
    """Options of every ground filter (keyword-only fields of each method's parameters).

    Attributes
    ----------
    reclassify : bool
        Overwrite classes other than 0/1/2 and use noise points (False).
    last_returns_only : bool
        Only last/only returns can be ground (True, as PDAL's ``returns="last,only"``).
    noise : bool
        Run the low-noise step first (True): isolated low points become class 7 and take no
        part (:func:`workstation.ground.noise.low_noise`; PDAL's ``filters.elm`` before its
        ground filters). Off: every point takes part, as in PDAL without it.
    noise_params : LowNoiseParams
        Its parameters (metres).
    bridges : bool
        Take bridge decks out of the ground as class 17 (True;
        :func:`workstation.ground.bridges.bridge_decks`), so a DTM runs under them.
    bridge_params : BridgeParams
        Its parameters (metres).
    """

    reclassify: bool = False
    last_returns_only: bool = True
    noise: bool = True
    noise_params: LowNoiseParams = field(default_factory=LowNoiseParams)
    bridges: bool = True
    bridge_params: BridgeParams = field(default_factory=BridgeParams)
