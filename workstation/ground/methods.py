"""One table of ground-filter methods: name -> (stage function, parameter class, presets).

``ground_filter(cloud, "smrf", preset="urban", window=25.0)`` runs a method with a preset and
overrides; ``ws ground`` is a thin layer over it.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Callable

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError

PRESET_NAMES = ("default", "flat", "urban", "forest", "steep")


@dataclass(frozen=True)
class Method:
    """A ground filter: its stage function, parameter dataclass and presets."""

    name: str
    func: Callable
    params: type
    presets: dict
    summary: str


def _table() -> dict[str, Method]:
    from . import auto, baselines, csf, pmf, ptd, smrf

    flat = {k: baselines.LowestParams() for k in PRESET_NAMES}
    lm = {k: baselines.LocalMinParams() for k in PRESET_NAMES}
    lm["steep"] = baselines.LocalMinParams(slope=1.0, threshold=1.0)
    lm["flat"] = baselines.LocalMinParams(slope=0.15)
    return {
        "smrf": Method("smrf", smrf.smrf, smrf.SMRFParams, smrf.PRESETS, "simple morphological filter (Pingel et al. 2013)"),
        "csf": Method("csf", csf.csf, csf.CSFParams, csf.PRESETS, "cloth simulation filter (Zhang et al. 2016)"),
        "pmf": Method("pmf", pmf.pmf, pmf.PMFParams, pmf.PRESETS, "progressive morphological filter (Zhang et al. 2003)"),
        "ptd": Method("ptd", ptd.ptd, ptd.PTDParams, ptd.PRESETS, "progressive TIN densification (Axelsson 2000)"),
        "auto": Method("auto", auto.auto, auto.AutoParams, auto.PRESETS, "majority vote of SMRF (2 settings), PMF, CSF and PTD"),
        "lowest": Method("lowest", baselines.lowest, baselines.LowestParams, flat, "lowest point per cell (baseline)"),
        "local_min": Method("local_min", baselines.local_min, baselines.LocalMinParams, lm,
                            "local minimum with a slope threshold (Vosselman 2000, baseline)"),
    }


_METHODS: dict[str, Method] | None = None


def methods() -> dict[str, Method]:
    """The method table (built on first use)."""
    global _METHODS
    if _METHODS is None:
        _METHODS = _table()
    return _METHODS


METHOD_NAMES = ("smrf", "csf", "pmf", "ptd", "auto", "lowest", "local_min")


def make_params(method: str, preset: str = "default", **overrides):
    """The parameter dataclass of ``method`` from ``preset`` with ``overrides`` (None ignored)."""
    table = methods()
    if method not in table:
        raise InvalidInputError(f"unknown ground method '{method}'", "use one of " + ", ".join(table))
    m = table[method]
    if preset not in m.presets:
        raise InvalidInputError(f"unknown preset '{preset}'", "use one of " + ", ".join(m.presets))
    base = m.presets[preset]
    fields = {f.name for f in dataclasses.fields(m.params)}
    ov = {k: v for k, v in overrides.items() if v is not None}
    bad = sorted(set(ov) - fields)
    if bad:
        raise InvalidInputError(f"method '{method}' has no parameter(s) {', '.join(bad)}",
                                "its parameters: " + ", ".join(sorted(fields)))
    return dataclasses.replace(base, **ov)


def ground_filter(cloud: Cloud, method: str = "smrf", preset: str = "default", tiles=None, **overrides) -> Cloud:
    """Run a ground filter by name.

    Parameters
    ----------
    cloud : Cloud
    method : str
        One of :data:`METHOD_NAMES`.
    preset : str
        "default", "flat", "urban", "forest" or "steep".
    tiles : workstation.ground.tiles.TileParams, optional
        Filter a cloud of more than ``tiles.tile_points`` points tile by tile with a buffer
        (:mod:`workstation.ground.tiles`); None: the whole cloud at once.
    **overrides
        Parameter fields to replace (None values are ignored).
    """
    p = make_params(method, preset, **overrides)
    if tiles is not None:
        from .tiles import ground_tiled

        return ground_tiled(cloud, method, p, tiles)
    return methods()[method].func(cloud, p)
