"""Demo step of registration: two overlapping stations registered, merged, result written.

With the simulated TLS survey of an earlier step (``ctx.products["tls_laz"]``, stations told
apart by ``point_source_id``), the second station is moved into its own frame (40 degrees
about z, 7 m away) and registered globally onto the first from the identity. Without it, two
synthetic stations of a small built-up block are made here (ground, box buildings with walls
and roofs), the second in its own rotated frame,
with a rough station pose (3 degrees and 0.5 m off, as from a field sketch or GNSS) refined
by ICP. (Global registration of these synthetic stations is not reliable yet: every box face
is sampled, including faces a real scanner would not see, which defeats FPFH's normal
orientation; the simulator's stations will not have that problem.)
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud


def _box_surface(rng, lo, hi, density):
    """Points on the four walls and the roof of an axis-aligned box, ``density`` per m^2."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    d = hi - lo
    faces = []
    for axis in (0, 1):  # walls
        for side in (lo, hi):
            other = 1 - axis
            area = d[other] * d[2]
            n = rng.poisson(density * area)
            p = np.empty((n, 3))
            p[:, axis] = side[axis]
            p[:, other] = rng.uniform(lo[other], hi[other], n)
            p[:, 2] = rng.uniform(lo[2], hi[2], n)
            faces.append(p)
    n = rng.poisson(density * d[0] * d[1])
    faces.append(np.column_stack([rng.uniform(lo[0], hi[0], n), rng.uniform(lo[1], hi[1], n), np.full(n, hi[2])]))
    return np.vstack(faces)


def synthetic_block(seed: int = 0, density: float = 40.0) -> np.ndarray:
    """A 40 m x 30 m block: gently sloping ground and five buildings of different sizes."""
    rng = np.random.default_rng(seed)
    n = int(density * 40 * 30)
    x, y = rng.uniform(0, 40, n), rng.uniform(0, 30, n)
    ground = np.column_stack([x, y, 0.02 * x + 0.01 * y])
    boxes = [((3, 3, 0), (11, 9, 6)), ((15, 4, 0), (19, 14, 9)), ((24, 2, 0), (36, 7, 4)),
             ((6, 17, 0), (12, 27, 12)), ((26, 15, 0), (33, 26, 7))]
    inside = np.zeros(n, bool)
    for lo, hi in boxes:
        inside |= (x > lo[0]) & (x < hi[0]) & (y > lo[1]) & (y < hi[1])
    parts = [ground[~inside]] + [_box_surface(rng, lo, hi, density) for lo, hi in boxes]
    return np.vstack(parts)


def _rz(deg):
    a = np.radians(deg)
    return np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])


def synthetic_stations(seed: int = 0, density: float = 15.0) -> tuple[Cloud, Cloud, np.ndarray]:
    """Two stations of :func:`synthetic_block` overlapping by about half, and the true
    4x4 transform station B -> station A (both in local metres)."""
    from workstation.registration.transforms import apply_transform, invert, make_transform

    a_pts = synthetic_block(seed, density)
    b_pts = synthetic_block(seed + 1, density)
    a = a_pts[a_pts[:, 0] < 26]
    b_world = b_pts[b_pts[:, 0] > 12]
    G = make_transform(_rz(40.0), [-6.0, 4.0, 0.3])  # world (= station A frame) -> station B frame
    b = apply_transform(G, b_world)
    ca = Cloud(a, {"intensity": np.full(len(a), 1000)})
    cb = Cloud(b, {"intensity": np.full(len(b), 2000)})
    return cb, ca, invert(G)


def _tls_stations(cloud: Cloud):
    """The first two stations of a multi-station TLS cloud (by ``point_source_id``), or None."""
    if "point_source_id" not in cloud.attrs:
        return None
    ids = np.unique(cloud.attrs["point_source_id"])
    if ids.size < 2:
        return None
    return [cloud[cloud.attrs["point_source_id"] == i] for i in ids[:2]]


def step(ctx) -> dict:
    from workstation.io import atomic_path, read_cloud, write_cloud
    from workstation.registration.merge import merge_clouds, transform_cloud
    from workstation.registration.register import RegisterParams, register
    from workstation.registration.transforms import transform_error

    out = Path(ctx.outdir)
    tls = ctx.products.get("tls_laz")
    truth = init = None
    params = RegisterParams()
    stations = _tls_stations(read_cloud(tls)) if tls else None
    if stations is not None:
        from workstation.registration.transforms import invert, make_transform

        G = make_transform(_rz(40.0), [5.0, -4.0, 0.2])
        target, source = stations[0], transform_cloud(stations[1], G)
        truth = invert(G)
    else:
        from workstation.registration.transforms import make_transform

        source, target, truth = synthetic_stations(ctx.seed)
        init = truth @ make_transform(_rz(3.0), [0.5, -0.4, 0.1])
        params = RegisterParams(method="icp", voxel_size=0.3)
    res = register(source, target, params, init=init)
    moved = transform_cloud(source, res.transform)
    merged = merge_clouds([target, source], [np.eye(4), res.transform])
    p_moved = out / "registered_source.laz"
    p_merged = out / "merged_stations.laz"
    p_json = out / "registration.json"
    write_cloud(moved, p_moved, overwrite=True)
    write_cloud(merged, p_merged, overwrite=True)
    summary = res.to_dict()
    if truth is not None:
        rot, tr = transform_error(res.transform, truth, center=source.xyz.mean(axis=0))
        summary.update({"rotation_error_deg": rot, "translation_error_m": tr})
    with atomic_path(p_json, overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(summary, indent=2, default=float))
    ctx.summaries["registration"] = summary
    return {"registered_laz": p_moved, "merged_laz": p_merged, "registration_json": p_json}
