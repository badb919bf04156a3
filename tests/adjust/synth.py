"""Tiny deterministic ALS strips over an analytic scene, with known mounting errors.

The scene is the plane z = 0 plus square plates (roof facets) tilted in several directions.
Each pulse's true beam (true lever arm, boresight) is intersected exactly with the scene; the
recorded range gets noise and a range offset; the point is georeferenced with the nominal
mounting, the way the simulator does it, and the navigation solution is exact.
"""

from __future__ import annotations

import numpy as np

from workstation.adjust.trajectory import Navigation
from workstation.lidar.georef import GeorefChain, beam_direction, rotate_rpy

ORIGIN = np.array([500000.0, 5000000.0, 100.0])


def plates(rng, n=30, half=6.0, area=70.0):
    """(n, 3) centres, (n, 3) unit normals (tilt 15-40 deg, any azimuth), half side (m)."""
    c = np.column_stack([rng.uniform(-area, area, n), rng.uniform(-area, area, n), rng.uniform(4, 12, n)])
    tilt, az = np.radians(rng.uniform(15, 40, n)), rng.uniform(0, 2 * np.pi, n)
    nrm = np.column_stack([np.sin(tilt) * np.cos(az), np.sin(tilt) * np.sin(az), np.cos(tilt)])
    return c, nrm, half


def _to_map(rpy, v):
    w = rotate_rpy(rpy, v)
    return np.column_stack([w[:, 1], w[:, 0], -w[:, 2]])


def _intersect(o, u, scene):
    """Range along rays (o, u) (n, 3) to the first hit of the ground or a plate."""
    t = -o[:, 2] / u[:, 2]  # ground z = 0
    if scene is not None:
        c, nrm, half = scene
        for ci, ni in zip(c, nrm):
            ti = ((ci - o) @ ni) / (u @ ni)
            p = o + ti[:, None] * u
            inside = (np.abs(p[:, 0] - ci[0]) < half) & (np.abs(p[:, 1] - ci[1]) < half) & (ti > 0)
            t = np.where(inside & (ti < t), ti, t)
    return t


def fly(lines, scene, *, boresight_err_deg=(0, 0, 0), range_offset=0.0, lever_err=(0, 0, 0), noise=0.02,
        line_shift=None, scan_scale=0.0, lever=(0.1, 0.0, 0.25), prf=20_000.0, scan_hz=40.0, fov_deg=40.0, speed=50.0, seed=0):
    """Points (n, 3), attrs and the Navigation of ``lines`` = [(sid, x0, y0, heading_deg, length, height)].

    ``line_shift`` = {sid: (dE, dN, dU)} moves a line's navigation positions (a strip offset);
    ``scan_scale`` makes the true mirror angle the encoder's times (1 + scan_scale).
    """
    rng = np.random.default_rng(seed)
    nominal = GeorefChain(lever, (0.0, 0.0, 0.0))
    true = GeorefChain(tuple(np.add(lever, lever_err)), tuple(np.radians(boresight_err_deg)))
    xyz, sid, gps, nav_t, nav_p, nav_a = [], [], [], [], [], []
    t_start = 1000.0
    for k, (s, x0, y0, hdg, length, h) in enumerate(lines):
        dur = length / speed
        t = np.arange(0, dur, 1 / prf)
        yaw = np.radians(hdg)
        fwd = np.array([np.sin(yaw), np.cos(yaw), 0.0])
        pos = np.array([x0, y0, h]) + t[:, None] * speed * fwd
        rpy = np.column_stack([0.01 * np.sin(t), 0.005 * np.cos(0.7 * t), np.full(t.size, yaw)])
        u_ = np.mod(t * scan_hz, 1.0)
        A = np.radians(fov_deg) / 2
        alpha = np.where(u_ < 0.5, A * (4 * u_ - 1), A * (3 - 4 * u_))
        d_s = beam_direction(alpha)
        o = pos + _to_map(rpy, np.broadcast_to(np.asarray(true.lever_arm), (t.size, 3)))
        u = _to_map(rpy, beam_direction(alpha * (1 + scan_scale)) @ true.R_bs.T)
        rng_true = _intersect(o, u, scene)
        r = rng_true + range_offset + rng.normal(0, noise, t.size)
        pos_nav = pos + np.asarray((line_shift or {}).get(s, (0, 0, 0)), float)
        xyz.append(nominal.forward(r, d_s, pos_nav, rpy))
        sid.append(np.full(t.size, s, np.uint16))
        gps.append(t_start + t)
        tt = np.arange(0, dur + 0.02, 0.01)
        nav_t.append(t_start + tt)
        nav_p.append(np.array([x0, y0, h]) + tt[:, None] * speed * fwd + np.asarray((line_shift or {}).get(s, (0, 0, 0)), float))
        nav_a.append(np.column_stack([0.01 * np.sin(tt), 0.005 * np.cos(0.7 * tt), np.full(tt.size, yaw)]))
        t_start += dur + 60.0
    nav = Navigation(np.concatenate(nav_t), np.concatenate(nav_p) + ORIGIN, np.concatenate(nav_a))
    attrs = {"point_source_id": np.concatenate(sid), "gps_time": np.concatenate(gps)}
    n = attrs["gps_time"].size
    attrs["number_of_returns"] = np.ones(n, np.uint8)
    attrs["intensity"] = rng.integers(0, 65535, n).astype(np.uint16)
    return np.concatenate(xyz) + ORIGIN, attrs, nav


def calibration_lines(length=160.0, h=250.0):
    """Four overlapping lines: two pairs flown in opposite directions and a same-direction pair."""
    return [(1, -80.0, -40.0, 90.0, length, h), (2, 80.0, 0.0, 270.0, length, h),
            (3, -80.0, 40.0, 90.0, length, h), (4, 80.0, 80.0, 270.0, length, h)]
