"""Scan-line point layouts shared by the mesh tests: airborne / terrestrial strips, points
close along each line, lines far apart."""

from __future__ import annotations

import numpy as np


def scan_line_xy(gap: float, along: float, angle_deg: float = 30.0, size: float = 20.0,
                 hole: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """x, y (m) of lines ``gap`` apart with points ``along`` apart on each, at ``angle_deg``
    from x, over a size x size square, less a ``hole`` x ``hole`` square in its middle."""
    u, v = np.meshgrid(np.arange(-size, 2 * size, along), np.arange(-size, 2 * size, gap))
    c, s = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
    x, y = (c * u - s * v).ravel(), (s * u + c * v).ravel()
    keep = (x >= 0) & (x <= size) & (y >= 0) & (y <= size)
    if hole > 0:
        keep &= (np.abs(x - size / 2) > hole / 2) | (np.abs(y - size / 2) > hole / 2)
    return x[keep], y[keep]
