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

from .common import PRESET_NAMES  # noqa: F401 - the preset names, here with the method table


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

    return {
        "smrf": Method("smrf", smrf.smrf, smrf.SMRFParams, smrf.PRESETS, "simple morphological filter (Pingel et al. 2013)"),
        "csf": Method("csf", csf.csf, csf.CSFParams, csf.PRESETS, "cloth simulation filter (Zhang et al. 2016)"),
        "pmf": Method("pmf", pmf.pmf, pmf.PMFParams, pmf.PRESETS, "progressive morphological filter (Zhang et al. 2003)"),
        "ptd": Method("ptd", ptd.ptd, ptd.PTDParams, ptd.PRESETS, "progressive TIN densification (Axelsson 2000)"),
        "auto": Method("auto", auto.auto, auto.AutoParams, auto.PRESETS, "majority vote of SMRF (2 settings), PMF, CSF and PTD"),
        "lowest": Method("lowest", baselines.lowest, baselines.LowestParams, baselines.LOWEST_PRESETS,
                         "lowest point per cell (baseline)"),
        "local_min": Method("local_min", baselines.local_min, baselines.LocalMinParams, baselines.LOCAL_MIN_PRESETS,
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
    p = fit_to_points(make_params(method, preset, **overrides), cloud, {k for k, v in overrides.items() if v is not None})
    if tiles is not None:
        from .tiles import ground_tiled

        return ground_tiled(cloud, method, p, tiles)
    return methods()[method].func(cloud, p)


#: Parameter fields that set a filter's grid cell (metres), in every method's dataclass.
GRID_FIELDS = ("cell", "cloth_resolution", "candidate_cell")


def fit_to_points(params, cloud: Cloud, given=()):
    """``params`` with every default grid cell (:data:`GRID_FIELDS`, nested parameter
    dataclasses too) coarsened so its grid is sized by the points, not by the bounding box
    (:func:`workstation.core.budget.fit_cell`): a few thousand points spread over kilometres
    then run in seconds instead of allocating a grid of the whole box. Cells in ``given``
    (chosen by the user) are kept; a grid too large for them is refused, naming the option.
    A change is logged with the old and new cell.
    """
    from workstation.core.budget import fit_cell
    from workstation.core.log import get_logger

    from .common import crs_unit_factors

    if cloud.n == 0:
        return params
    hf, _ = crs_unit_factors(cloud.crs)
    xy = cloud.xyz[:, :2]
    ext = (xy.max(axis=0) - xy.min(axis=0)) * hf
    local = None  # local metres, made only when a cell is too fine for the box

    def spread():
        nonlocal local
        local = (xy - xy.min(axis=0)) * hf if local is None else local
        return local

    def fit(p, prefix=""):
        changes = {}
        for f in dataclasses.fields(p):
            v = getattr(p, f.name)
            if dataclasses.is_dataclass(v) and not isinstance(v, type):
                changes[f.name] = fit(v, f"{prefix}{f.name}.")
            elif f.name in GRID_FIELDS and f.name not in given and isinstance(v, float):
                new = fit_cell(v, ext[0], ext[1], cloud.n, spread() if _too_fine(v, ext, cloud.n) else None)
                if new != v:
                    get_logger(__name__).warning(
                        "%s%s %g m -> %g m: %d points over %.0f m x %.0f m are too sparse for the default grid",
                        prefix, f.name, v, new, cloud.n, ext[0], ext[1])
                    changes[f.name] = new
        return dataclasses.replace(p, **changes) if changes else p

    return fit(params)


def _too_fine(cell: float, ext, n: int) -> bool:
    """Whether :func:`~workstation.core.budget.fit_cell` would consider coarsening ``cell``."""
    from workstation.core.budget import fit_cell

    return fit_cell(cell, ext[0], ext[1], n) != cell
