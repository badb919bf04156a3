"""Merge registered clouds: apply poses, keep every attribute, tag each input, thin overlaps.

The attribute set of the result is the union of the inputs' (missing values filled as in
:func:`~workstation.core.cloud.concatenate`); ``point_source_id`` records the input each
point came from; normals are rotated with their points. Optional duplicate removal drops the
points of a later input that lie within a distance of an earlier input's points (overlap
thinning, the "keep the first scan" rule of CloudCompare's merge + subsample); optional voxel
thinning then keeps the first point of every voxel, so attributes stay those of real points.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud, concatenate
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger

from .transforms import apply_transform, split_transform

log = get_logger(__name__)
STAGE = "merge"


@dataclass(frozen=True)
class MergeParams:
    """Parameters of :func:`merge_clouds`.

    Attributes
    ----------
    duplicate_distance : float, optional
        Metres (CRS units): a point of input k closer than this to any point of inputs
        0..k-1 is dropped. None keeps every point.
    voxel_size : float, optional
        Metres: keep the first point of each voxel of this edge after merging. None keeps all.
    source_ids : tuple of int, optional
        ``point_source_id`` of each input (default 1, 2, ...). Existing values are replaced.
    check_crs : bool
        Refuse inputs with different CRSs (None joins anything).
    """

    duplicate_distance: float | None = None
    voxel_size: float | None = None
    source_ids: tuple | None = None
    check_crs: bool = True


def transform_cloud(cloud: Cloud, T: np.ndarray) -> Cloud:
    """A new cloud with points mapped by a 4x4 (similarity) transform; normals rotated."""
    T = np.asarray(T, dtype=np.float64)
    if T.shape != (4, 4) or not np.isfinite(T).all():
        raise InvalidInputError(f"pose must be a finite 4x4 matrix, got shape {T.shape}", field="pose")
    out = cloud.with_xyz(apply_transform(T, cloud.xyz))
    if "normal" in cloud.attrs:
        R, _, _ = split_transform(T)
        out = out.with_attrs(normal=(np.asarray(cloud.attrs["normal"], np.float64) @ R.T).astype(np.float32))
    return out


def merge_clouds(clouds: list[Cloud], poses: list | None = None, params: MergeParams = MergeParams()) -> Cloud:
    """Merge clouds into one frame.

    Parameters
    ----------
    clouds : list of Cloud
    poses : list of (4, 4) float, optional
        Pose of each cloud (its coordinates -> merged frame); identity when None.
    params : MergeParams

    Returns
    -------
    Cloud
        Union of points and attributes, ``point_source_id`` per input.

    Examples
    --------
    >>> a = Cloud(np.zeros((2, 3)), {"intensity": [1, 2]})
    >>> b = Cloud(np.ones((1, 3)), {"classification": [6]})
    >>> m = merge_clouds([a, b])
    >>> m.attrs["point_source_id"].tolist(), m.attrs["intensity"].tolist()
    ([1, 1, 2], [1, 2, 0])
    """
    from scipy.spatial import cKDTree

    clouds = list(clouds)
    if not clouds:
        raise InvalidInputError("nothing to merge", "give at least one cloud")
    if poses is not None and len(poses) != len(clouds):
        raise InvalidInputError(f"{len(poses)} poses for {len(clouds)} clouds", field="poses")
    ids = params.source_ids or tuple(range(1, len(clouds) + 1))
    if len(ids) != len(clouds):
        raise InvalidInputError(f"{len(ids)} source ids for {len(clouds)} clouds", field="source_ids")
    crs_set = {c.crs for c in clouds if c.crs}
    if params.check_crs and len(crs_set) > 1:
        raise InvalidInputError(f"inputs have {len(crs_set)} different CRSs",
                                "reproject them to one CRS first (ws convert --to-crs)", field="crs")
    parts = []
    trees = []
    for k, c in enumerate(clouds):
        cc = c if poses is None else transform_cloud(c, poses[k])
        cc = cc.with_attrs(point_source_id=np.full(cc.n, ids[k]))
        if params.duplicate_distance and trees:
            dup = np.zeros(cc.n, dtype=bool)
            for t in trees:
                d, _ = t.query(cc.xyz, distance_upper_bound=float(params.duplicate_distance), workers=-1)
                dup |= np.isfinite(d)
            log.info("input %d: %d of %d points duplicate earlier inputs", k, int(dup.sum()), cc.n)
            cc = cc[~dup]
        if params.duplicate_distance and cc.n:
            trees.append(cKDTree(cc.xyz))
        parts.append(cc)
    merged = concatenate(parts, check_crs=params.check_crs)
    if params.voxel_size:
        v = float(params.voxel_size)
        keys = np.floor((merged.xyz - merged.xyz.min(axis=0)) / v).astype(np.int64)
        _, first = np.unique(keys, axis=0, return_index=True)
        merged = merged[np.sort(first)]
    if merged.n == 0:
        raise StageError(STAGE, "the merged cloud is empty", "check the inputs and the thinning distances")
    return merged.with_history(STAGE, {"inputs": len(clouds), "duplicate_distance": params.duplicate_distance,
                                       "voxel_size": params.voxel_size})
