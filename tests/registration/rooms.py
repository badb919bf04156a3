"""Synthetic cluttered indoor scenes and partial RGB-D-like views."""
import numpy as np


def room_mesh(seed=0):
    """A room 5-7 m x 4-6 m with counters along two walls, wall cabinets, a table, boxes and
    round objects scattered on the surfaces (metres, floor at z = 0)."""
    import trimesh
    rng = np.random.default_rng(seed)
    T = trimesh.transformations.translation_matrix
    L, W, H = rng.uniform(5.0, 7.0), rng.uniform(4.0, 6.0), rng.uniform(2.4, 2.8)
    parts = [trimesh.creation.box(extents=(L, W, H), transform=T((0, 0, H / 2)))]
    tops = []  # (x0, x1, y0, y1, z) of horizontal surfaces objects stand on
    x = -L / 2
    while x < L / 2 - 0.5:  # counter run along the wall y = -W/2, units of varied width and height
        w = rng.uniform(0.4, 1.0); h = rng.choice([0.9, 0.9, 0.75, 1.1]); d = rng.uniform(0.55, 0.65)
        parts.append(trimesh.creation.box(extents=(w, d, h), transform=T((x + w / 2, -W / 2 + d / 2, h / 2))))
        tops.append((x, x + w, -W / 2, -W / 2 + d, h)); x += w + rng.choice([0.0, 0.0, 0.3])
        if rng.random() < 0.5:
            parts.append(trimesh.creation.box(extents=(w, 0.35, 0.7), transform=T((x - w / 2, -W / 2 + 0.175, 1.85))))
    y = -W / 2 + 0.7
    while y < W / 2 - 0.5:  # second run along x = -L/2
        w = rng.uniform(0.4, 1.0); h = rng.choice([0.9, 1.9, 0.9]); d = 0.6
        parts.append(trimesh.creation.box(extents=(d, w, h), transform=T((-L / 2 + d / 2, y + w / 2, h / 2))))
        tops.append((-L / 2, -L / 2 + d, y, y + w, h)); y += w
    tx, ty = rng.uniform(-0.5, 1.0), rng.uniform(-0.5, 1.0)
    M = trimesh.transformations.rotation_matrix(rng.uniform(-0.5, 0.5), (0, 0, 1)); M[:3, 3] = (tx, ty, 0.74)
    parts.append(trimesh.creation.box(extents=(1.4, 0.8, 0.04), transform=M))
    for sx in (-0.6, 0.6):
        for sy in (-0.3, 0.3):
            parts.append(trimesh.creation.cylinder(radius=0.03, height=0.72, transform=M @ T((sx, sy, -0.37))))
    tops.append((tx - 0.4, tx + 0.4, ty - 0.25, ty + 0.25, 0.76))
    for _ in range(14):  # clutter on the surfaces
        x0, x1, y0, y1, z = tops[rng.integers(len(tops))]
        px, py = rng.uniform(x0 + 0.1, max(x1 - 0.1, x0 + 0.11)), rng.uniform(y0 + 0.1, max(y1 - 0.1, y0 + 0.11))
        k = rng.integers(3)
        if k == 0:
            e = rng.uniform(0.08, 0.3, 3)
            Mo = trimesh.transformations.rotation_matrix(rng.uniform(0, np.pi), (0, 0, 1)); Mo[:3, 3] = (px, py, z + e[2] / 2)
            parts.append(trimesh.creation.box(extents=e, transform=Mo))
        elif k == 1:
            r, h = rng.uniform(0.04, 0.12), rng.uniform(0.1, 0.35)
            parts.append(trimesh.creation.cylinder(radius=r, height=h, transform=T((px, py, z + h / 2))))
        else:
            r = rng.uniform(0.05, 0.15)
            parts.append(trimesh.creation.icosphere(subdivisions=2, radius=r).apply_translation((px, py, z + r)))
    return trimesh.util.concatenate(parts), (L, W, H)


def view(mesh, position, yaw_deg, pitch_deg=-30.0, hfov=90.0, vfov=70.0, step=0.5, noise=0.004, max_range=3.0, seed=0):
    """Points seen from ``position`` looking along ``yaw_deg`` / ``pitch_deg`` (ray casting,
    Gaussian range noise)."""
    from regutil import tls_station

    return tls_station(mesh, position, step, max_range, noise, seed, (yaw_deg - hfov / 2, yaw_deg + hfov / 2),
                       (pitch_deg - vfov / 2, pitch_deg + vfov / 2))


def view_pair_with_sensors(seed, lo=0.2, hi=0.35, step=0.5):
    """Two views of one room whose overlap (share of the first within 5 cm of the second) lies in
    [lo, hi], with the sensor positions: ``(a, b, overlap, position_a, position_b)``."""
    from scipy.spatial import cKDTree
    rng = np.random.default_rng(seed)
    mesh, (L, W, H) = room_mesh(seed)
    for _ in range(200):
        p1 = np.array([rng.uniform(-L / 4, L / 4), rng.uniform(-W / 4, W / 4), rng.uniform(1.3, 1.7)])
        p2 = p1 + np.array([*rng.uniform(-0.8, 0.8, 2), rng.uniform(-0.2, 0.2)])
        y1 = rng.uniform(0, 360); y2 = y1 + rng.choice([-1, 1]) * rng.uniform(40, 90)
        a = view(mesh, p1, y1, step=step, seed=seed); b = view(mesh, p2, y2, step=step, seed=seed + 1)
        if len(a) < 5000 or len(b) < 5000:
            continue
        ov = float((cKDTree(b).query(a, distance_upper_bound=0.05)[0] < 0.05).mean())
        if lo <= ov <= hi:
            return a, b, ov, p1, p2
    raise RuntimeError("no view pair with that overlap")
